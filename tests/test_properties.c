/* Property tests of the pair functions over >= 1e5 seeded random cases each (float twins with
 * -DTEST_FLOAT): symmetry under swapping a and b, exact invariance under translation far from
 * the origin (1e12) and under power-of-two scaling, the returned contact really touching, the
 * time of impact against a wider-precision reference within a few ulps times the condition
 * number, conservation laws of cc_respond, and cc_sweep_many bit-identical to cc_sweep.
 *
 * Random inputs lie on a binary grid (multiples of 2^-10 below 64 in double, 2^-4 below 16 in
 * float) so that adding the far offsets is exact: then the relative problem is bit-for-bit the
 * same and the answers must be too. Error figures are printed as multiples of the precision's
 * epsilon times the problem's scale. */
#include <stdio.h>

#include "core_precision.h"

void setUp(void) {}
void tearDown(void) {}

#define N_CASES 100000

#ifdef TEST_FLOAT
typedef double Wide; /* the reference precision: double for the float API */
#define GRID 0x1p-4
#define SPAN 16.0
#define FAR_OFFSET 65536.0  /* 2^16: grid points + offset stay exact in 24 bits */
#define FAR_SPEED 16384.0   /* 2^14 */
#define WIDE_EPS DBL_EPSILON
#define SCALE_WIDE 60
#define REAL_TRUE_MIN 0x1p-149
#define RANGE_LIMIT 0x1p-100
#else
typedef long double Wide; /* 64-bit significand on x86; == double elsewhere (then skipped) */
#define GRID 0x1p-10
#define SPAN 64.0
#define FAR_OFFSET 1e12 /* ulp at 1e12 is 2^-13: grid points + 1e12 are exact */
#define FAR_SPEED 1e6
#define WIDE_EPS LDBL_EPSILON
#define SCALE_WIDE 400
#define REAL_TRUE_MIN 0x1p-1074
#define RANGE_LIMIT 0x1p-960
#endif
/* the reference is useful when it carries at least 8 more bits than the precision tested */
#define HAVE_WIDE_REFERENCE (WIDE_EPS * 256 <= EPS)

static double grid(uint64_t *s, double span) { return floor(rng_range(s, -span, span) / GRID) * GRID; }

/* A random pair: half of them aimed so that many hit (b heads for a point near a), the rest
 * uniform. Masses random in (0.1, 10). */
static void random_pair(uint64_t *s, Circle *a, Circle *b)
{
    double ra = GRID * (1 + rng_int(s, (int)(SPAN / 8 / GRID))), rb = GRID * (1 + rng_int(s, (int)(SPAN / 8 / GRID)));
    *a = circle(grid(s, SPAN / 2), grid(s, SPAN / 2), grid(s, SPAN / 4), grid(s, SPAN / 4), ra, rng_range(s, 0.1, 10));
    *b = circle(grid(s, SPAN / 2), grid(s, SPAN / 2), grid(s, SPAN / 4), grid(s, SPAN / 4), rb, rng_range(s, 0.1, 10));
    if (rng_int(s, 2)) {
        /* relative velocity towards a point within (ra + rb) of a, over a time of 1..4 */
        double T = rng_range(s, 1, 4), R = ra + rb;
        double tx = (double)a->pos.x + rng_range(s, -1.2, 1.2) * R, ty = (double)a->pos.y + rng_range(s, -1.2, 1.2) * R;
        double dvx = (tx - (double)b->pos.x) / T, dvy = (ty - (double)b->pos.y) / T;
        b->vel = vec((double)a->vel.x + floor(dvx / GRID) * GRID, (double)a->vel.y + floor(dvy / GRID) * GRID);
    }
}

/* ---- the reference: the same contact equation solved in the wider precision ---------------- */

/* Returns CC_OVERLAP, CC_HIT (*t) or CC_MISS for t in [0, inf); *margin is how far the case is
 * from a decision boundary, relative (0 = on it: tangent, touching, at rest...). */
static int ref_sweep(const Circle *a, const Circle *b, Wide *t, Wide *margin, Wide *closing)
{
    Wide dpx = (Wide)b->pos.x - a->pos.x, dpy = (Wide)b->pos.y - a->pos.y;
    Wide dvx = (Wide)b->vel.x - a->vel.x, dvy = (Wide)b->vel.y - a->vel.y;
    Wide R = (Wide)a->radius + b->radius, dd = dpx * dpx + dpy * dpy, d = sqrtl(dd);
    Wide bb = dpx * dvx + dpy * dvy, v2 = dvx * dvx + dvy * dvy, sp = sqrtl(v2);
    Wide h = fabsl(dpx * dvy - dpy * dvx), q = sp * R;
    Wide m1 = fabsl(d - R) / R, m2 = v2 > 0 ? fabsl(bb) / (d * sp) : 0, m3 = q > 0 ? fabsl(q - h) / q : 0;
    *margin = m1 < m2 ? (m1 < m3 ? m1 : m3) : (m2 < m3 ? m2 : m3);
    if (d < R)
        return CC_OVERLAP;
    if (!(bb < 0) || !(q > h))
        return CC_MISS;
    *t = (d - R) * (d + R) / (-bb + sqrtl((q - h) * (q + h)));
    /* -d'(t) at the first contact: sqrt(|dv|^2 R^2 - (dp x dv)^2) / R, free of cancellation */
    *closing = sqrtl((q - h) * (q + h)) / R;
    return CC_HIT;
}

/* |dp| + |dv| t + R: the length scale of the problem at time t */
static double scale_at(const Circle *a, const Circle *b, double t)
{
    double dpx = (double)b->pos.x - a->pos.x, dpy = (double)b->pos.y - a->pos.y;
    double dvx = (double)b->vel.x - a->vel.x, dvy = (double)b->vel.y - a->vel.y;
    return hypot(dpx, dpy) + hypot(dvx, dvy) * t + (double)a->radius + b->radius;
}

/* Swapping a and b: the same code, the same t (bit for bit: every difference only changes
 * sign), the normal exactly reversed, the same touching point up to rounding. */
static void test_swap_symmetry(void)
{
    uint64_t seed = 1;
    int i, hits = 0;
    double worst = 0;
    for (i = 0; i < N_CASES; i++) {
        Circle a, b;
        Contact k1 = sentinel_contact(), k2 = sentinel_contact();
        int r1, r2;
        random_pair(&seed, &a, &b);
        r1 = F(cc_sweep)(&a, &b, (Real)INFINITY, &k1);
        r2 = F(cc_sweep)(&b, &a, (Real)INFINITY, &k2);
        TEST_ASSERT_EQUAL_INT(r1, r2);
        if (r1 == CC_MISS)
            continue;
        EXPECT_EXACT(k1.t, k2.t);
        EXPECT_EXACT(k1.depth, k2.depth);
        if (a.pos.x != b.pos.x || a.pos.y != b.pos.y) {
            EXPECT_EXACT(-k1.normal.x, k2.normal.x);
            EXPECT_EXACT(-k1.normal.y, k2.normal.y);
        }
        if (r1 == CC_HIT) {
            double s = scale_at(&a, &b, k1.t) + fabs((double)a.pos.x) + fabs((double)a.pos.y) +
                       hypot((double)a.vel.x, (double)a.vel.y) * k1.t;
            double e = hypot((double)k1.point.x - k2.point.x, (double)k1.point.y - k2.point.y) / (EPS * s);
            worst = e > worst ? e : worst;
            TEST_ASSERT_TRUE(e <= 8);
            hits++;
        }
    }
    printf("swap (%s): %d cases, %d hits, touching points agree within %.2f eps * scale (bound 8)\n", PREC_NAME,
           N_CASES, hits, worst);
    TEST_ASSERT_TRUE(hits > N_CASES / 5);
}

/* The contact at t really touches: | |pb(t) - pa(t)| - R | <= K eps (|dp| + |dv| t + R), with
 * the distance evaluated in the wider precision; the bodies approach there; and t agrees with
 * the wider reference within K eps times the condition number (|dp| + |dv| t + R) / closing
 * speed, wherever the case is not within 1e4 eps (relative) of a decision boundary. Misses and
 * overlaps agree with the reference there too. */
static void test_contact_touches_and_matches_reference(void)
{
    uint64_t seed = 2;
    int i, hits = 0, compared = 0;
    double worst_touch = 0, worst_t = 0;
    const double K = 8, boundary = 1e4 * EPS;
    for (i = 0; i < N_CASES; i++) {
        Circle a, b;
        Contact k = sentinel_contact();
        int r, rr;
        Wide tr = 0, margin = 0, closing_w = 0;
        random_pair(&seed, &a, &b);
        r = F(cc_sweep)(&a, &b, (Real)INFINITY, &k);
        if (r == CC_HIT) {
            Wide t = k.t;
            Wide px = (Wide)b.pos.x + (Wide)b.vel.x * t - ((Wide)a.pos.x + (Wide)a.vel.x * t);
            Wide py = (Wide)b.pos.y + (Wide)b.vel.y * t - ((Wide)a.pos.y + (Wide)a.vel.y * t);
            Wide dvx = (Wide)b.vel.x - a.vel.x, dvy = (Wide)b.vel.y - a.vel.y;
            double s = scale_at(&a, &b, k.t);
            double e = (double)fabsl(sqrtl(px * px + py * py) - ((Wide)a.radius + b.radius)) / (EPS * s);
            worst_touch = e > worst_touch ? e : worst_touch;
            TEST_ASSERT_TRUE_MESSAGE(e <= K, "contact does not touch");
            TEST_ASSERT_TRUE_MESSAGE((double)(px * dvx + py * dvy) <= K * EPS * s * (double)sqrtl(dvx * dvx + dvy * dvy),
                                     "not approaching at the contact");
            hits++;
        }
        if (!HAVE_WIDE_REFERENCE)
            continue;
        rr = ref_sweep(&a, &b, &tr, &margin, &closing_w);
        if (!((double)margin > boundary))
            continue;
        compared++;
        TEST_ASSERT_EQUAL_INT_MESSAGE(rr, r, "hit/miss/overlap differs from the reference");
        if (r == CC_HIT) {
            double cond = scale_at(&a, &b, (double)tr) / (double)closing_w;
            double e = fabs((double)(k.t - tr)) / (EPS * cond);
            worst_t = e > worst_t ? e : worst_t;
            TEST_ASSERT_TRUE_MESSAGE(e <= K, "t differs from the reference");
        }
    }
    printf("touch (%s): %d hits, max | |dp(t)| - R | = %.2f eps * scale (bound %.0f)\n", PREC_NAME, hits, worst_touch,
           K);
    if (HAVE_WIDE_REFERENCE)
        printf("reference (%s): %d cases compared, max |t - t_ref| = %.2f eps * condition (bound %.0f)\n", PREC_NAME,
               compared, worst_t, K);
    else
        printf("reference (%s): skipped, long double is not wider than double here\n", PREC_NAME);
    TEST_ASSERT_TRUE(hits > N_CASES / 5);
    TEST_ASSERT_TRUE(!HAVE_WIDE_REFERENCE || compared > N_CASES * 9 / 10);
}

/* Translation far from the origin, and a fast common velocity: on the grid, pos + X and
 * vel + W are exact, the relative problem is identical, so the code, t and the normal are
 * bit-identical; the point moves by X + W t (up to the rounding at that magnitude). */
static void test_translation_invariance(void)
{
    uint64_t seed = 3;
    int i, hits = 0;
    for (i = 0; i < N_CASES; i++) {
        Circle a, b, fa, fb;
        Contact k = sentinel_contact(), kf = sentinel_contact();
        double X = rng_int(&seed, 2) ? FAR_OFFSET : -FAR_OFFSET, Y = rng_int(&seed, 2) ? FAR_OFFSET : -FAR_OFFSET;
        double W = rng_int(&seed, 2) ? FAR_SPEED : -FAR_SPEED;
        int r;
        random_pair(&seed, &a, &b);
        fa = a;
        fb = b;
        fa.pos = vec((double)a.pos.x + X, (double)a.pos.y + Y);
        fb.pos = vec((double)b.pos.x + X, (double)b.pos.y + Y);
        fa.vel.x = (Real)((double)a.vel.x + W);
        fb.vel.x = (Real)((double)b.vel.x + W);
        TEST_ASSERT_TRUE((double)fa.pos.x - X == (double)a.pos.x && (double)fb.vel.x - W == (double)b.vel.x);
        r = F(cc_sweep)(&a, &b, (Real)INFINITY, &k);
        TEST_ASSERT_EQUAL_INT(r, F(cc_sweep)(&fa, &fb, (Real)INFINITY, &kf));
        if (r == CC_MISS)
            continue;
        EXPECT_EXACT(k.t, kf.t);
        EXPECT_EXACT(k.depth, kf.depth);
        TEST_ASSERT_EQUAL_MEMORY(&k.normal, &kf.normal, sizeof k.normal);
        if (r == CC_HIT) {
            double sx = X + W * k.t, tol = 4 * EPS * (fabs(X) + fabs(W) * k.t + SPAN * (1 + k.t));
            TEST_ASSERT_DOUBLE_WITHIN(tol, (double)k.point.x + sx, (double)kf.point.x);
            TEST_ASSERT_DOUBLE_WITHIN(tol, (double)k.point.y + Y, (double)kf.point.y);
            hits++;
        }
    }
    printf("translation (%s): %d cases, %d hits, offsets %g and speed %g: t bit-identical\n", PREC_NAME, N_CASES, hits,
           FAR_OFFSET, FAR_SPEED);
}

/* Scaling lengths by 2^kl and speeds by 2^kv (exact) scales t by 2^(kl - kv) exactly and the
 * point by 2^kl, with the normal unchanged: rounding commutes with power-of-two scaling, and
 * the solver's own rescaling is by powers of two, so any difference is a bug. */
static void test_scale_invariance(void)
{
    uint64_t seed = 4;
    int i, hits = 0;
    for (i = 0; i < N_CASES; i++) {
        Circle a, b, sa, sb;
        Contact k = sentinel_contact(), ks = sentinel_contact();
        /* 3 in 4 within 2^-30..2^30 (the contract's 1e-9..1e9); the rest out to the extremes
         * that keep every input and t normal: 2^-400..2^400 (float 2^-60..2^60) */
        int wide = rng_int(&seed, 4) == 0, span = wide ? SCALE_WIDE : 30;
        int kl = rng_int(&seed, 2 * span + 1) - span, kv = rng_int(&seed, 2 * span + 1) - span, r;
        double L = ldexp(1.0, kl), V = ldexp(1.0, kv);
        random_pair(&seed, &a, &b);
        sa = circle(a.pos.x * L, a.pos.y * L, a.vel.x * V, a.vel.y * V, a.radius * L, a.mass);
        sb = circle(b.pos.x * L, b.pos.y * L, b.vel.x * V, b.vel.y * V, b.radius * L, b.mass);
        r = F(cc_sweep)(&a, &b, (Real)INFINITY, &k);
        TEST_ASSERT_EQUAL_INT(r, F(cc_sweep)(&sa, &sb, (Real)INFINITY, &ks));
        if (r == CC_MISS)
            continue;
        EXPECT_EXACT(ldexp((double)k.t, kl - kv), ks.t);
        EXPECT_EXACT(k.depth * L, ks.depth);
        TEST_ASSERT_EQUAL_MEMORY(&k.normal, &ks.normal, sizeof k.normal);
        EXPECT_EXACT(k.point.x * L, ks.point.x);
        EXPECT_EXACT(k.point.y * L, ks.point.y);
        hits += r == CC_HIT;
    }
    printf("scale (%s): %d cases, %d hits, scales 2^-30..2^30 and 2^-%d..2^%d: t, normal, point exact\n", PREC_NAME,
           N_CASES, hits, SCALE_WIDE, SCALE_WIDE);
}

/* cc_respond on random bodies and unit normals: momentum conserved (finite masses), kinetic
 * energy too for e = 1, relative normal velocity after = -e times before, tangential
 * velocities unchanged, an immovable body untouched; all within K eps of the scale
 * sum m |v| (momentum), sum m |v|^2 (energy) or |va| + |vb| (velocities). */
static void test_respond_conservation(void)
{
    uint64_t seed = 5;
    int i, hits = 0;
    double worst_p = 0, worst_e = 0, worst_v = 0;
    const double K = 16;
    for (i = 0; i < N_CASES; i++) {
        double ang = rng_range(&seed, 0, 6.283185307179586), e = rng_int(&seed, 3) ? rng_unit(&seed) : 1.0;
        Circle a = circle(0, 0, rng_range(&seed, -10, 10), rng_range(&seed, -10, 10), 1, rng_range(&seed, 0.01, 100));
        Circle b = circle(2, 0, rng_range(&seed, -10, 10), rng_range(&seed, -10, 10), 1, rng_range(&seed, 0.01, 100));
        Circle a0, b0;
        Contact k;
        double nx, ny, vn0, vn1, sv, sp, se, ma, mb;
        int kind = rng_int(&seed, 10), r;
        memset(&k, 0, sizeof k);
        k.normal = vec(cos(ang), sin(ang));
        if (kind == 0)
            a.mass = (Real)INFINITY;
        else if (kind == 1)
            b.mass = (Real)INFINITY;
        a0 = a;
        b0 = b;
        nx = k.normal.x;
        ny = k.normal.y;
        r = F(cc_respond)(&a, &b, &k, (Real)e);
        vn0 = ((double)b0.vel.x - a0.vel.x) * nx + ((double)b0.vel.y - a0.vel.y) * ny;
        if (r == CC_MISS) {
            TEST_ASSERT_TRUE(vn0 >= -4 * EPS * 20);
            TEST_ASSERT_EQUAL_MEMORY(&a0, &a, sizeof a);
            TEST_ASSERT_EQUAL_MEMORY(&b0, &b, sizeof b);
            continue;
        }
        TEST_ASSERT_EQUAL_INT(CC_HIT, r);
        hits++;
        sv = hypot(a0.vel.x, a0.vel.y) + hypot(b0.vel.x, b0.vel.y);
        vn1 = ((double)b.vel.x - a.vel.x) * nx + ((double)b.vel.y - a.vel.y) * ny;
        worst_v = fmax(worst_v, fabs(vn1 + e * vn0) / (EPS * sv));
        TEST_ASSERT_TRUE_MESSAGE(fabs(vn1 + e * vn0) <= K * EPS * sv, "relative normal velocity is not -e times");
        /* tangential parts: v x n unchanged for each body */
        TEST_ASSERT_DOUBLE_WITHIN(K * EPS * sv, (double)a0.vel.x * ny - (double)a0.vel.y * nx,
                                  (double)a.vel.x * ny - (double)a.vel.y * nx);
        TEST_ASSERT_DOUBLE_WITHIN(K * EPS * sv, (double)b0.vel.x * ny - (double)b0.vel.y * nx,
                                  (double)b.vel.x * ny - (double)b.vel.y * nx);
        if (kind == 0) {
            TEST_ASSERT_EQUAL_MEMORY(&a0, &a, sizeof a);
            continue;
        }
        if (kind == 1) {
            TEST_ASSERT_EQUAL_MEMORY(&b0, &b, sizeof b);
            continue;
        }
        ma = a.mass;
        mb = b.mass;
        sp = ma * hypot(a0.vel.x, a0.vel.y) + mb * hypot(b0.vel.x, b0.vel.y);
        worst_p = fmax(worst_p, hypot(ma * a.vel.x + mb * b.vel.x - ma * a0.vel.x - mb * b0.vel.x,
                                      ma * a.vel.y + mb * b.vel.y - ma * a0.vel.y - mb * b0.vel.y) / (EPS * sp));
        TEST_ASSERT_DOUBLE_WITHIN(K * EPS * sp, ma * a0.vel.x + mb * b0.vel.x, ma * a.vel.x + mb * b.vel.x);
        TEST_ASSERT_DOUBLE_WITHIN(K * EPS * sp, ma * a0.vel.y + mb * b0.vel.y, ma * a.vel.y + mb * b.vel.y);
        if (e == 1.0) {
            double E0 = ma * (a0.vel.x * (double)a0.vel.x + a0.vel.y * (double)a0.vel.y) +
                        mb * (b0.vel.x * (double)b0.vel.x + b0.vel.y * (double)b0.vel.y);
            double E1 = ma * (a.vel.x * (double)a.vel.x + a.vel.y * (double)a.vel.y) +
                        mb * (b.vel.x * (double)b.vel.x + b.vel.y * (double)b.vel.y);
            se = E0;
            worst_e = fmax(worst_e, fabs(E1 - E0) / (EPS * se));
            TEST_ASSERT_DOUBLE_WITHIN(K * EPS * se, E0, E1);
        }
    }
    printf("respond (%s): %d cases, %d impulses; max errors in eps * scale: momentum %.2f, energy (e = 1) %.2f, "
           "relative normal velocity %.2f (bound %.0f)\n",
           PREC_NAME, N_CASES, hits, worst_p, worst_e, worst_v, K);
    TEST_ASSERT_TRUE(hits > N_CASES / 3);
}

/* A random circle and wall. */
static void random_wall_case(uint64_t *s, Circle *c, Segment *w)
{
    double r = GRID * (1 + rng_int(s, (int)(SPAN / 8 / GRID)));
    *w = segment(grid(s, SPAN / 2), grid(s, SPAN / 2), grid(s, SPAN / 2), grid(s, SPAN / 2));
    if (rng_int(s, 8) == 0)
        w->b = w->a; /* a point obstacle now and then */
    *c = circle(grid(s, SPAN / 2), grid(s, SPAN / 2), grid(s, SPAN / 4), grid(s, SPAN / 4), r, 1);
    if (rng_int(s, 2)) {
        /* aim at a point of the wall, over a time of 1..4 */
        double u = rng_range(s, -0.2, 1.2), T = rng_range(s, 1, 4);
        double tx = (double)w->a.x + u * ((double)w->b.x - w->a.x), ty = (double)w->a.y + u * ((double)w->b.y - w->a.y);
        c->vel = vec(floor((tx - (double)c->pos.x) / T / GRID) * GRID, floor((ty - (double)c->pos.y) / T / GRID) * GRID);
    }
}

/* Distance from p to the segment, in the wider precision. */
static Wide wide_seg_dist(Wide px, Wide py, const Segment *w)
{
    Wide ux = (Wide)w->b.x - w->a.x, uy = (Wide)w->b.y - w->a.y, wx = px - w->a.x, wy = py - w->a.y;
    Wide l2 = ux * ux + uy * uy, lam = l2 > 0 ? (wx * ux + wy * uy) / l2 : 0;
    lam = lam < 0 ? 0 : (lam > 1 ? 1 : lam);
    wx -= lam * ux;
    wy -= lam * uy;
    return sqrtl(wx * wx + wy * wy);
}

/* Closest approach of the centre's path c + v t, t >= 0, to the wall, in the wider precision:
 * 0 when the path crosses the wall, else the least of the start's distance to the wall and
 * each end point's distance to the path (the minimum of two disjoint convex sets' distance
 * along a ray and a segment is attained at an end of one of them). */
static Wide wide_path_wall_dist(const Circle *c, const Segment *w)
{
    Wide cx = c->pos.x, cy = c->pos.y, vx = c->vel.x, vy = c->vel.y, ux = (Wide)w->b.x - w->a.x,
         uy = (Wide)w->b.y - w->a.y;
    Wide ax = (Wide)w->a.x - cx, ay = (Wide)w->a.y - cy, den = vx * uy - vy * ux, best = wide_seg_dist(cx, cy, w);
    Wide v2 = vx * vx + vy * vy;
    int i;
    if (den != 0) {
        Wide t = (ax * uy - ay * ux) / den, lam = (ax * vy - ay * vx) / den;
        if (t >= 0 && lam >= 0 && lam <= 1)
            return 0;
    }
    for (i = 0; i < 2 && v2 > 0; i++) {
        Wide px = (i ? (Wide)w->b.x : (Wide)w->a.x) - cx, py = (i ? (Wide)w->b.y : (Wide)w->a.y) - cy;
        Wide t = (px * vx + py * vy) / v2, d;
        t = t < 0 ? 0 : t;
        d = sqrtl((px - vx * t) * (px - vx * t) + (py - vy * t) * (py - vy * t));
        best = d < best ? d : best;
    }
    return best;
}

/* Circle against wall: the contact touches (the centre at t is r from the wall) and is
 * approached; the circle is not within the wall's reach before t (checked at 64 earlier
 * times); a miss never comes within r of the wall (exact closest approach of the path); reversing the wall's end points gives the same answer; translating everything by
 * a far grid offset changes neither the code nor t. */
static void test_sweep_segment_properties(void)
{
    uint64_t seed = 6;
    int i, j, hits = 0, misses = 0;
    double worst = 0, worst_miss = -1e300;
    const double K = 8;
    for (i = 0; i < N_CASES; i++) {
        Circle c, fc;
        Segment w, rw, fw;
        Contact k = sentinel_contact(), kr = sentinel_contact(), kf = sentinel_contact();
        double X = rng_int(&seed, 2) ? FAR_OFFSET : -FAR_OFFSET;
        int r;
        random_wall_case(&seed, &c, &w);
        rw = segment(w.b.x, w.b.y, w.a.x, w.a.y);
        fc = c;
        fc.pos = vec((double)c.pos.x + X, (double)c.pos.y - X);
        fw = segment((double)w.a.x + X, (double)w.a.y - X, (double)w.b.x + X, (double)w.b.y - X);
        r = F(cc_sweep_segment)(&c, &w, (Real)INFINITY, &k);
        TEST_ASSERT_EQUAL_INT(r, F(cc_sweep_segment)(&fc, &fw, (Real)INFINITY, &kf));
        if (r != CC_MISS)
            EXPECT_EXACT(k.t, kf.t);
        if (r == CC_MISS) {
            /* a miss: the path never comes within r of the wall (beyond rounding) */
            double s = hypot((double)c.pos.x - w.a.x, (double)c.pos.y - w.a.y) +
                       hypot((double)w.b.x - w.a.x, (double)w.b.y - w.a.y) + c.radius;
            double e = (double)((Wide)c.radius - wide_path_wall_dist(&c, &w)) / (EPS * s);
            worst_miss = e > worst_miss ? e : worst_miss;
            TEST_ASSERT_TRUE_MESSAGE(e <= K, "a miss whose path comes within r of the wall");
            misses++;
        }
        if (r != CC_HIT)
            continue;
        hits++;
        {
            Wide t = k.t, px = (Wide)c.pos.x + (Wide)c.vel.x * t, py = (Wide)c.pos.y + (Wide)c.vel.y * t;
            double s = hypot((double)c.pos.x - w.a.x, (double)c.pos.y - w.a.y) +
                       hypot((double)w.b.x - w.a.x, (double)w.b.y - w.a.y) + hypot(c.vel.x, c.vel.y) * k.t + c.radius;
            double e = (double)fabsl(wide_seg_dist(px, py, &w) - (Wide)c.radius) / (EPS * s);
            worst = e > worst ? e : worst;
            TEST_ASSERT_TRUE_MESSAGE(e <= K, "contact does not touch the wall");
            for (j = 0; j < 64; j++) {
                Wide tj = t * j / 64;
                Wide qx = (Wide)c.pos.x + (Wide)c.vel.x * tj, qy = (Wide)c.pos.y + (Wide)c.vel.y * tj;
                TEST_ASSERT_TRUE_MESSAGE((double)wide_seg_dist(qx, qy, &w) >= (double)c.radius - K * EPS * s,
                                         "the wall was reached before t");
            }
            /* the normal points from the centre at t to the touching point, which is on the wall */
            TEST_ASSERT_TRUE((double)wide_seg_dist((Wide)k.point.x, (Wide)k.point.y, &w) <= K * EPS * s);
            TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_sweep_segment)(&c, &rw, (Real)INFINITY, &kr));
            TEST_ASSERT_DOUBLE_WITHIN(K * EPS * s, k.point.x, kr.point.x);
            TEST_ASSERT_DOUBLE_WITHIN(K * EPS * s, k.point.y, kr.point.y);
        }
    }
    printf("sweep_segment (%s): %d cases, %d hits, max | dist(centre(t), wall) - r | = %.2f eps * scale (bound %.0f); "
           "%d misses, deepest reach of a missing path %.2f eps * scale (bound %.0f)\n",
           PREC_NAME, N_CASES, hits, worst, K, misses, worst_miss, K);
    TEST_ASSERT_TRUE(hits > N_CASES / 5);
}

/* A finite number of random sign and magnitude anywhere in the precision's range (zero now
 * and then), up to 2^9 below the largest finite number: within 2^8 of it the contract's
 * outputs (an overlap's point and depth) may not be representable (docs/NUMERICS.md). */
static double wild(uint64_t *s)
{
    int max_exp = (int)(log2(REAL_MAX)) - 9, k = rng_int(s, 2 * max_exp + 1) - max_exp;
    if (rng_int(s, 16) == 0)
        return 0;
    return (rng_int(s, 2) ? 1 : -1) * ldexp(rng_range(s, 1, 2), k);
}

static int unit_ok(Vec n) { return fabs(hypot((double)n.x, (double)n.y) - 1) <= 8 * EPS; }

/* Inputs with magnitudes anywhere from the smallest normal to the largest finite number, mixed
 * freely (differences that overflow, radii tiny against distances and the reverse): the
 * answer is always one of the contract's codes, and every number written is finite: t in
 * [0, t_max], unit normals, finite points and depths. Any NaN or Inf here is a bug, and the
 * sanitizer build also catches undefined behaviour on these paths. */
static void test_extreme_inputs_never_produce_nan(void)
{
    uint64_t seed = 8;
    int i, counts[3] = {0, 0, 0}, compared = 0;
    for (i = 0; i < N_CASES; i++) {
        /* drawn one by one: the order in which arguments are evaluated differs by platform */
        double v[14];
        int j;
        Circle a, b;
        Segment w;
        for (j = 0; j < 14; j++)
            v[j] = wild(&seed);
        a = circle(v[0], v[1], v[2], v[3], fabs(v[4]), 1);
        b = circle(v[5], v[6], v[7], v[8], fabs(v[9]), 1);
        w = segment(v[10], v[11], v[12], v[13]);
        Contact k = sentinel_contact();
        double t_max = rng_int(&seed, 2) ? INFINITY : fabs(wild(&seed));
        int r;
        if (!(a.radius > 0))
            a.radius = 1;
        if (!(b.radius > 0))
            b.radius = 1;
        r = F(cc_sweep)(&a, &b, (Real)t_max, &k);
        TEST_ASSERT_TRUE(r == CC_MISS || r == CC_HIT || r == CC_OVERLAP);
        counts[r == CC_HIT ? 1 : (r == CC_OVERLAP ? 2 : 0)]++;
        if (r != CC_MISS) {
            TEST_ASSERT_TRUE_MESSAGE(k.t >= 0 && k.t <= (Real)t_max, "t outside [0, t_max]");
            TEST_ASSERT_TRUE_MESSAGE(unit_ok(k.normal), "normal not a unit vector");
            TEST_ASSERT_TRUE_MESSAGE(isfinite(k.point.x) && isfinite(k.point.y), "point not finite");
            TEST_ASSERT_TRUE_MESSAGE(isfinite(k.depth) && k.depth >= 0, "depth not finite");
        }
        if (HAVE_WIDE_REFERENCE) {
            /* against the wider reference (whose exponent range is wider too), away from the
             * decision boundaries, t_max and contacts beyond the representable plane */
            Wide tr = 0, margin = 0, closing = 0, px, py, mL, R = (Wide)a.radius + b.radius;
            int rr = ref_sweep(&a, &b, &tr, &margin, &closing), ref_hit = rr == CC_HIT; /* before t_max */
            px = (Wide)a.pos.x + (Wide)a.vel.x * tr;
            py = (Wide)a.pos.y + (Wide)a.vel.y * tr;
            if (rr == CC_HIT && tr > (Wide)t_max)
                rr = CC_MISS;
            mL = fabsl((Wide)b.pos.x - a.pos.x);
            mL = fabsl((Wide)b.pos.y - a.pos.y) > mL ? fabsl((Wide)b.pos.y - a.pos.y) : mL;
            mL = R > mL ? R : mL;
            /* known limit, not compared: the solver scales lengths by the largest of |dp| and R,
             * so R below that by more than the exponent range (2^-1022, float 2^-126) underflows */
            if ((double)margin > 1e4 * EPS && !(ref_hit && fabsl(tr - (Wide)t_max) <= 1e-3L * tr + (Wide)REAL_TRUE_MIN) &&
                !(ref_hit && (fabsl(px) + fabsl(py) + (Wide)a.radius) > (Wide)REAL_MAX / 4) &&
                !(ref_hit && tr > (Wide)REAL_MAX) && R > mL * (Wide)RANGE_LIMIT) {
                compared++;
                TEST_ASSERT_EQUAL_INT_MESSAGE(rr, r, "extreme: differs from the reference");
                if (r == CC_HIT) {
                    Wide vx = (Wide)b.vel.x - a.vel.x, vy = (Wide)b.vel.y - a.vel.y;
                    Wide cond = (sqrtl(((Wide)b.pos.x - a.pos.x) * ((Wide)b.pos.x - a.pos.x) +
                                       ((Wide)b.pos.y - a.pos.y) * ((Wide)b.pos.y - a.pos.y)) +
                                 sqrtl(vx * vx + vy * vy) * tr + R) / closing;
                    /* plus the smallest subnormal: a t below the range rounds to it or to 0 */
                    TEST_ASSERT_TRUE_MESSAGE(fabsl((Wide)k.t - tr) <= 8 * (Wide)EPS * cond + (Wide)REAL_TRUE_MIN,
                                             "extreme: t");
                }
            }
        }
        if (r == CC_OVERLAP) { /* the contract: the cc_detect_static contact */
            Contact d = sentinel_contact();
            TEST_ASSERT_EQUAL_INT(CC_OVERLAP, F(cc_detect_static)(&a, &b, &d));
            TEST_ASSERT_EQUAL_MEMORY(&d, &k, sizeof k);
        }
        k = sentinel_contact();
        r = F(cc_sweep_segment)(&a, &w, (Real)t_max, &k);
        TEST_ASSERT_TRUE(r == CC_MISS || r == CC_HIT || r == CC_OVERLAP);
        if (r != CC_MISS) {
            TEST_ASSERT_TRUE_MESSAGE(k.t >= 0 && k.t <= (Real)t_max, "segment: t outside [0, t_max]");
            TEST_ASSERT_TRUE_MESSAGE(unit_ok(k.normal), "segment: normal not a unit vector");
            TEST_ASSERT_TRUE_MESSAGE(isfinite(k.point.x) && isfinite(k.point.y), "segment: point not finite");
            TEST_ASSERT_TRUE_MESSAGE(isfinite(k.depth) && k.depth >= 0, "segment: depth not finite");
        }
        k = sentinel_contact();
        r = F(cc_detect_static)(&a, &b, &k);
        TEST_ASSERT_TRUE(r == CC_MISS || r == CC_OVERLAP);
        if (r == CC_OVERLAP) {
            TEST_ASSERT_TRUE_MESSAGE(unit_ok(k.normal), "detect: normal not a unit vector");
            TEST_ASSERT_TRUE_MESSAGE(isfinite(k.depth) && k.depth > 0, "detect: depth");
            TEST_ASSERT_TRUE_MESSAGE(isfinite(k.point.x) && isfinite(k.point.y), "detect: point not finite");
            {
                Circle a0 = a, b0 = b;
                r = F(cc_separate)(&a, &b);
                /* pushed apart to finite positions, or (radii near the overflow limit) refused
                 * with nothing changed */
                TEST_ASSERT_TRUE(r == CC_OVERLAP || r == CC_ERR_INVALID);
                TEST_ASSERT_TRUE_MESSAGE(isfinite(a.pos.x) && isfinite(a.pos.y) && isfinite(b.pos.x) &&
                                             isfinite(b.pos.y),
                                         "separate: positions not finite");
                if (r == CC_ERR_INVALID) {
                    TEST_ASSERT_EQUAL_MEMORY(&a0, &a, sizeof a);
                    TEST_ASSERT_EQUAL_MEMORY(&b0, &b, sizeof b);
                }
            }
        }
        {
            Circle c = a, d = b, c0 = a, d0 = b;
            Contact kn;
            double ang = rng_range(&seed, 0, 6.283185307179586);
            memset(&kn, 0, sizeof kn);
            kn.normal = vec(cos(ang), sin(ang));
            c.mass = (Real)fabs(wild(&seed));
            d.mass = (Real)fabs(wild(&seed));
            if (!(c.mass > 0))
                c.mass = 1;
            if (!(d.mass > 0))
                d.mass = 1;
            c0.mass = c.mass;
            d0.mass = d.mass;
            r = F(cc_respond)(&c, &d, &kn, (Real)rng_unit(&seed));
            TEST_ASSERT_TRUE(r == CC_MISS || r == CC_HIT || r == CC_ERR_INVALID);
            if (r == CC_HIT)
                TEST_ASSERT_TRUE_MESSAGE(isfinite(c.vel.x) && isfinite(c.vel.y) && isfinite(d.vel.x) && isfinite(d.vel.y),
                                         "respond: velocities not finite");
            else {
                TEST_ASSERT_EQUAL_MEMORY(&c0, &c, sizeof c);
                TEST_ASSERT_EQUAL_MEMORY(&d0, &d, sizeof d);
            }
        }
    }
    printf("extreme inputs (%s): %d cases (miss %d, hit %d, overlap %d): no NaN or Inf written; %d compared with "
           "the wider reference\n",
           PREC_NAME, N_CASES, counts[0], counts[1], counts[2], compared);
}

#ifndef TEST_FLOAT
/* cc_sweep_many over 100 batches of 1000 pairs, with a finite t_max: bit-identical to cc_sweep
 * per pair (t for CC_HIT, 0 for CC_OVERLAP, +INFINITY for CC_MISS), the same codes, and the
 * number of hits and overlaps returned. */
static void test_sweep_many_matches_sweep(void)
{
    enum { BATCH = 1000 };
    static double px[BATCH], py[BATCH], vx[BATCH], vy[BATCH], r[BATCH];
    static double qx[BATCH], qy[BATCH], wx[BATCH], wy[BATCH], s[BATCH], t[BATCH];
    static int res[BATCH];
    cc_circle_soa A = {px, py, vx, vy, r}, B = {qx, qy, wx, wy, s};
    uint64_t seed = 7;
    int round, i, total = 0;
    for (round = 0; round < N_CASES / BATCH; round++) {
        long expect_hits = 0;
        Circle a[BATCH], b[BATCH];
        for (i = 0; i < BATCH; i++) {
            random_pair(&seed, &a[i], &b[i]);
            px[i] = a[i].pos.x, py[i] = a[i].pos.y, vx[i] = a[i].vel.x, vy[i] = a[i].vel.y, r[i] = a[i].radius;
            qx[i] = b[i].pos.x, qy[i] = b[i].pos.y, wx[i] = b[i].vel.x, wy[i] = b[i].vel.y, s[i] = b[i].radius;
        }
        TEST_ASSERT_TRUE(cc_sweep_many(BATCH, &A, &B, 3.0, t, res) >= 0);
        for (i = 0; i < BATCH; i++) {
            Contact k = sentinel_contact();
            int code = cc_sweep(&a[i], &b[i], 3.0, &k);
            double expect = code == CC_HIT ? k.t : (code == CC_OVERLAP ? 0.0 : INFINITY);
            TEST_ASSERT_EQUAL_INT(code, res[i]);
            TEST_ASSERT_EQUAL_MEMORY(&expect, &t[i], sizeof expect);
            expect_hits += code != CC_MISS;
        }
        TEST_ASSERT_EQUAL_INT((int)expect_hits, (int)cc_sweep_many(BATCH, &A, &B, 3.0, t, NULL));
        total += (int)expect_hits;
    }
    printf("sweep_many: %d pairs, %d hits or overlaps, bit-identical to cc_sweep\n", N_CASES, total);
}
#endif

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_swap_symmetry);
    RUN_TEST(test_contact_touches_and_matches_reference);
    RUN_TEST(test_translation_invariance);
    RUN_TEST(test_scale_invariance);
    RUN_TEST(test_respond_conservation);
    RUN_TEST(test_sweep_segment_properties);
    RUN_TEST(test_extreme_inputs_never_produce_nan);
#ifndef TEST_FLOAT
    RUN_TEST(test_sweep_many_matches_sweep);
#endif
    return UNITY_END();
}
