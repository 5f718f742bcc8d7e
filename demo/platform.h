/* What cc_demo needs that C99 lacks: making folders, a wall clock, knowing a terminal. */
#ifndef DEMO_PLATFORM_H
#define DEMO_PLATFORM_H

/* Creates the folder and its missing parents (like mkdir -p). 0, or -1 (errno says why). */
int demo_make_dir(const char *path);
/* Seconds on a monotonic clock, for the wall time of the summary (never for the pictures). */
double demo_wall_seconds(void);

/* 1 when stderr is a terminal (progress then rewrites one line), else 0. */
int demo_is_terminal_stderr(void);

#endif
