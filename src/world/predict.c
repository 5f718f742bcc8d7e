/* EXACT mode's prediction: a moving body's earliest hit (a circle of its 3x3 cell
 * neighbourhood, or of the whole world when it is small; a large circle; a wall) and the time
 * it leaves its grid cell. Circles are searched without a time limit, so that after a cell
 * crossing the hit already known stays the best among the cells still adjacent and only the
 * newly adjacent row or column of cells is searched (unless the known hit went stale). Walls
 * are searched up to min(hit, crossing) and only when their box is within reach
 * (predict_walls.c); the crossing's time: crossing.c. Bodies at rest predict nothing: whatever
 * moves towards them holds the event. */
#include "world_internal.h"
#include "predict.h"

#include "precision_double.h"
#include "helpers.inc"
#include "solver.inc"
#include "precision_end.h"

/* The neighbour scans inline the cheap rejection of a pair and call the solver out of line. */
#if defined(__GNUC__)
#define CC__INLINE_ALWAYS static inline __attribute__((always_inline))
#define CC__NOINLINE static __attribute__((noinline))
#else
#define CC__INLINE_ALWAYS static inline
#define CC__NOINLINE static
#endif

/* The solver's part of cc__try_circle_x, out of line: most pairs never get here. */
CC__NOINLINE void cc__try_close(const cc_world *w, const cc__body *bi, const cc__body *bj, int j, cc_vec2 dp,
                                cc_vec2 dv, double now, cc__cand *best)
{
    double t;
    cc_vec2 n;
    int r = cc__sweep_rel(dp, dv, bi->r + bj->r, 0, 0, best->t - now, &t, &n);
    if (r == CC_MISS || !(now + t < best->t))
        return;
    if (!cc__approaching(w, -cc__dot(dv, n), fabs(bi->vx) + fabs(bi->vy) + fabs(bj->vx) + fabs(bj->vy)))
        return;
    best->t = now + t; /* now for an overlap */
    best->kind = CC__EV_CIRCLE;
    best->partner = j;
    best->pcount = bj->count;
}

/* What cc__predict_pair_alone looks for besides the hit: a circle other than partner within the
 * radius sum + reach now (near is set). In the plain prediction check is 0 and this compiles
 * away. */
typedef struct cc__alone {
    int partner, near;
    double reach;
} cc__alone;

/* The sensor pair i-j's next begin or end, kept when it comes first (out of line: sensor worlds
 * only). */
CC__NOINLINE void cc__try_sensor(const cc_world *w, int i, int j, double sx, double sy, cc__cand *best,
                                 uint64_t *tests)
{
    double t;
    ++*tests;
    t = cc__sensor_next(w, i, j, sx, sy);
    if (!(t < best->t))
        return;
    best->t = t;
    best->kind = cc__sensor_inside(w, i, j) ? CC__EV_END : CC__EV_BEGIN;
    best->partner = j;
    best->pcount = CC__CARR(w, cc__body, off_body)[j].count;
}

/* A pair of which at least one circle rolls (w->features & CC__F_ROLL): the rolling sweep from
 * both states now, the approach judged with the velocities at contact. Out of line: rolling
 * worlds only. check/al: as cc__try_circle_x. */
CC__NOINLINE void cc__try_roll(const cc_world *w, int i, int j, double sx, double sy, double now, cc__cand *best,
                               uint64_t *tests, int check, cc__alone *al)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const cc__body *bi = &B[i], *bj = &B[j];
    double xj, yj, vxj, vyj, kj, ki = CC__CARR(w, cc__props, off_props)[i].roll, R = bi->r + bj->r;
    double dpx, dpy, t, nx, ny, gi, gdi, gj, gdj, vn, speeds;
    int r;
    cc__roll_state(w, j, now, &xj, &yj, &vxj, &vyj, &kj);
    dpx = (xj + sx) - bi->px;
    dpy = (yj + sy) - bi->py;
    if (check && j != al->partner) {
        double Rn = R + al->reach;
        al->near |= dpx * dpx + dpy * dpy <= Rn * Rn;
    }
    if (bi->vx == 0.0 && bi->vy == 0.0 && vxj == 0.0 && vyj == 0.0)
        return;
    ++*tests;
    speeds = fabs(bi->vx) + fabs(bi->vy) + fabs(vxj) + fabs(vyj);
    r = cc__roll_sweep(dpx, dpy, bi->vx, bi->vy, ki, vxj, vyj, kj, R, best->t - now, -1, 2.0 * cc__approach_min(w, speeds),
                       &t, &nx, &ny);
    if (r == CC_MISS || !(now + t < best->t))
        return;
    cc__roll_motion(ki, t, &gi, &gdi);
    cc__roll_motion(kj, t, &gj, &gdj);
    vn = -((vxj * gdj - bi->vx * gdi) * nx + (vyj * gdj - bi->vy * gdi) * ny);
    speeds = fabs(bi->vx * gdi) + fabs(bi->vy * gdi) + fabs(vxj * gdj) + fabs(vyj * gdj);
    if (!cc__approaching(w, vn, speeds))
        return;
    best->t = now + t;
    best->kind = CC__EV_CIRCLE;
    best->partner = j;
    best->pcount = bj->count;
}

/* What a world with filters or sensors decides before the geometry of pair i-j (feat): 1 when
 * the pair is done with (filtered out, two sensors, or a sensor pair handled here). */
CC__INLINE_ALWAYS int cc__featured_pair(const cc_world *w, int i, int j, double sx, double sy, cc__cand *best,
                                        uint64_t *tests)
{
    const cc__props *P = CC__CARR(w, cc__props, off_props);
    if (!cc__filter_pass(&P[i], &P[j]))
        return 1;
    if (P[i].sensor < 0 && P[j].sensor < 0)
        return 0;
    if (P[i].sensor < 0 || P[j].sensor < 0) /* a sensor and its visitor (sensors sense no sensor) */
        cc__try_sensor(w, i, j, sx, sy, best, tests);
    return 1;
}

/* Contact of moving body i (at now) with circle j (its image shifted by (sx, sy) in a periodic
 * world): a hit approaching faster than rounding, or an overlap left by rounding whose bodies
 * approach (a contact now). Inline: the scans call it for every neighbour, and most are rejected
 * by the first test. feat: the world has filters, sensors or periods (a constant, so that a
 * world without them compiles the pair test of 1.0, shifts 0 included). */
CC__INLINE_ALWAYS void cc__try_circle_x(const cc_world *w, const cc__body *B, const cc__body *bi, int i, int i_fixed,
                                        int j, double sx, double sy, double now, cc__cand *best, uint64_t *tests,
                                        int check, cc__alone *al, int feat)
{
    const cc__body *bj = &B[j];
    double dt = now - bj->t, R, dv2, cr;
    cc_vec2 dp, dv;
    if (feat && (w->features & (CC__F_FILTER | CC__F_SENSOR)) && cc__featured_pair(w, i, j, sx, sy, best, tests))
        return; /* (without filters or sensors every pair passes: a periodic world reads no props) */
    if (i_fixed && isinf(CC__CARR(w, cc__cold, off_cold)[j].m))
        return; /* two immovable circles pass through each other */
    if (feat && (w->features & CC__F_ROLL) &&
        (CC__CARR(w, cc__props, off_props)[i].roll > 0.0 || CC__CARR(w, cc__props, off_props)[j].roll > 0.0)) {
        cc__try_roll(w, i, j, sx, sy, now, best, tests, check, al);
        return;
    } /* (two circles that do not decelerate, in a world where some do: the straight sweep) */
    dp.x = (bj->px + bj->vx * dt + sx) - bi->px;
    dp.y = (bj->py + bj->vy * dt + sy) - bi->py;
    dv.x = bj->vx - bi->vx;
    dv.y = bj->vy - bi->vy;
    if (check && j != al->partner) { /* the same distance near.c computes, against a larger reach */
        double Rn = bi->r + bj->r + al->reach;
        al->near |= dp.x * dp.x + dp.y * dp.y <= Rn * Rn;
    }
    if (!(dp.x * dv.x + dp.y * dv.y < 0.0))
        return; /* never closer than now */
    ++*tests;
    /* closest approach |dp x dv| / |dv| not below R, and not overlapping now: a miss (the
     * solver decides every case near the boundary) */
    R = bi->r + bj->r;
    dv2 = dv.x * dv.x + dv.y * dv.y;
    cr = dp.x * dv.y - dp.y * dv.x;
    if (cr * cr > 1.0000001 * dv2 * R * R && dp.x * dp.x + dp.y * dp.y > R * R)
        return;
    if (best->t < HUGE_VAL) { /* farther than R + |dv| h: no contact within h = best - now, by a
                                 relative margin of 1e-9 (far more than the solver's rounding) */
        double s = R + sqrt(dv2) * (best->t - now);
        if (dp.x * dp.x + dp.y * dp.y > 1.000000001 * (s * s))
            return;
    }
    cc__try_close(w, bi, bj, j, dp, dv, now, best);
}

/* Whether the nx x ny cells from (x0, y0) all lie within the period along each periodic axis:
 * then each is its own image (shift 0), and the plain walk below visits the same cells in the
 * same order as the wrapped one, without its divisions. */
static inline int cc__block_within(const cc_world *w, int32_t x0, int32_t y0, int nx, int ny)
{
    return (w->ncell[0] == 0 || (x0 >= 0 && x0 + nx <= w->ncell[0])) &&
           (w->ncell[1] == 0 || (y0 >= 0 && y0 + ny <= w->ncell[1]));
}

/* The only feature a prediction reads is the period (no filters, sensors or rolling): a block
 * within the period can take the plain scan. */
static inline int cc__periodic_only(const cc_world *w)
{
    return (w->features & CC__F_PREDICT) == CC__F_PERIODIC;
}

/* Circles filed under the nx x ny cells from (x0, y0), row by row, tested against body i. Within
 * a tile (cc__grid_slot) a row's slots are consecutive and rows are a tile's width apart, so
 * the hash is computed only where a tile begins. One flat loop, the world's fields read once:
 * the scans are the hot path. */
CC__INLINE_ALWAYS void cc__scan_block_x(const cc_world *w, const cc__body *B, int i, int i_fixed, int32_t x0,
                                        int32_t y0, int nx, int ny, cc__cand *best, uint64_t *tests, int check,
                                        cc__alone *al, int feat)
{
    const int32_t *slot = CC__CARR(w, int32_t, off_slot);
    const uint32_t mx = (1u << w->tile_bits_x) - 1u, my = (1u << w->tile_bits_y) - 1u, mask = w->slot_mask;
    const uint32_t row = 1u << w->tile_bits_x;
    const double now = w->now;
    uint32_t s_row = cc__grid_slot(w, x0, y0), s;
    int32_t x, y;
    int j;
    if (feat && (w->features & CC__F_PERIODIC) && !cc__block_within(w, x0, y0, nx, ny)) {
        /* the cells by their logical coordinates: across a period's edge each is the image of a
         * cell of the period, and its circles are seen shifted by the period */
        for (y = y0; y < y0 + ny; y++)
            for (x = x0; x < x0 + nx; x++) {
                double sx, sy;
                int32_t cx = cc__cell_image(w, x, 0, &sx), cy = cc__cell_image(w, y, 1, &sy);
                for (j = slot[cc__grid_slot(w, cx, cy)]; j >= 0; j = B[j].next)
                    if (B[j].cx == cx && B[j].cy == cy && j != i)
                        cc__try_circle_x(w, B, &B[i], i, i_fixed, j, sx, sy, now, best, tests, check, al, feat);
            }
        return;
    }
    for (y = y0; y < y0 + ny; y++) {
        if (y != y0)
            s_row = ((uint32_t)y & my) ? (s_row + row) & mask : cc__grid_slot(w, x0, y);
        for (x = x0, s = s_row; x < x0 + nx; x++) {
            if (x != x0)
                s = ((uint32_t)x & mx) ? (s + 1u) & mask : cc__grid_slot(w, x, y);
            for (j = slot[s]; j >= 0; j = B[j].next)
                if (B[j].cx == x && B[j].cy == y && j != i)
                    cc__try_circle_x(w, B, &B[i], i, i_fixed, j, 0.0, 0.0, now, best, tests, check, al, feat);
        }
    }
}

static void cc__scan_block(const cc_world *w, const cc__body *B, int i, int i_fixed, int32_t x0, int32_t y0, int nx,
                           int ny, cc__cand *best, uint64_t *tests)
{
    cc__scan_block_x(w, B, i, i_fixed, x0, y0, nx, ny, best, tests, 0, NULL, 0);
}

static void cc__scan_block_alone(const cc_world *w, const cc__body *B, int i, int i_fixed, int32_t x0, int32_t y0,
                                 cc__cand *best, uint64_t *tests, cc__alone *al)
{
    cc__scan_block_x(w, B, i, i_fixed, x0, y0, 3, 3, best, tests, 1, al, 0);
}

/* The same for a world with filters or sensors. */
static void cc__scan_block_feat(const cc_world *w, const cc__body *B, int i, int i_fixed, int32_t x0, int32_t y0,
                                int nx, int ny, cc__cand *best, uint64_t *tests)
{
    cc__scan_block_x(w, B, i, i_fixed, x0, y0, nx, ny, best, tests, 0, NULL, 1);
}

static void cc__scan_block_alone_feat(const cc_world *w, const cc__body *B, int i, int i_fixed, int32_t x0,
                                      int32_t y0, cc__cand *best, uint64_t *tests, cc__alone *al)
{
    cc__scan_block_x(w, B, i, i_fixed, x0, y0, 3, 3, best, tests, 1, al, 1);
}

/* Circle j, not filed in the cells around i (a large circle), against body i in a periodic
 * world: its images one period either way along each periodic axis. Body i stays within a
 * period of where it is until it crosses the period's edge, where it predicts anew
 * (cc__predict_crossed), so that no other image can be reached first. */
static void cc__try_images(const cc_world *w, const cc__body *B, const cc__body *bi, int i, int fixed, int j,
                           cc__cand *best, uint64_t *tests, int check, cc__alone *al)
{
    /* around the image nearest i now (a large circle that moves is nowhere in particular) */
    double sx = cc__near_shift(w, bi->px, cc__bx(w, &B[j], w->now), 0), sy = cc__near_shift(w, bi->py, cc__by(w, &B[j], w->now), 1);
    int a, b;
    for (a = -1; a <= 1; a++)
        for (b = -1; b <= 1; b++)
            if ((a == 0 || w->period[0] > 0.0) && (b == 0 || w->period[1] > 0.0))
                cc__try_circle_x(w, B, bi, i, fixed, j, sx + a * w->period[0], sy + b * w->period[1], w->now, best,
                                 tests, check, al, 1);
}

/* Stores the prediction and queues the body by its earlier event. */
static void cc__finish(cc_world *w, int i, cc__cand *best, double t_cross, int32_t dir)
{
    cc__body *bi = &CC__ARR(w, cc__body, off_body)[i];
    cc__event *ev = &CC__ARR(w, cc__event, off_ev)[i];
    if (w->n_segments > 0 && !isinf(CC__CARR(w, cc__cold, off_cold)[i].m))
        cc__predict_walls(w, i, bi, t_cross, best);
    ev->t = best->t;
    ev->kind = best->kind;
    ev->partner = best->partner;
    ev->pcount = best->pcount;
    ev->t_cross = t_cross;
    ev->dir = dir;
    if (best->kind == CC__EV_NONE && !(t_cross < HUGE_VAL))
        cc__queue_remove(w, i);
    else
        cc__queue_update(w, i, best->t < t_cross ? best->t : t_cross);
}

/* The neighbour scan of a prediction of moving body i, at now: its earliest hit on a circle
 * into *best and its cell crossing into *t_cross, *dir. Returns the pair tests made. */
CC__INLINE_ALWAYS uint64_t cc__predict_scan(cc_world *w, int i, cc__cand *best, double *t_cross, int32_t *dir,
                                            int check, cc__alone *al, int feat)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
    const cc__body *bi = &B[i];
    uint64_t tests = 0;
    int j, fixed = isinf(C[i].m);
    *t_cross = HUGE_VAL;
    *dir = -1;
    best->t = HUGE_VAL;
    best->kind = CC__EV_NONE;
    best->partner = -1;
    best->pcount = 0;
    if (!w->use_grid || (C[i].flags & CC__LARGE)) {
        for (j = 0; j < w->id_end; j++)
            if (j != i && (C[j].flags & CC__ALIVE)) {
                if (feat && (w->features & CC__F_PERIODIC))
                    cc__try_images(w, B, bi, i, fixed, j, best, &tests, check, al);
                else
                    cc__try_circle_x(w, B, bi, i, fixed, j, 0.0, 0.0, w->now, best, &tests, check, al, feat);
            }
        if (feat && (w->features & CC__F_PERIODIC)) {
            *t_cross = cc__again_time(w, bi);
            *dir = CC__DIR_AGAIN;
        }
        if (feat && (w->features & CC__F_ROLL) && CC__CARR(w, cc__props, off_props)[i].roll > 0.0) {
            double stop = w->now + 0.5 / CC__CARR(w, cc__props, off_props)[i].roll; /* no cells: its stop */
            if (stop <= *t_cross) {
                *t_cross = stop;
                *dir = CC__DIR_STOP;
            }
        }
    } else {
        /* a periodic world with no other feature, around a cell away from the period's edges:
         * the plain scan (the same cells, order and pair tests, without the feature branches) */
        int plain = feat && cc__periodic_only(w) && cc__block_within(w, bi->cx - 1, bi->cy - 1, 3, 3);
        if (check && feat && !plain)
            cc__scan_block_alone_feat(w, B, i, fixed, bi->cx - 1, bi->cy - 1, best, &tests, al);
        else if (check)
            cc__scan_block_alone(w, B, i, fixed, bi->cx - 1, bi->cy - 1, best, &tests, al);
        else if (feat && !plain)
            cc__scan_block_feat(w, B, i, fixed, bi->cx - 1, bi->cy - 1, 3, 3, best, &tests);
        else
            cc__scan_block(w, B, i, fixed, bi->cx - 1, bi->cy - 1, 3, 3, best, &tests);
        for (j = w->large_head; j >= 0; j = B[j].next)
            if (j != i) {
                if (feat && (w->features & CC__F_PERIODIC))
                    cc__try_images(w, B, bi, i, fixed, j, best, &tests, check, al);
                else
                    cc__try_circle_x(w, B, bi, i, fixed, j, 0.0, 0.0, w->now, best, &tests, check, al, feat);
            }
        *t_cross = cc__next_move(w, i, bi, dir);
    }
    return tests;
}

void cc__predict(cc_world *w, int i)
{
    cc__body *bi = &CC__ARR(w, cc__body, off_body)[i];
    double t_cross;
    int32_t dir;
    cc__cand best;
    if ((w->features & CC__F_ROLL) && (CC__CARR(w, cc__cold, off_cold)[i].flags & CC__ALIVE))
        cc__advance_body(w, bi, w->now); /* a rolling body may have come to rest since */
    if (!(CC__CARR(w, cc__cold, off_cold)[i].flags & CC__ALIVE) || (bi->vx == 0.0 && bi->vy == 0.0)) {
        cc__event *ev = &CC__ARR(w, cc__event, off_ev)[i];
        ev->kind = CC__EV_NONE;
        ev->t = ev->t_cross = HUGE_VAL;
        cc__queue_remove(w, i);
        return;
    }
    cc__advance_body(w, bi, w->now);
    if (w->features & CC__F_PREDICT)
        w->stats.pairs_tested += cc__predict_scan(w, i, &best, &t_cross, &dir, 0, NULL, 1);
    else
        w->stats.pairs_tested += cc__predict_scan(w, i, &best, &t_cross, &dir, 0, NULL, 0);
    cc__finish(w, i, &best, t_cross, dir);
}

int cc__predict_pair_alone(cc_world *w, int a, int b, double reach_a, double reach_b)
{
    cc__body *B = CC__ARR(w, cc__body, off_body);
    double tc_a, tc_b;
    int32_t dir_a, dir_b;
    uint64_t tests;
    cc__cand best_a, best_b;
    cc__alone al;
    if ((B[a].vx == 0.0 && B[a].vy == 0.0) || (B[b].vx == 0.0 && B[b].vy == 0.0))
        return 1; /* a body at rest predicts nothing, so it scans nothing */
    cc__advance_body(w, &B[a], w->now);
    cc__advance_body(w, &B[b], w->now);
    al.near = 0;
    al.partner = b;
    al.reach = reach_a;
    if (w->features & CC__F_PREDICT)
        tests = cc__predict_scan(w, a, &best_a, &tc_a, &dir_a, 1, &al, 1);
    else
        tests = cc__predict_scan(w, a, &best_a, &tc_a, &dir_a, 1, &al, 0);
    if (al.near)
        return 1;
    al.partner = a;
    al.reach = reach_b;
    if (w->features & CC__F_PREDICT)
        tests += cc__predict_scan(w, b, &best_b, &tc_b, &dir_b, 1, &al, 1);
    else
        tests += cc__predict_scan(w, b, &best_b, &tc_b, &dir_b, 1, &al, 0);
    if (al.near)
        return 1;
    w->stats.pairs_tested += tests;
    cc__finish(w, a, &best_a, tc_a, dir_a);
    cc__finish(w, b, &best_b, tc_b, dir_b);
    return 0;
}

void cc__predict_crossed(cc_world *w, int i, int dir)
{
    cc__body *B = CC__ARR(w, cc__body, off_body);
    const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
    const cc__event *ev = &CC__CARR(w, cc__event, off_ev)[i];
    int32_t cx = B[i].cx, cy = B[i].cy;
    uint64_t tests = 0;
    double t_cross;
    int32_t ndir;
    int fixed = isinf(C[i].m);
    cc__cand best;
    if (ev->kind != CC__EV_NONE && ev->kind != CC__EV_SEGMENT &&
        (!(C[ev->partner].flags & CC__ALIVE) || B[ev->partner].count != ev->pcount)) {
        cc__predict(w, i); /* the known hit is stale: the old cells need a new look too */
        return;
    }
    if ((w->features & CC__F_PERIODIC) &&
        ((dir == 0 && cx == 0) || (dir == 1 && cx == w->ncell[0] - 1) || (dir == 2 && cy == 0) ||
         (dir == 3 && cy == w->ncell[1] - 1)) && w->ncell[dir >> 1] > 0) {
        cc__predict(w, i); /* through a period's edge: every image (the large circles') anew */
        return;
    }
    best.t = ev->t;
    best.kind = ev->kind;
    best.partner = ev->partner;
    best.pcount = ev->pcount;
    if ((w->features & CC__F_PREDICT) &&
        !(cc__periodic_only(w) && (dir < 2 ? cc__block_within(w, dir == 0 ? cx + 1 : cx - 1, cy - 1, 1, 3)
                                            : cc__block_within(w, cx - 1, dir == 2 ? cy + 1 : cy - 1, 3, 1)))) {
        if (dir < 2)
            cc__scan_block_feat(w, B, i, fixed, dir == 0 ? cx + 1 : cx - 1, cy - 1, 1, 3, &best, &tests);
        else
            cc__scan_block_feat(w, B, i, fixed, cx - 1, dir == 2 ? cy + 1 : cy - 1, 3, 1, &best, &tests);
    } else if (dir < 2) { /* a new column of cells right or left */
        cc__scan_block(w, B, i, fixed, dir == 0 ? cx + 1 : cx - 1, cy - 1, 1, 3, &best, &tests);
    } else { /* a new row of cells above or below */
        cc__scan_block(w, B, i, fixed, cx - 1, dir == 2 ? cy + 1 : cy - 1, 3, 1, &best, &tests);
    }
    w->stats.pairs_tested += tests;
    t_cross = cc__next_move(w, i, &B[i], &ndir);
    cc__finish(w, i, &best, t_cross, ndir);
}

/* After body id appeared, moved or stopped: every moving body that could meet it predicts
 * again (a body at rest holds no event, so its movers must find it). */
void cc__predict_neighbours(cc_world *w, int id)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
    int j;
    if (!w->use_grid || (C[id].flags & CC__LARGE)) {
        for (j = 0; j < w->id_end; j++)
            if (j != id && (C[j].flags & CC__ALIVE) && (B[j].vx != 0.0 || B[j].vy != 0.0))
                cc__predict(w, j);
    } else if (w->features & CC__F_PERIODIC) { /* the cells around, wrapped, each once */
        const int32_t *slot = CC__CARR(w, int32_t, off_slot);
        int32_t xs[9], ys[9];
        int c, nc = cc__cells_around(w, B[id].cx, B[id].cy, xs, ys);
        for (c = 0; c < nc; c++)
            for (j = slot[cc__grid_slot(w, xs[c], ys[c])]; j >= 0; j = B[j].next)
                if (B[j].cx == xs[c] && B[j].cy == ys[c] && j != id && (B[j].vx != 0.0 || B[j].vy != 0.0))
                    cc__predict(w, j);
        for (j = w->large_head; j >= 0; j = B[j].next)
            if (j != id && (B[j].vx != 0.0 || B[j].vy != 0.0))
                cc__predict(w, j);
    } else {
        const int32_t *slot = CC__CARR(w, int32_t, off_slot);
        int32_t cx = B[id].cx, cy = B[id].cy, x, y;
        for (y = cy - 1; y <= cy + 1; y++)
            for (x = cx - 1; x <= cx + 1; x++)
                for (j = slot[cc__grid_slot(w, x, y)]; j >= 0; j = B[j].next)
                    if (B[j].cx == x && B[j].cy == y && j != id && (B[j].vx != 0.0 || B[j].vy != 0.0))
                        cc__predict(w, j);
        for (j = w->large_head; j >= 0; j = B[j].next)
            if (j != id && (B[j].vx != 0.0 || B[j].vy != 0.0))
                cc__predict(w, j);
    }
}
