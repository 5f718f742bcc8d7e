/* EXACT's prediction of a moving body's earliest wall: the walls' tree walked over the box of
 * its path up to its earliest circle hit or cell crossing (whichever comes first), each wall
 * swept (the rolling sweep for a rolling body), a hit kept when it approaches faster than
 * rounding. */
#include "predict.h"
#include "walls.h"

#include "precision_double.h"
#include "helpers.inc"
#include "precision_end.h"

/* Walls within reach before min(best, t_cross). */
void cc__predict_walls(cc_world *w, int i, const cc__body *bi, double t_cross, cc__cand *best)
{
    const cc_segment *seg = CC__CARR(w, cc_segment, off_seg);
    double now = w->now, h = (best->t < t_cross ? best->t : t_cross) - now;
    double x0 = -HUGE_VAL, x1 = HUGE_VAL, y0 = -HUGE_VAL, y1 = HUGE_VAL;
    cc_circle c;
    cc_contact k;
    cc__wall_walk walk;
    double roll = (w->features & CC__F_ROLL) ? CC__CARR(w, cc__props, off_props)[i].roll : 0.0;
    int s;
    c.pos.x = bi->px;
    c.pos.y = bi->py;
    c.vel.x = bi->vx;
    c.vel.y = bi->vy;
    c.radius = bi->r;
    c.mass = 1.0;
    if (h < HUGE_VAL) { /* the path's box, grown by the radius (and a little, for rounding) */
        double ex = bi->px + bi->vx * h, ey = bi->py + bi->vy * h, g = bi->r * 1.001;
        x0 = (ex < bi->px ? ex : bi->px) - g;
        x1 = (ex < bi->px ? bi->px : ex) + g;
        y0 = (ey < bi->py ? ey : bi->py) - g;
        y1 = (ey < bi->py ? bi->py : ey) + g;
    }
    cc__walls_begin(w, &walk, x0, y0, x1, y1);
    while ((s = cc__walls_next(w, &walk)) >= 0) {
        const cc_segment *q = &seg[s];
        int r;
        if ((w->features & (CC__F_FILTER | CC__F_SENSOR)) && !cc__wall_interacts(w, i, s))
            continue;
        w->stats.pairs_tested++;
        if (roll > 0.0) {
            double g, gd;
            r = cc__roll_sweep_segment(&c, roll, q, best->t - now, &k);
            if (r == CC_MISS || r < 0 || !(now + k.t < best->t))
                continue;
            cc__roll_motion(roll, k.t, &g, &gd); /* the velocity at contact */
            if (!cc__approaching(w, gd * cc__dot(c.vel, k.normal), gd * (fabs(c.vel.x) + fabs(c.vel.y))))
                continue;
        } else {
            r = cc_sweep_segment(&c, q, best->t - now, &k);
            if (r == CC_MISS || r < 0 || !(now + k.t < best->t))
                continue;
            if (!cc__approaching(w, cc__dot(c.vel, k.normal), fabs(c.vel.x) + fabs(c.vel.y)))
                continue;
        }
        best->t = now + k.t;
        best->kind = CC__EV_SEGMENT;
        best->partner = s;
    }
}
