/* Contact queries for resolvers that treat several contacts at one instant (issue 5): which
 * circles and walls touch a given circle now, found through the same grid as everything else.
 * Reads only: positions are taken at w->now from the lazy states, nothing is advanced. The grid
 * is used in EXACT between events; otherwise (other modes, or before the first step) every
 * circle is checked. */
#include "world_internal.h"
#include "walls.h"

#include "precision_double.h"
#include "helpers.inc"
#include "precision_end.h"

/* Circles k and j interact (filters and sensors: only a world with them asks). */
static int cc__near_interacts(const cc_world *w, int k, int j)
{
    return !(w->features & (CC__F_FILTER | CC__F_SENSOR)) || cc__circles_interact(w, k, j);
}

/* Circle j within tol of the circle of radius kr at (kx, ky) at w->now. */
static int cc__touching_circle(const cc_world *w, const cc__body *bj, double kx, double ky, double kr, double tol)
{
    double dx = cc__near_d(w, cc__bx(w, bj, w->now) - kx, 0);
    double dy = cc__near_d(w, cc__by(w, bj, w->now) - ky, 1);
    double R = kr + bj->r + tol;
    return dx * dx + dy * dy <= R * R;
}

int cc__world_touching(const cc_world *w, int k, double tol, cc__touch_visit visit, void *ctx)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
    const cc_segment *seg = CC__CARR(w, cc_segment, off_seg);
    const double kx = cc__bx(w, &B[k], w->now), ky = cc__by(w, &B[k], w->now), kr = B[k].r, reach = kr + tol;
    cc__wall_walk walk;
    int j, s, n = 0;
    if (w->mode != CC_MODE_EXACT || w->dirty || !w->use_grid || (C[k].flags & CC__LARGE)) {
        for (j = 0; j < w->id_end; j++)
            if (j != k && (C[j].flags & CC__ALIVE) && cc__touching_circle(w, &B[j], kx, ky, kr, tol) &&
                cc__near_interacts(w, k, j)) {
                visit(ctx, j, -1);
                n++;
            }
    } else if (w->features & CC__F_PERIODIC) { /* the cells around, wrapped, each once */
        const int32_t *slot = CC__CARR(w, int32_t, off_slot);
        int32_t xs[9], ys[9];
        int c, nc = cc__cells_around(w, B[k].cx, B[k].cy, xs, ys);
        for (c = 0; c < nc; c++)
            for (j = slot[cc__grid_slot(w, xs[c], ys[c])]; j >= 0; j = B[j].next)
                if (B[j].cx == xs[c] && B[j].cy == ys[c] && j != k && cc__touching_circle(w, &B[j], kx, ky, kr, tol) &&
                    cc__near_interacts(w, k, j)) {
                    visit(ctx, j, -1);
                    n++;
                }
        for (j = w->large_head; j >= 0; j = B[j].next)
            if (j != k && cc__touching_circle(w, &B[j], kx, ky, kr, tol) && cc__near_interacts(w, k, j)) {
                visit(ctx, j, -1);
                n++;
            }
    } else {
        /* the 3 x 3 cells row by row; within a tile (cc__grid_slot) a row's slots are consecutive and
         * rows are a tile's width apart */
        const int32_t *slot = CC__CARR(w, int32_t, off_slot);
        const uint32_t mx = (1u << w->tile_bits_x) - 1u, my = (1u << w->tile_bits_y) - 1u, mask = w->slot_mask;
        const uint32_t row = 1u << w->tile_bits_x;
        int32_t x, y, x0 = B[k].cx - 1, y0 = B[k].cy - 1;
        uint32_t s_row = cc__grid_slot(w, x0, y0), t;
        for (y = y0; y < y0 + 3; y++) {
            if (y != y0)
                s_row = ((uint32_t)y & my) ? (s_row + row) & mask : cc__grid_slot(w, x0, y);
            for (x = x0, t = s_row; x < x0 + 3; x++) {
                if (x != x0)
                    t = ((uint32_t)x & mx) ? (t + 1u) & mask : cc__grid_slot(w, x, y);
                for (j = slot[t]; j >= 0; j = B[j].next)
                    if (B[j].cx == x && B[j].cy == y && j != k && cc__touching_circle(w, &B[j], kx, ky, kr, tol) &&
                        cc__near_interacts(w, k, j)) {
                        visit(ctx, j, -1);
                        n++;
                    }
            }
        }
        for (j = w->large_head; j >= 0; j = B[j].next)
            if (j != k && cc__touching_circle(w, &B[j], kx, ky, kr, tol) && cc__near_interacts(w, k, j)) {
                visit(ctx, j, -1);
                n++;
            }
    }
    cc__walls_begin(w, &walk, kx - reach, ky - reach, kx + reach, ky + reach);
    while ((s = cc__walls_next(w, &walk)) >= 0) {
        const cc_segment *g = &seg[s];
        cc_vec2 p = cc__v(kx, ky), q;
        /* the tree's boxes are grown a little: the segment's own box grown by the reach decides */
        if (kx + reach < (g->a.x < g->b.x ? g->a.x : g->b.x) || kx - reach > (g->a.x > g->b.x ? g->a.x : g->b.x) ||
            ky + reach < (g->a.y < g->b.y ? g->a.y : g->b.y) || ky - reach > (g->a.y > g->b.y ? g->a.y : g->b.y))
            continue;
        if ((w->features & (CC__F_FILTER | CC__F_SENSOR)) && !cc__wall_interacts(w, k, s))
            continue;
        q = cc_closest_point_on_segment(p, g);
        if (cc__length(cc__sub(q, p)) <= reach) {
            visit(ctx, -1, s);
            n++;
        }
    }
    return n;
}
