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

#endif
