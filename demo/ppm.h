/* Binary PPM (P6) output: the simplest picture format every converter reads. */
#ifndef DEMO_PPM_H
#define DEMO_PPM_H

#include <stddef.h>

/* Writes "P6\n<w> <h>\n255\n" into buf (at least 32 bytes) and returns its length. */
size_t demo_ppm_header(char *buf, size_t size, int w, int h);

/* Writes w*h RGB triples (row by row, top row first) as a P6 file. 0 on success, -1 on an I/O
 * error (errno says which). */
int demo_ppm_write(const char *path, const unsigned char *rgb, int w, int h);

/* "<dir>/frame_<index, 4 digits or more>.ppm" into buf; 0, or -1 when buf is too small. */
int demo_frame_path(char *buf, size_t size, const char *dir, long index);

#endif
