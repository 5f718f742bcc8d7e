/* SWEPT and DISCRETE: walls keep their side. A circle's centre that crossed a wall within the
 * step (DISCRETE moves every circle by v dt unswept; SWEPT moves a circle unswept after its one
 * impact of the step) would be pushed out of the wall towards the side nearer to it, which is
 * the far side once the centre is past the wall's line: the circle would leave the table for
 * good. Instead the centre is put back on the side it came from, a radius from the wall's line,
 * and given the wall's impulse. The path looked at is the chord from where the body's lazy state
 * starts (its last impulse, push or the step's start) to where it is now, straight or rolling
 * (a rolling circle slows along a straight line). A crossing is a proper one: the centre on one
 * side of the line at the start and on the other side or on it now, through the segment itself
 * (ends included); a circle that passes beyond a wall's end went round it. A corner, or walls
 * close together, are met one after the other: the pass looks again from the new position. */
#include "world_internal.h"
#include "walls.h"

#define CC__SIDE_ROUNDS 4 /* walls put back across, per body and step: a corner takes two */

/* The earliest wall whose segment the path p0 -> p1 crosses (its parameter on the path in *t),
 * or -1. */
static int cc__first_crossed(const cc_world *w, int i, double x0, double y0, double x1, double y1, double *t_first)
{
    const cc_segment *seg = CC__CARR(w, cc_segment, off_seg);
    cc__wall_walk walk;
    int s, best = -1;
    double bt = HUGE_VAL;
    cc__walls_begin(w, &walk, x0 < x1 ? x0 : x1, y0 < y1 ? y0 : y1, x0 < x1 ? x1 : x0, y0 < y1 ? y1 : y0);
    while ((s = cc__walls_next(w, &walk)) >= 0) {
        const cc_segment *g = &seg[s];
        double ex = g->b.x - g->a.x, ey = g->b.y - g->a.y, e2 = ex * ex + ey * ey;
        double s0 = ex * (y0 - g->a.y) - ey * (x0 - g->a.x), s1 = ex * (y1 - g->a.y) - ey * (x1 - g->a.x);
        double t, cx, cy, u;
        if (!(e2 > 0.0) || s0 == 0.0 || (s0 > 0.0 ? s1 > 0.0 : s1 < 0.0))
            continue; /* a point wall has no sides; the centre started on the line, or stayed on its side */
        if ((w->features & (CC__F_FILTER | CC__F_SENSOR)) && !cc__wall_interacts(w, i, s))
            continue;
        t = s0 / (s0 - s1);
        cx = x0 + (x1 - x0) * t;
        cy = y0 + (y1 - y0) * t;
        u = (cx - g->a.x) * ex + (cy - g->a.y) * ey;
        if (!(u >= 0.0 && u <= e2) || !(t < bt))
            continue;
        bt = t;
        best = s;
    }
    *t_first = bt;
    return best;
}

void cc__side_stash(cc_world *w)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    cc__event *ev = CC__ARR(w, cc__event, off_ev);
    int i;
    if (w->n_segments == 0)
        return;
    for (i = 0; i < w->id_end; i++) {
        ev[i].t = B[i].px; /* every body is at w->now here (the rebuild carried it) */
        ev[i].t_cross = B[i].py;
    }
}

/* Body i, from (x0, y0) to where it is at w->now: put back across each wall its centre crossed. */
static void cc__keep_side(cc_world *w, int i, double x0, double y0)
{
    cc__body *b = &CC__ARR(w, cc__body, off_body)[i];
    cc__cold *C = CC__ARR(w, cc__cold, off_cold);
    const cc_segment *seg = CC__CARR(w, cc_segment, off_seg);
    double x1, y1, t;
    int round;
    if (!(C[i].flags & CC__ALIVE) || isinf(C[i].m))
        return;
    if ((w->features & CC__F_SENSOR) && CC__CARR(w, cc__props, off_props)[i].sensor >= 0)
        return; /* a sensor touches no wall */
    cc__body_pos(w, i, w->now, &x1, &y1);
    if (x1 == x0 && y1 == y0)
        return;
    for (round = 0; round < CC__SIDE_ROUNDS; round++) {
        int s = cc__first_crossed(w, i, x0, y0, x1, y1, &t);
        const cc_segment *g;
        double ex, ey, len, nx, ny, past;
        cc__touch tc;
        if (s < 0)
            break;
        g = &seg[s];
        ex = g->b.x - g->a.x;
        ey = g->b.y - g->a.y;
        len = sqrt(ex * ex + ey * ey);
        /* the wall's unit normal towards the side the centre came from */
        nx = -ey / len;
        ny = ex / len;
        if (nx * (x0 - g->a.x) + ny * (y0 - g->a.y) < 0.0)
            nx = -nx, ny = -ny;
        past = -(nx * (x1 - g->a.x) + ny * (y1 - g->a.y)); /* >= 0: how far beyond the line */
        cc__advance_body(w, b, w->now);
        cc__world_overlap_seen(w, b->r + past);
        b->px = x1 = x1 + nx * (b->r + past);
        b->py = y1 = y1 + ny * (b->r + past);
        C[i].flags |= CC__MOVED;
        cc__world_mark(w, i);
        tc.a = i;
        tc.b = -1;
        tc.segment = s;
        (void)cc__world_resolve(w, &tc, 1); /* the wall's impulse when the circle approaches it */
    }
}

void cc__keep_body_side(cc_world *w, int i)
{
    const cc__body *b = &CC__CARR(w, cc__body, off_body)[i];
    if (w->n_segments > 0 && b->t != w->now)
        cc__keep_side(w, i, b->px, b->py);
}

void cc__keep_wall_sides(cc_world *w, int from_stash)
{
    const cc__event *ev = CC__CARR(w, cc__event, off_ev);
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    int i;
    if (w->n_segments == 0)
        return;
    for (i = 0; i < w->id_end; i++)
        cc__keep_side(w, i, from_stash ? ev[i].t : B[i].px, from_stash ? ev[i].t_cross : B[i].py);
    while (cc__world_take_touched(w) >= 0)
        ; /* SWEPT and DISCRETE predict nothing */
}
