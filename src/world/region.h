/* What the queries (query.c, cast.c) share: the circles that may lie in a region of the plane,
 * found through the grid so that the cost follows the region, not the world. Private. */
#ifndef CC_WORLD_REGION_H
#define CC_WORLD_REGION_H

#include "world_internal.h"
#include "scan.h"

/* j: a circle's storage index; (sx, sy): the shift of its image in a periodic world. */
typedef void (*cc__region_visit)(void *ctx, int j, double sx, double sy);

/* How many periods either way a logical cell counts: at most a million million, and few enough
 * that periods x cells stay far inside int64_t (2^52; up to 2^30 cells a period: world fuzzer
 * D24, 1e15 x 1.3e6 overflowed). A box reaching beyond is not walked by cells (below). */
static inline double cc__logical_reach(const cc_world *w, int k)
{
    double q = floor(0x1p52 / (double)w->ncell[k]);
    return q < 1e15 ? q : 1e15;
}

/* The logical cell (numbered on through the periods, see cc__cell_image) of coordinate x along
 * periodic axis k. */
static inline int64_t cc__logical_cell(const cc_world *w, double x, int k)
{
    double P = w->period[k], q = floor(x / P), c = floor((x - q * P) * w->inv_cs), qm = cc__logical_reach(w, k);
    int64_t n = w->ncell[k];
    if (!(q > -qm && q < qm))
        q = q < 0.0 ? -qm : qm; /* a box across that many periods is clamped */
    /* x = +-Inf (a cast whose path p + d overflows: world fuzzer D15) gives q = +-Inf and c = NaN,
     * whose conversion was undefined: the end of the clamped range of periods */
    c = !(c >= 0.0) ? (q < 0.0 ? 0.0 : (double)(n - 1)) : c >= (double)n ? (double)(n - 1) : c;
    return (int64_t)q * n + (int64_t)c;
}

/* The first and last image index n (centre q + n P) whose centre lies in [lo, hi] along periodic
 * axis k, widened by far more than the rounding of the subtraction and the division (2^-48 of
 * the index, and of 1); an empty range (n1 < n0) when none. */
static inline void cc__image_range(const cc_world *w, double q, double lo, double hi, int k, double *n0, double *n1)
{
    double P = w->period[k], a = (lo - q) / P, b = (hi - q) / P;
    *n0 = ceil(a - 0x1p-48 * (fabs(a) + 1.0));
    *n1 = floor(b + 0x1p-48 * (fabs(b) + 1.0));
}

/* Circle j's nearest image to (cx, cy) (a point, a box's centre or a path's middle). */
static inline void cc__visit_nearest(const cc_world *w, int j, double cx, double cy, cc__region_visit visit, void *ctx)
{
    double px, py;
    cc__body_pos(w, j, w->now, &px, &py);
    visit(ctx, j, cc__near_shift(w, cx, px, 0), cc__near_shift(w, cy, py, 1));
}

/* Every image of circle j whose disc can meet the box [x0, x1] x [y0, y1] (its centre within its
 * radius of the box along each periodic axis; shift 0 along an open one), each once. The box is
 * a few cells or a cast's piece: a handful of images. */
static inline void cc__visit_images_in_box(const cc_world *w, int j, double x0, double y0, double x1, double y1,
                                           cc__region_visit visit, void *ctx)
{
    double q[2], lo[2] = {x0, y0}, hi[2] = {x1, y1}, n0[2] = {0.0, 0.0}, n1[2] = {0.0, 0.0}, a, b;
    double r = CC__CARR(w, cc__body, off_body)[j].r;
    int k;
    cc__body_pos(w, j, w->now, &q[0], &q[1]);
    for (k = 0; k < 2; k++)
        if (w->period[k] > 0.0)
            cc__image_range(w, q[k], lo[k] - r, hi[k] + r, k, &n0[k], &n1[k]);
    if (!(fabs(n0[0]) + fabs(n1[0]) + fabs(n0[1]) + fabs(n1[1]) < 0x1p52 &&
          (n1[0] - n0[0] + 1.0) * (n1[1] - n0[1] + 1.0) <= 0x1p20)) {
        /* a box that has lost its place within the period (or a path that overflowed), or holds
         * a million images (the casts keep far below): the nearest image to its centre */
        cc__visit_nearest(w, j, 0.5 * (x0 + x1), 0.5 * (y0 + y1), visit, ctx);
        return;
    }
    for (a = n0[0]; a <= n1[0]; a++)
        for (b = n0[1]; b <= n1[1]; b++)
            visit(ctx, j, a * w->period[0], b * w->period[1]);
}

/* The periodic version of cc__visit_region: the logical cells of the box and one around. With
 * `images`, each cell's circles are visited with the shift of its image, as often as the box
 * holds images of it (casts: every image along the path); without, each cell once, shifts 0
 * (queries: the caller takes the nearest image). */
static inline void cc__visit_region_periodic(const cc_world *w, double x0, double y0, double x1, double y1,
                                             int images, cc__region_visit visit, void *ctx)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const int32_t *slot = CC__CARR(w, int32_t, off_slot);
    int64_t lo[2], hi[2], x, y;
    double lox[2] = {x0, y0}, hix[2] = {x1, y1};
    int k, j, far = 0;
    /* a box reaching past the clamp of cc__logical_cell has lost the phase within the period:
     * every circle (below), never a cell range that the clamp left reversed (world fuzzer D23: a
     * cast at x = -6.7e127 walked 2^31 empty rows of cells, 17 s) */
    for (k = 0; k < 2; k++)
        if (w->ncell[k] > 0) {
            double reach = cc__logical_reach(w, k) * w->period[k];
            far |= !(fabs(lox[k]) < reach && fabs(hix[k]) < reach);
        }
    for (k = 0; k < 2 && !far; k++) {
        if (w->ncell[k] > 0) {
            lo[k] = cc__logical_cell(w, lox[k], k) - 1;
            hi[k] = cc__logical_cell(w, hix[k], k) + 1;
            if (!images && hi[k] - lo[k] + 1 >= w->ncell[k])
                lo[k] = 0, hi[k] = w->ncell[k] - 1;
        } else {
            lo[k] = cc__cell_of(w, lox[k]) - 1;
            hi[k] = cc__cell_of(w, hix[k]) + 1;
        }
    }
    if (far || hi[0] < lo[0] || hi[1] < lo[1] || /* (far: lo and hi are not set; || stops there) */
        ((double)hi[0] - (double)lo[0] + 1.0) * ((double)hi[1] - (double)lo[1] + 1.0) > 4.0 * (double)w->id_end + 9.0) {
        /* more cells than circles: each circle, with every image of it the box holds (its
         * nearest image to the box's centre once the box has lost its place, or for a query) */
        const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
        for (j = 0; j < w->id_end; j++)
            if (C[j].flags & CC__ALIVE) {
                if (!images)
                    visit(ctx, j, 0.0, 0.0);
                else if (far)
                    cc__visit_nearest(w, j, 0.5 * (x0 + x1), 0.5 * (y0 + y1), visit, ctx);
                else
                    cc__visit_images_in_box(w, j, x0, y0, x1, y1, visit, ctx);
            }
        return;
    }
    for (y = lo[1]; y <= hi[1]; y++)
        for (x = lo[0]; x <= hi[0]; x++) {
            double sx, sy;
            int32_t cx = cc__cell_image(w, x, 0, &sx), cy = cc__cell_image(w, y, 1, &sy);
            for (j = slot[cc__grid_slot(w, cx, cy)]; j >= 0; j = B[j].next)
                if (B[j].cx == cx && B[j].cy == cy)
                    visit(ctx, j, images ? sx : 0.0, images ? sy : 0.0);
        }
    for (j = w->large_head; j >= 0; j = B[j].next) { /* large circles: their images in the box */
        if (!images)
            visit(ctx, j, 0.0, 0.0);
        else
            cc__visit_images_in_box(w, j, x0, y0, x1, y1, visit, ctx);
    }
}

/* Whether the grid may answer: EXACT keeps every circle filed under its current cell between
 * steps; the other modes file at the start of a step, and a world waiting for its rebuild has
 * not filed what was added since. */
static inline int cc__grid_current(const cc_world *w)
{
    return w->use_grid && w->mode == CC_MODE_EXACT && !w->dirty;
}

/* Calls visit(ctx, j, ...) once for every live circle j (storage index) that can overlap the box
 * [x0, x1] x [y0, y1] now: those filed in the cells of the box and one cell around it (a circle
 * filed by its centre reaches at most half a cell out of it, and the ring covers the rounding of
 * cell crossings), and the large circles; every live circle when the grid cannot answer or the
 * box covers more cells than there are circles. With `images` (periodic), once for each image
 * of it that the box holds, whichever way the circles are found: in every mode and state. */
static inline void cc__visit_region(const cc_world *w, double x0, double y0, double x1, double y1, int images,
                                    cc__region_visit visit, void *ctx)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
    const int32_t *slot = CC__CARR(w, int32_t, off_slot);
    int32_t cx0, cx1, cy0, cy1, x, y;
    uint32_t s = 0;
    int j;
    if ((w->features & CC__F_PERIODIC) && cc__grid_current(w)) {
        cc__visit_region_periodic(w, x0, y0, x1, y1, images, visit, ctx);
        return;
    }
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
                            visit(ctx, j, 0.0, 0.0);
            for (j = w->large_head; j >= 0; j = B[j].next)
                visit(ctx, j, 0.0, 0.0);
            return;
        }
    }
    /* every circle: once (open, or a query: the caller takes the nearest image), or with every
     * image of it the box holds (periodic, for a cast): the grid's answer, without the grid */
    for (j = 0; j < w->id_end; j++)
        if (C[j].flags & CC__ALIVE) {
            if (images && (w->features & CC__F_PERIODIC))
                cc__visit_images_in_box(w, j, x0, y0, x1, y1, visit, ctx);
            else
                visit(ctx, j, 0.0, 0.0);
        }
}

/* Whether circle j's category meets mask (a world without properties: every category is 1). */
static inline int cc__category_meets(const cc_world *w, int j, uint32_t mask)
{
    if (!(w->features & CC__F_FILTER))
        return (mask & 1u) != 0; /* every circle has the default category (a world may have no props) */
    return (CC__CARR(w, cc__props, off_props)[j].category & mask) != 0;
}

#endif
