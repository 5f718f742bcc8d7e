/* The textbook time of impact of two rolling (decelerating) circles: the comparison column of
 * docs/NUMERICS.md's rolling table. Test-only code, never linked into the library.
 *
 * As event-driven billiards code commonly writes it (faithful to practice, not improved):
 *   - each ball at r(t) = r0 + v t + a t^2 / 2 with a = -decel v / |v|, until its stop |v| / decel;
 *   - before the first stop, |dr(t)|^2 = R^2 expanded into a quartic a4 t^4 + ... + a0 from the
 *     relative position dp = pb - pa, velocity dv = vb - va and acceleration da = ab - aa:
 *       a4 = da.da / 4, a3 = dv.da, a2 = dv.dv + dp.da, a1 = 2 dp.dv, a0 = dp.dp - R^2;
 *   - a0 < 0: overlap at t = 0; else the quartic solved in closed form (Ferrari: resolvent
 *     cubic by Cardano, in complex double), roots with |Im| <= 1e-9 (1 + |Re|) taken as real,
 *     the smallest real root in [0, piece end] is the contact;
 *   - none: both balls advanced to the stop (positions and velocities from the same formulas),
 *     the next piece solved likewise (a quadratic when nothing decelerates any more), up to
 *     t_max.
 * Same signature and result codes as cc_sweep_rolling; the contact's normal and point from
 * both centres advanced in the absolute frame. */
#include "textbook.h"

#include <complex.h>
#include <math.h>

typedef double complex cplx;

static cplx ccbrt(cplx z)
{
    if (z == 0)
        return 0;
    return cpow(z, 1.0 / 3.0);
}

/* the roots of x^3 + b x^2 + c x + d (Cardano, complex) into r[0..2] */
static void cubic(cplx b, cplx c, cplx d, cplx *r)
{
    cplx p = c - b * b / 3.0, q = 2.0 * b * b * b / 27.0 - b * c / 3.0 + d;
    cplx disc = csqrt(q * q / 4.0 + p * p * p / 27.0), u = ccbrt(-q / 2.0 + disc), v;
    cplx w = -0.5 + 0.5 * sqrt(3.0) * I;
    int k;
    if (cabs(u) == 0.0)
        u = ccbrt(-q / 2.0 - disc);
    for (k = 0; k < 3; k++) {
        v = u == 0 ? 0 : -p / (3.0 * u);
        r[k] = u + v - b / 3.0;
        u *= w;
    }
}

/* the roots of a4 x^4 + ... + a0 (a4 != 0) into r[0..3] (Ferrari) */
static void quartic(double a4, double a3, double a2, double a1, double a0, cplx *r)
{
    double b = a3 / a4, c = a2 / a4, d = a1 / a4, e = a0 / a4;
    double p = c - 3.0 * b * b / 8.0, q = b * b * b / 8.0 - b * c / 2.0 + d;
    double rr = -3.0 * b * b * b * b / 256.0 + b * b * c / 16.0 - b * d / 4.0 + e;
    cplx m3[3], m, s, C1, C2, d1, d2;
    int k;
    if (q == 0.0) { /* biquadratic */
        cplx z1 = (-p + csqrt(p * p - 4.0 * rr)) / 2.0, z2 = (-p - csqrt(p * p - 4.0 * rr)) / 2.0;
        r[0] = csqrt(z1), r[1] = -r[0], r[2] = csqrt(z2), r[3] = -r[2];
    } else {
        /* resolvent: m^3 + p m^2 + (p^2/4 - r) m - q^2/8 = 0; the root of largest modulus */
        cubic(p, p * p / 4.0 - rr, -q * q / 8.0, m3);
        m = m3[0];
        for (k = 1; k < 3; k++)
            if (cabs(m3[k]) > cabs(m))
                m = m3[k];
        s = csqrt(2.0 * m);
        C1 = p / 2.0 + m + q / (2.0 * s);
        C2 = p / 2.0 + m - q / (2.0 * s);
        d1 = csqrt(s * s - 4.0 * C1);
        d2 = csqrt(s * s - 4.0 * C2);
        r[0] = (s + d1) / 2.0, r[1] = (s - d1) / 2.0, r[2] = (-s + d2) / 2.0, r[3] = (-s - d2) / 2.0;
    }
    for (k = 0; k < 4; k++)
        r[k] -= b / 4.0;
}

/* the smallest real root in [lo, hi] of the polynomial (degree 4, or 2 when a4 = a3 = 0); -1 none */
static double first_root(double a4, double a3, double a2, double a1, double a0, double lo, double hi)
{
    cplx r[4];
    int n = 4, k;
    double best = -1.0;
    if (a4 == 0.0 && a3 == 0.0) {
        double disc = a1 * a1 - 4.0 * a2 * a0;
        if (a2 == 0.0 || disc < 0.0)
            return -1.0;
        r[0] = (-a1 - sqrt(disc)) / (2.0 * a2);
        r[1] = (-a1 + sqrt(disc)) / (2.0 * a2);
        n = 2;
    } else {
        quartic(a4, a3, a2, a1, a0, r);
    }
    for (k = 0; k < n; k++) {
        double re = creal(r[k]);
        if (fabs(cimag(r[k])) <= 1e-9 * (1.0 + fabs(re)) && re >= lo && re <= hi && (best < 0.0 || re < best))
            best = re;
    }
    return best;
}

typedef struct ball {
    double px, py, vx, vy, ax, ay, stop; /* stop: time left until it stops (HUGE_VAL: never) */
} ball;

static ball make_ball(const cc_circle *c, double decel)
{
    ball b;
    double s = sqrt(c->vel.x * c->vel.x + c->vel.y * c->vel.y);
    b.px = c->pos.x, b.py = c->pos.y, b.vx = c->vel.x, b.vy = c->vel.y;
    if (decel > 0.0 && s > 0.0) {
        b.ax = -decel * c->vel.x / s, b.ay = -decel * c->vel.y / s;
        b.stop = s / decel;
    } else {
        b.ax = b.ay = 0.0;
        b.stop = HUGE_VAL;
    }
    return b;
}

static void advance(ball *b, double t)
{
    b->px += b->vx * t + 0.5 * b->ax * t * t;
    b->py += b->vy * t + 0.5 * b->ay * t * t;
    b->vx += b->ax * t, b->vy += b->ay * t;
    b->stop -= t;
    if (b->stop <= 0.0) { /* at rest */
        b->vx = b->vy = b->ax = b->ay = 0.0;
        b->stop = HUGE_VAL;
    }
}

int tb_sweep_rolling(const cc_circle *a, double decel_a, const cc_circle *b, double decel_b, double t_max,
                     cc_contact *out)
{
    ball A = make_ball(a, decel_a), B = make_ball(b, decel_b);
    double R = a->radius + b->radius, t0 = 0.0;
    int piece;
    for (piece = 0; piece < 3 && t0 <= t_max; piece++) {
        double dpx = B.px - A.px, dpy = B.py - A.py, dvx = B.vx - A.vx, dvy = B.vy - A.vy;
        double dax = B.ax - A.ax, day = B.ay - A.ay;
        double a4 = 0.25 * (dax * dax + day * day), a3 = dvx * dax + dvy * day;
        double a2 = dvx * dvx + dvy * dvy + dpx * dax + dpy * day, a1 = 2.0 * (dpx * dvx + dpy * dvy);
        double a0 = dpx * dpx + dpy * dpy - R * R;
        double end = A.stop < B.stop ? A.stop : B.stop, t;
        if (piece == 0 && a0 < 0.0) {
            double l = sqrt(dpx * dpx + dpy * dpy);
            out->t = 0.0;
            out->normal.x = l > 0.0 ? dpx / l : 1.0, out->normal.y = l > 0.0 ? dpy / l : 0.0;
            out->depth = R - l;
            out->point.x = a->pos.x + a->radius * out->normal.x, out->point.y = a->pos.y + a->radius * out->normal.y;
            return CC_OVERLAP;
        }
        if (t0 + end > t_max)
            end = t_max - t0;
        t = first_root(a4, a3, a2, a1, a0, 0.0, end);
        if (t >= 0.0) {
            double nx, ny, l;
            advance(&A, t), advance(&B, t);
            nx = B.px - A.px, ny = B.py - A.py, l = sqrt(nx * nx + ny * ny);
            out->t = t0 + t;
            out->normal.x = nx / l, out->normal.y = ny / l;
            out->depth = 0.0;
            out->point.x = A.px + a->radius * out->normal.x, out->point.y = A.py + a->radius * out->normal.y;
            return CC_HIT;
        }
        if (!(end < HUGE_VAL) || (A.stop == HUGE_VAL && B.stop == HUGE_VAL))
            break;
        advance(&A, end), advance(&B, end);
        t0 += end;
        if (A.vx == 0.0 && A.vy == 0.0 && B.vx == 0.0 && B.vy == 0.0)
            break;
    }
    return CC_MISS;
}
