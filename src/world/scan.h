/* What SWEPT's and DISCRETE's passes over every circle share: walking rows of grid cells (the
 * slot of the next cell to the right is one more than this one's while both lie in the same
 * tile, see cc__grid_slot, so a row costs one hash per tile it touches instead of one per
 * cell), cells without a call to floor, and the walls' boxes. */
#ifndef CC_WORLD_SCAN_H
#define CC_WORLD_SCAN_H

#include "world_internal.h"

#include <math.h>

/* The slot of cell (x, y), given the slot s of cell (x - 1, y) (ignored when x is the first
 * cell of the row: first != 0). */
static inline uint32_t cc__row_slot(const cc_world *w, int32_t x, int32_t y, uint32_t s, int first)
{
    if (first || ((uint32_t)x & ((1u << w->tile_bits_x) - 1u)) == 0)
        return cc__grid_slot(w, x, y);
    return (s + 1u) & w->slot_mask;
}

/* cc__grid_coord(w, x) without a call to floor: the same cell for every x. */
static inline int32_t cc__cell_of(const cc_world *w, double x)
{
    double c = x * w->inv_cs;
    int32_t k;
    if (!(c > (double)-CC__CELL_MAX))
        return -CC__CELL_MAX; /* also NaN */
    if (c >= (double)CC__CELL_MAX)
        return CC__CELL_MAX;
    k = (int32_t)c; /* towards zero: one less for a negative fraction */
    return k - (c < (double)k);
}

/* A wall's box, exact and grown by 2^-30 of the size of its coordinates (for tests that must
 * be conservative to far above rounding). A pass that tests every circle against every wall
 * boxes the first CC__WALL_BOXES walls once (cc__box_walls) and the others when tested. */
typedef struct cc__wall_box {
    double x0, y0, x1, y1;     /* exact */
    double gx0, gy0, gx1, gy1; /* grown */
} cc__wall_box;

static inline cc__wall_box cc__wall_box_of(const cc_segment *g)
{
    cc__wall_box k;
    double m;
    k.x0 = g->a.x < g->b.x ? g->a.x : g->b.x;
    k.x1 = g->a.x < g->b.x ? g->b.x : g->a.x;
    k.y0 = g->a.y < g->b.y ? g->a.y : g->b.y;
    k.y1 = g->a.y < g->b.y ? g->b.y : g->a.y;
    m = 0x1p-30 * (fabs(k.x0) + fabs(k.x1) + fabs(k.y0) + fabs(k.y1));
    k.gx0 = k.x0 - m;
    k.gx1 = k.x1 + m;
    k.gy0 = k.y0 - m;
    k.gy1 = k.y1 + m;
    return k;
}

#define CC__WALL_BOXES 32
typedef struct cc__walls_boxed {
    int n;
    cc__wall_box box[CC__WALL_BOXES];
} cc__walls_boxed;

static inline void cc__box_walls(const cc_world *w, cc__walls_boxed *wb)
{
    const cc_segment *seg = CC__CARR(w, cc_segment, off_seg);
    int s;
    wb->n = w->n_segments < CC__WALL_BOXES ? w->n_segments : CC__WALL_BOXES;
    for (s = 0; s < wb->n; s++)
        wb->box[s] = cc__wall_box_of(&seg[s]);
}

/* Wall s's box: the pass's when it has it (nb = its count, 0 without), else made in *tmp. */
static inline const cc__wall_box *cc__wall_box_at(const cc_world *w, const cc__walls_boxed *wb, int nb, int s,
                                                  cc__wall_box *tmp)
{
    if (s < nb)
        return &wb->box[s];
    *tmp = cc__wall_box_of(&CC__CARR(w, cc_segment, off_seg)[s]);
    return tmp;
}

#endif
