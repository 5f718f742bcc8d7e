/* EXACT mode's prediction: a moving body's earliest event from now on, among a contact with a
 * circle of its 3x3 cell neighbourhood (or of the whole world when it is small), with a large
 * circle, with a wall, and the crossing into the next grid cell. The search horizon shrinks as
 * candidates are found, and never reaches past the cell crossing: when the body enters a new
 * cell it predicts again with its new neighbours. Bodies at rest predict nothing: whatever
 * moves towards them holds the event. */
#include "world_internal.h"

#include "precision_double.h"
#include "helpers.inc"
#include "solver.inc"
#include "precision_end.h"

typedef struct cc__cand {
    double t; /* relative to now */
    int kind, partner;
    uint32_t pcount;
} cc__cand;

/* Contact of moving body i (at now) with circle j: a hit approaching faster than rounding, or
 * an overlap left by rounding whose bodies approach (a contact now). */
static void cc__try_circle(const cc_world *w, const cc__body *B, const cc__body *bi, int j, double now, cc__cand *best, uint64_t *tests)
{
    const cc__body *bj = &B[j];
    double dt = now - bj->t, t;
    cc_vec2 dp, dv, n;
    int r;
    if (isinf(bi->m) && isinf(bj->m))
        return; /* two immovable circles pass through each other */
    dp.x = (bj->px + bj->vx * dt) - bi->px;
    dp.y = (bj->py + bj->vy * dt) - bi->py;
    dv.x = bj->vx - bi->vx;
    dv.y = bj->vy - bi->vy;
    if (!(dp.x * dv.x + dp.y * dv.y < 0.0))
        return; /* never closer than now */
    ++*tests;
    r = cc__sweep_rel(dp, dv, bi->r + bj->r, 0, 0, best->t, &t, &n);
    if (r == CC_MISS || !(t < best->t))
        return;
    if (!cc__approaching(w, -cc__dot(dv, n), fabs(bi->vx) + fabs(bi->vy) + fabs(bj->vx) + fabs(bj->vy)))
        return;
    best->t = t; /* 0 for an overlap */
    best->kind = CC__EV_CIRCLE;
    best->partner = j;
    best->pcount = bj->count;
}

static void cc__try_segments(cc_world *w, const cc__body *bi, cc__cand *best)
{
    const cc_segment *seg = CC__CARR(w, cc_segment, off_seg);
    cc_circle c;
    cc_contact k;
    int s;
    c.pos.x = bi->px;
    c.pos.y = bi->py;
    c.vel.x = bi->vx;
    c.vel.y = bi->vy;
    c.radius = bi->r;
    c.mass = 1.0;
    for (s = 0; s < w->n_segments; s++) {
        int r = cc_sweep_segment(&c, &seg[s], best->t, &k);
        w->stats.pairs_tested++;
        if (r == CC_MISS || r < 0 || !(k.t < best->t))
            continue;
        if (!cc__approaching(w, cc__dot(c.vel, k.normal), fabs(c.vel.x) + fabs(c.vel.y)))
            continue;
        best->t = k.t;
        best->kind = CC__EV_SEGMENT;
        best->partner = s;
    }
}

/* Time until body b (at now, in cell c) leaves its cell, and through which side. */
static void cc__try_cross(const cc_world *w, const cc__body *b, const cc__cell *c, cc__cand *best)
{
    double tx = HUGE_VAL, ty = HUGE_VAL;
    int dx = -1, dy = -1;
    if (b->vx > 0.0 && c->cx < CC__CELL_MAX) {
        tx = ((double)(c->cx + 1) * w->cs - b->px) / b->vx;
        dx = 0;
    } else if (b->vx < 0.0 && c->cx > -CC__CELL_MAX) {
        tx = ((double)c->cx * w->cs - b->px) / b->vx;
        dx = 1;
    }
    if (b->vy > 0.0 && c->cy < CC__CELL_MAX) {
        ty = ((double)(c->cy + 1) * w->cs - b->py) / b->vy;
        dy = 2;
    } else if (b->vy < 0.0 && c->cy > -CC__CELL_MAX) {
        ty = ((double)c->cy * w->cs - b->py) / b->vy;
        dy = 3;
    }
    if (ty < tx) {
        tx = ty;
        dx = dy;
    }
    if (dx < 0)
        return;
    best->t = tx > 0.0 ? tx : 0.0;
    best->kind = CC__EV_CROSS;
    best->partner = dx;
}

void cc__predict(cc_world *w, int i)
{
    cc__body *B = CC__ARR(w, cc__body, off_body);
    cc__body *bi = &B[i];
    cc__event *ev = &CC__ARR(w, cc__event, off_ev)[i];
    const cc__cell *cell = CC__CARR(w, cc__cell, off_cell);
    double now = w->now;
    uint64_t tests = 0;
    cc__cand best;
    int j;
    if (!(bi->flags & CC__ALIVE) || (bi->vx == 0.0 && bi->vy == 0.0)) {
        ev->kind = CC__EV_NONE;
        cc__heap_remove(w, i);
        return;
    }
    cc__advance_body(bi, now);
    best.t = HUGE_VAL;
    best.kind = CC__EV_NONE;
    best.partner = -1;
    best.pcount = 0;
    if (!w->use_grid || (bi->flags & CC__LARGE)) {
        for (j = 0; j < w->id_end; j++)
            if (j != i && (B[j].flags & CC__ALIVE))
                cc__try_circle(w, B, bi, j, now, &best, &tests);
    } else {
        const int32_t *slot = CC__CARR(w, int32_t, off_slot);
        int64_t cx = cell[i].cx, cy = cell[i].cy, x, y;
        cc__try_cross(w, bi, &cell[i], &best);
        for (y = cy - 1; y <= cy + 1; y++)
            for (x = cx - 1; x <= cx + 1; x++)
                for (j = slot[cc__grid_slot(w, x, y)]; j >= 0; j = cell[j].next)
                    if (cell[j].cx == x && cell[j].cy == y && j != i)
                        cc__try_circle(w, B, bi, j, now, &best, &tests);
        for (j = w->large_head; j >= 0; j = cell[j].next)
            if (j != i)
                cc__try_circle(w, B, bi, j, now, &best, &tests);
    }
    w->stats.pairs_tested += tests;
    if (!isinf(bi->m) && w->n_segments > 0)
        cc__try_segments(w, bi, &best);
    if (best.kind == CC__EV_NONE) {
        ev->kind = CC__EV_NONE;
        cc__heap_remove(w, i);
        return;
    }
    ev->t = now + best.t;
    ev->kind = best.kind;
    ev->partner = best.partner;
    ev->pcount = best.pcount;
    cc__heap_update(w, i);
}

/* After body id appeared, moved or stopped: every moving body that could meet it predicts
 * again (a body at rest holds no event, so its movers must find it). */
void cc__predict_neighbours(cc_world *w, int id)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const cc__cell *cell = CC__CARR(w, cc__cell, off_cell);
    int j;
    if (!w->use_grid || (B[id].flags & CC__LARGE)) {
        for (j = 0; j < w->id_end; j++)
            if (j != id && (B[j].flags & CC__ALIVE) && (B[j].vx != 0.0 || B[j].vy != 0.0))
                cc__predict(w, j);
    } else {
        const int32_t *slot = CC__CARR(w, int32_t, off_slot);
        int64_t cx = cell[id].cx, cy = cell[id].cy, x, y;
        for (y = cy - 1; y <= cy + 1; y++)
            for (x = cx - 1; x <= cx + 1; x++)
                for (j = slot[cc__grid_slot(w, x, y)]; j >= 0; j = cell[j].next)
                    if (cell[j].cx == x && cell[j].cy == y && j != id && (B[j].vx != 0.0 || B[j].vy != 0.0))
                        cc__predict(w, j);
        for (j = w->large_head; j >= 0; j = cell[j].next)
            if (j != id && (B[j].vx != 0.0 || B[j].vy != 0.0))
                cc__predict(w, j);
    }
}
