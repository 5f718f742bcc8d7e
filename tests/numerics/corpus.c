/* Generates the extreme-case corpus (see corpus.h). Each class builds a problem whose answer
 * is known by construction in real numbers (contact time t*, impact parameter h, foot on the
 * segment, ...), then rounds it to the inputs; the reference judges the rounded inputs. */
#include "corpus.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct rng {
    uint64_t s;
} rng;

static uint64_t next(rng *r) /* splitmix64 */
{
    uint64_t z = (r->s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

static double uni(rng *r, double lo, double hi) /* uniform in [lo, hi) */
{
    return lo + (hi - lo) * ((double)(next(r) >> 11) * 0x1p-53);
}

static int coin(rng *r, double p) { return uni(r, 0.0, 1.0) < p; }

/* 10^k, correctly rounded by the C library's decimal conversion */
static double pow10i(int k)
{
    char buf[16];
    snprintf(buf, sizeof buf, "1e%d", k);
    return strtod(buf, NULL);
}

/* roughly log-uniform in [10^lo, 10^hi]: a random decade, then a mantissa in [1, 10) */
static double logu(rng *r, int lo, int hi)
{
    int k = lo + (int)(next(r) % (uint64_t)(hi - lo + 1));
    return k == hi ? pow10i(k) : uni(r, 1.0, 10.0) * pow10i(k);
}

static double sgn(rng *r) { return coin(r, 0.5) ? 1.0 : -1.0; }

static cc_vec2 v2(double x, double y)
{
    cc_vec2 v;
    v.x = x, v.y = y;
    return v;
}

static cc_vec2 unit(rng *r)
{
    double x, y, l;
    do {
        x = uni(r, -1.0, 1.0), y = uni(r, -1.0, 1.0);
        l = x * x + y * y;
    } while (l > 1.0 || l < 1e-4);
    l = sqrt(l);
    return v2(x / l, y / l);
}

static cc_circle circle(cc_vec2 p, cc_vec2 v, double r)
{
    cc_circle c;
    c.pos = p, c.vel = v, c.radius = r, c.mass = 1.0;
    return c;
}

/* Circles of radii ra, rb whose relative motion has speed `speed`, impact parameter h (closest
 * approach of the centres) and along-track distance s before closest approach at t = 0;
 * a's position and velocity are random in a scene of size L with speeds up to vmax. */
static void pair(rng *r, corpus_case *c, double ra, double rb, double speed, double h, double s, double L,
                 double vmax)
{
    cc_vec2 d = unit(r), e = v2(-d.y, d.x);
    cc_vec2 pa = v2(uni(r, -L, L), uni(r, -L, L)), va = v2(uni(r, -vmax, vmax), uni(r, -vmax, vmax));
    cc_vec2 dp = v2(h * e.x - s * d.x, h * e.y - s * d.y), dv = v2(speed * d.x, speed * d.y);
    c->is_segment = 0;
    c->a = circle(pa, va, ra);
    c->b = circle(v2(pa.x + dp.x, pa.y + dp.y), v2(va.x + dv.x, va.y + dv.y), rb);
}

/* along-track distance for first contact at t* (h < R), or any approach for a miss */
static double along(double R, double h, double speed, double tstar)
{
    return speed * tstar + (h < R ? sqrt((R - h) * (R + h)) : 0.0);
}

/* an ordinary pair: radii 0.1..2, speeds up to 10, contact (or near miss) around t in [0, 1.5 t_max] */
static void ordinary(rng *r, corpus_case *c)
{
    double ra = uni(r, 0.1, 2.0), rb = uni(r, 0.1, 2.0), R = ra + rb, speed = uni(r, 0.1, 10.0);
    double h = R * uni(r, 0.0, 1.2);
    c->t_max = uni(r, 1.0, 10.0);
    if (coin(r, 0.15)) { /* anything: overlapping, parting, resting */
        c->is_segment = 0;
        c->a = circle(v2(uni(r, -5, 5), uni(r, -5, 5)), v2(uni(r, -5, 5), uni(r, -5, 5)), ra);
        c->b = circle(v2(uni(r, -5, 5), uni(r, -5, 5)), coin(r, 0.2) ? c->a.vel : v2(uni(r, -5, 5), uni(r, -5, 5)), rb);
        return;
    }
    pair(r, c, ra, rb, speed, h, along(R, h, speed, c->t_max * uni(r, 0.0, 1.5)), 100.0, 10.0);
}

static void scale_case(corpus_case *c, double S) /* lengths and speeds by S: times unchanged */
{
    c->a.pos.x *= S, c->a.pos.y *= S, c->a.vel.x *= S, c->a.vel.y *= S, c->a.radius *= S;
    c->b.pos.x *= S, c->b.pos.y *= S, c->b.vel.x *= S, c->b.vel.y *= S, c->b.radius *= S;
    c->s.a.x *= S, c->s.a.y *= S, c->s.b.x *= S, c->s.b.y *= S;
}

static void offset_case(corpus_case *c, cc_vec2 o)
{
    c->a.pos.x += o.x, c->a.pos.y += o.y, c->b.pos.x += o.x, c->b.pos.y += o.y;
    c->s.a.x += o.x, c->s.a.y += o.y, c->s.b.x += o.x, c->s.b.y += o.y;
}

/* A circle of radius rc against segment e0-e1, first touching at t* at the segment point of
 * parameter lam (0 or 1: an end point, from a random outward direction; else the interior,
 * from one side), moving at `speed`; when miss, the path is shifted off by `off` radii. */
static void seg_case(rng *r, corpus_case *c, double rc, cc_vec2 e0, cc_vec2 e1, double lam, double speed,
                     double tstar)
{
    cc_vec2 u = v2(e1.x - e0.x, e1.y - e0.y), q = v2(e0.x + lam * u.x, e0.y + lam * u.y), n, dir, cs;
    double len = sqrt(u.x * u.x + u.y * u.y), side = sgn(r), ct;
    if (lam > 0.0 && lam < 1.0 && len > 0.0)
        n = v2(-u.y / len * side, u.x / len * side); /* from the wall towards the circle */
    else {
        n = unit(r);
        if (len > 0.0 && (lam <= 0.0 ? -1.0 : 1.0) * (n.x * u.x + n.y * u.y) < 0.0)
            n = v2(-n.x, -n.y); /* outward from the end */
    }
    /* approach direction within 80 degrees of -n */
    do {
        dir = unit(r);
        ct = -(dir.x * n.x + dir.y * n.y);
    } while (ct < 0.17);
    cs = v2(q.x + rc * n.x, q.y + rc * n.y); /* centre at contact */
    c->is_segment = 1;
    c->a = circle(v2(cs.x - speed * dir.x * tstar, cs.y - speed * dir.y * tstar), v2(speed * dir.x, speed * dir.y), rc);
    c->s.a = e0, c->s.b = e1;
}

static void seg_ordinary(rng *r, corpus_case *c, double len, int ends)
{
    cc_vec2 d = unit(r), e0 = v2(uni(r, -10, 10), uni(r, -10, 10));
    double lam = ends ? (coin(r, 0.5) ? 0.0 : 1.0) : uni(r, 0.0, 1.0);
    c->t_max = uni(r, 1.0, 10.0);
    seg_case(r, c, uni(r, 0.1, 2.0), e0, v2(e0.x + len * d.x, e0.y + len * d.y), lam, uni(r, 0.1, 10.0),
             c->t_max * uni(r, 0.0, 1.3));
    if (coin(r, 0.2)) /* shift the path sideways: many of these miss */
        c->a.pos.x += uni(r, -3, 3), c->a.pos.y += uni(r, -3, 3);
}

/* ---- rolling to rest ------------------------------------------------------------------------ */

/* where a circle from p with velocity v and deceleration d is at t (the contract's motion) */
static cc_vec2 rolled(cc_vec2 p, cc_vec2 v, double d, double t)
{
    double s = sqrt(v.x * v.x + v.y * v.y), g = t;
    if (d > 0.0 && s > 0.0) {
        double ts = s / d;
        g = t < ts ? t - 0.5 * t * t / ts : 0.5 * ts;
    }
    return v2(p.x + v.x * g, p.y + v.y * g);
}

static double stop_time(cc_vec2 v, double d)
{
    double s = sqrt(v.x * v.x + v.y * v.y);
    return d > 0.0 && s > 0.0 ? s / d : HUGE_VAL;
}

/* a and b rolling (velocities va, vb, decelerations da, db) placed so that at tc their centres
 * are R * sep apart along a random direction (sep = 1: touching then, a contact at or before tc
 * when they approach) */
static void roll_place(rng *r, corpus_case *c, double ra, double rb, cc_vec2 va, double da, cc_vec2 vb, double db,
                       double tc, double sep, double L)
{
    cc_vec2 pa = v2(uni(r, -L, L), uni(r, -L, L)), at = rolled(pa, va, da, tc), n = unit(r), bt, b0;
    double R = ra + rb;
    bt = v2(at.x + R * sep * n.x, at.y + R * sep * n.y);
    b0 = rolled(v2(0, 0), vb, db, tc); /* b's displacement by tc */
    c->is_segment = 0, c->rolling = 1;
    c->a = circle(pa, va, ra);
    c->b = circle(v2(bt.x - b0.x, bt.y - b0.y), vb, rb);
    c->decel_a = da, c->decel_b = db;
}

static cc_vec2 rvel(rng *r, double lo, double hi)
{
    cc_vec2 d = unit(r);
    double s = uni(r, lo, hi);
    return v2(s * d.x, s * d.y);
}

/* an ordinary rolling pair: speeds 0.1..10 (b at rest a fifth of the time), decelerations
 * 0.05..20 (0 for b a tenth of the time), contact (or a near miss) before the first stop or
 * after it, t_max 1..10 or unbounded */
static void roll_ordinary(rng *r, corpus_case *c)
{
    double ra = uni(r, 0.1, 2.0), rb = uni(r, 0.1, 2.0), da = logu(r, -1, 1), db = coin(r, 0.1) ? 0.0 : logu(r, -1, 1);
    cc_vec2 va = rvel(r, 0.1, 10.0), vb = coin(r, 0.2) ? v2(0, 0) : rvel(r, 0.1, 10.0);
    double ts = stop_time(va, da), tb = stop_time(vb, db);
    double tc = (ts < tb ? ts : tb) * uni(r, 0.0, 1.5);
    if (!(tc < HUGE_VAL))
        tc = ts * uni(r, 0.0, 1.5);
    roll_place(r, c, ra, rb, va, da, vb, db, tc, uni(r, 0.9, 1.1), 20.0);
    c->t_max = coin(r, 0.5) ? HUGE_VAL : uni(r, 1.0, 10.0);
}

/* a rolling along d at impact parameter h from b, which rests or rolls along the same line
 * (the relative path is then straight): a grazing contact at R (1 -+ m) */
static void roll_grazing(rng *r, corpus_case *c, int digits)
{
    cc_vec2 d = unit(r), e = v2(-d.y, d.x), pa = v2(uni(r, -10, 10), uni(r, -10, 10));
    double R = uni(r, 0.5, 4.0), m = logu(r, -digits, -3), h = R * (coin(r, 0.5) ? 1.0 - m : 1.0 + m);
    double sa = uni(r, 1.0, 10.0), da = uni(r, 0.5, 5.0), travel = 0.5 * sa * sa / da, sb = 0.0, db = 0.0;
    double ahead = travel * uni(r, 0.3, 0.9); /* where b's centre projects onto a's line, ahead of a */
    if (coin(r, 0.5)) { /* b rolls along the line too, slower, either way */
        sb = sgn(r) * sa * uni(r, 0.05, 0.3);
        db = da * uni(r, 0.5, 2.0);
        if (sb > 0.0)
            ahead = 0.5 * ahead; /* running away: start it nearer */
    }
    c->is_segment = 0, c->rolling = 1;
    c->a = circle(pa, v2(sa * d.x, sa * d.y), R * 0.5);
    c->b = circle(v2(pa.x + ahead * d.x + h * e.x, pa.y + ahead * d.y + h * e.y), v2(sb * d.x, sb * d.y), R * 0.5);
    c->decel_a = da, c->decel_b = db;
    c->t_max = HUGE_VAL;
}

/* a rolls nearly straight at b at rest and stops with its centre R (1 -+ m) from b's: a contact
 * just before its stop (closing at ~sqrt(m)), or stopping just short */
static void roll_stop_short(rng *r, corpus_case *c, int digits)
{
    cc_vec2 d = unit(r), e = v2(-d.y, d.x), pa = v2(uni(r, -10, 10), uni(r, -10, 10)), rest;
    double R = uni(r, 0.5, 4.0), m = logu(r, -digits, -3), sa = uni(r, 0.5, 10.0), da = logu(r, -1, 1);
    double h = R * uni(r, 0.0, 0.5), gap = R * (coin(r, 0.5) ? 1.0 - m : 1.0 + m), along = sqrt(gap * gap - h * h);
    rest = v2(pa.x + 0.5 * sa * sa / da * d.x, pa.y + 0.5 * sa * sa / da * d.y);
    c->is_segment = 0, c->rolling = 1;
    c->a = circle(pa, v2(sa * d.x, sa * d.y), R * uni(r, 0.2, 0.8));
    c->b = circle(v2(rest.x + along * d.x + h * e.x, rest.y + along * d.y + h * e.y), v2(0, 0), R - c->a.radius);
    c->decel_a = da, c->decel_b = coin(r, 0.5) ? 0.0 : logu(r, -1, 1);
    c->t_max = HUGE_VAL;
}

/* a rolling wall case: a circle rolling at a segment, stopping at about the contact distance
 * (ratio `reach` of the distance it would need), or R (1 -+ m) from it */
static void roll_wall(rng *r, corpus_case *c, double reach)
{
    seg_ordinary(r, c, uni(r, 1.0, 20.0), coin(r, 0.3));
    c->rolling = 1;
    c->decel_b = 0.0;
    {
        /* the straight time of the constructed contact is not kept: take the distance to the
         * segment's nearest point along the motion as the travel scale */
        double sp = sqrt(c->a.vel.x * c->a.vel.x + c->a.vel.y * c->a.vel.y);
        cc_vec2 q = cc_closest_point_on_segment(c->a.pos, &c->s);
        double dist = sqrt((q.x - c->a.pos.x) * (q.x - c->a.pos.x) + (q.y - c->a.pos.y) * (q.y - c->a.pos.y));
        double travel = (dist > c->a.radius ? dist - c->a.radius : c->a.radius) * reach;
        c->decel_a = sp > 0.0 ? 0.5 * sp * sp / travel : 1.0;
    }
}

/* a rolls straight at a wall (interior contact) and stops with its centre r (1 -+ m) from it */
static void roll_wall_stop(rng *r, corpus_case *c, int digits)
{
    cc_vec2 d = unit(r), e0 = v2(uni(r, -10, 10), uni(r, -10, 10)), n = v2(-d.y, d.x), dir;
    double len = uni(r, 2.0, 20.0), rc = uni(r, 0.5, 2.0), m = logu(r, -digits, -3), sa = uni(r, 0.5, 10.0);
    double da = logu(r, -1, 1), travel = 0.5 * sa * sa / da, ct, stop_dist = rc * (coin(r, 0.5) ? 1.0 - m : 1.0 + m);
    cc_vec2 foot = v2(e0.x + uni(r, 0.3, 0.7) * len * d.x, e0.y + uni(r, 0.3, 0.7) * len * d.y), rest;
    do {
        dir = unit(r);
        ct = -(dir.x * n.x + dir.y * n.y);
    } while (ct < 0.5);
    /* rest point at distance stop_dist from the line on n's side, reached after `travel` along dir */
    rest = v2(foot.x + stop_dist * n.x, foot.y + stop_dist * n.y);
    c->is_segment = 1, c->rolling = 1;
    c->s.a = e0, c->s.b = v2(e0.x + len * d.x, e0.y + len * d.y);
    c->a = circle(v2(rest.x - travel * dir.x, rest.y - travel * dir.y), v2(sa * dir.x, sa * dir.y), rc);
    c->decel_a = da, c->decel_b = 0.0;
    c->t_max = HUGE_VAL;
}

static void corpus_make_rolling(rng *r, int cls, int for_float, corpus_case *c)
{
    int digits = for_float ? 7 : 15, off = for_float ? 6 : 15;
    switch (cls - CORPUS_ROLL_FIRST) {
    case 0:
        roll_ordinary(r, c);
        break;
    case 1:
        roll_grazing(r, c, digits);
        break;
    case 2:
        roll_stop_short(r, c, digits);
        break;
    case 3: { /* both rolling, touching at (1 - m) of the first stop */
        double da = logu(r, -1, 1), db = logu(r, -1, 1), m = logu(r, -digits, -1);
        cc_vec2 va = rvel(r, 0.5, 10.0), vb = rvel(r, 0.5, 10.0);
        double ts = stop_time(va, da), tb = stop_time(vb, db);
        roll_place(r, c, uni(r, 0.1, 2.0), uni(r, 0.1, 2.0), va, da, vb, db, (ts < tb ? ts : tb) * (1.0 - m), 1.0, 20.0);
        c->t_max = HUGE_VAL;
        break;
    }
    case 4: /* nearly straight: decelerations 1e-12..1e-6 (float 1e-6..1e-3) */
        roll_ordinary(r, c);
        c->decel_a = logu(r, for_float ? -6 : -12, for_float ? -3 : -6);
        c->decel_b = coin(r, 0.5) ? 0.0 : logu(r, for_float ? -6 : -12, for_float ? -3 : -6);
        if (coin(r, 0.7)) { /* a contact in reach: straight-line placement */
            double R = c->a.radius + c->b.radius, tc = uni(r, 0.0, 10.0);
            roll_place(r, c, c->a.radius, c->b.radius, c->a.vel, c->decel_a, c->b.vel, c->decel_b, tc, uni(r, 0.9, 1.1), 20.0);
            (void)R;
        }
        c->t_max = uni(r, 1.0, 20.0);
        break;
    case 5: { /* deceleration ratios to 1e9: a stops almost at once, b barely slows */
        double da = logu(r, 3, for_float ? 6 : 9), db = logu(r, -3, 0);
        cc_vec2 va = rvel(r, 0.5, 10.0), vb = rvel(r, 0.5, 10.0);
        double ts = stop_time(va, da);
        if (coin(r, 0.5))
            roll_place(r, c, uni(r, 0.1, 2.0), uni(r, 0.1, 2.0), va, da, vb, db, ts * uni(r, 0.0, 1.0), uni(r, 0.95, 1.05), 20.0);
        else
            roll_place(r, c, uni(r, 0.1, 2.0), uni(r, 0.1, 2.0), va, da, vb, db, uni(r, 0.0, 5.0), uni(r, 0.95, 1.05), 20.0);
        if (coin(r, 0.5)) { /* either way round */
            cc_circle t = c->a;
            double dt = c->decel_a;
            c->a = c->b, c->b = t, c->decel_a = c->decel_b, c->decel_b = dt;
        }
        c->t_max = HUGE_VAL;
        break;
    }
    case 6: { /* a whole scene scaled by 2^k, k in -900..900 (float -100..100): lengths, speeds and
                 decelerations by the same power of two, times unchanged, exactly */
        int k = (int)(next(r) % (for_float ? 201u : 1801u)) - (for_float ? 100 : 900);
        double S = ldexp(1.0, k);
        roll_ordinary(r, c);
        scale_case(c, S);
        c->decel_a *= S, c->decel_b *= S;
        break;
    }
    case 7:
        roll_ordinary(r, c);
        offset_case(c, v2(sgn(r) * logu(r, 3, off), sgn(r) * logu(r, 3, off)));
        break;
    case 8: /* equal decelerations; a third of them along one line (the quartic's t^4 term cancels) */
        roll_ordinary(r, c);
        c->decel_b = c->decel_a;
        if (coin(r, 0.33)) {
            double sa = sqrt(c->a.vel.x * c->a.vel.x + c->a.vel.y * c->a.vel.y), sb = uni(r, 0.1, 10.0);
            c->b.vel = v2(c->a.vel.x / sa * sb, c->a.vel.y / sa * sb);
            roll_place(r, c, c->a.radius, c->b.radius, c->a.vel, c->decel_a, c->b.vel, c->decel_b,
                       stop_time(c->a.vel, c->decel_a) * uni(r, 0.0, 1.2), uni(r, 0.9, 1.1), 20.0);
        }
        break;
    case 9:
        roll_wall(r, c, uni(r, 0.5, 2.0));
        break;
    default:
        roll_wall_stop(r, c, digits);
        break;
    }
}

const char *corpus_class_name(int cls)
{
    static const char *const names[CORPUS_CLASSES] = {
        "ordinary",     "offset 1e15",  "scaled 1e-9..1e9", "radius ratio 1e9", "grazing near",
        "grazing far",  "slow rel. 1e8", "subnormal",       "near t_max",       "seg ordinary",
        "seg offset",   "seg len ~0",   "seg len ~1e9",     "seg end points",   "seg grazing",
        "roll ordinary", "roll grazing", "roll stop short", "roll near stops", "roll tiny decel",
        "roll huge decel", "roll scaled 2^+-900", "roll offset 1e15", "roll equal decel", "roll wall",
        "roll wall stop"};
    return cls >= 0 && cls < CORPUS_CLASSES ? names[cls] : "?";
}

void corpus_make(uint64_t seed, int cls, uint32_t index, int for_float, corpus_case *c)
{
    rng r;
    int digits = for_float ? 7 : 15; /* grazing margins and t_max nearness down to 10^-digits */
    int off = for_float ? 6 : 15;    /* offsets up to 10^off */
    double R, h, speed, m;
    r.s = seed ^ ((uint64_t)cls << 40) ^ ((uint64_t)index * 0xD1B54A32D192ED03ull) ^ (for_float ? 0xF1 : 0);
    (void)next(&r);
    c->s.a = v2(0, 0), c->s.b = v2(0, 0);
    c->rolling = 0, c->decel_a = c->decel_b = 0.0;
    if (cls >= CORPUS_ROLL_FIRST) {
        corpus_make_rolling(&r, cls, for_float, c);
        return;
    }
    switch (cls) {
    case 0:
        ordinary(&r, c);
        break;
    case 1:
        ordinary(&r, c);
        offset_case(c, v2(sgn(&r) * logu(&r, 3, off), sgn(&r) * logu(&r, 3, off)));
        break;
    case 2:
        ordinary(&r, c);
        scale_case(c, logu(&r, -9, 9));
        break;
    case 3: { /* radius ratio up to 1e9: a small circle against a huge one, either way round */
        double small = uni(&r, 0.5, 2.0), big = small * logu(&r, 0, 9);
        speed = uni(&r, 0.1, 10.0);
        R = small + big;
        h = R * uni(&r, 0.0, 1.1);
        c->t_max = uni(&r, 1.0, 10.0);
        if (coin(&r, 0.5))
            pair(&r, c, small, big, speed, h, along(R, h, speed, c->t_max * uni(&r, 0.0, 1.3)), big, 10.0);
        else
            pair(&r, c, big, small, speed, h, along(R, h, speed, c->t_max * uni(&r, 0.0, 1.3)), big, 10.0);
        break;
    }
    case 4: /* grazing from near: closest approach R (1 -+ m), a few radii away */
    case 5: /* ... and from far: 1e6 radii away */
        R = uni(&r, 0.5, 4.0);
        m = logu(&r, -digits, -3);
        h = R * (coin(&r, 0.5) ? 1.0 - m : 1.0 + m);
        speed = uni(&r, 0.1, 10.0);
        pair(&r, c, R * 0.5, R * 0.5, speed, h, (cls == 4 ? uni(&r, 1.5, 5.0) : uni(&r, 1e6, 2e6)) * R, 100.0, 10.0);
        c->t_max = HUGE_VAL;
        break;
    case 6: { /* near-zero relative velocity under a fast common motion */
        cc_vec2 d = unit(&r);
        double common = uni(&r, 1e7, 1e8);
        R = uni(&r, 0.5, 4.0);
        speed = logu(&r, for_float ? -1 : -8, 0);
        h = R * uni(&r, 0.0, 1.2);
        c->t_max = uni(&r, 1.0, 10.0);
        pair(&r, c, R * 0.5, R * 0.5, speed, h, along(R, h, speed, c->t_max * uni(&r, 0.0, 1.3)), 100.0, 0.0);
        c->a.vel.x += common * d.x, c->a.vel.y += common * d.y;
        c->b.vel.x += common * d.x, c->b.vel.y += common * d.y;
        break;
    }
    case 7: /* the whole scene in subnormal numbers */
        ordinary(&r, c);
        scale_case(c, for_float ? logu(&r, -44, -41) : logu(&r, -320, -312));
        break;
    case 8: { /* t_max within a relative 10^-digits..1e-3 of the contact (either side) */
        double tstar;
        R = uni(&r, 0.5, 4.0);
        h = R * uni(&r, 0.0, 0.9);
        speed = uni(&r, 0.1, 10.0);
        tstar = uni(&r, 0.5, 10.0);
        pair(&r, c, R * 0.5, R * 0.5, speed, h, along(R, h, speed, tstar), 100.0, 10.0);
        c->t_max = tstar * (1.0 + sgn(&r) * logu(&r, -digits - 1, -3));
        break;
    }
    case 9:
        seg_ordinary(&r, c, uni(&r, 1.0, 20.0), 0);
        break;
    case 10:
        seg_ordinary(&r, c, uni(&r, 1.0, 20.0), coin(&r, 0.3));
        offset_case(c, v2(sgn(&r) * logu(&r, 3, off), sgn(&r) * logu(&r, 3, off)));
        break;
    case 11: /* length ~0: 1e-3 .. 1e-12 (1e-6 for float) of the radius, or exactly 0 */
        seg_ordinary(&r, c, coin(&r, 0.2) ? 0.0 : logu(&r, for_float ? -6 : -12, -3), coin(&r, 0.5));
        break;
    case 12: { /* length ~1e9, touched in its interior or near an end */
        cc_vec2 d = unit(&r), e0 = v2(uni(&r, -1e9, 1e9), uni(&r, -1e9, 1e9));
        double len = uni(&r, 1e9, 2e9), lam = coin(&r, 0.5) ? uni(&r, 0.0, 1.0) : (coin(&r, 0.5) ? 1e-9 : 1.0 - 1e-9);
        c->t_max = uni(&r, 1.0, 10.0);
        seg_case(&r, c, uni(&r, 0.5, 2.0), e0, v2(e0.x + len * d.x, e0.y + len * d.y), lam, uni(&r, 0.1, 10.0),
                 c->t_max * uni(&r, 0.0, 1.3));
        break;
    }
    case 13:
        seg_ordinary(&r, c, uni(&r, 0.1, 20.0), 1);
        break;
    default: { /* grazing a segment: passing an end point at distance r (1 -+ m), or parallel to it */
        cc_vec2 d = unit(&r), e0 = v2(uni(&r, -10, 10), uni(&r, -10, 10)), e1;
        double rc = uni(&r, 0.5, 2.0), len = uni(&r, 1.0, 10.0);
        m = logu(&r, -digits, -3);
        h = rc * (coin(&r, 0.5) ? 1.0 - m : 1.0 + m);
        e1 = v2(e0.x + len * d.x, e0.y + len * d.y);
        c->is_segment = 1;
        c->s.a = e0, c->s.b = e1;
        speed = uni(&r, 0.1, 10.0);
        if (coin(&r, 0.5)) { /* moving along the line towards end a, offset h to the side */
            double back = 5.0 * rc;
            c->a = circle(v2(e0.x - back * d.x - h * d.y, e0.y - back * d.y + h * d.x), v2(speed * d.x, speed * d.y), rc);
        } else { /* passing across the end point e1 (beyond the segment) with impact parameter h */
            cc_vec2 dir = unit(&r), e = v2(-dir.y, dir.x);
            if (e.x * d.x + e.y * d.y < 0.0)
                e = v2(-e.x, -e.y); /* offset away from the segment, beyond its end */
            c->a = circle(v2(e1.x + h * e.x - 5.0 * rc * dir.x, e1.y + h * e.y - 5.0 * rc * dir.y),
                          v2(speed * dir.x, speed * dir.y), rc);
        }
        c->t_max = HUGE_VAL;
        break;
    }
    }
}

static cc_circlef to_float(const cc_circle *c)
{
    cc_circlef f;
    f.pos.x = (float)c->pos.x, f.pos.y = (float)c->pos.y, f.vel.x = (float)c->vel.x, f.vel.y = (float)c->vel.y;
    f.radius = (float)c->radius, f.mass = (float)c->mass;
    if (!(f.radius > 0.0f))
        f.radius = 0x1p-149f; /* a radius lost to rounding: the smallest there is */
    return f;
}

void corpus_to_float(const corpus_case *c, corpus_casef *out)
{
    out->is_segment = c->is_segment;
    out->a = to_float(&c->a);
    out->b = to_float(&c->b);
    out->s.a.x = (float)c->s.a.x, out->s.a.y = (float)c->s.a.y, out->s.b.x = (float)c->s.b.x, out->s.b.y = (float)c->s.b.y;
    out->t_max = (float)c->t_max;
    out->rolling = c->rolling;
    out->decel_a = (float)c->decel_a, out->decel_b = (float)c->decel_b;
}
