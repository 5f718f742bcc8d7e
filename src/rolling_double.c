/* Rolling to rest (rolling.inc) in double: the public cc_sweep_rolling, cc_sweep_segment_rolling
 * and cc_rolling_advance, and the solver the world's rolling circles use (world/roll.c), whose
 * entry points cc__roll_motion, cc__roll_sweep and cc__roll_sweep_segment are extern here. Its own
 * object, apart from pair_double.c, so that the pair functions' size figures stay theirs. */
#include "cc_internal.h"

#include "precision_double.h"
#include "helpers.inc"
#include "solver.inc"
#define CC__ROLL_LINK
#include "rolling.inc"
