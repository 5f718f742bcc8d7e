/* Rolling to rest in the world (issue 12): a body's rolling state, carried along its motion.
 *
 * Motion: a circle with velocity v at its own time t0 and rolling coefficient k = decel / (2|v|)
 * is at p0 + v g(tau) after tau, with g(tau) = tau (1 - k tau) until it stops at ts = 1 / (2 k)
 * (g(ts) = ts / 2), and at rest from then on; its velocity is v (1 - 2 k tau). This is the
 * contract's p(t) = pos + v (t - decel t^2 / (2 s)).
 *
 * The motion itself (cc__roll_motion) and the times at which two rolling circles, or one and a
 * wall, meet (cc__roll_sweep, cc__roll_sweep_segment) are the pair functions' solver, shared with
 * cc_sweep_rolling: src/rolling.inc, compiled in double by src/rolling_double.c. */
#include "world_internal.h"

/* Rolling coefficient k = decel / (2 |v|), 0 for a circle at rest or without deceleration. */
double cc__roll_coef(double vx, double vy, double decel)
{
    double s;
    if (!(decel > 0.0) || (vx == 0.0 && vy == 0.0))
        return 0.0;
    s = sqrt(vx * vx + vy * vy);
    return decel / (2.0 * s);
}

/* ---- a rolling circle against a cell's side ------------------------------------------------- */

double cc__roll_reach(double x0, double v, double k, double X)
{
    double D = X - x0, disc, t;
    if (k == 0.0)
        return v != 0.0 ? D / v : HUGE_VAL;
    /* x0 + v t (1 - k t) = X: k v t^2 - v t + D = 0, the smaller root before the stop (where the
     * discriminant v^2 - 4 k v D is 0: the farthest the circle gets) */
    if (v == 0.0 || (D > 0.0) != (v > 0.0))
        return D == 0.0 ? 0.0 : HUGE_VAL;
    disc = v * v - 4.0 * k * v * D;
    if (disc < 0.0)
        return HUGE_VAL;
    t = 2.0 * D / (v + (v > 0.0 ? sqrt(disc) : -sqrt(disc)));
    return t;
}

/* ---- a body's rolling state ------------------------------------------------------------------ */

void cc__roll_at(const cc_world *w, const cc__body *b, double t, double *x, double *y, double *vx, double *vy)
{
    int j = (int)(b - CC__CARR(w, cc__body, off_body));
    double k = CC__CARR(w, cc__props, off_props)[j].roll, g, gd;
    cc__roll_motion(k, t - b->t, &g, &gd);
    *x = b->px + b->vx * g;
    *y = b->py + b->vy * g;
    *vx = b->vx * gd;
    *vy = b->vy * gd;
}

void cc__roll_advance(cc_world *w, cc__body *b, double t)
{
    int j = (int)(b - CC__CARR(w, cc__body, off_body));
    cc__props *p = &CC__ARR(w, cc__props, off_props)[j];
    double k = p->roll, tau = t - b->t, g, gd;
    if (k == 0.0) { /* straight motion, as without friction */
        b->px += b->vx * tau;
        b->py += b->vy * tau;
        b->t = t;
        return;
    }
    cc__roll_motion(k, tau, &g, &gd);
    b->px += b->vx * g;
    b->py += b->vy * g;
    b->t = t;
    if (gd == 0.0) { /* stopped: at rest from here on */
        b->vx = b->vy = 0.0;
        p->roll = 0.0;
    } else { /* slower, the same deceleration: k grows as the speed falls */
        b->vx *= gd;
        b->vy *= gd;
        p->roll = k / gd;
    }
}

void cc__roll_state(const cc_world *w, int j, double t, double *x, double *y, double *vx, double *vy, double *k)
{
    const cc__body *b = &CC__CARR(w, cc__body, off_body)[j];
    double k0 = CC__CARR(w, cc__props, off_props)[j].roll, g, gd;
    cc__roll_motion(k0, t - b->t, &g, &gd);
    *x = b->px + b->vx * g;
    *y = b->py + b->vy * g;
    *vx = b->vx * gd;
    *vy = b->vy * gd;
    *k = gd > 0.0 ? k0 / gd : 0.0;
}

void cc__roll_stop(cc_world *w, int j)
{
    cc__body *b = &CC__ARR(w, cc__body, off_body)[j];
    cc__props *p = &CC__ARR(w, cc__props, off_props)[j];
    if (p->roll > 0.0) { /* where it rests: g(ts) = 1 / (4k) exactly, whatever the clock's rounding */
        double g = 0.25 / p->roll;
        b->px += b->vx * g;
        b->py += b->vy * g;
    }
    b->vx = b->vy = 0.0;
    b->t = w->now;
    p->roll = 0.0;
}

void cc__roll_reset(cc_world *w, int j)
{
    const cc__body *b = &CC__CARR(w, cc__body, off_body)[j];
    cc__props *p = &CC__ARR(w, cc__props, off_props)[j];
    p->roll = isinf(CC__CARR(w, cc__cold, off_cold)[j].m) ? 0.0 : cc__roll_coef(b->vx, b->vy, p->decel);
}
