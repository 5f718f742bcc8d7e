/* Contact queries for resolvers that treat several contacts at one instant (issue 5): which
 * circles and walls touch a given circle now, found through the same grid as everything else.
 * Reads only: positions are taken at w->now from the lazy states, nothing is advanced. The grid
 * is used in EXACT between events; otherwise (other modes, or before the first step) every
 * circle is checked. */
#include "world_internal.h"

#include "precision_double.h"
#include "helpers.inc"
#include "precision_end.h"

static int cc__touching_circle(const cc_world *w, int k, int j, double tol)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    double dx = cc__bx(&B[j], w->now) - cc__bx(&B[k], w->now);
    double dy = cc__by(&B[j], w->now) - cc__by(&B[k], w->now);
    double R = B[k].r + B[j].r + tol;
    return dx * dx + dy * dy <= R * R;
}

int cc__world_touching(const cc_world *w, int k, double tol, cc__touch_visit visit, void *ctx)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
    const cc_segment *seg = CC__CARR(w, cc_segment, off_seg);
    int j, s, n = 0;
    if (w->mode != CC_MODE_EXACT || w->dirty || !w->use_grid || (C[k].flags & CC__LARGE)) {
        for (j = 0; j < w->id_end; j++)
            if (j != k && (C[j].flags & CC__ALIVE) && cc__touching_circle(w, k, j, tol)) {
                visit(ctx, j, -1);
                n++;
            }
    } else {
        const int32_t *slot = CC__CARR(w, int32_t, off_slot);
        int32_t x, y;
        for (y = B[k].cy - 1; y <= B[k].cy + 1; y++)
            for (x = B[k].cx - 1; x <= B[k].cx + 1; x++)
                for (j = slot[cc__grid_slot(w, x, y)]; j >= 0; j = B[j].next)
                    if (B[j].cx == x && B[j].cy == y && j != k && cc__touching_circle(w, k, j, tol)) {
                        visit(ctx, j, -1);
                        n++;
                    }
        for (j = w->large_head; j >= 0; j = B[j].next)
            if (j != k && cc__touching_circle(w, k, j, tol)) {
                visit(ctx, j, -1);
                n++;
            }
    }
    for (s = 0; s < w->n_segments; s++) {
        cc_vec2 p = cc__v(cc__bx(&B[k], w->now), cc__by(&B[k], w->now)), q;
        double reach = B[k].r + tol;
        const cc_segment *g = &seg[s];
        /* most walls are far: the segment's box grown by the reach rules them out cheaply */
        if (p.x + reach < (g->a.x < g->b.x ? g->a.x : g->b.x) || p.x - reach > (g->a.x > g->b.x ? g->a.x : g->b.x) ||
            p.y + reach < (g->a.y < g->b.y ? g->a.y : g->b.y) || p.y - reach > (g->a.y > g->b.y ? g->a.y : g->b.y))
            continue;
        q = cc_closest_point_on_segment(p, g);
        if (cc__length(cc__sub(q, p)) <= reach) {
            visit(ctx, -1, s);
            n++;
        }
    }
    return n;
}
