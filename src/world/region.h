/* What the queries (query.c, cast.c) share: the circles that may lie in a region of the plane,
 * found through the grid so that the cost follows the region, not the world. Private. */
#ifndef CC_WORLD_REGION_H
#define CC_WORLD_REGION_H

#include "world_internal.h"
#include "scan.h"

typedef void (*cc__region_visit)(void *ctx, int j);

/* Whether the grid may answer: EXACT keeps every circle filed under its current cell between
 * steps; the other modes file at the start of a step, and a world waiting for its rebuild has
 * not filed what was added since. */
static inline int cc__grid_current(const cc_world *w)
{
    return w->use_grid && w->mode == CC_MODE_EXACT && !w->dirty;
}

/* Calls visit(ctx, j) once for every live circle j (storage index) that can overlap the box
 * [x0, x1] x [y0, y1] now: those filed in the cells of the box and one cell around it (a circle
 * filed by its centre reaches at most half a cell out of it, and the ring covers the rounding of
 * cell crossings), and the large circles; every live circle when the grid cannot answer or the
 * box covers more cells than there are circles. */
static inline void cc__visit_region(const cc_world *w, double x0, double y0, double x1, double y1,
                                    cc__region_visit visit, void *ctx)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
    const int32_t *slot = CC__CARR(w, int32_t, off_slot);
    int32_t cx0, cx1, cy0, cy1, x, y;
    uint32_t s = 0;
    int j;
    if (cc__grid_current(w)) {
        cx0 = cc__cell_of(w, x0);
        cx1 = cc__cell_of(w, x1);
        cy0 = cc__cell_of(w, y0);
        cy1 = cc__cell_of(w, y1);
        cx0 -= cx0 > -CC__CELL_MAX;
        cy0 -= cy0 > -CC__CELL_MAX;
        cx1 += cx1 < CC__CELL_MAX;
        cy1 += cy1 < CC__CELL_MAX;
        if (((double)cx1 - (double)cx0 + 1.0) * ((double)cy1 - (double)cy0 + 1.0) <= (double)w->id_end) {
            for (y = cy0; y <= cy1; y++)
                for (x = cx0; x <= cx1; x++)
                    for (s = cc__row_slot(w, x, y, s, x == cx0), j = slot[s]; j >= 0; j = B[j].next)
                        if (B[j].cx == x && B[j].cy == y)
                            visit(ctx, j);
            for (j = w->large_head; j >= 0; j = B[j].next)
                visit(ctx, j);
            return;
        }
    }
    for (j = 0; j < w->id_end; j++)
        if (C[j].flags & CC__ALIVE)
            visit(ctx, j);
}

/* Whether circle j's category meets mask (a world without properties: every category is 1). */
static inline int cc__category_meets(const cc_world *w, int j, uint32_t mask)
{
    return (CC__CARR(w, cc__props, off_props)[j].category & mask) != 0;
}

#endif
