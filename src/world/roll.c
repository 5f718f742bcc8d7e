/* Rolling to rest in the world (issue 12): the motion of a decelerating circle, and the times at
 * which two such circles (or one and a wall, or one and a cell's side) meet.
 *
 * Motion: a circle with velocity v at its own time t0 and rolling coefficient k = decel / (2|v|)
 * is at p0 + v g(tau) after tau, with g(tau) = tau (1 - k tau) until it stops at ts = 1 / (2 k)
 * (g(ts) = ts / 2), and at rest from then on; its velocity is v (1 - 2 k tau). This is the
 * contract's p(t) = pos + v (t - decel t^2 / (2 s)).
 *
 * Meeting times: the offset of two circles is a quadratic polynomial in t between the stop
 * times (each circle's part is quadratic while it rolls, constant once it rests), so its squared
 * length less R^2 is a polynomial f of degree four at most on each piece. The earliest root at
 * which f falls through zero is found by isolating it between the roots of the derivatives
 * (f''' is linear, f'' quadratic: the roots of each split the next into monotone pieces, found by
 * bisection), then bisecting to the last bit. f is evaluated from the offset vector itself,
 * never from expanded coefficients: no cancellation the inputs do not force. */
#include "world_internal.h"

#include "precision_double.h"
#include "helpers.inc"
#include "solver.inc"
#include "precision_end.h"

/* Rolling coefficient k = decel / (2 |v|), 0 for a circle at rest or without deceleration. */
double cc__roll_coef(double vx, double vy, double decel)
{
    double s;
    if (!(decel > 0.0) || (vx == 0.0 && vy == 0.0))
        return 0.0;
    s = sqrt(vx * vx + vy * vy);
    return decel / (2.0 * s);
}

void cc__roll_motion(double k, double tau, double *g, double *gd)
{
    double ts = k > 0.0 ? 0.5 / k : HUGE_VAL;
    if (tau >= ts) {
        *g = 0.5 * ts;
        *gd = 0.0;
    } else {
        *g = k > 0.0 ? tau * (1.0 - k * tau) : tau;
        *gd = k > 0.0 ? 1.0 - 2.0 * k * tau : 1.0;
    }
}

/* ---- the offset of two rolling circles over a piece of time ---------------------------------- */

typedef struct cc__pair_path {
    double dpx, dpy;   /* offset b - a at t = 0 */
    double vax, vay, ka, vbx, vby, kb;
    double R;
    /* within the piece searched: whether each circle still rolls there (then its motion is the
     * polynomial itself, up to and at the piece's end, its stop: f and its derivatives are those
     * of the piece at both ends, not the resting circle's at the stop, which would hide a sign
     * change at the end, as f'' < 0 at the stop of a ball rolling away from one at rest);
     * -1: by the clock (the motion of the circle at t, clamped at its stop) */
    int a_on, b_on;
} cc__pair_path;

/* Motion of one circle within the piece: on (1 rolls, 0 rests or never rolled, -1 by clock). */
static void cc__piece_motion(double k, int on, double t, double *g, double *gd)
{
    if (on < 0 || k == 0.0) {
        cc__roll_motion(k, t, g, gd);
    } else if (on) {
        *g = t * (1.0 - k * t);
        *gd = 1.0 - 2.0 * k * t;
    } else {
        *g = 0.25 / k;
        *gd = 0.0;
    }
}

/* Whether a circle with coefficient k rolls at time t of a piece (by the clock when on < 0). */
static int cc__rolls(double k, int on, double t)
{
    return on < 0 ? (k > 0.0 && t < 0.5 / k) : (k > 0.0 && on);
}

/* The offset at t (from t = 0). */
static void cc__offset(const cc__pair_path *p, double t, double *x, double *y, double *dx, double *dy)
{
    double ga, gda, gb, gdb;
    cc__piece_motion(p->ka, p->a_on, t, &ga, &gda);
    cc__piece_motion(p->kb, p->b_on, t, &gb, &gdb);
    *x = p->dpx + (p->vbx * gb - p->vax * ga);
    *y = p->dpy + (p->vby * gb - p->vay * ga);
    *dx = p->vbx * gdb - p->vax * gda; /* the rate of change of the offset */
    *dy = p->vby * gdb - p->vay * gda;
}

/* f(t) = |offset|^2 - R^2 as (|o| - R)(|o| + R), and its first three derivatives, at t. The
 * offset's second derivative is constant on a piece: -2 k v of each rolling circle. */
static void cc__f(const cc__pair_path *p, double t, double d[4])
{
    double x, y, dx, dy, ax = 0.0, ay = 0.0, len;
    cc__offset(p, t, &x, &y, &dx, &dy);
    if (cc__rolls(p->kb, p->b_on, t))
        ax += -2.0 * p->kb * p->vbx, ay += -2.0 * p->kb * p->vby;
    if (cc__rolls(p->ka, p->a_on, t))
        ax -= -2.0 * p->ka * p->vax, ay -= -2.0 * p->ka * p->vay;
    len = sqrt(x * x + y * y);
    d[0] = (len - p->R) * (len + p->R);
    d[1] = 2.0 * (x * dx + y * dy);
    d[2] = 2.0 * (dx * dx + dy * dy + x * ax + y * ay);
    d[3] = 6.0 * (dx * ax + dy * ay);
}

/* The root of derivative `order` of f in [lo, hi], where it is monotone and changes sign
 * (bisection to the last bit). */
static double cc__bisect(const cc__pair_path *p, int order, double lo, double hi)
{
    double d[4], slo;
    cc__f(p, lo, d);
    slo = d[order];
    for (;;) {
        double mid = lo + 0.5 * (hi - lo);
        if (!(mid > lo && mid < hi))
            return hi;
        cc__f(p, mid, d);
        if ((d[order] > 0.0) == (slo > 0.0))
            lo = mid;
        else
            hi = mid;
    }
}

/* The points in (lo, hi) where derivative `order` of f changes sign, ascending, into out (at
 * most 3 for order 1): found through the next derivative's. Returns how many. */
static int cc__sign_changes(const cc__pair_path *p, int order, double lo, double hi, double *out)
{
    double cuts[8], d0[4], d1[4];
    int n = 0, k, m;
    if (order == 3) { /* f''' is linear on a piece: at most one */
        cc__f(p, lo, d0);
        cc__f(p, hi, d1);
        if ((d0[3] > 0.0) != (d1[3] > 0.0) && d0[3] != 0.0)
            out[n++] = cc__bisect(p, 3, lo, hi);
        return n;
    }
    cuts[0] = lo;
    m = 1 + cc__sign_changes(p, order + 1, lo, hi, cuts + 1);
    cuts[m++] = hi;
    for (k = 0; k + 1 < m; k++) {
        cc__f(p, cuts[k], d0);
        cc__f(p, cuts[k + 1], d1);
        if ((d0[order] > 0.0) != (d1[order] > 0.0) && d0[order] != 0.0 && d1[order] != 0.0 && n < 4)
            out[n++] = cc__bisect(p, order, cuts[k], cuts[k + 1]);
    }
    return n;
}

/* The earliest t in [lo, hi] where f falls through 0 (approach, dir = -1) or rises through it
 * (separation, dir = +1); -1 when none. */
static double cc__first_crossing(const cc__pair_path *p, double lo, double hi, int dir)
{
    double cuts[8], d0[4], d1[4];
    int m = 1, k;
    cuts[0] = lo;
    m += cc__sign_changes(p, 1, lo, hi, cuts + 1);
    cuts[m++] = hi;
    for (k = 0; k + 1 < m; k++) {
        cc__f(p, cuts[k], d0);
        cc__f(p, cuts[k + 1], d1);
        if (dir < 0 && d0[0] > 0.0 && d1[0] <= 0.0)
            return cc__bisect(p, 0, cuts[k], cuts[k + 1]);
        if (dir > 0 && d0[0] < 0.0 && d1[0] >= 0.0)
            return cc__bisect(p, 0, cuts[k], cuts[k + 1]);
    }
    return -1.0;
}

/* The first t in [lo, hi] at which the pair closes at vmin or faster (f' <= -2 |o| vmin), or -1:
 * the sign changes of f' split the piece into monotone parts, each bisected where it crosses. */
static double cc__closing_at(const cc__pair_path *p, double lo, double hi, double vmin)
{
    double cuts[8], d[4];
    int m = 1, k;
    cuts[0] = lo;
    m += cc__sign_changes(p, 2, lo, hi, cuts + 1);
    cuts[m++] = hi;
    for (k = 0; k + 1 < m; k++) {
        double a = cuts[k], b = cuts[k + 1], x, y, dx, dy, ga, gb;
        cc__offset(p, a, &x, &y, &dx, &dy);
        cc__f(p, a, d);
        ga = d[1] + 2.0 * sqrt(x * x + y * y) * vmin;
        cc__offset(p, b, &x, &y, &dx, &dy);
        cc__f(p, b, d);
        gb = d[1] + 2.0 * sqrt(x * x + y * y) * vmin;
        if (ga <= 0.0 && a > lo)
            return a;
        if (ga > 0.0 && gb <= 0.0) { /* bisect g = f' + 2 |o| vmin, monotone enough here */
            for (;;) {
                double mid = a + 0.5 * (b - a), gm;
                if (!(mid > a && mid < b))
                    return b;
                cc__offset(p, mid, &x, &y, &dx, &dy);
                cc__f(p, mid, d);
                gm = d[1] + 2.0 * sqrt(x * x + y * y) * vmin;
                if (gm > 0.0)
                    a = mid;
                else
                    b = mid;
            }
        }
    }
    return -1.0;
}

/* Squared distance from point (px, py) to the segment from (ax, ay) to (bx, by). */
static double cc__point_seg2(double px, double py, double ax, double ay, double bx, double by)
{
    double ux = bx - ax, uy = by - ay, wx = px - ax, wy = py - ay, uu = ux * ux + uy * uy, s;
    s = uu > 0.0 ? (wx * ux + wy * uy) / uu : 0.0;
    s = s < 0.0 ? 0.0 : s > 1.0 ? 1.0 : s;
    wx -= s * ux;
    wy -= s * uy;
    return wx * wx + wy * wy;
}

/* Whether the two circles' paths over [0, t_max] (a straight segment each, relative to a's
 * start) stay further apart than R: then no time brings them to R. Only for finite paths. */
static int cc__paths_apart(const cc__pair_path *p, double t_max)
{
    double ga, gb, gd, ax, ay, bx0, by0, bx1, by1, d2, m, cross1, cross2, cross3, cross4;
    if (!(t_max < HUGE_VAL) && ((p->ka == 0.0 && (p->vax != 0.0 || p->vay != 0.0)) ||
                                (p->kb == 0.0 && (p->vbx != 0.0 || p->vby != 0.0))))
        return 0; /* a path without end */
    cc__roll_motion(p->ka, t_max, &ga, &gd);
    cc__roll_motion(p->kb, t_max, &gb, &gd);
    ax = p->vax * ga, ay = p->vay * ga;           /* a: from (0, 0) to (ax, ay) */
    bx0 = p->dpx, by0 = p->dpy;                   /* b: from its offset on */
    bx1 = bx0 + p->vbx * gb, by1 = by0 + p->vby * gb;
    if (!(fabs(ax) + fabs(ay) + fabs(bx1) + fabs(by1) < HUGE_VAL))
        return 0;
    /* crossing segments are 0 apart */
    cross1 = ax * by0 - ay * bx0;
    cross2 = ax * by1 - ay * bx1;
    cross3 = (bx1 - bx0) * (0.0 - by0) - (by1 - by0) * (0.0 - bx0);
    cross4 = (bx1 - bx0) * (ay - by0) - (by1 - by0) * (ax - bx0);
    if ((cross1 > 0.0) != (cross2 > 0.0) && (cross3 > 0.0) != (cross4 > 0.0))
        return 0;
    d2 = cc__point_seg2(0.0, 0.0, bx0, by0, bx1, by1);
    m = cc__point_seg2(ax, ay, bx0, by0, bx1, by1);
    d2 = m < d2 ? m : d2;
    m = cc__point_seg2(bx0, by0, 0.0, 0.0, ax, ay);
    d2 = m < d2 ? m : d2;
    m = cc__point_seg2(bx1, by1, 0.0, 0.0, ax, ay);
    d2 = m < d2 ? m : d2;
    m = p->R * (1.0 + 0x1p-20) + 0x1p-40 * (fabs(ax) + fabs(ay) + fabs(bx0) + fabs(by0) + fabs(bx1) + fabs(by1));
    return d2 > m * m;
}

/* Which circles roll in the piece starting at lo (the stops sa, sb, -1 for none, are cuts). */
static void cc__piece(cc__pair_path *p, double sa, double sb, double lo)
{
    p->a_on = sa > lo;
    p->b_on = sb > lo;
}

int cc__roll_sweep(double dpx, double dpy, double vax, double vay, double ka, double vbx, double vby, double kb,
                   double R, double t_max, int dir, double vmin, double *t_out, double *nx, double *ny)
{
    cc__pair_path p;
    double cuts[4], t = -1.0, x, y, dx, dy, len, sa, sb, s_lo, s_hi, last;
    int m = 0, k;
    p.dpx = dpx, p.dpy = dpy, p.vax = vax, p.vay = vay, p.ka = ka, p.vbx = vbx, p.vby = vby, p.kb = kb, p.R = R;
    p.a_on = p.b_on = -1;
    len = sqrt(dpx * dpx + dpy * dpy);
    if (dir < 0) {
        double reach;
        if (len < R && dpx * (vbx - vax) + dpy * (vby - vay) < 0.0) { /* overlapping now, closing */
            *t_out = 0.0;
            *nx = len > 0.0 ? dpx / len : 1.0;
            *ny = len > 0.0 ? dpy / len : 0.0;
            return CC_OVERLAP;
        }
        /* (overlapping by rounding but parting: a rolling pair may come back, found below) */
        /* the farthest each can travel (to its stop, or in t_max): a pair further apart misses */
        reach = (ka > 0.0 ? 0.25 / ka : t_max) * sqrt(vax * vax + vay * vay) +
                (kb > 0.0 ? 0.25 / kb : t_max) * sqrt(vbx * vbx + vby * vby);
        if (len - R > reach * (1.0 + 0x1p-20))
            return CC_MISS;
        /* each circle moves along a straight segment (to its stop, or to t_max): two paths
         * further apart than R, at any times, cannot meet (a bound, with room for rounding) */
        if (cc__paths_apart(&p, t_max))
            return CC_MISS;
    }
    /* pieces of quadratic motion: from 0 to the first stop, to the second, or to t_max while a
     * circle still rolls; then, if anything still moves, a straight tail */
    sa = ka > 0.0 ? 0.5 / ka : -1.0;
    sb = kb > 0.0 ? 0.5 / kb : -1.0;
    s_lo = sa < sb ? sa : sb;
    s_hi = sa < sb ? sb : sa;
    cuts[m++] = 0.0;
    if (s_lo > 0.0 && s_lo < t_max)
        cuts[m++] = s_lo;
    if (s_hi > 0.0 && s_hi != s_lo)
        cuts[m++] = s_hi < t_max ? s_hi : t_max;
    else if (s_hi > 0.0 && s_hi >= t_max && m == 1)
        cuts[m++] = t_max;
    {   /* touching now and approaching (or separating): the crossing is now */
        double d[4];
        cc__f(&p, 0.0, d);
        if (d[0] == 0.0 && (dir < 0 ? d[1] < 0.0 : d[1] > 0.0))
            t = 0.0;
    }
    if (dir < 0 && t < 0.0 && len < R) {
        /* closer than R but parting: contact again when they close at vmin, if still closer */
        for (k = 0; k + 1 < m && t < 0.0; k++)
            if (cuts[k + 1] > cuts[k]) {
                cc__piece(&p, sa, sb, cuts[k]);
                t = cc__closing_at(&p, cuts[k], cuts[k + 1], vmin);
            }
        if (t >= 0.0) {
            double d[4];
            cc__f(&p, t, d);
            if (!(d[0] < 0.0))
                t = -1.0; /* parted first: an ordinary crossing, looked for below */
        }
    }
    for (k = 0; k + 1 < m && t < 0.0; k++)
        if (cuts[k + 1] > cuts[k]) {
            cc__piece(&p, sa, sb, cuts[k]);
            t = cc__first_crossing(&p, cuts[k], cuts[k + 1], dir);
        }
    p.a_on = p.b_on = -1;
    last = cuts[m - 1];
    if (t < 0.0 && last < t_max) {
        /* after the last stop the offset moves on in a straight line (a circle that does not
         * decelerate: a kinematic one, or one without friction), or not at all */
        double o[2], od[2], tt;
        cc_vec2 n;
        cc__offset(&p, last, &o[0], &o[1], &od[0], &od[1]);
        if (od[0] == 0.0 && od[1] == 0.0)
            return CC_MISS;
        if (dir < 0) {
            if (cc__sweep_rel(cc__v(o[0], o[1]), cc__v(od[0], od[1]), R, 0, 0, t_max - last, &tt, &n) != CC_HIT)
                return CC_MISS;
        } else {
            /* the later root of |o + od s| = R, without cancellation either way */
            double vv = od[0] * od[0] + od[1] * od[1], bb = o[0] * od[0] + o[1] * od[1];
            double h = fabs(o[0] * od[1] - o[1] * od[0]), q = sqrt(vv) * R, dd = sqrt(o[0] * o[0] + o[1] * o[1]), disc, c;
            if (!(q > h))
                return CC_MISS;
            disc = (q - h) * (q + h);
            c = (dd - R) * (dd + R);
            tt = bb <= 0.0 ? (-bb + sqrt(disc)) / vv : -c / (bb + sqrt(disc));
            if (!(tt >= 0.0 && tt <= t_max - last))
                return CC_MISS;
        }
        t = last + tt;
    }
    if (t < 0.0)
        return CC_MISS;
    cc__offset(&p, t, &x, &y, &dx, &dy);
    len = sqrt(x * x + y * y);
    *t_out = t;
    *nx = len > 0.0 ? x / len : 1.0;
    *ny = len > 0.0 ? y / len : 0.0;
    return CC_HIT;
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

/* ---- a rolling circle against a wall ---------------------------------------------------------- */

int cc__roll_sweep_segment(const cc_circle *c, double k, const cc_segment *s, double t_max, cc_contact *out)
{
    cc_vec2 ends[2], q, n = {1.0, 0.0};
    double dist, t = 0.0;
    int i, found = 0, interior = 0;
    if (k == 0.0)
        return cc_sweep_segment(c, s, t_max, out);
    /* overlapping now: as cc_sweep_segment */
    ends[0] = cc__sub(s->a, c->pos);
    ends[1] = cc__sub(s->b, c->pos);
    q = cc__segment_point(ends[0], ends[1], cc__segment_param(cc__v(0.0, 0.0), ends[0], ends[1]));
    dist = cc__length(q);
    if (dist < c->radius)
        return cc_sweep_segment(c, s, t_max, out);
    if (s->a.x != s->b.x || s->a.y != s->b.y) {
        /* the interior: the signed distance from the line moves as g(t); it reaches the radius when
         * g(t) = gap / closing speed, before the stop only if that is within reach */
        cc_vec2 u = cc__sub(s->b, s->a), nl = cc__unit(cc__v(-u.y, u.x)), w0 = cc__sub(c->pos, s->a);
        double sd = cc__dot(w0, nl), vs = cc__dot(c->vel, nl), side = sd > 0.0 ? 1.0 : -1.0;
        double gap = fabs(sd) - c->radius, closing = -side * vs;
        if (sd != 0.0 && closing > 0.0 && gap >= 0.0) {
            double G = gap / closing, disc = 1.0 - 4.0 * k * G;
            if (disc >= 0.0) {
                double tt = 2.0 * G / (1.0 + sqrt(disc)), g, gd, lambda;
                cc__roll_motion(k, tt, &g, &gd);
                lambda = cc__dot(cc__advance(w0, c->vel, g), u);
                if (tt <= t_max && lambda >= 0.0 && lambda <= cc__dot(u, u)) {
                    t = tt;
                    n = cc__scale(nl, -side);
                    found = interior = 1;
                }
            }
        }
    }
    for (i = 0; i < 2 && !interior; i++) { /* the end points: circles of radius 0 at rest */
        double te, nx, ny;
        cc_vec2 dp = cc__sub(i ? s->b : s->a, c->pos);
        if (cc__roll_sweep(dp.x, dp.y, c->vel.x, c->vel.y, k, 0.0, 0.0, 0.0, c->radius, found ? t : t_max, -1, 0.0, &te,
                           &nx, &ny) == CC_HIT &&
            (!found || te < t)) {
            found = 1;
            t = te;
            n = cc__v(nx, ny);
        }
    }
    if (!found)
        return CC_MISS;
    {
        double g, gd;
        cc__roll_motion(k, t, &g, &gd);
        out->t = t;
        out->normal = n;
        out->depth = 0.0;
        out->point = cc__advance(cc__advance(c->pos, c->vel, g), n, c->radius);
    }
    return CC_HIT;
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
