/* Rolling to rest (1.1): cc_sweep_rolling, cc_sweep_segment_rolling, cc_rolling_advance and their
 * float twins. Hand-derived cases (inputs chosen so that the answers are exact binary numbers
 * where possible), decel = 0 against cc_sweep bit for bit, invalid inputs, float against double,
 * and a brute-force reference: the same motion in long double, sampled finely and bisected.
 *
 * Motion (the contract): p(t) = pos + v (t - decel t^2 / (2 s)) until t_stop = s / decel, then
 * pos + v t_stop / 2, with s = |v|. */
#include "core_precision.h"

#include <stdio.h>

void setUp(void) {}
void tearDown(void) {}

static void expect_hit(const cc_circle *a, double da, const cc_circle *b, double db, double t_max, double t, double nx,
                       double ny, double px, double py, double tol)
{
    cc_contact k = sentinel_contact();
    TEST_ASSERT_EQUAL_INT_MESSAGE(CC_HIT, cc_sweep_rolling(a, da, b, db, t_max, &k), "result");
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(tol * (t > 1 ? t : 1), t, k.t, "t");
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(tol, nx, k.normal.x, "normal.x");
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(tol, ny, k.normal.y, "normal.y");
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(tol * (fabs(px) > 1 ? fabs(px) : 1), px, k.point.x, "point.x");
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(tol * (fabs(py) > 1 ? fabs(py) : 1), py, k.point.y, "point.y");
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(0.0, 0.0, k.depth, "depth");
}

static void expect_miss(const cc_circle *a, double da, const cc_circle *b, double db, double t_max)
{
    cc_contact k = sentinel_contact(), before = k;
    TEST_ASSERT_EQUAL_INT_MESSAGE(CC_MISS, cc_sweep_rolling(a, da, b, db, t_max, &k), "result");
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&before, &k, sizeof k, "out changed on CC_MISS");
}

/* a from 0 at speed 2, decel 0.5: t_stop = 4, p(t) = 2t - t^2/4, at rest at x = 4 from t = 4;
 * at t = 2: x = 3, v = 2 (1 - 2/4) = 1. */
static void test_advance_stops(void)
{
    cc_circle a = circle(0, 0, 2, 0, 0.5, 1), c;
    c = a;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_rolling_advance(&c, 0.5, 2));
    EXPECT_VEC_EXACT(3, 0, c.pos);
    EXPECT_VEC_EXACT(1, 0, c.vel);
    c = a;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_rolling_advance(&c, 0.5, 4));
    EXPECT_VEC_EXACT(4, 0, c.pos);
    EXPECT_VEC_EXACT(0, 0, c.vel);
    c = a;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_rolling_advance(&c, 0.5, 100));
    EXPECT_VEC_EXACT(4, 0, c.pos);
    EXPECT_VEC_EXACT(0, 0, c.vel);
    /* decel 0: straight motion */
    c = a;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_rolling_advance(&c, 0.0, 3));
    EXPECT_VEC_EXACT(6, 0, c.pos);
    EXPECT_VEC_EXACT(2, 0, c.vel);
    /* the float twin */
    {
        cc_circlef f = {{0.0f, 0.0f}, {2.0f, 0.0f}, 0.5f, 1.0f};
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_rolling_advancef(&f, 0.5f, 2.0f));
        TEST_ASSERT_EQUAL_FLOAT(3.0f, f.pos.x);
        TEST_ASSERT_EQUAL_FLOAT(1.0f, f.vel.x);
    }
}

/* The contract's example: radii 0.1, a at 0 speed 2 decel 0.4, b at rest at 1. Contact when
 * a is at 0.8: 2t - 0.2 t^2 = 0.8, t = (2 - sqrt(3.36)) / 0.4 (before a's stop at 5). */
static void test_ball_into_resting_ball(void)
{
    cc_circle a = circle(0, 0, 2, 0, 0.1, 1), b = circle(1, 0, 0, 0, 0.1, 1);
    double t = (2 - sqrt(3.36)) / 0.4;
    expect_hit(&a, 0.4, &b, 0.0, 10, t, 1, 0, 0.9, 0, 1e-14);
    expect_hit(&a, 0.4, &b, 3.0, HUGE_VAL, t, 1, 0, 0.9, 0, 1e-14); /* b's decel: it is at rest */
    expect_miss(&a, 0.4, &b, 0.0, t * (1 - 1e-12));                  /* cut off by t_max */
    /* swapped: the normal from b to a */
    {
        cc_contact k;
        TEST_ASSERT_EQUAL_INT(CC_HIT, cc_sweep_rolling(&b, 0.0, &a, 0.4, 10, &k));
        TEST_ASSERT_DOUBLE_WITHIN(1e-14, t, k.t);
        TEST_ASSERT_DOUBLE_WITHIN(1e-15, -1, k.normal.x);
        TEST_ASSERT_DOUBLE_WITHIN(1e-14, 0.9, k.point.x);
    }
}

/* a from 0 at speed 2, decel 0.5 stops at x = 4; radii 0.125, so R = 0.25: b at rest at 4.25
 * is touched exactly at the stop (not a hit: no approach), at 4.25 + 1e-9 never, at 4.25 - 1e-9
 * when 4 - (4 - t)^2 / 4 = 4 - 1e-9, t = 4 - 2 sqrt(1e-9). */
static void test_stop_short_exact_long(void)
{
    cc_circle a = circle(0, 0, 2, 0, 0.125, 1), b;
    double t;
    b = circle(4.25, 0, 0, 0, 0.125, 1);
    expect_miss(&a, 0.5, &b, 0.0, HUGE_VAL);
    b = circle(4.25 + 1e-9, 0, 0, 0, 0.125, 1);
    expect_miss(&a, 0.5, &b, 0.0, HUGE_VAL);
    b = circle(4.25 - 1e-9, 0, 0, 0, 0.125, 1);
    t = 4 - 2 * sqrt(4.25 - b.pos.x); /* (4 - t)^2 / 4 = 4.25 - b.pos.x, with b.pos.x as rounded */
    expect_hit(&a, 0.5, &b, 0.0, HUGE_VAL, t, 1, 0, b.pos.x - 0.125, 0, 1e-10);
    /* the same far from the origin (the relative frame): shift both by 2^20 */
    a.pos.x += 0x1p20;
    b = circle(0x1p20 + 4.25 + 1e-9, 0, 0, 0, 0.125, 1);
    expect_miss(&a, 0.5, &b, 0.0, HUGE_VAL);
}

/* Head-on, both rolling: a from 0 at +2, b from 10 at -2, both decel 0.5: a stops at 4, b at 6
 * (t = 4). Gap 10 - 4t + t^2/2. Radii 1.25 (R = 2.5): t^2 - 8t + 15 = 0, t = 3; a at 3.75, point
 * 5. Radii 1 (R = 2): t = 4 double root: they come to rest exactly touching: no hit. */
static void test_head_on_both_rolling(void)
{
    cc_circle a = circle(0, 0, 2, 0, 1.25, 1), b = circle(10, 0, -2, 0, 1.25, 1);
    expect_hit(&a, 0.5, &b, 0.5, HUGE_VAL, 3, 1, 0, 5, 0, 1e-15);
    a.radius = b.radius = 1;
    expect_miss(&a, 0.5, &b, 0.5, HUGE_VAL);
    /* a without deceleration at +1, b at -2 with decel 1 stops at t = 2 at x = 8; a reaches
     * 8 - 2 = 6 at t = 6 (the straight tail after b's stop) */
    a = circle(0, 0, 1, 0, 1, 1);
    b = circle(10, 0, -2, 0, 1, 1);
    expect_hit(&a, 0.0, &b, 1.0, HUGE_VAL, 6, 1, 0, 7, 0, 1e-15);
    expect_miss(&a, 0.0, &b, 1.0, 5.5);
    /* the float twin: the same exact numbers */
    {
        cc_circlef fa = {{0, 0}, {2, 0}, 1.25f, 1}, fb = {{10, 0}, {-2, 0}, 1.25f, 1};
        cc_contactf fk;
        TEST_ASSERT_EQUAL_INT(CC_HIT, cc_sweep_rollingf(&fa, 0.5f, &fb, 0.5f, HUGE_VALF, &fk));
        TEST_ASSERT_FLOAT_WITHIN(4 * FLT_EPSILON * 3, 3.0f, fk.t);
        TEST_ASSERT_FLOAT_WITHIN(4 * FLT_EPSILON * 5, 5.0f, fk.point.x);
        fa.radius = fb.radius = 1;
        TEST_ASSERT_EQUAL_INT(CC_MISS, cc_sweep_rollingf(&fa, 0.5f, &fb, 0.5f, HUGE_VALF, &fk));
    }
    /* overlapping at the start: cc_sweep's contact, whatever the deceleration */
    {
        cc_contact k1 = sentinel_contact(), k2 = sentinel_contact();
        b = circle(1, 0, -2, 0, 1, 1);
        TEST_ASSERT_EQUAL_INT(CC_OVERLAP, cc_sweep_rolling(&a, 3.0, &b, 1.0, 10, &k1));
        TEST_ASSERT_EQUAL_INT(CC_OVERLAP, cc_sweep(&a, &b, 10, &k2));
        TEST_ASSERT_EQUAL_MEMORY(&k2, &k1, sizeof k1);
    }
}

/* Crossing paths, the contact on the edge of the first bound's windows (cc__across_apart): a
 * from (-1.5, 0) at (2, 0) with decel 1 (k = 1/4), b from (0, -2.75) at (0, 2) with decel 0.5
 * (k = 1/8), radii 0.5 (R = 1). x_a = -1.5 + 2t - t^2/2, y_b = -2.75 + 2t - t^2/4: at t = 1 a
 * is at (0, 0), b at (0, -1): touching, b closing at 1.5 (a's velocity is across the normal).
 * b enters a's strip |y| <= R at that same instant, so t = 1 is the lower end of b's time
 * window: with t_max = 1 the bound must not part them (b's window taken to time with a's k, or
 * rounded the wrong way without margins, does). Swapped, the same contact. */
static void test_crossing_paths_touch_at_a_window_edge(void)
{
    cc_circle a = circle(-1.5, 0, 2, 0, 0.5, 1), b = circle(0, -2.75, 0, 2, 0.5, 1);
    expect_hit(&a, 1.0, &b, 0.5, HUGE_VAL, 1, 0, -1, 0, -0.5, 1e-15);
    expect_hit(&a, 1.0, &b, 0.5, 1.0, 1, 0, -1, 0, -0.5, 1e-15);
    expect_hit(&b, 0.5, &a, 1.0, 1.0, 1, 0, 1, 0, -0.5, 1e-15);
    expect_miss(&a, 1.0, &b, 0.5, 0.999);
    { /* the float twin: the same exact numbers */
        cc_circlef fa = {{-1.5f, 0}, {2, 0}, 0.5f, 1}, fb = {{0, -2.75f}, {0, 2}, 0.5f, 1};
        cc_contactf fk;
        TEST_ASSERT_EQUAL_INT(CC_HIT, cc_sweep_rollingf(&fa, 1.0f, &fb, 0.5f, 1.0f, &fk));
        TEST_ASSERT_FLOAT_WITHIN(8 * FLT_EPSILON, 1.0f, fk.t);
        TEST_ASSERT_EQUAL_INT(CC_HIT, cc_sweep_rollingf(&fb, 0.5f, &fa, 1.0f, 1.0f, &fk));
        TEST_ASSERT_FLOAT_WITHIN(8 * FLT_EPSILON, 1.0f, fk.t);
    }
}

/* A ball against a wall from (0,0) to (10,0).
 * Straight at it: centre (5, 2), r 0.5, v (0, -2), decel 1: k = 1/4, y = 2 - 2(t - t^2/4);
 * y = 0.5 at t^2 - 4t + 3 = 0, t = 1; point (5, 0), normal (0, -1). With decel 2 it stops
 * (t = 1) exactly touching: no hit.
 * Rolling along it at a shallow angle: centre (1, 1.5), v (4, -2), k = 1/4 (decel = sqrt(20)/2):
 * the distance to the line 1.5 - 2 g(t) = 0.5 at g = t - t^2/4 = 1/2, t = 2 - sqrt(2); x = 3.
 * Parallel to it, 0.5 above the radius: never. */
static void test_ball_and_wall(void)
{
    cc_segment s = {{0, 0}, {10, 0}};
    cc_circle c = circle(5, 2, 0, -2, 0.5, 1);
    cc_contact k = sentinel_contact(), before = k;
    TEST_ASSERT_EQUAL_INT(CC_HIT, cc_sweep_segment_rolling(&c, 1.0, &s, 10, &k));
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 1.0, k.t);
    EXPECT_VEC_NEAR(4, 0, -1, k.normal);
    EXPECT_VEC_NEAR(4, 5, 0, k.point);
    c = circle(5, 1.5, 0, -2, 0.5, 1);
    k = before;
    TEST_ASSERT_EQUAL_INT(CC_MISS, cc_sweep_segment_rolling(&c, 2.0, &s, 10, &k));
    TEST_ASSERT_EQUAL_MEMORY(&before, &k, sizeof k);
    c = circle(1, 1.5, 4, -2, 0.5, 1);
    TEST_ASSERT_EQUAL_INT(CC_HIT, cc_sweep_segment_rolling(&c, sqrt(20.0) / 2, &s, 10, &k));
    TEST_ASSERT_DOUBLE_WITHIN(1e-14, 2 - sqrt(2.0), k.t);
    TEST_ASSERT_DOUBLE_WITHIN(1e-14, 3, k.point.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-14, 0, k.point.y);
    k = before;
    c = circle(1, 1.0, 4, 0, 0.5, 1);
    TEST_ASSERT_EQUAL_INT(CC_MISS, cc_sweep_segment_rolling(&c, 1.0, &s, 10, &k));
    TEST_ASSERT_EQUAL_MEMORY(&before, &k, sizeof k);
    /* rolling towards the wall's end point (10, 0) along the x axis: centre (5, 0), v (2, 0),
     * decel 0.25 (k = 1/16): x = 5 + 2 (t - t^2/16) = 9.5 at t^2 - 16t + 36 = 0,
     * t = 8 - sqrt(28); normal (1, 0), point (10, 0); with decel 0.5 it stops at 9 */
    s.a.x = 11, s.a.y = 0, s.b.x = 10, s.b.y = 0;
    c = circle(5, 0, 2, 0, 0.5, 1);
    TEST_ASSERT_EQUAL_INT(CC_HIT, cc_sweep_segment_rolling(&c, 0.25, &s, 100, &k));
    TEST_ASSERT_DOUBLE_WITHIN(1e-13, 8 - sqrt(28.0), k.t);
    EXPECT_VEC_NEAR(4, 1, 0, k.normal);
    TEST_ASSERT_DOUBLE_WITHIN(1e-13, 10, k.point.x);
    k = before;
    TEST_ASSERT_EQUAL_INT(CC_MISS, cc_sweep_segment_rolling(&c, 0.5, &s, 100, &k));
    TEST_ASSERT_EQUAL_MEMORY(&before, &k, sizeof k);
    /* coming to rest exactly touching the end point: centre (5, 0.25), v (3, 0), decel 1 stops
     * after 4.5 at x = 9.5, radius 0.5 from (10, 0.25): no hit. Started d = 1e-9 further on, it
     * reaches 9.5 when 5 + d + 4.5 - (3 - t)^2 / 2 = 9.5, t = 3 - sqrt(2 d) (the speed there is
     * 3 - t ~ 4.5e-5: the position's rounding, 1e-15, moves t by ~2e-11); 1e-9 short: no hit. */
    s.a.y = s.b.y = 0.25;
    c = circle(5, 0.25, 3, 0, 0.5, 1);
    TEST_ASSERT_EQUAL_INT(CC_MISS, cc_sweep_segment_rolling(&c, 1.0, &s, 100, &k));
    TEST_ASSERT_EQUAL_MEMORY(&before, &k, sizeof k);
    c.pos.x = 5 + 1e-9;
    TEST_ASSERT_EQUAL_INT(CC_HIT, cc_sweep_segment_rolling(&c, 1.0, &s, 100, &k));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 3 - sqrt(2 * (c.pos.x - 5)), k.t);
    k = before;
    c.pos.x = 5 - 1e-9;
    TEST_ASSERT_EQUAL_INT(CC_MISS, cc_sweep_segment_rolling(&c, 1.0, &s, 100, &k));
    TEST_ASSERT_EQUAL_MEMORY(&before, &k, sizeof k);
    /* touching an end point now and rolling into it: the wall from (1, 0) to (2, 0) along the
     * motion (no interior contact), the circle of radius 1 at the origin with v (1, 0): its
     * distance to (1, 0) is exactly R at t = 0 and falls, so the contact is now, t = 0, normal
     * (1, 0), point (1, 0) (the solver's "touching now" answer: f(0) = 0, f'(0) < 0) */
    s.a.x = 1, s.a.y = 0, s.b.x = 2, s.b.y = 0;
    c = circle(0, 0, 1, 0, 1, 1);
    k = before;
    TEST_ASSERT_EQUAL_INT(CC_HIT, cc_sweep_segment_rolling(&c, 0.5, &s, 10, &k));
    TEST_ASSERT_EQUAL_DOUBLE(0.0, k.t);
    EXPECT_VEC_NEAR(0, 1, 0, k.normal);
    EXPECT_VEC_NEAR(0, 1, 0, k.point);
}

/* A random circle for the random tests: positions in a box of side 10 * L (shifted by up to
 * `far` in common), speeds up to 4 L, radii L / 16 .. L. */
static cc_circle random_circle(uint64_t *s, double L, double ox, double oy)
{
    return circle(ox + rng_range(s, -5, 5) * L, oy + rng_range(s, -5, 5) * L, rng_range(s, -4, 4) * L,
                  rng_range(s, -4, 4) * L, rng_range(s, 0.0625, 1) * L, 1);
}

/* Half the time, a is sent roughly towards b (at up to 4 L, within +-0.3 rad): more contacts. */
static void aim(uint64_t *s, cc_circle *a, const cc_circle *b, double L)
{
    double dx = b->pos.x - a->pos.x, dy = b->pos.y - a->pos.y, d = sqrt(dx * dx + dy * dy), sp, th, c, sn;
    if (!rng_int(s, 2) || !(d > 0))
        return;
    sp = rng_range(s, 0.5, 4) * L / d;
    th = rng_range(s, -0.3, 0.3);
    c = cos(th), sn = sin(th);
    a->vel = vec((dx * c - dy * sn) * sp, (dx * sn + dy * c) * sp);
}

/* decel 0, or a circle at rest: cc_sweep's bits (result and contact), 10,000 random pairs; and
 * cc_sweep_segment's for a circle and a wall. */
static void test_decel_zero_is_cc_sweep(void)
{
    uint64_t s = 12;
    int i, hits = 0;
    for (i = 0; i < 10000; i++) {
        double L = ldexp(1.0, rng_int(&s, 61) - 30);
        cc_circle a = random_circle(&s, L, 0, 0), b = random_circle(&s, L, 0, 0);
        cc_segment w = segment(rng_range(&s, -5, 5) * L, rng_range(&s, -5, 5) * L, rng_range(&s, -5, 5) * L,
                               rng_range(&s, -5, 5) * L);
        double da = 0, db = 0, t_max = rng_int(&s, 4) ? rng_range(&s, 0, 10) : HUGE_VAL;
        cc_contact k1 = sentinel_contact(), k2 = sentinel_contact();
        int r1, r2;
        aim(&s, &a, &b, L);
        if (rng_int(&s, 2)) { /* a at rest with a deceleration */
            a.vel = vec(0, 0);
            da = rng_range(&s, 0, 3) * L;
        }
        if (rng_int(&s, 2)) {
            b.vel = vec(0, 0);
            db = rng_range(&s, 0, 3) * L;
        }
        r1 = cc_sweep_rolling(&a, da, &b, db, t_max, &k1);
        r2 = cc_sweep(&a, &b, t_max, &k2);
        TEST_ASSERT_EQUAL_INT(r2, r1);
        TEST_ASSERT_EQUAL_MEMORY(&k2, &k1, sizeof k1);
        hits += r1 == CC_HIT;
        k1 = k2 = sentinel_contact();
        r1 = cc_sweep_segment_rolling(&b, 0.0, &w, t_max, &k1);
        r2 = cc_sweep_segment(&b, &w, t_max, &k2);
        TEST_ASSERT_EQUAL_INT(r2, r1);
        TEST_ASSERT_EQUAL_MEMORY(&k2, &k1, sizeof k1);
    }
    TEST_ASSERT_TRUE(hits > 1000); /* the sample exercises hits, not only misses */
}

static void test_invalid_inputs(void)
{
    cc_circle a = circle(0, 0, 1, 0, 1, 1), b = circle(5, 0, 0, 0, 1, 1), bad = a, c0 = a;
    cc_segment s = {{3, -1}, {3, 1}};
    cc_contact k = sentinel_contact(), before = k;
    double bads[] = {-1.0, NAN, HUGE_VAL, -HUGE_VAL, -0x1p-1074};
    size_t i;
    for (i = 0; i < sizeof bads / sizeof bads[0]; i++) {
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_sweep_rolling(&a, bads[i], &b, 0, 10, &k));
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_sweep_rolling(&a, 0, &b, bads[i], 10, &k));
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_sweep_segment_rolling(&a, bads[i], &s, 10, &k));
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_rolling_advance(&c0, bads[i], 1));
        if (bads[i] != HUGE_VAL) { /* t_max = +INFINITY is valid */
            TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_sweep_rolling(&a, 1, &b, 1, bads[i], &k));
            TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_sweep_segment_rolling(&a, 1, &s, bads[i], &k));
        }
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_rolling_advance(&c0, 1, bads[i])); /* t must be finite */
    }
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_sweep_rolling(NULL, 1, &b, 1, 10, &k));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_sweep_rolling(&a, 1, NULL, 1, 10, &k));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_sweep_rolling(&a, 1, &b, 1, 10, NULL));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_sweep_segment_rolling(NULL, 1, &s, 10, &k));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_sweep_segment_rolling(&a, 1, NULL, 10, &k));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_sweep_segment_rolling(&a, 1, &s, 10, NULL));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_rolling_advance(NULL, 1, 1));
    bad.radius = 0;
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_sweep_rolling(&bad, 1, &b, 1, 10, &k));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_sweep_segment_rolling(&bad, 1, &s, 10, &k));
    bad = a;
    bad.vel.y = NAN;
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_sweep_rolling(&a, 1, &bad, 1, 10, &k));
    {
        cc_circle bad2 = bad;
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_rolling_advance(&bad2, 1, 1));
        TEST_ASSERT_EQUAL_MEMORY(&bad, &bad2, sizeof bad);
    }
    s.a.x = NAN;
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_sweep_segment_rolling(&a, 1, &s, 10, &k));
    TEST_ASSERT_EQUAL_MEMORY(&before, &k, sizeof k);
    TEST_ASSERT_EQUAL_MEMORY(&a, &c0, sizeof a);
    /* float twins */
    {
        cc_circlef fa = {{0, 0}, {1, 0}, 1, 1}, fb = {{5, 0}, {0, 0}, 1, 1};
        cc_segmentf fs = {{3, -1}, {3, 1}};
        cc_contactf fk, fbefore;
        memset(&fk, 0xA5, sizeof fk);
        fbefore = fk;
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_sweep_rollingf(&fa, -1.0f, &fb, 0, 10, &fk));
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_sweep_rollingf(&fa, 0, &fb, NAN, 10, &fk));
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_sweep_rollingf(&fa, 0, &fb, 1, -1, &fk));
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_sweep_segment_rollingf(&fa, HUGE_VALF, &fs, 10, &fk));
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_rolling_advancef(&fa, 1, HUGE_VALF));
        TEST_ASSERT_EQUAL_MEMORY(&fbefore, &fk, sizeof fk);
    }
}

/* ---- the brute-force reference: the contract's motion in long double -------------------------- */

typedef struct ref_motion {
    long double px, py, vx, vy, ts; /* ts: the stop time, or -1 for straight motion */
} ref_motion;

static ref_motion ref_of(const cc_circle *c, double decel)
{
    ref_motion m;
    long double s = sqrtl((long double)c->vel.x * c->vel.x + (long double)c->vel.y * c->vel.y);
    m.px = c->pos.x, m.py = c->pos.y, m.vx = c->vel.x, m.vy = c->vel.y;
    m.ts = decel > 0 && s > 0 ? s / decel : -1;
    return m;
}

/* the distance's g(t): t - decel t^2 / (2 s) = t - t^2 / (2 ts), clamped at the stop */
static long double ref_g(const ref_motion *m, long double t)
{
    if (m->ts < 0)
        return t;
    if (t > m->ts)
        t = m->ts;
    return t - t * t / (2 * m->ts);
}

static long double ref_gd(const ref_motion *m, long double t)
{
    return m->ts < 0 ? 1 : t >= m->ts ? 0 : 1 - t / m->ts;
}

typedef struct ref_pair {
    ref_motion a, b;
    long double R;
} ref_pair;

/* |pb - pa|^2 - R^2 at t; *approach: the speed at which the distance falls there */
static long double ref_f(const ref_pair *p, long double t, long double *approach)
{
    long double ga = ref_g(&p->a, t), gb = ref_g(&p->b, t);
    long double x = (p->b.px - p->a.px) + (p->b.vx * gb - p->a.vx * ga);
    long double y = (p->b.py - p->a.py) + (p->b.vy * gb - p->a.vy * ga);
    if (approach) {
        long double gda = ref_gd(&p->a, t), gdb = ref_gd(&p->b, t), len = sqrtl(x * x + y * y);
        long double dx = p->b.vx * gdb - p->a.vx * gda, dy = p->b.vy * gdb - p->a.vy * gda;
        *approach = len > 0 ? -(x * dx + y * dy) / len : 0;
    }
    return x * x + y * y - p->R * p->R;
}

/* The first t in [lo, hi] (n samples) at which f < 0, bisected in long double; -1 when none. */
static long double ref_first(const ref_pair *p, long double lo, long double hi, long n)
{
    long i;
    long double prev = lo;
    for (i = 1; i <= n; i++) {
        long double t = lo + (hi - lo) * i / n;
        if (ref_f(p, t, NULL) < 0) {
            long double a = prev, b = t;
            int j;
            for (j = 0; j < 200 && b - a > 0; j++) {
                long double m = a + (b - a) / 2;
                if (m <= a || m >= b)
                    break;
                if (ref_f(p, m, NULL) < 0)
                    b = m;
                else
                    a = m;
            }
            return b;
        }
        prev = t;
    }
    return -1;
}

/* 20,000 random rolling pairs (mostly both rolling, some one at rest or straight, a sixth placed
 * so that b rests about R from where a stops, decel ratios up to 2^30 ~ 1e9, lengths scaled
 * 2^-30 .. 2^30 ~ 1e-9 .. 1e9 and moved up to 2^49 L ~ 5.6e14 L from the origin, t_max finite or
 * not). The reference samples [0, min(t_max, the last stop)] at 4,000 points and bisects the first
 * sign change in long double; where it and the library disagree on hit or miss, the window is
 * sampled again 4,000 times finer around the library's time (a dip between two samples). What is
 * left must lie in the rounding band: the reference's approach speed at its contact below 1e-6 of
 * the speeds (grazing, or coming to rest at the touch), or its time within 1e-9 of t_max. */
static void test_brute_force(void)
{
    uint64_t s = 77;
    int i, hits = 0, misses = 0, overlaps = 0, band = 0, refined = 0, nearstop = 0;
    double worst = 0, worst_t = 0;
    char msg[200];
    for (i = 0; i < 20000; i++) {
        double L = ldexp(1.0, rng_int(&s, 61) - 30), far = rng_int(&s, 4) ? 0 : ldexp(1.0, rng_int(&s, 50)) * L;
        double ox = rng_range(&s, -far, far), oy = rng_range(&s, -far, far);
        cc_circle a = random_circle(&s, L, ox, oy), b = random_circle(&s, L, ox, oy);
        double da = rng_range(&s, 0, 2) * L * (rng_int(&s, 8) ? 1 : ldexp(1.0, rng_int(&s, 30) - 15));
        double db = rng_range(&s, 0, 2) * L * (rng_int(&s, 8) ? 1 : ldexp(1.0, rng_int(&s, 30) - 15));
        double t_max = rng_int(&s, 3) ? rng_range(&s, 0, 12) : HUGE_VAL, vscale;
        cc_contact k = sentinel_contact();
        ref_pair p;
        long double horizon, tr, app = 0;
        int r, rhit;
        aim(&s, &a, &b, L);
        switch (rng_int(&s, 6)) {
        case 0: da = 0; break;              /* a straight */
        case 1: b.vel = vec(0, 0); break;   /* b at rest */
        case 2: db = 0; break;              /* b straight */
        case 3: {                           /* near a stop: b at rest about R from where a stops */
            double sp = sqrt(a.vel.x * a.vel.x + a.vel.y * a.vel.y), g = sp / (2 * da), th = rng_range(&s, -0.5, 0.5);
            double ux = a.vel.x / sp, uy = a.vel.y / sp, rr = (a.radius + b.radius) *
                                                             (1 + (rng_int(&s, 2) ? 1 : -1) * ldexp(1.0, -rng_int(&s, 45) - 5));
            if (!(da > 0 && sp > 0))
                break;
            b.vel = vec(0, 0);
            b.pos = vec(a.pos.x + ux * g + (ux * cos(th) - uy * sin(th)) * rr,
                        a.pos.y + uy * g + (ux * sin(th) + uy * cos(th)) * rr);
            nearstop++;
            break;
        }
        default: break;                     /* both rolling */
        }
        if (da == 0 && db == 0)
            db = L;
        if (t_max == HUGE_VAL && (da == 0 || db == 0))
            t_max = 20; /* a straight path has no end: the reference needs one */
        r = cc_sweep_rolling(&a, da, &b, db, t_max, &k);
        TEST_ASSERT_TRUE(r == CC_HIT || r == CC_MISS || r == CC_OVERLAP);
        p.a = ref_of(&a, da);
        p.b = ref_of(&b, db);
        p.R = (long double)a.radius + b.radius;
        if (r == CC_OVERLAP) {
            overlaps++;
            continue;
        }
        horizon = t_max;
        if (p.a.ts >= 0 && p.b.ts >= 0 && (p.a.ts > p.b.ts ? p.a.ts : p.b.ts) < horizon)
            horizon = p.a.ts > p.b.ts ? p.a.ts : p.b.ts; /* both at rest from then on */
        if (p.a.ts >= 0 && (p.b.vx == 0 && p.b.vy == 0) && p.a.ts < horizon)
            horizon = p.a.ts;
        tr = ref_first(&p, 0, horizon, 4000);
        if (r == CC_HIT && tr < 0) { /* a dip between two samples? look closer */
            long double w = horizon / 4000, lo = k.t - w > 0 ? k.t - w : 0, hi = k.t + w < horizon ? k.t + w : horizon;
            tr = ref_first(&p, lo, hi, 8000);
            refined++;
        }
        rhit = tr >= 0;
        vscale = fabs(a.vel.x) + fabs(a.vel.y) + fabs(b.vel.x) + fabs(b.vel.y);
        if (rhit)
            (void)ref_f(&p, tr, &app);
        if ((r == CC_HIT) != rhit) {
            int in_band = (rhit && app < 1e-6 * vscale) || (rhit && fabsl(tr - t_max) <= 1e-9 * t_max);
            if (!rhit) { /* the library hit where the reference sees none: grazing at its time? */
                long double a2;
                long double f = ref_f(&p, k.t, &a2);
                in_band = fabsl(f) <= 1e-12L * p.R * p.R || a2 < 1e-6 * vscale;
            }
            if (!in_band) {
                snprintf(msg, sizeof msg, "case %d: library %d at %.17g, reference %.17Lg (approach %Lg of %g)", i, r,
                         r == CC_HIT ? k.t : -1.0, tr, app, vscale);
                TEST_FAIL_MESSAGE(msg);
            }
            band++;
            continue;
        }
        if (r == CC_HIT) {
            double e = (double)(fabsl(k.t - tr) / (tr > 1e-3L ? tr : 1e-3L));
            hits++;
            /* a grazing contact has a condition number of 1 / its approach: allow for it */
            if (!(e <= 1e-12 + 1e-14 * vscale / (double)(app > 0 ? app : 1e-300))) {
                snprintf(msg, sizeof msg, "case %d: t %.17g, reference %.17Lg (error %g, approach %Lg of %g)", i, k.t,
                         tr, e, app, vscale);
                TEST_FAIL_MESSAGE(msg);
            }
            if (e > worst)
                worst = e, worst_t = k.t;
        } else {
            misses++;
        }
    }
    printf("brute force: 20000 pairs (%d placed near a stop), %d hits, %d misses, %d overlaps at the start, %d disagreements in the rounding "
           "band, %d refined; worst relative time error %.3g (at t %.6g)\n",
           nearstop, hits, misses, overlaps, band, refined, worst, worst_t);
    TEST_ASSERT_TRUE(hits > 2000 && misses > 2000);
    TEST_ASSERT_TRUE(band <= 20);
}

/* The same for a rolling circle and a wall: 10,000 random pairs (scales 2^-30 .. 2^30, a quarter
 * of the walls points, a sixth of the circles aimed to stop about r from an end point), against
 * the distance from the centre to the segment in long double, sampled and bisected. */
static long double ref_seg_f(const ref_motion *m, const cc_segment *w, long double r, long double t)
{
    long double g = ref_g(m, t), px = m->px + m->vx * g, py = m->py + m->vy * g;
    long double ux = (long double)w->b.x - w->a.x, uy = (long double)w->b.y - w->a.y;
    long double qx = px - w->a.x, qy = py - w->a.y, uu = ux * ux + uy * uy, l = uu > 0 ? (qx * ux + qy * uy) / uu : 0;
    l = l < 0 ? 0 : l > 1 ? 1 : l;
    qx -= l * ux, qy -= l * uy;
    return qx * qx + qy * qy - r * r;
}

static void test_brute_force_wall(void)
{
    uint64_t s = 4242;
    int i, j, hits = 0, misses = 0, overlaps = 0, band = 0;
    double worst = 0;
    char msg[200];
    for (i = 0; i < 10000; i++) {
        double L = ldexp(1.0, rng_int(&s, 61) - 30), decel = rng_range(&s, 0.01, 2) * L;
        cc_circle c = random_circle(&s, L, 0, 0), e = random_circle(&s, L, 0, 0);
        cc_segment w = segment(e.pos.x, e.pos.y, rng_int(&s, 4) ? e.pos.x + e.vel.x : e.pos.x,
                               rng_int(&s, 4) ? e.pos.y + e.vel.y : e.pos.y);
        double t_max = rng_int(&s, 3) ? rng_range(&s, 0, 12) : HUGE_VAL, sp;
        cc_contact k = sentinel_contact();
        ref_motion m;
        long double horizon, lo = 0, tr = -1, app;
        int r, n = 4000;
        aim(&s, &c, &e, L);
        sp = sqrt(c.vel.x * c.vel.x + c.vel.y * c.vel.y);
        if (rng_int(&s, 6) == 0 && sp > 0) { /* the end point a about r from where it stops */
            double g = sp / (2 * decel), th = rng_range(&s, -1, 1);
            double rr = c.radius * (1 + (rng_int(&s, 2) ? 1 : -1) * ldexp(1.0, -rng_int(&s, 45) - 5));
            double ux = c.vel.x / sp, uy = c.vel.y / sp;
            w.a = vec(c.pos.x + ux * g + (ux * cos(th) - uy * sin(th)) * rr,
                      c.pos.y + uy * g + (ux * sin(th) + uy * cos(th)) * rr);
            w.b = vec(w.a.x + (ux * cos(th) - uy * sin(th)) * L, w.a.y + (ux * sin(th) + uy * cos(th)) * L);
        }
        r = cc_sweep_segment_rolling(&c, decel, &w, t_max, &k);
        TEST_ASSERT_TRUE(r == CC_HIT || r == CC_MISS || r == CC_OVERLAP);
        if (r == CC_OVERLAP) {
            overlaps++;
            continue;
        }
        m = ref_of(&c, decel);
        horizon = m.ts >= 0 && m.ts < t_max ? m.ts : t_max;
        if (!(horizon < HUGE_VAL))
            continue; /* (at rest: cc_sweep_segment's case) */
        for (j = 1; j <= n; j++) {
            long double t = horizon * j / n;
            if (ref_seg_f(&m, &w, c.radius, t) < 0) {
                long double a = lo, b = t;
                while (b - a > 0) {
                    long double mid = a + (b - a) / 2;
                    if (mid <= a || mid >= b)
                        break;
                    if (ref_seg_f(&m, &w, c.radius, mid) < 0)
                        b = mid;
                    else
                        a = mid;
                }
                tr = b;
                break;
            }
            lo = t;
        }
        /* the approach speed at the reference's contact: the rate at which sqrt(f + r^2) falls */
        app = 0;
        if (tr >= 0) {
            long double h = tr * 1e-9L + 1e-30L, f0 = ref_seg_f(&m, &w, c.radius, tr - h), f1 = ref_seg_f(&m, &w, c.radius, tr);
            app = (f0 - f1) / h / (2 * c.radius);
        }
        if ((r == CC_HIT) != (tr >= 0)) {
            int in_band = (tr >= 0 && app < 1e-6 * sp) || (tr >= 0 && fabsl(tr - t_max) <= 1e-9 * t_max);
            if (tr < 0) {
                long double f = ref_seg_f(&m, &w, c.radius, k.t);
                in_band = fabsl(f) <= 1e-9L * c.radius * c.radius;
            }
            if (!in_band) {
                snprintf(msg, sizeof msg, "wall case %d: library %d at %.17g, reference %.17Lg (approach %Lg of %g)", i,
                         r, r == CC_HIT ? k.t : -1.0, tr, app, sp);
                TEST_FAIL_MESSAGE(msg);
            }
            band++;
            continue;
        }
        if (r == CC_HIT) {
            double err = (double)(fabsl(k.t - tr) / (tr > 1e-3L ? tr : 1e-3L));
            hits++;
            if (!(err <= 1e-12 + 1e-14 * sp / (double)(app > 0 ? app : 1e-300))) {
                snprintf(msg, sizeof msg, "wall case %d: t %.17g, reference %.17Lg (error %g, approach %Lg of %g)", i, k.t,
                         tr, err, app, sp);
                TEST_FAIL_MESSAGE(msg);
            }
            if (err > worst)
                worst = err;
        } else {
            misses++;
        }
    }
    printf("brute force, walls: 10000 pairs, %d hits, %d misses, %d overlaps at the start, %d disagreements in the "
           "rounding band; worst relative time error %.3g\n",
           hits, misses, overlaps, band, worst);
    TEST_ASSERT_TRUE(hits > 1000 && misses > 1000);
    TEST_ASSERT_TRUE(band <= 20);
}

/* The float twins against double on the float-rounded inputs: hit or miss the same except in the
 * band (the double time near t_max, or a grazing contact), times within a float tolerance. */
static void test_float_agrees(void)
{
    uint64_t s = 99;
    int i, same = 0, hits = 0, differ = 0;
    double worst = 0;
    for (i = 0; i < 20000; i++) {
        cc_circle a = random_circle(&s, 1, 0, 0), b = random_circle(&s, 1, 0, 0);
        double da = rng_range(&s, 0, 2), db = rng_int(&s, 4) ? rng_range(&s, 0, 2) : 0, t_max = rng_range(&s, 0, 12);
        cc_circlef fa, fb;
        cc_contact k;
        cc_contactf fk;
        int r, rf;
        fa.pos.x = (float)a.pos.x, fa.pos.y = (float)a.pos.y, fa.vel.x = (float)a.vel.x, fa.vel.y = (float)a.vel.y;
        fa.radius = (float)a.radius, fa.mass = 1;
        fb.pos.x = (float)b.pos.x, fb.pos.y = (float)b.pos.y, fb.vel.x = (float)b.vel.x, fb.vel.y = (float)b.vel.y;
        fb.radius = (float)b.radius, fb.mass = 1;
        a.pos.x = fa.pos.x, a.pos.y = fa.pos.y, a.vel.x = fa.vel.x, a.vel.y = fa.vel.y, a.radius = fa.radius;
        b.pos.x = fb.pos.x, b.pos.y = fb.pos.y, b.vel.x = fb.vel.x, b.vel.y = fb.vel.y, b.radius = fb.radius;
        da = (float)da, db = (float)db, t_max = (float)t_max;
        r = cc_sweep_rolling(&a, da, &b, db, t_max, &k);
        rf = cc_sweep_rollingf(&fa, (float)da, &fb, (float)db, (float)t_max, &fk);
        if (r != rf) {
            differ++;
            continue;
        }
        same++;
        if (r == CC_HIT) {
            double e = fabs((double)fk.t - k.t) / (k.t > 1 ? k.t : 1);
            hits++;
            if (e > worst)
                worst = e;
            TEST_ASSERT_DOUBLE_WITHIN(2e-3 * (k.t > 1 ? k.t : 1), k.t, (double)fk.t);
            TEST_ASSERT_DOUBLE_WITHIN(2e-3, k.normal.x, (double)fk.normal.x);
            TEST_ASSERT_DOUBLE_WITHIN(2e-3, k.normal.y, (double)fk.normal.y);
        }
        {   /* the wall twin and the advance twin */
            cc_segment w = segment(b.pos.x, b.pos.y, b.pos.x + b.vel.x, b.pos.y + b.vel.y);
            cc_segmentf fw;
            cc_circle c = a;
            cc_circlef fc = fa;
            fw.a.x = (float)w.a.x, fw.a.y = (float)w.a.y, fw.b.x = (float)w.b.x, fw.b.y = (float)w.b.y;
            w.a.x = fw.a.x, w.a.y = fw.a.y, w.b.x = fw.b.x, w.b.y = fw.b.y;
            r = cc_sweep_segment_rolling(&a, da, &w, t_max, &k);
            rf = cc_sweep_segment_rollingf(&fa, (float)da, &fw, (float)t_max, &fk);
            if (r == rf && r == CC_HIT)
                TEST_ASSERT_DOUBLE_WITHIN(2e-3 * (k.t > 1 ? k.t : 1), k.t, (double)fk.t);
            else if (r != rf)
                differ++;
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_rolling_advance(&c, da, t_max));
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_rolling_advancef(&fc, (float)da, (float)t_max));
            TEST_ASSERT_DOUBLE_WITHIN(1e-5 * (1 + fabs(c.pos.x)), c.pos.x, (double)fc.pos.x);
            TEST_ASSERT_DOUBLE_WITHIN(1e-5 * (1 + fabs(c.pos.y)), c.pos.y, (double)fc.pos.y);
            TEST_ASSERT_DOUBLE_WITHIN(1e-5 * (1 + fabs(a.vel.x)), c.vel.x, (double)fc.vel.x);
        }
    }
    printf("float vs double: 20000 pairs (+ 20000 walls), %d agree (%d hits), %d differ in hit/miss; worst "
           "relative time error %.3g\n",
           same, hits, differ, worst);
    TEST_ASSERT_TRUE(differ <= 200); /* 0.5 %: grazing and cut-off cases of a 24-bit problem */
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_advance_stops);
    RUN_TEST(test_ball_into_resting_ball);
    RUN_TEST(test_stop_short_exact_long);
    RUN_TEST(test_head_on_both_rolling);
    RUN_TEST(test_crossing_paths_touch_at_a_window_edge);
    RUN_TEST(test_ball_and_wall);
    RUN_TEST(test_decel_zero_is_cc_sweep);
    RUN_TEST(test_invalid_inputs);
    RUN_TEST(test_brute_force);
    RUN_TEST(test_brute_force_wall);
    RUN_TEST(test_float_agrees);
    return UNITY_END();
}
