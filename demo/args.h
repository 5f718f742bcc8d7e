/* cc_demo's command line: the options, their defaults and their parser. Kept apart from main so
 * that every error path is unit-tested without running a simulation. */
#ifndef DEMO_ARGS_H
#define DEMO_ARGS_H

#include <stddef.h>
#include <stdio.h>

typedef struct demo_options {
    const char *scene; /* a name that demo_find_scene knows */
    const char *out;   /* folder for frame_NNNN.ppm */
    long frames;       /* how many frames to write */
    int width, height; /* frame size in pixels */
    double fps;        /* frames per second of simulated time */
    int mode;          /* a cc_mode; the tunnel scene ignores it (it shows all three) */
    unsigned long long seed; /* PRNG seed of the scenes with random starts (gas, air-hockey) */
} demo_options;

#define DEMO_ARGS_RUN 0    /* options valid: run */
#define DEMO_ARGS_HELP 1   /* --help: print the usage and exit 0 */
#define DEMO_ARGS_ERROR 2  /* bad command line: err holds the reason; exit with this code */

/* Fills o from argv[1..argc). Returns DEMO_ARGS_RUN, DEMO_ARGS_HELP or DEMO_ARGS_ERROR with a
 * one-line English reason in err (always NUL-terminated when err_size > 0). o->scene and o->out
 * point into argv. */
int demo_parse_args(int argc, char **argv, demo_options *o, char *err, size_t err_size);

/* The --help text. */
void demo_print_usage(FILE *f);

#endif
