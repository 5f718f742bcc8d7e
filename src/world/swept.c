/* SWEPT mode: the tutorial's loop done once per step. At the start of the step the grid is
 * rebuilt (overlaps pushed apart), then for every candidate pair the first time of impact
 * inside the step is computed from the motions at the start of the step; each body keeps the
 * earliest of its impacts. Those impacts are resolved in time order (bodies advanced along their
 * current velocities to the impact time, impulse only if still approaching), without predicting
 * again after a collision: a body's second impact within a step is missed, which is the mode's
 * trade. Finally every body is carried to the end of the step.
 *
 * Candidate pairs: a "slow" body moves at most half a cell in the step and meets slow bodies
 * within a few cells of its own; a "fast" one is taken out of the grid and looks up the slow
 * bodies in the cells its whole path covers, and tests every other fast body directly. */
#include "world_internal.h"

#include "precision_double.h"
#include "helpers.inc"
#include "solver.inc"
#include "precision_end.h"

#define CC__FAST 16

/* Offers an impact at relative time t to body i (kept when earlier than what it holds). */
static void cc__offer(cc_world *w, int i, double t, int kind, int partner)
{
    cc__event *ev = &CC__ARR(w, cc__event, off_ev)[i];
    if (ev->kind != CC__EV_NONE && !(t < ev->t))
        return;
    ev->t = t;
    ev->kind = kind;
    ev->partner = partner;
}

static void cc__pair(cc_world *w, int i, int j, double dt)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
    const cc__body *bi = &B[i], *bj = &B[j];
    cc_vec2 dp, dv, n;
    double t;
    int r;
    if ((bi->vx == 0.0 && bi->vy == 0.0 && bj->vx == 0.0 && bj->vy == 0.0) || (isinf(C[i].m) && isinf(C[j].m)))
        return;
    dp = cc__v(bj->px - bi->px, bj->py - bi->py);
    dv = cc__v(bj->vx - bi->vx, bj->vy - bi->vy);
    if (!(cc__dot(dp, dv) < 0.0))
        return;
    w->stats.pairs_tested++;
    r = cc__sweep_rel(dp, dv, bi->r + bj->r, 0, 0, dt, &t, &n);
    if (r == CC_MISS ||
        !cc__approaching(w, -cc__dot(dv, n), fabs(bi->vx) + fabs(bi->vy) + fabs(bj->vx) + fabs(bj->vy)))
        return;
    cc__offer(w, i, w->now + t, CC__EV_CIRCLE, j);
    cc__offer(w, j, w->now + t, CC__EV_CIRCLE, i);
}

static void cc__walls(cc_world *w, int i, double dt)
{
    const cc__body *b = &CC__CARR(w, cc__body, off_body)[i];
    const cc_segment *seg = CC__CARR(w, cc_segment, off_seg);
    double x0 = b->px < b->px + b->vx * dt ? b->px : b->px + b->vx * dt;
    double x1 = b->px + (b->px + b->vx * dt) - x0;
    double y0 = b->py < b->py + b->vy * dt ? b->py : b->py + b->vy * dt;
    double y1 = b->py + (b->py + b->vy * dt) - y0;
    cc_circle c;
    cc_contact k;
    int s;
    double m = CC__CARR(w, cc__cold, off_cold)[i].m;
    if (isinf(m) || (b->vx == 0.0 && b->vy == 0.0))
        return;
    c.pos = cc__v(b->px, b->py);
    c.vel = cc__v(b->vx, b->vy);
    c.radius = b->r;
    c.mass = m;
    for (s = 0; s < w->n_segments; s++) {
        const cc_segment *g = &seg[s];
        /* the path's box grown by the radius against the wall's box */
        if ((g->a.x < g->b.x ? g->a.x : g->b.x) > x1 + b->r || (g->a.x > g->b.x ? g->a.x : g->b.x) < x0 - b->r ||
            (g->a.y < g->b.y ? g->a.y : g->b.y) > y1 + b->r || (g->a.y > g->b.y ? g->a.y : g->b.y) < y0 - b->r)
            continue;
        w->stats.pairs_tested++;
        if (cc_sweep_segment(&c, g, dt, &k) <= CC_MISS ||
            !cc__approaching(w, cc__dot(c.vel, k.normal), fabs(c.vel.x) + fabs(c.vel.y)))
            continue;
        cc__offer(w, i, w->now + k.t, CC__EV_SEGMENT, s);
    }
}

/* Finds each body's first impact in [now, now + dt]. */
static void cc__find_impacts(cc_world *w, double dt)
{
    cc__body *B = CC__ARR(w, cc__body, off_body);
    cc__cold *C = CC__ARR(w, cc__cold, off_cold);
    cc__event *ev = CC__ARR(w, cc__event, off_ev);
    const int32_t *slot = CC__CARR(w, int32_t, off_slot);
    double half = 0.5 * w->cs, dslow = 0.0, rmax = 0.0;
    int fast_head = -1, i, j, k;
    for (i = 0; i < w->id_end; i++) {
        double d;
        ev[i].kind = CC__EV_NONE;
        ev[i].t = ev[i].t_cross = HUGE_VAL;
        if (!(C[i].flags & CC__ALIVE))
            continue;
        d = (fabs(B[i].vx) + fabs(B[i].vy)) * dt;
        if (!(C[i].flags & CC__LARGE) && B[i].r > rmax)
            rmax = B[i].r;
        if (w->use_grid && !(C[i].flags & CC__LARGE) && d > half) {
            cc__grid_remove(w, i);
            C[i].flags |= CC__FAST;
            B[i].next = fast_head;
            fast_head = i;
        } else if (d > dslow) {
            dslow = d;
        }
    }
    if (!w->use_grid) {
        for (i = 0; i < w->id_end; i++)
            for (j = i + 1; j < w->id_end; j++)
                if ((C[i].flags & CC__ALIVE) && (C[j].flags & CC__ALIVE))
                    cc__pair(w, i, j, dt);
    } else {
        /* two slow bodies that meet are within 2 rmax + 2 dslow of each other */
        k = (int)ceil((2.0 * rmax + 2.0 * dslow) * w->inv_cs);
        for (i = 0; i < w->id_end; i++) {
            int32_t x, y;
            if (!(C[i].flags & CC__ALIVE) || (C[i].flags & (CC__LARGE | CC__FAST)))
                continue;
            for (y = B[i].cy - k; y <= B[i].cy + k; y++)
                for (x = B[i].cx - k; x <= B[i].cx + k; x++)
                    for (j = slot[cc__grid_slot(w, x, y)]; j >= 0; j = B[j].next)
                        if (j > i && B[j].cx == x && B[j].cy == y)
                            cc__pair(w, i, j, dt);
            for (j = w->large_head; j >= 0; j = B[j].next)
                cc__pair(w, i, j, dt);
        }
        for (i = fast_head; i >= 0; i = B[i].next) {
            const cc__body *b = &B[i];
            double reach = b->r + rmax + dslow;
            int32_t x0 = cc__grid_coord(w, (b->vx < 0 ? b->px + b->vx * dt : b->px) - reach);
            int32_t x1 = cc__grid_coord(w, (b->vx > 0 ? b->px + b->vx * dt : b->px) + reach);
            int32_t y0 = cc__grid_coord(w, (b->vy < 0 ? b->py + b->vy * dt : b->py) - reach);
            int32_t y1 = cc__grid_coord(w, (b->vy > 0 ? b->py + b->vy * dt : b->py) + reach), x, y;
            for (j = B[i].next; j >= 0; j = B[j].next)
                cc__pair(w, i, j, dt); /* fast against fast */
            for (j = w->large_head; j >= 0; j = B[j].next)
                cc__pair(w, i, j, dt);
            if ((double)(x1 - x0 + 1) * (double)(y1 - y0 + 1) > (double)w->id_end) {
                for (j = 0; j < w->id_end; j++) /* a path over more cells than there are bodies */
                    if ((C[j].flags & CC__ALIVE) && !(C[j].flags & (CC__LARGE | CC__FAST)))
                        cc__pair(w, i, j, dt);
                continue;
            }
            for (y = y0; y <= y1; y++)
                for (x = x0; x <= x1; x++)
                    for (j = slot[cc__grid_slot(w, x, y)]; j >= 0; j = B[j].next)
                        if (B[j].cx == x && B[j].cy == y)
                            cc__pair(w, i, j, dt);
        }
    }
    for (i = 0; i < w->id_end; i++)
        if (C[i].flags & CC__ALIVE)
            cc__walls(w, i, dt);
    for (i = 0; i < w->id_end; i++) {
        C[i].flags &= ~CC__FAST;
        if (ev[i].kind != CC__EV_NONE)
            cc__heap_update(w, i, ev[i].t);
    }
}

int cc__step_swept(cc_world *w, double dt)
{
    cc__body *B = CC__ARR(w, cc__body, off_body);
    const cc__event *EV = CC__CARR(w, cc__event, off_ev);
    double t_end = w->now + dt;
    int i;
    cc__rebuild(w);
    cc__find_impacts(w, dt);
    while ((i = cc__heap_top(w)) >= 0) {
        cc__event e = EV[i];
        cc__touch tc;
        cc__heap_remove(w, i);
        w->stats.events++;
        w->now = e.t;
        cc__advance_body(&B[i], e.t);
        tc.a = i;
        tc.b = -1;
        tc.segment = -1;
        if (e.kind == CC__EV_CIRCLE) {
            cc__advance_body(&B[e.partner], e.t);
            tc.b = e.partner;
        } else {
            tc.segment = e.partner;
        }
        (void)cc__world_resolve(w, &tc, 1);
        while (cc__world_take_touched(w) >= 0)
            ; /* no prediction again within the step: that is the mode */
    }
    w->now = t_end;
    return CC_OK;
}
