/* What the parts of EXACT's prediction share: predict.c (the circles: a body's earliest hit
 * among its neighbours, and the whole prediction), predict_walls.c (its earliest wall) and
 * crossing.c (when it leaves its cell). */
#ifndef CC_WORLD_PREDICT_H
#define CC_WORLD_PREDICT_H

#include "world_internal.h"

/* A body's best event so far. */
typedef struct cc__cand {
    double t; /* absolute */
    int kind, partner;
    uint32_t pcount;
} cc__cand;

/* Walls within reach of moving body i (bi, at now) before min(best->t, t_cross): an earlier hit
 * replaces *best (kind CC__EV_SEGMENT). */
void cc__predict_walls(cc_world *w, int i, const cc__body *bi, double t_cross, cc__cand *best);
/* When body b (storage index i, at now) leaves its cell through side *dir, or (rolling) stops
 * (*dir CC__DIR_STOP); HUGE_VAL with *dir -1 when it leaves none. */
double cc__next_move(const cc_world *w, int i, const cc__body *b, int32_t *dir);
/* A body that has no cells to cross (a large circle) in a periodic world: when it looks again
 * (dir CC__DIR_AGAIN). */
double cc__again_time(const cc_world *w, const cc__body *b);

#endif
