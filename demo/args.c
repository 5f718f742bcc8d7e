/* Parses cc_demo's options strictly: every value is range-checked, nothing is guessed, and the
 * first problem found is reported in words that say what to type instead. */
#include "args.h"

#include "scene.h"

#include <circlecollide.h>
#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

/* Limits that keep a run finite and a frame addressable; generous for real use. */
#define DEMO_MIN_SIDE 16
#define DEMO_MAX_SIDE 8192
#define DEMO_MAX_FRAMES 1000000L
#define DEMO_MAX_FPS 1000.0

void demo_print_usage(FILE *f)
{
    fprintf(f,
        "usage: cc_demo --scene NAME --frames N --out DIR [options]\n"
        "\n"
        "Simulates a scene with circlecollide and writes binary PPM (P6) frames\n"
        "DIR/frame_0000.ppm, DIR/frame_0001.ppm, ... (DIR is created if missing).\n"
        "The same command always writes the same bytes.\n"
        "\n"
        "  --scene NAME   pool        a 15-ball rack break with cushions and pockets\n"
        "                 air-hockey  a fast puck between two moving mallets and the rails\n"
        "                 cradle      Newton's cradle: touching balls in a row, 1 to 3 hitting\n"
        "                 gas         thousands of circles in a box, one heavy one among them\n"
        "                 tunnel      fast bullets in a box in EXACT, SWEPT and DISCRETE mode\n"
        "                             side by side: who passes through whom\n"
        "                 hard-disks  1040 disks in a periodic box at area fraction 0.70,\n"
        "                             with their pressure from the virial\n"
        "  --frames N     number of frames to write, 1 to %ld\n"
        "  --out DIR      output folder\n"
        "  --size WxH     frame size in pixels, each side %d to %d (default 640x360)\n"
        "  --fps F        frames per second of simulated time, (0, %g] (default 60)\n"
        "  --mode M       exact | swept | discrete: the world's mode (default exact;\n"
        "                 the tunnel scene always shows all three)\n"
        "  --seed S       seed of the random starts of gas, air-hockey and hard-disks,\n"
        "                 an unsigned integer (default 1)\n"
        "  --help         this text\n"
        "\n"
        "Progress goes to stderr, then a summary: collisions, energy drift, wall time.\n"
        "Make a video:  ffmpeg -framerate 60 -i DIR/frame_%%04d.ppm -pix_fmt yuv420p out.mp4\n"
        "Make a GIF:    convert -delay 2 -loop 0 DIR/frame_*.ppm out.gif\n",
        DEMO_MAX_FRAMES, DEMO_MIN_SIDE, DEMO_MAX_SIDE, DEMO_MAX_FPS);
}

static int fail(char *err, size_t n, const char *fmt, ...)
{
    va_list ap;
    if (n > 0) {
        va_start(ap, fmt);
        vsnprintf(err, n, fmt, ap);
        va_end(ap);
    }
    return DEMO_ARGS_ERROR;
}

/* A whole decimal integer in [lo, hi]: no sign games, no trailing characters. */
static int parse_long(const char *s, long lo, long hi, long *out)
{
    char *end;
    long v;
    if (*s < '0' || *s > '9')
        return 0;
    errno = 0;
    v = strtol(s, &end, 10);
    if (errno != 0 || *end != '\0' || v < lo || v > hi)
        return 0;
    *out = v;
    return 1;
}

static int parse_seed(const char *s, unsigned long long *out)
{
    char *end;
    unsigned long long v;
    if (*s < '0' || *s > '9')
        return 0; /* strtoull would quietly wrap "-1" */
    errno = 0;
    v = strtoull(s, &end, 10);
    if (errno != 0 || *end != '\0')
        return 0;
    *out = v;
    return 1;
}

static int parse_size(const char *s, int *w, int *h)
{
    char buf[32];
    const char *x = strchr(s, 'x');
    long a, b;
    size_t n;
    if (x == NULL)
        return 0;
    n = (size_t)(x - s);
    if (n == 0 || n >= sizeof buf)
        return 0;
    memcpy(buf, s, n);
    buf[n] = '\0';
    if (!parse_long(buf, DEMO_MIN_SIDE, DEMO_MAX_SIDE, &a) ||
        !parse_long(x + 1, DEMO_MIN_SIDE, DEMO_MAX_SIDE, &b))
        return 0;
    *w = (int)a;
    *h = (int)b;
    return 1;
}

static int parse_fps(const char *s, double *out)
{
    char *end;
    double v;
    if ((*s < '0' || *s > '9') && *s != '.')
        return 0;
    errno = 0;
    v = strtod(s, &end);
    if (errno != 0 || *end != '\0' || !(v > 0.0) || v > DEMO_MAX_FPS)
        return 0;
    *out = v;
    return 1;
}

static int parse_mode(const char *s, int *out)
{
    if (strcmp(s, "exact") == 0)
        *out = CC_MODE_EXACT;
    else if (strcmp(s, "swept") == 0)
        *out = CC_MODE_SWEPT;
    else if (strcmp(s, "discrete") == 0)
        *out = CC_MODE_DISCRETE;
    else
        return 0;
    return 1;
}

int demo_parse_args(int argc, char **argv, demo_options *o, char *err, size_t err_size)
{
    int i;
    int have_frames = 0;
    if (err_size > 0)
        err[0] = '\0';
    o->scene = NULL;
    o->out = NULL;
    o->frames = 0;
    o->width = 640;
    o->height = 360;
    o->fps = 60.0;
    o->mode = CC_MODE_EXACT;
    o->seed = 1;

    for (i = 1; i < argc; ++i) {
        const char *opt = argv[i];
        const char *val;
        if (strcmp(opt, "--help") == 0 || strcmp(opt, "-h") == 0)
            return DEMO_ARGS_HELP;
        if (strncmp(opt, "--", 2) != 0)
            return fail(err, err_size, "unexpected argument '%s' (options start with --)", opt);
        if (strcmp(opt, "--scene") != 0 && strcmp(opt, "--frames") != 0 &&
            strcmp(opt, "--out") != 0 && strcmp(opt, "--size") != 0 &&
            strcmp(opt, "--fps") != 0 && strcmp(opt, "--mode") != 0 &&
            strcmp(opt, "--seed") != 0)
            return fail(err, err_size, "unknown option '%s'", opt);
        if (i + 1 >= argc)
            return fail(err, err_size, "option %s needs a value", opt);
        val = argv[++i];

        if (strcmp(opt, "--scene") == 0) {
            if (demo_find_scene(val) == NULL)
                return fail(err, err_size,
                            "unknown scene '%s' (choose pool, air-hockey, cradle, gas, tunnel "
                            "or hard-disks)",
                            val);
            o->scene = val;
        } else if (strcmp(opt, "--frames") == 0) {
            if (!parse_long(val, 1, DEMO_MAX_FRAMES, &o->frames))
                return fail(err, err_size, "--frames wants a whole number from 1 to %ld, not '%s'",
                            DEMO_MAX_FRAMES, val);
            have_frames = 1;
        } else if (strcmp(opt, "--out") == 0) {
            if (val[0] == '\0')
                return fail(err, err_size, "--out wants a folder name, not an empty string");
            o->out = val;
        } else if (strcmp(opt, "--size") == 0) {
            if (!parse_size(val, &o->width, &o->height))
                return fail(err, err_size,
                            "--size wants WxH with each side from %d to %d (e.g. 640x360), not '%s'",
                            DEMO_MIN_SIDE, DEMO_MAX_SIDE, val);
        } else if (strcmp(opt, "--fps") == 0) {
            if (!parse_fps(val, &o->fps))
                return fail(err, err_size, "--fps wants a number above 0 and at most %g, not '%s'",
                            DEMO_MAX_FPS, val);
        } else if (strcmp(opt, "--mode") == 0) {
            if (!parse_mode(val, &o->mode))
                return fail(err, err_size, "--mode wants exact, swept or discrete, not '%s'", val);
        } else {
            if (!parse_seed(val, &o->seed))
                return fail(err, err_size, "--seed wants an unsigned whole number, not '%s'", val);
        }
    }
    if (o->scene == NULL)
        return fail(err, err_size,
                    "missing --scene (pool, air-hockey, cradle, gas, tunnel or hard-disks)");
    if (!have_frames)
        return fail(err, err_size, "missing --frames N");
    if (o->out == NULL)
        return fail(err, err_size, "missing --out DIR");
    return DEMO_ARGS_RUN;
}
