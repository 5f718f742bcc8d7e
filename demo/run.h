/* One run of cc_demo: build the scene, step and paint every frame, write it, summarise. */
#ifndef DEMO_RUN_H
#define DEMO_RUN_H

#include "args.h"

/* Returns the process exit code: 0, or 1 after printing what failed (I/O or the library). */
int demo_run(const demo_options *o);

#endif
