/* cc_sweep (and cc_sweepf when built with -DTEST_FLOAT): hand-derived cases of the circle-circle
 * time of impact. Notation of the derivations: dp = pb - pa, dv = vb - va, R = ra + rb; contact
 * is |dp + dv t| = R while the distance decreases. Inputs are chosen so that the answers are
 * exact binary numbers wherever possible. */
#include "core_precision.h"

void setUp(void) {}
void tearDown(void) {}

/* Expects CC_HIT at t with the given normal and point (depth 0), within `ulps`. */
static void expect_hit(const Circle *a, const Circle *b, double t_max, double t, double nx, double ny,
                       double px, double py, double ulps)
{
    Contact k = sentinel_contact();
    int r = F(cc_sweep)(a, b, (Real)t_max, &k);
    expect_hit_contact(r, &k, t, nx, ny, px, py, ulps);
}

/* Expects CC_MISS and out left exactly as it was. */
static void expect_miss(const Circle *a, const Circle *b, double t_max)
{
    Contact k = sentinel_contact(), before = k;
    TEST_ASSERT_EQUAL_INT_MESSAGE(CC_MISS, F(cc_sweep)(a, b, (Real)t_max, &k), "result");
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&before, &k, sizeof k, "out changed on CC_MISS");
}

/* a (0,0) v (1,0), b (10,0) v (-1,0), radii 1: dp = (10,0), dv = (-2,0), R = 2, so
 * 10 - 2t = 2, t = 4 (solver: c = 8 * 12 = 96, b = -20, disc = 4^2, t = 96 / (20 + 4) = 4,
 * exact). Then a is at (4,0): normal (1,0), point (5,0). */
static void test_head_on(void)
{
    Circle a = circle(0, 0, 1, 0, 1, 1), b = circle(10, 0, -1, 0, 1, 1);
    expect_hit(&a, &b, 10, 4, 1, 0, 5, 0, 0);
}

/* a still at (0,0) r 0.5; b at (0,7) r 1.5 v (0,-2): 7 - 2t = 2, t = 2.5 (c = 5 * 9 = 45,
 * b = -14, sqrt(disc) = 4, t = 45 / 18, exact). Normal (0,1), point (0, 0.5). */
static void test_moving_vs_still(void)
{
    Circle a = circle(0, 0, 0, 0, 0.5, 1), b = circle(0, 7, 0, -2, 1.5, 1);
    expect_hit(&a, &b, 10, 2.5, 0, 1, 0, 0.5, 0);
}

/* a (0,0) v (1,1) r 2; b (6,8) v (-2,-3) r 3: dp = (6,8), dv = (-3,-4), head-on along the
 * 3-4-5 direction: 10 - 5t = 5, t = 1 (c = 5 * 15 = 75, b = -50, sqrt(disc) = 25, t = 75/75).
 * a is then at (1,1), normal (0.6,0.8), point (1,1) + 2 (0.6,0.8) = (2.2, 2.6). */
static void test_both_moving(void)
{
    Circle a = circle(0, 0, 1, 1, 2, 1), b = circle(6, 8, -2, -3, 3, 1);
    expect_hit(&a, &b, 10, 1, 0.6, 0.8, 2.2, 2.6, 4);
}

/* Glancing: a still at (0,0) r 2; b at (-8,3) r 3 moving (1,0). |(-8 + t, 3)| = 5 gives
 * (t - 8)^2 = 16, first root t = 4 (12 is the exit). Closest approach 3 < R = 5. Solver:
 * h = |dp x dv| = 3, q = 5, disc = 2 * 8 = 16, t = c / (8 + 4), c = 73 - 25 = 48 up to the
 * rounding of sqrt(73). At t = 4, dp = (-4,3): normal (-0.8,0.6), point 2 n = (-1.6, 1.2). */
static void test_glancing(void)
{
    Circle a = circle(0, 0, 0, 0, 2, 1), b = circle(-8, 3, 1, 0, 3, 1);
    expect_hit(&a, &b, 10, 4, -0.8, 0.6, -1.6, 1.2, 16);
}

/* The same glancing pair seen from b: t is the same, the normal reversed, and the point lies
 * on b's surface: b at (-4,3) plus 3 (0.8,-0.6) = (-1.6, 1.2), the same touching point. */
static void test_glancing_swapped(void)
{
    Circle a = circle(0, 0, 0, 0, 2, 1), b = circle(-8, 3, 1, 0, 3, 1);
    expect_hit(&b, &a, 10, 4, 0.8, -0.6, -1.6, 1.2, 16);
}

/* Touching (d = R = 2) and approaching: a hit at t = 0 (c = 0), normal (1,0), point (1,0). */
static void test_touching_approaching(void)
{
    Circle a = circle(0, 0, 0, 0, 1, 1), b = circle(2, 0, -1, 0.5, 1, 1);
    expect_hit(&a, &b, 10, 0, 1, 0, 1, 0, 0);
}

/* Touching and leaving (dp.dv = 2 > 0), touching and sliding (dp.dv = 0): no contact. */
static void test_touching_leaving_or_tangent(void)
{
    Circle a = circle(0, 0, 0, 0, 1, 1), leaving = circle(2, 0, 1, 0, 1, 1), sliding = circle(2, 0, 0, 1, 1, 1);
    expect_miss(&a, &leaving, 10);
    expect_miss(&a, &sliding, 10);
}

/* b passes a at exactly distance R: b at (-10,2) r 1 moving (1,0) past a at (0,0) r 1. The
 * closest approach |dp x dv| / |dv| = 2 = R: tangent, which the contract calls a miss. One
 * unit closer (y = 1) it is a hit at 10 - sqrt(3) (|(t - 10, 1)| = 2), where dp = (-sqrt(3), 1):
 * normal (-sqrt(3)/2, 1/2), point a + 1 n. */
static void test_tangent_pass(void)
{
    Circle a = circle(0, 0, 0, 0, 1, 1), b = circle(-10, 2, 1, 0, 1, 1), c = circle(-10, 1, 1, 0, 1, 1);
    expect_miss(&a, &b, 100);
    expect_hit(&a, &c, 100, 10 - sqrt(3.0), -0.5 * sqrt(3.0), 0.5, -0.5 * sqrt(3.0), 0.5, 32);
}

/* Closest approach 3 > R = 2: a miss however long we look. */
static void test_passes_too_far(void)
{
    Circle a = circle(0, 0, 0, 0, 1, 1), b = circle(-10, 3, 1, 0, 1, 1);
    expect_miss(&a, &b, INFINITY);
}

/* Parallel motion (same velocity), both at rest, moving apart: never closer than now. */
static void test_parallel_rest_apart(void)
{
    Circle a = circle(0, 0, 3, -1, 1, 1), b = circle(5, 0, 3, -1, 1, 1);
    Circle c = circle(0, 0, 0, 0, 1, 1), d = circle(5, 0, 0, 0, 1, 1);
    Circle e = circle(0, 0, -1, 0, 1, 1), f = circle(5, 0, 1, 2, 1, 1);
    expect_miss(&a, &b, INFINITY);
    expect_miss(&c, &d, INFINITY);
    expect_miss(&e, &f, INFINITY);
}

/* The head-on pair touches at t = 4: t_max 3.5 misses, t_max 4 includes it, t_max +INFINITY
 * is allowed, t_max 0 sees only the start (apart). */
static void test_t_max_cut_off(void)
{
    Circle a = circle(0, 0, 1, 0, 1, 1), b = circle(10, 0, -1, 0, 1, 1);
    expect_miss(&a, &b, 3.5);
    expect_miss(&a, &b, 0);
    expect_hit(&a, &b, 4, 4, 1, 0, 5, 0, 0);
    expect_hit(&a, &b, INFINITY, 4, 1, 0, 5, 0, 0);
}

/* Overlapping at start: a (0,0) r 3, b (3,4) r 3: d = 5 < 6. CC_OVERLAP with t = 0,
 * depth 6 - 5 = 1, normal (0.6,0.8), point midway through the overlap a + n (d + ra - rb)/2 =
 * 2.5 n = (1.5, 2); byte-for-byte the cc_detect_static contact. */
static void test_overlap_at_start(void)
{
    Circle a = circle(0, 0, 1, 0, 3, 1), b = circle(3, 4, -1, 0, 3, 1);
    Contact k = sentinel_contact(), s = sentinel_contact();
    TEST_ASSERT_EQUAL_INT(CC_OVERLAP, F(cc_sweep)(&a, &b, 10, &k));
    EXPECT_EXACT(0, k.t);
    EXPECT_NEAR(4, 1, k.depth);
    EXPECT_VEC_NEAR(4, 0.6, 0.8, k.normal);
    EXPECT_VEC_NEAR(4, 1.5, 2, k.point);
    TEST_ASSERT_EQUAL_INT(CC_OVERLAP, F(cc_detect_static)(&a, &b, &s));
    TEST_ASSERT_EQUAL_MEMORY(&s, &k, sizeof k);
}

/* Concentric: a (1,2) r 1, b (1,2) r 2: normal (+1,0) by contract, depth 3, point
 * a + (1,0) (0 + 1 - 2)/2 = (0.5, 2). Exact. */
static void test_concentric(void)
{
    Circle a = circle(1, 2, 0, 0, 1, 1), b = circle(1, 2, 5, 5, 2, 1);
    Contact k = sentinel_contact();
    TEST_ASSERT_EQUAL_INT(CC_OVERLAP, F(cc_sweep)(&a, &b, 10, &k));
    EXPECT_EXACT(0, k.t);
    EXPECT_EXACT(3, k.depth);
    EXPECT_VEC_EXACT(1, 0, k.normal);
    EXPECT_VEC_EXACT(0.5, 2, k.point);
}

#ifdef TEST_FLOAT
#define FAR_OFFSET 0x1p20 /* X + 4101 is exact in float (24 bits) */
#define COMMON_SPEED 0x1p10
#define SCALE_EXP 120 /* 10 * 2^120 < FLT_MAX, 2 * 2^-120 > FLT_MIN */
#else
#define FAR_OFFSET 0x1p50 /* ~1.1e15; X + 2^32 + 5 exact in double (ulp 2^-2) */
#define COMMON_SPEED 0x1p30
#define SCALE_EXP 1000
#endif

/* The head-on pair moved to (X, -X) with a common velocity W added to both: the relative
 * problem is unchanged, so t = 4 exactly, and the point is a's centre at t plus (1,0):
 * (X + 4 (1 + W) + 1, -X), every sum exact at the chosen X and W. */
static void test_far_from_origin_fast_common_motion(void)
{
    double X = FAR_OFFSET, W = COMMON_SPEED;
    Circle a = circle(X, -X, 1 + W, 0, 1, 1), b = circle(X + 10, -X, W - 1, 0, 1, 1);
    expect_hit(&a, &b, 10, 4, 1, 0, X + 4 * (1 + W) + 1, -X, 0);
}

/* Scaling lengths and speeds by the same power of two leaves t = 4 exact and scales the point:
 * scenes of 2^-1000 and 2^1000 (float: 2^-120, 2^120). */
static void test_tiny_and_huge_scenes(void)
{
    int i;
    for (i = -1; i <= 1; i += 2) {
        double s = ldexp(1.0, i * SCALE_EXP);
        Circle a = circle(0, 0, s, 0, s, 1), b = circle(10 * s, 0, -s, 0, s, 1);
        expect_hit(&a, &b, 10, 4, 1, 0, 5 * s, 0, 0);
    }
}

/* Differences that overflow: a at -0.75 M moving +0.75 M, b at +0.75 M moving -0.75 M
 * (M = largest finite number), radii 1: dp = 1.5 M and dv = -1.5 M are not representable.
 * Contact when 1.5 M (1 - t) = 2, t = 1 - 2 / (1.5 M), which rounds to 1. Normal (1,0). */
static void test_differences_overflow(void)
{
    double m = 0.75 * REAL_MAX;
    Circle a = circle(-m, 0, m, 0, 1, 1), b = circle(m, 0, -m, 0, 1, 1);
    Contact k = sentinel_contact();
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_sweep)(&a, &b, 2, &k));
    EXPECT_NEAR(2, 1, k.t);
    EXPECT_VEC_EXACT(1, 0, k.normal);
    TEST_ASSERT_TRUE(isfinite(k.point.x) && isfinite(k.point.y));
}

/* Different radii and an off-axis approach: a (1,1) r 1 still, b (1 + 12, 1 + 16) r 4 moving
 * (-3,-4) = straight at a: d = 20, R = 5, 20 - 5t = 5, t = 3. b is then at (4,5): normal
 * (0.6, 0.8) from a to b, point (1,1) + (0.6,0.8) = (1.6, 1.8). */
static void test_different_radii(void)
{
    Circle a = circle(1, 1, 0, 0, 1, 1), b = circle(13, 17, -3, -4, 4, 1);
    expect_hit(&a, &b, 10, 3, 0.6, 0.8, 1.6, 1.8, 4);
}

#ifdef TEST_FLOAT
#define GRAZE_DELTA 0x1p-21 /* 2 - delta is representable: ulp(2) = 2^-22 */
#else
#define GRAZE_DELTA 0x1p-50 /* ulp(2) = 2^-51 */
#endif

/* Grazing: b at (-10, 2 - delta) r 1 moving (1,0) past a at (0,0) r 1, closest approach
 * 2 - delta < R = 2 by a few ulps of 2. A hit: |(t - 10, 2 - delta)| = 2 gives
 * t = 10 - sqrt(delta (4 - delta)) (about 10 - 2^-24 in double, 10 - 2^-9.5 in float). The
 * factored discriminant sees it: |dv| R - |dp x dv| = 2 - (2 - delta) = delta exactly, while
 * b^2 - a c = 100 - (100 - 4 delta) loses 4 delta entirely (100's ulp is 2^-46 > 4 delta), and a
 * textbook solver calls this a miss. The closing speed at contact is sqrt(delta (4 - delta)) / 2,
 * so the contract's tolerance is 8 eps (|dp| + |dv| t + R) / closing. */
static void test_grazing_few_ulps_inside(void)
{
    double delta = GRAZE_DELTA, root = sqrt(delta * (4 - delta)), t = 10 - root;
    Circle a = circle(0, 0, 0, 0, 1, 1), b = circle(-10, 2 - delta, 1, 0, 1, 1);
    Contact k = sentinel_contact();
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_sweep)(&a, &b, 100, &k));
    TEST_ASSERT_DOUBLE_WITHIN(8 * EPS * (sqrt(100 + 4.0) + t + 2) / (root / 2), t, k.t);
    /* exactly tangent (delta = 0) is the contract's miss */
    b.pos.y = 2;
    k = sentinel_contact();
    TEST_ASSERT_EQUAL_INT(CC_MISS, F(cc_sweep)(&a, &b, 100, &k));
}

#ifdef TEST_FLOAT
#define HUGE_RADIUS 0x1p100
#define TINY_OFFSET 0x1p-40
#else
#define HUGE_RADIUS 0x1p950
#define TINY_OFFSET 0x1p-110
#endif

/* Overlap of circles of radius S = 2^950 whose centres are T = 2^-110 apart along (0.6, 0.8)
 * (float: 2^100 and 2^-40): the normal is still (0.6, 0.8), a unit vector, and the contact
 * is cc_detect_static's, byte for byte. (A bug found by the extreme-input property: the solver
 * scaled dp to R's size, 2^-1060, subnormal with a dozen bits left, and took the normal from
 * that: |n| = 1 - 2e-6, which cc_respond then rejects.) */
static void test_overlap_normal_tiny_offset_huge_radii(void)
{
    double S = HUGE_RADIUS, T = TINY_OFFSET;
    Circle a = circle(0, 0, 1, 0, S, 1), b = circle(0.6 * T, 0.8 * T, -1, 0, S, 1);
    Contact k = sentinel_contact(), d = sentinel_contact();
    TEST_ASSERT_EQUAL_INT(CC_OVERLAP, F(cc_sweep)(&a, &b, 1, &k));
    EXPECT_VEC_NEAR(4, 0.6, 0.8, k.normal);
    EXPECT_NEAR(4, 2 * S, k.depth);
    TEST_ASSERT_EQUAL_INT(CC_OVERLAP, F(cc_detect_static)(&a, &b, &d));
    TEST_ASSERT_EQUAL_MEMORY(&d, &k, sizeof k);
}

#ifdef TEST_FLOAT
#define SMALLEST_SUBNORMAL 0x1p-149
#else
#define SMALLEST_SUBNORMAL 0x1p-1074
#endif

/* Overlap by less than the smallest subnormal: radii 16128 m and m, centres (16128, 128) m apart
 * (m the smallest subnormal), distance 16128.508 m against R = 16129 m: the solver, scaled up,
 * sees the overlap, but the depth R - d taken at the inputs' scale rounded to 0 (fuzz_pair, seed
 * 4848, in float; the contract says depth > 0 on an overlap). It is now the smallest subnormal,
 * as cc_sweep_segment_rolling's was made before. */
static void test_overlap_below_the_smallest_subnormal_has_depth(void)
{
    double m = SMALLEST_SUBNORMAL;
    Circle a = circle(0, 0, 1, 0, 16128 * m, 1), b = circle(16128 * m, 128 * m, -1, 0, m, 1);
    Contact k = sentinel_contact();
    TEST_ASSERT_EQUAL_INT(CC_OVERLAP, F(cc_sweep)(&a, &b, 1, &k));
    TEST_ASSERT_TRUE(k.depth > 0 && k.depth <= m);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_head_on);
    RUN_TEST(test_moving_vs_still);
    RUN_TEST(test_both_moving);
    RUN_TEST(test_glancing);
    RUN_TEST(test_glancing_swapped);
    RUN_TEST(test_touching_approaching);
    RUN_TEST(test_touching_leaving_or_tangent);
    RUN_TEST(test_tangent_pass);
    RUN_TEST(test_passes_too_far);
    RUN_TEST(test_parallel_rest_apart);
    RUN_TEST(test_t_max_cut_off);
    RUN_TEST(test_overlap_at_start);
    RUN_TEST(test_concentric);
    RUN_TEST(test_far_from_origin_fast_common_motion);
    RUN_TEST(test_tiny_and_huge_scenes);
    RUN_TEST(test_differences_overflow);
    RUN_TEST(test_different_radii);
    RUN_TEST(test_grazing_few_ulps_inside);
    RUN_TEST(test_overlap_normal_tiny_offset_huge_radii);
    RUN_TEST(test_overlap_below_the_smallest_subnormal_has_depth);
    return UNITY_END();
}
