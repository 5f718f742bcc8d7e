/* SWEPT mode: the tutorial's loop done once per step. At the start of the step the grid is
 * rebuilt (overlaps pushed apart), then for every candidate pair the first time of impact
 * inside the step is computed from the motions at the start of the step; each body keeps the
 * earliest of its impacts. Those impacts are resolved in time order (bodies advanced along their
 * current velocities to the impact time, impulse only if still approaching), without predicting
 * again after a collision: a body's second impact within a step is missed, which is the mode's
 * trade. Finally every body is carried to the end of the step.
 *
 * Candidate pairs: each pair is swept once, from the neighbouring cells when both bodies move
 * little in the step, else by the body that travels further, among the cells its own motion
 * covers (cc__sweeps_from). */
#include "world_internal.h"
#include "scan.h"
#include "walls.h"

#include "precision_double.h"
#include "helpers.inc"
#include "solver.inc"
#include "precision_end.h"

/* floor(v) as a cell index, clamped to +-2^62 (a very fast circle's reach, or NaN, would make
 * the conversion undefined); the span of cells is cut to the period or the grid after. */
static int64_t cc__cell64(double v)
{
    if (!(v > -0x1p62))
        return -((int64_t)1 << 62);
    if (!(v < 0x1p62))
        return (int64_t)1 << 62;
    return (int64_t)floor(v);
}

/* Offers an impact at relative time t to body i (kept when earlier than what it holds). */
static void cc__offer(cc_world *w, int i, double t, int kind, int partner)
{
    cc__event *ev = &CC__ARR(w, cc__event, off_ev)[i];
    /* on a tie the lower (kind, partner): the outcome does not depend on the order of the tests */
    if (ev->kind != CC__EV_NONE &&
        !(t < ev->t || (t == ev->t && (kind < ev->kind || (kind == ev->kind && partner < ev->partner)))))
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
    double t, R = bi->r + bj->r, reach2;
    int r;
    if (bi->vx == 0.0 && bi->vy == 0.0 && bj->vx == 0.0 && bj->vy == 0.0)
        return;
    /* periodic: the nearest image (a step must not carry a body half a period: see the header) */
    dp = cc__v(cc__near_d(w, bj->px - bi->px, 0), cc__near_d(w, bj->py - bi->py, 1));
    dv = cc__v(bj->vx - bi->vx, bj->vy - bi->vy);
    if (w->features & CC__F_ROLL) {
        const cc__props *P = CC__CARR(w, cc__props, off_props);
        if (P[i].roll > 0.0 || P[j].roll > 0.0) { /* along the rolling motions (both at now) */
            double gi, gdi, gj, gdj;
            if ((isinf(C[i].m) && isinf(C[j].m)) ||
                ((w->features & (CC__F_FILTER | CC__F_SENSOR)) && !cc__circles_interact(w, i, j)))
                return;
            w->stats.pairs_tested++;
            {
                double sp = fabs(bi->vx) + fabs(bi->vy) + fabs(bj->vx) + fabs(bj->vy);
                r = cc__roll_sweep(dp.x, dp.y, bi->vx, bi->vy, P[i].roll, bj->vx, bj->vy, P[j].roll, R, dt, -1,
                                   2.0 * cc__approach_min(w, sp), &t, &n.x, &n.y);
            }
            if (r == CC_MISS)
                return;
            cc__roll_motion(P[i].roll, t, &gi, &gdi);
            cc__roll_motion(P[j].roll, t, &gj, &gdj);
            if (!cc__approaching(w, -((bj->vx * gdj - bi->vx * gdi) * n.x + (bj->vy * gdj - bi->vy * gdi) * n.y),
                                 fabs(bi->vx * gdi) + fabs(bi->vy * gdi) + fabs(bj->vx * gdj) + fabs(bj->vy * gdj)))
                return;
            cc__offer(w, i, w->now + t, CC__EV_CIRCLE, j);
            cc__offer(w, j, w->now + t, CC__EV_CIRCLE, i);
            return;
        }
    }
    if (!(cc__dot(dp, dv) < 0.0))
        return;
    /* too far apart to close the gap in the step: |dp| > R + |dv| dt, with a margin far above
     * the rounding of this test and of the sweep (squares below 2^-1000 lose precision) */
    reach2 = R + (fabs(dv.x) + fabs(dv.y)) * dt;
    reach2 *= reach2;
    if (reach2 > 0x1p-1000 && dp.x * dp.x + dp.y * dp.y > reach2 * (1.0 + 0x1p-20))
        return;
    if (isinf(C[i].m) && isinf(C[j].m))
        return;
    if ((w->features & (CC__F_FILTER | CC__F_SENSOR)) && !cc__circles_interact(w, i, j))
        return; /* they pass through each other (a sensor's overlaps: cc__sensor_pass) */
    w->stats.pairs_tested++;
    r = cc__sweep_rel(dp, dv, R, 0, 0, dt, &t, &n);
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
    double x0, x1, y0, y1;
    cc_circle c;
    cc_contact k;
    cc__wall_walk walk;
    double roll = (w->features & CC__F_ROLL) ? CC__CARR(w, cc__props, off_props)[i].roll : 0.0;
    int s, first = 1;
    if (w->n_segments == 0 || (b->vx == 0.0 && b->vy == 0.0))
        return;
    /* the path's box grown by the radius */
    x0 = (b->px < b->px + b->vx * dt ? b->px : b->px + b->vx * dt) - b->r;
    x1 = (b->px < b->px + b->vx * dt ? b->px + b->vx * dt : b->px) + b->r;
    y0 = (b->py < b->py + b->vy * dt ? b->py : b->py + b->vy * dt) - b->r;
    y1 = (b->py < b->py + b->vy * dt ? b->py + b->vy * dt : b->py) + b->r;
    cc__walls_begin(w, &walk, x0, y0, x1, y1);
    while ((s = cc__walls_next(w, &walk)) >= 0) {
        cc__wall_box g = s < w->wall_tree_n ? cc__wall_boxes(w)[s] : cc__wall_box_of(&seg[s]);
        if ((g.x0 > x1) | (g.x1 < x0) | (g.y0 > y1) | (g.y1 < y0))
            continue; /* the tree's boxes are grown: the exact box decides, as before the tree */
        if ((w->features & (CC__F_FILTER | CC__F_SENSOR)) && !cc__wall_interacts(w, i, s))
            continue;
        if (first) { /* the body's cold part only when a wall is near */
            c.mass = CC__CARR(w, cc__cold, off_cold)[i].m;
            if (isinf(c.mass))
                return;
            c.pos = cc__v(b->px, b->py);
            c.vel = cc__v(b->vx, b->vy);
            c.radius = b->r;
            first = 0;
        }
        w->stats.pairs_tested++;
        if (roll > 0.0) { /* along its rolling motion: the velocity at contact is the slower */
            double g, gd;
            if (cc__roll_sweep_segment(&c, roll, &seg[s], dt, &k) <= CC_MISS)
                continue;
            cc__roll_motion(roll, k.t, &g, &gd);
            if (!cc__approaching(w, gd * cc__dot(c.vel, k.normal), gd * (fabs(c.vel.x) + fabs(c.vel.y))))
                continue;
        } else if (cc_sweep_segment(&c, &seg[s], dt, &k) <= CC_MISS ||
                   !cc__approaching(w, cc__dot(c.vel, k.normal), fabs(c.vel.x) + fabs(c.vel.y)))
            continue;
        cc__offer(w, i, w->now + k.t, CC__EV_SEGMENT, s);
    }
}

/* How far body b may move along either axis in the step (an upper bound: |vx| + |vy| >= each). */
static double cc__travel(const cc__body *b, double dt) { return (fabs(b->vx) + fabs(b->vy)) * dt; }

/* Who sweeps which pair. Two bodies i, j meet only if along each axis their centres are within
 * r_i + r_j + travel_i + travel_j. A "slow" body travels at most half the slack of a cell (its
 * width less the largest diameter in it, less a margin far above rounding): two slow bodies
 * that meet are then in the same or adjacent cells, and their pair is swept in a walk over the
 * cells that sees each pair of adjacent cells once (as cc__unoverlap_cells does). A pair with a
 * fast body is swept by the body of the two that travels further (the higher index on a tie),
 * among the cells within r_i + rmax + 2 travel_i, which covers its own motion, not the fastest
 * body's. */
static int cc__sweeps_from(double di, int i, double dj, int j) { return dj < di || (dj == di && j < i); }

/* The same in a periodic world: the cells around a slow body, or those its reach covers, wrapped
 * and each once; a pair of slow bodies is swept by the lower index. */
static void cc__sweep_body_periodic(cc_world *w, int i, double dt, double rmax, double slow)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const int32_t *slot = CC__CARR(w, int32_t, off_slot);
    const cc__body *b = &B[i];
    double di = cc__travel(b, dt);
    int64_t lo[2], hi[2], x, y;
    int j, k;
    for (j = w->large_head; j >= 0; j = B[j].next)
        cc__pair(w, i, j, dt);
    cc__walls(w, i, dt);
    if (di <= slow) {
        lo[0] = b->cx - 1, hi[0] = b->cx + 1, lo[1] = b->cy - 1, hi[1] = b->cy + 1;
    } else {
        double reach = (b->r + rmax + 2.0 * di) * (1.0 + 0x1p-20) + 0x1p-40 * (fabs(b->px) + fabs(b->py));
        lo[0] = cc__cell64((b->px - reach) * w->inv_cs) - 1, hi[0] = cc__cell64((b->px + reach) * w->inv_cs) + 1;
        lo[1] = cc__cell64((b->py - reach) * w->inv_cs) - 1, hi[1] = cc__cell64((b->py + reach) * w->inv_cs) + 1;
    }
    for (k = 0; k < 2; k++) { /* each cell once: a span of a whole period or more is the period */
        int64_t n = w->ncell[k] > 0 ? w->ncell[k] : CC__CELL_MAX;
        if (hi[k] - lo[k] + 1 >= n)
            lo[k] = 0, hi[k] = n - 1;
    }
    if (((double)hi[0] - (double)lo[0] + 1.0) * ((double)hi[1] - (double)lo[1] + 1.0) > 4.0 * (double)w->id_end + 9.0) {
        const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
        lo[0] = hi[0] = lo[1] = hi[1] = 0; /* more cells than bodies: every body instead */
        for (j = 0; j < w->id_end; j++)
            if ((C[j].flags & (CC__ALIVE | CC__LARGE)) == CC__ALIVE && j != i) {
                double dj = cc__travel(&B[j], dt);
                if (dj <= slow && di <= slow ? j > i : cc__sweeps_from(di, i, dj, j))
                    cc__pair(w, i, j, dt);
            }
        return;
    }
    for (y = lo[1]; y <= hi[1]; y++)
        for (x = lo[0]; x <= hi[0]; x++) {
            double sh;
            int32_t cx = cc__cell_image(w, x, 0, &sh), cy = cc__cell_image(w, y, 1, &sh);
            if (di <= slow && (x != (int64_t)b->cx || y != (int64_t)b->cy) && cx == b->cx && cy == b->cy)
                continue; /* a period of two cells: the own cell again */
            for (j = slot[cc__grid_slot(w, cx, cy)]; j >= 0; j = B[j].next)
                if (B[j].cx == cx && B[j].cy == cy && j != i) {
                    double dj = cc__travel(&B[j], dt);
                    if (dj <= slow && di <= slow ? j > i : cc__sweeps_from(di, i, dj, j))
                        cc__pair(w, i, j, dt);
                }
        }
}

/* Body i (in the grid) against the large circles, the circles it sweeps and the walls. */
static void cc__sweep_body(cc_world *w, int i, double dt, double rmax, double slow)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const int32_t *slot = CC__CARR(w, int32_t, off_slot);
    const cc__body *b = &B[i];
    double di = cc__travel(b, dt), reach;
    int32_t x0, x1, y0, y1, x, y;
    uint32_t sl = 0;
    int j;
    for (j = w->large_head; j >= 0; j = B[j].next)
        cc__pair(w, i, j, dt);
    cc__walls(w, i, dt);
    if (di <= slow) {
        /* the slow after it in its own cell and in the four cells ahead: (x+1, y), row y+1 */
        for (j = b->next; j >= 0; j = B[j].next)
            if (B[j].cx == b->cx && B[j].cy == b->cy && cc__travel(&B[j], dt) <= slow)
                cc__pair(w, i, j, dt);
        for (sl = cc__row_slot(w, b->cx + 1, b->cy, sl, 1), j = slot[sl]; j >= 0; j = B[j].next)
            if (B[j].cx == b->cx + 1 && B[j].cy == b->cy && cc__travel(&B[j], dt) <= slow)
                cc__pair(w, i, j, dt);
        for (x = b->cx - 1; x <= b->cx + 1; x++)
            for (sl = cc__row_slot(w, x, b->cy + 1, sl, x == b->cx - 1), j = slot[sl]; j >= 0; j = B[j].next)
                if (B[j].cx == x && B[j].cy == b->cy + 1 && cc__travel(&B[j], dt) <= slow)
                    cc__pair(w, i, j, dt);
        return;
    }
    /* margins far above the rounding of the cell bounds and of the sweep */
    reach = (b->r + rmax + 2.0 * di) * (1.0 + 0x1p-20) + 0x1p-40 * (fabs(b->px) + fabs(b->py));
    x0 = cc__cell_of(w, b->px - reach);
    x1 = cc__cell_of(w, b->px + reach);
    y0 = cc__cell_of(w, b->py - reach);
    y1 = cc__cell_of(w, b->py + reach);
    if (((double)x1 - (double)x0 + 1.0) * ((double)y1 - (double)y0 + 1.0) > (double)w->id_end) {
        const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
        for (j = 0; j < w->id_end; j++) /* more cells than there are bodies */
            if ((C[j].flags & (CC__ALIVE | CC__LARGE)) == CC__ALIVE && j != i) {
                double dj = cc__travel(&B[j], dt);
                if (dj <= slow || cc__sweeps_from(di, i, dj, j))
                    cc__pair(w, i, j, dt);
            }
        return;
    }
    for (y = y0; y <= y1; y++)
        for (x = x0; x <= x1; x++)
            for (sl = cc__row_slot(w, x, y, sl, x == x0), j = slot[sl]; j >= 0; j = B[j].next)
                if (B[j].cx == x && B[j].cy == y && j != i) {
                    double dj = cc__travel(&B[j], dt);
                    if (dj <= slow || cc__sweeps_from(di, i, dj, j))
                        cc__pair(w, i, j, dt);
                }
}

/* Finds each body's first impact in [now, now + dt]. */
static void cc__find_impacts(cc_world *w, double dt)
{
    cc__body *B = CC__ARR(w, cc__body, off_body);
    const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
    cc__event *ev = CC__ARR(w, cc__event, off_ev);
    const int32_t *slot = CC__CARR(w, int32_t, off_slot);
    double rmax = 0.0;
    int i, j;
    for (i = 0; i < w->id_end; i++) {
        ev[i].kind = CC__EV_NONE;
        ev[i].t = ev[i].t_cross = HUGE_VAL;
        if ((C[i].flags & (CC__ALIVE | CC__LARGE)) == CC__ALIVE && B[i].r > rmax)
            rmax = B[i].r;
    }
    if (!w->use_grid) {
        for (i = 0; i < w->id_end; i++)
            for (j = i + 1; j < w->id_end; j++)
                if ((C[i].flags & CC__ALIVE) && (C[j].flags & CC__ALIVE))
                    cc__pair(w, i, j, dt);
        for (i = 0; i < w->id_end; i++)
            if (C[i].flags & CC__ALIVE)
                cc__walls(w, i, dt);
    } else {
        uint32_t s;
        double slow = 0.5 * (w->cs - 2.0 * rmax) * (1.0 - 0x1p-10);
        /* in the order of the slots, not of storage: what a body looks at was mostly looked at
         * just before (see cc__unoverlap_cells); the outcome does not depend on the order */
        for (s = 0; s <= w->slot_mask; s++)
            for (i = slot[s]; i >= 0; i = B[i].next)
                if (w->features & CC__F_PERIODIC)
                    cc__sweep_body_periodic(w, i, dt, rmax, slow);
                else
                    cc__sweep_body(w, i, dt, rmax, slow); /* (large circles are immovable: no walls) */
    }
    for (i = 0; i < w->id_end; i++)
        if (ev[i].kind != CC__EV_NONE)
            cc__heap_update(w, i, ev[i].t);
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
        cc__keep_body_side(w, i); /* its path since its last impulse, a wall's missed included */
        if (e.kind == CC__EV_CIRCLE)
            cc__keep_body_side(w, e.partner);
        cc__advance_body(w, &B[i], e.t);
        tc.a = i;
        tc.b = -1;
        tc.segment = -1;
        if (e.kind == CC__EV_CIRCLE) {
            cc__advance_body(w, &B[e.partner], e.t);
            tc.b = e.partner;
        } else {
            tc.segment = e.partner;
        }
        (void)cc__world_resolve(w, &tc, 1);
        while (cc__world_take_touched(w) >= 0)
            ; /* no prediction again within the step: that is the mode */
    }
    w->now = t_end;
    cc__keep_wall_sides(w, 0); /* a second impact missed may have been a wall's: the centre comes back */
    cc__sensor_pass(w);
    return CC_OK;
}
