/* Sensors (issue 13): circles that take and give no impulses and report when another circle
 * begins or stops overlapping them. Each visitor (a non-sensor circle) keeps the set of sensors
 * it overlaps as bits of its properties (one per sensor slot, CC_MAX_SENSORS of them), so that
 * what the world reports always alternates begin, end, begin for a pair, whatever rounding does
 * at the boundary. EXACT predicts each pair's next change like an impact, from both bodies (the
 * grid finds a pair from whichever of the two crosses into the other's neighbourhood); the
 * event says which change it is, and the second body to reach it finds it done. SWEPT and
 * DISCRETE compare at the end of each step. */
#include "world_internal.h"

#include "precision_double.h"
#include "helpers.inc"
#include "solver.inc"
#include "precision_end.h"

/* The pair's sensor (*s) and visitor (*v), given circles i and j one of which is a sensor. */
static void cc__roles(const cc_world *w, int i, int j, int *s, int *v)
{
    int i_is = CC__CARR(w, cc__props, off_props)[i].sensor >= 0;
    *s = i_is ? i : j;
    *v = i_is ? j : i;
}

static int cc__inside(const cc_world *w, int s, int v)
{
    const cc__props *P = CC__CARR(w, cc__props, off_props);
    return (int)(P[v].inside >> P[s].sensor & 1u);
}

static void cc__report(cc_world *w, int s, int v, int begin)
{
    cc__props *P = CC__ARR(w, cc__props, off_props);
    cc_sensor_event e;
    P[v].inside ^= (uint64_t)1 << P[s].sensor;
    if (w->on_sensor == NULL)
        return;
    e.sensor = cc__idx2id(w, s);
    e.visitor = cc__idx2id(w, v);
    e.begin = begin;
    e.t = w->now;
    w->on_sensor(&e, w->user);
}

/* Sensor s senses circle v: a live non-sensor circle that the filters admit. */
static int cc__senses(const cc_world *w, int s, int v)
{
    const cc__props *P = CC__CARR(w, cc__props, off_props);
    return s != v && (CC__CARR(w, cc__cold, off_cold)[v].flags & CC__ALIVE) && P[v].sensor < 0 &&
           cc__filter_pass(&P[s], &P[v]);
}

int cc__sensor_overlaps(const cc_world *w, int s, int v)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    double dx = cc__near_d(w, cc__bx(w, &B[v], w->now) - cc__bx(w, &B[s], w->now), 0);
    double dy = cc__near_d(w, cc__by(w, &B[v], w->now) - cc__by(w, &B[s], w->now), 1);
    double R = B[s].r + B[v].r;
    return dx * dx + dy * dy < R * R;
}

/* Brings the pair's bit up to date with the overlap now, reporting a change. */
static void cc__sync(cc_world *w, int s, int v)
{
    int now_in = cc__senses(w, s, v) && cc__sensor_overlaps(w, s, v);
    if (now_in != cc__inside(w, s, v))
        cc__report(w, s, v, now_in);
}

void cc__sensor_refresh(cc_world *w, int i)
{
    const cc__props *P = CC__CARR(w, cc__props, off_props);
    const int32_t *id2idx = CC__CARR(w, int32_t, off_id2idx);
    int j, slot;
    if (!(w->features & CC__F_SENSOR))
        return;
    if (P[i].sensor >= 0) {
        for (j = 0; j < w->id_end; j++)
            if (j != i && (CC__CARR(w, cc__cold, off_cold)[j].flags & CC__ALIVE) && P[j].sensor < 0)
                cc__sync(w, i, j);
        return;
    }
    for (slot = 0; slot < CC_MAX_SENSORS; slot++)
        if (w->sensor_slots >> slot & 1u)
            cc__sync(w, id2idx[w->sensor_id[slot]], i);
}

void cc__sensor_forget(cc_world *w, int i, int quiet)
{
    cc__props *P = CC__ARR(w, cc__props, off_props);
    const int32_t *id2idx = CC__CARR(w, int32_t, off_id2idx);
    int j, slot;
    if (!(w->features & CC__F_SENSOR))
        return;
    if (P[i].sensor >= 0) { /* a sensor: out of every visitor, then its slot is free */
        uint64_t bit = (uint64_t)1 << P[i].sensor;
        for (j = 0; j < w->id_end; j++)
            if ((P[j].inside & bit) && (CC__CARR(w, cc__cold, off_cold)[j].flags & CC__ALIVE)) {
                if (quiet)
                    P[j].inside &= ~bit;
                else
                    cc__report(w, i, j, 0);
            }
        w->sensor_slots &= ~bit;
        P[i].sensor = -1;
        return;
    }
    for (slot = 0; slot < CC_MAX_SENSORS; slot++)
        if (P[i].inside >> slot & 1u) {
            if (quiet)
                P[i].inside &= ~((uint64_t)1 << slot);
            else
                cc__report(w, id2idx[w->sensor_id[slot]], i, 0);
        }
}

/* The tolerance within which the boundary is rounding's: 2^-40 of the numbers that make the
 * distance (as the simultaneous-impact gathering's, docs/SIMULTANEOUS.md). */
static double cc__boundary_tol(const cc_world *w, const cc__body *a, const cc__body *b, double ax, double ay,
                               double bx, double by)
{
    double m = fabs(ax) + fabs(ay) + fabs(bx) + fabs(by) + a->r + b->r;
    double v = fabs(a->vx) + fabs(a->vy) + fabs(b->vx) + fabs(b->vy);
    return 0x1p-40 * (m + v * fabs(w->now));
}

double cc__sensor_next(const cc_world *w, int i, int j, double sx, double sy)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const cc__body *a = &B[i], *b = &B[j];
    double ax = cc__bx(w, a, w->now), ay = cc__by(w, a, w->now), bx = cc__bx(w, b, w->now) + sx, by = cc__by(w, b, w->now) + sy;
    double R = a->r + b->r, d, gap, tol, t;
    cc_vec2 dp, dv, n;
    int s, v;
    cc__roles(w, i, j, &s, &v);
    if ((w->features & CC__F_PERIODIC) && cc__inside(w, s, v) &&
        (cc__near_d(w, bx - ax, 0) != bx - ax || cc__near_d(w, by - ay, 1) != by - ay))
        return HUGE_VAL; /* inside through the nearest image: this one ends nothing */
    if (w->features & CC__F_ROLL) {
        double ka, kb, vax, vay, vbx, vby, nx, ny;
        cc__roll_state(w, i, w->now, &ax, &ay, &vax, &vay, &ka);
        cc__roll_state(w, j, w->now, &bx, &by, &vbx, &vby, &kb);
        bx += sx;
        by += sy;
        if (ka > 0.0 || kb > 0.0) { /* along the rolling motions */
            int inside = cc__inside(w, s, v);
            gap = sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay)) - R;
            tol = cc__boundary_tol(w, a, b, ax, ay, bx, by);
            if (inside ? gap > tol : gap < -tol)
                return w->now; /* on the other side by more than rounding (set, pushed): now */
            if (!inside && gap < 0.0)
                return (bx - ax) * (vbx - vax) + (by - ay) * (vby - vay) < 0.0 ? w->now : HUGE_VAL;
            if (cc__roll_sweep(bx - ax, by - ay, vax, vay, ka, vbx, vby, kb, R, HUGE_VAL, inside ? 1 : -1, 0.0, &t, &nx, &ny) !=
                CC_HIT)
                return HUGE_VAL;
            return w->now + t;
        }
    }
    dp = cc__v(bx - ax, by - ay);
    dv = cc__v(b->vx - a->vx, b->vy - a->vy);
    d = sqrt(dp.x * dp.x + dp.y * dp.y);
    gap = d - R;
    tol = cc__boundary_tol(w, a, b, ax, ay, bx, by);
    if (cc__inside(w, s, v)) {
        /* inside: it ends where the distance comes back to R while growing, the larger root of
         * |dp + dv t| = R; out by more than rounding (set, pushed): it ends now */
        double vv = cc__dot(dv, dv), bb, h, q, disc, c;
        if (gap > tol)
            return w->now;
        if (vv == 0.0)
            return HUGE_VAL;
        bb = cc__dot(dp, dv);
        h = fabs(cc__cross(dp, dv));
        q = sqrt(vv) * R;
        if (!(q > h))
            return w->now; /* the line passes outside: at the boundary only by rounding */
        disc = (q - h) * (q + h);
        c = (d - R) * (d + R);
        /* the roots' product is c / vv: the larger one without cancellation either way */
        t = bb <= 0.0 ? (-bb + sqrt(disc)) / vv : -c / (bb + sqrt(disc));
        return t > 0.0 ? w->now + t : w->now;
    }
    if (gap < -tol)
        return w->now; /* inside by more than rounding (set, pushed): it begins now */
    switch (cc__sweep_rel(dp, dv, R, 0, 0, HUGE_VAL, &t, &n)) {
    case CC_HIT: return w->now + t;
    case CC_OVERLAP: return cc__dot(dp, dv) < 0.0 ? w->now : HUGE_VAL; /* within rounding of R */
    default: return HUGE_VAL;
    }
}

int cc__sensor_inside(const cc_world *w, int i, int j)
{
    int s, v;
    cc__roles(w, i, j, &s, &v);
    return cc__inside(w, s, v);
}

int cc__sensor_event(cc_world *w, int i, int j, int kind)
{
    int s, v, begin = kind == CC__EV_BEGIN;
    cc__roles(w, i, j, &s, &v);
    if (cc__inside(w, s, v) == begin)
        return 0;
    cc__report(w, s, v, begin);
    return 1;
}

void cc__sensor_pass(cc_world *w)
{
    const int32_t *id2idx = CC__CARR(w, int32_t, off_id2idx);
    int slot, j;
    if (!(w->features & CC__F_SENSOR))
        return;
    for (slot = 0; slot < CC_MAX_SENSORS; slot++) {
        int s;
        if (!(w->sensor_slots >> slot & 1u))
            continue;
        s = id2idx[w->sensor_id[slot]];
        for (j = 0; j < w->id_end; j++)
            if (j != s && (CC__CARR(w, cc__cold, off_cold)[j].flags & CC__ALIVE) &&
                CC__CARR(w, cc__props, off_props)[j].sensor < 0)
                cc__sync(w, s, j);
    }
}
