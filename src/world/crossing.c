/* EXACT's cell crossings: when a moving body leaves its grid cell and through which side
 * (along its straight path, or a rolling body's slowing one, whose stop may come first), and
 * when a large circle, which has no cells to cross, looks again in a periodic world. */
#include "predict.h"

/* The upper bound of cell c along axis k: the period's end for the last cell of a periodic axis. */
static double cc__cell_top(const cc_world *w, int32_t c, int k)
{
    return w->ncell[k] > 0 && c == w->ncell[k] - 1 ? w->period[k] : ((double)c + 1.0) * w->cs;
}

/* When body b (at now, in cell c) leaves its cell, and through which side. Along a periodic axis
 * every cell has both sides (the last cell's upper one is the period's end, beyond which the
 * first cell begins again); along an open axis the outermost cells have none outwards. */
static double cc__cross_time(const cc_world *w, const cc__body *b, int32_t *dir)
{
    double tx = HUGE_VAL, ty = HUGE_VAL;
    int dx = -1, dy = -1, px = w->ncell[0] > 0, py = w->ncell[1] > 0;
    if (b->vx > 0.0 && (px || b->cx < CC__CELL_MAX)) {
        tx = cc__cell_top(w, b->cx, 0) - b->px;
        tx /= b->vx;
        dx = 0;
    } else if (b->vx < 0.0 && (px || b->cx > -CC__CELL_MAX)) {
        tx = ((double)b->cx * w->cs - b->px) / b->vx;
        dx = 1;
    }
    if (b->vy > 0.0 && (py || b->cy < CC__CELL_MAX)) {
        ty = cc__cell_top(w, b->cy, 1) - b->py;
        ty /= b->vy;
        dy = 2;
    } else if (b->vy < 0.0 && (py || b->cy > -CC__CELL_MAX)) {
        ty = ((double)b->cy * w->cs - b->py) / b->vy;
        dy = 3;
    }
    if (ty < tx) {
        tx = ty;
        dx = dy;
    }
    *dir = dx;
    if (dx < 0)
        return HUGE_VAL;
    return w->now + (tx > 0.0 ? tx : 0.0);
}

/* The same for a rolling body (coefficient k > 0): along its slowing path, and its stop when it
 * comes first (dir CC__DIR_STOP). */
static double cc__roll_cross_time(const cc_world *w, const cc__body *b, double k, int32_t *dir)
{
    double best = 0.5 / k, t; /* the stop */
    int px = w->ncell[0] > 0, py = w->ncell[1] > 0;
    *dir = CC__DIR_STOP;
    if (b->vx > 0.0 && (px || b->cx < CC__CELL_MAX) && (t = cc__roll_reach(b->px, b->vx, k, cc__cell_top(w, b->cx, 0))) < best)
        best = t, *dir = 0;
    else if (b->vx < 0.0 && (px || b->cx > -CC__CELL_MAX) && (t = cc__roll_reach(b->px, b->vx, k, (double)b->cx * w->cs)) < best)
        best = t, *dir = 1;
    if (b->vy > 0.0 && (py || b->cy < CC__CELL_MAX) && (t = cc__roll_reach(b->py, b->vy, k, cc__cell_top(w, b->cy, 1))) < best)
        best = t, *dir = 2;
    else if (b->vy < 0.0 && (py || b->cy > -CC__CELL_MAX) && (t = cc__roll_reach(b->py, b->vy, k, (double)b->cy * w->cs)) < best)
        best = t, *dir = 3;
    return w->now + (best > 0.0 ? best : 0.0);
}

/* When body b (storage index i, at now) leaves its cell or (rolling) stops. */
double cc__next_move(const cc_world *w, int i, const cc__body *b, int32_t *dir)
{
    if (w->features & CC__F_ROLL) {
        double k = CC__CARR(w, cc__props, off_props)[i].roll;
        if (k > 0.0)
            return cc__roll_cross_time(w, b, k, dir);
    }
    return cc__cross_time(w, b, dir);
}

/* A body that has no cells to cross (a large circle) in a periodic world: it looks again once it
 * has travelled half a period along an axis, so that the images it looks at stay the ones it can
 * reach (dir CC__DIR_AGAIN). */
double cc__again_time(const cc_world *w, const cc__body *b)
{
    double t = HUGE_VAL;
    if (w->period[0] > 0.0 && b->vx != 0.0)
        t = 0.5 * w->period[0] / fabs(b->vx);
    if (w->period[1] > 0.0 && b->vy != 0.0 && 0.5 * w->period[1] / fabs(b->vy) < t)
        t = 0.5 * w->period[1] / fabs(b->vy);
    return w->now + t;
}
