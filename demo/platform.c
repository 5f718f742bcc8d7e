/* POSIX (or Windows) calls behind a C99 face: mkdir -p, a monotonic clock, isatty. The clock only
 * measures how long a run took; nothing drawn depends on it. */
#if !defined(_WIN32)
#define _POSIX_C_SOURCE 200809L
#endif

#include "platform.h"

#include <errno.h>
#include <string.h>
#include <time.h>

#if defined(_WIN32)
#include <direct.h>
#include <io.h>
#include <sys/stat.h>
#define DEMO_BACKSLASH_SEPARATES 1

static int make_one(const char *path)
{
    struct _stat st;
    if (_stat(path, &st) == 0)
        return (st.st_mode & _S_IFDIR) ? 0 : (errno = ENOTDIR, -1);
    if (_mkdir(path) == 0)
        return 0;
    /* made by another process since the look above (parallel runs share parent folders) */
    return errno == EEXIST && _stat(path, &st) == 0 && (st.st_mode & _S_IFDIR) ? 0 : -1;
}

double demo_wall_seconds(void)
{
    return (double)clock() / CLOCKS_PER_SEC;
}

int demo_is_terminal_stderr(void)
{
    return _isatty(2) != 0;
}
#else
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>
#define DEMO_BACKSLASH_SEPARATES 0

static int make_one(const char *path)
{
    struct stat st;
    if (stat(path, &st) == 0)
        return S_ISDIR(st.st_mode) ? 0 : (errno = ENOTDIR, -1);
    if (mkdir(path, 0777) == 0)
        return 0;
    /* made by another process since the look above (parallel runs share parent folders) */
    return errno == EEXIST && stat(path, &st) == 0 && S_ISDIR(st.st_mode) ? 0 : -1;
}

double demo_wall_seconds(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_MONOTONIC, &ts) != 0)
        return (double)clock() / CLOCKS_PER_SEC;
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int demo_is_terminal_stderr(void)
{
    return isatty(2) != 0;
}
#endif

int demo_make_dir(const char *path)
{
    /* like mkdir -p: each parent first, cut at every separator after the first character */
    char buf[4096];
    size_t i, n = strlen(path);
    if (n == 0 || n >= sizeof buf) {
        errno = ENAMETOOLONG;
        return -1;
    }
    memcpy(buf, path, n + 1);
    for (i = 1; i < n; ++i)
        if (buf[i] == '/' || (DEMO_BACKSLASH_SEPARATES && buf[i] == '\\')) {
            char sep = buf[i];
            buf[i] = '\0';
            if (make_one(buf) != 0)
                return -1;
            buf[i] = sep;
        }
    return make_one(buf);
}
