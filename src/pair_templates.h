/* Every pair-function template, in dependency order, for the precision bound just before by
 * precision_double.h or precision_float.h. Included once by pair_double.c and once by
 * pair_float.c: that is how each algorithm is written once for both precisions. */
#include "helpers.inc"  /* vector arithmetic, validation, segment geometry */
#include "solver.inc"   /* the relative-frame time-of-impact solver */
#include "detect.inc"   /* static overlap and push-apart */
#include "sweep.inc"    /* time of impact, circle-circle and circle-segment */
#include "respond.inc"  /* impulses */
#include "segment.inc"  /* closest point on a segment */
