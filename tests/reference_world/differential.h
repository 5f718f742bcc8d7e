/* Differential runs: one random scene (seeded) played through two simulators call by call --
 * the library's EXACT world and the reference world, or two worlds of different shapes (all
 * pairs against the grid) -- comparing every result code, every contact event (pair or wall,
 * time, impulse, normal) and the states after every step. Horizons are kept short: after each
 * step the reference is set to the world's state, so that rounding differences do not grow
 * through chaos from one step to the next. A difference is a failure unless something that
 * rounding decides explains it: a near tie between two events, a near graze, an approach at
 * the rounding threshold, or states already apart by more than rounding. */
#ifndef CC_DIFFERENTIAL_H
#define CC_DIFFERENTIAL_H

#include "circlecollide.h"

#include <stdint.h>

typedef enum dw_pairing {
    DW_WORLD_VS_REFERENCE = 0, /* the world (its shape drawn per scene) against the reference */
    DW_SMALL_VS_GRID = 1       /* all-pairs world (max_circles <= 32) against a gridded one */
} dw_pairing;

/* How a scene's comparison ended. */
typedef enum dw_end {
    DW_END_DONE = 0,     /* every step compared, or the event budget reached */
    DW_END_TIE,          /* a near tie, graze or threshold approach: rounding may reorder */
    DW_END_DIVERGED,     /* states apart by more than rounding after a legitimate doubt */
    DW_END_JAMMED,       /* the reference hit its cap of impacts in a step: a circle squeezed by a
                            kinematic body (the header's "impossible scene"), whose events never end */
    DW_END_FAILED,       /* a difference nothing explains: a bug */
    DW_END_COUNT
} dw_end;

typedef struct dw_result {
    dw_end end;
    unsigned long events_compared; /* contact events matched in both */
    unsigned long sensor_events_compared;
    unsigned long steps_compared;
    unsigned long calls;           /* API calls made on each simulator */
    unsigned long batches;         /* of those, batch adds (cc_world_add_circles) */
    unsigned long batches_refused; /* batch adds both refused alike (an invalid circle, full) */
    double worst_dt;               /* largest |t_a - t_b| / time scale among matched events whose
                                      states before differed by rounding only (< 1e-13 L) */
    double worst_dp;               /* largest position difference / length scale after a step */
    char why[512];                 /* for DW_END_FAILED (and the others): what differed */
} dw_result;

/* Nonzero: every call is printed (for looking into one scene). */
extern int dw_trace;

/* Plays scene `seed` through the pairing, comparing up to max_events contact events. */
void dw_run_scene(uint64_t seed, dw_pairing pairing, unsigned long max_events, dw_result *out);

#endif
