/* Writes frames as binary PPM (P6, maxval 255) and names them frame_0000.ppm, frame_0001.ppm, ...
 * so that ffmpeg's frame_%04d pattern and a shell glob both list them in order. */
#include "ppm.h"

#include <stdio.h>

size_t demo_ppm_header(char *buf, size_t size, int w, int h)
{
    int n = snprintf(buf, size, "P6\n%d %d\n255\n", w, h);
    return n < 0 ? 0 : (size_t)n;
}

int demo_ppm_write(const char *path, const unsigned char *rgb, int w, int h)
{
    char head[64];
    size_t n = demo_ppm_header(head, sizeof head, w, h);
    size_t bytes = (size_t)w * (size_t)h * 3u;
    int ok;
    FILE *f = fopen(path, "wb");
    if (f == NULL)
        return -1;
    ok = fwrite(head, 1, n, f) == n && fwrite(rgb, 1, bytes, f) == bytes;
    if (fclose(f) != 0)
        ok = 0;
    return ok ? 0 : -1;
}

int demo_frame_path(char *buf, size_t size, const char *dir, long index)
{
    int n = snprintf(buf, size, "%s/frame_%04ld.ppm", dir, index);
    return (n < 0 || (size_t)n >= size) ? -1 : 0;
}
