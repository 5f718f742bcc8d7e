/* cc_closest_point_on_segment (and the float twin with -DTEST_FLOAT): the interior projection,
 * both end points, a degenerate segment, extreme lengths, and the no-error-channel rules
 * (NaN input returns p itself, NULL segment returns (0,0)). */
#include "core_precision.h"

void setUp(void) {}
void tearDown(void) {}

static Vec closest(double px, double py, const Segment *s) { return F(cc_closest_point_on_segment)(vec(px, py), s); }

/* S = (0,0)-(8,6), direction (0.8,0.6), length 10. p = (1,7): along = (1,7).(8,6)/100 = 50/100
 * = 1/2, foot (4,3) (p - foot = (-3,4), perpendicular). p = (8.5, 6) projects to lambda 1.05 >
 * 1: end b (8,6); p = (-1,-1) to lambda -0.14 < 0: end a (0,0). */
static void test_interior_and_beyond_ends(void)
{
    Segment s = segment(0, 0, 8, 6);
    Vec q = closest(1, 7, &s);
    EXPECT_VEC_NEAR(4, 4, 3, q);
    q = closest(8.5, 6, &s);
    EXPECT_VEC_EXACT(8, 6, q);
    q = closest(-1, -1, &s);
    EXPECT_VEC_EXACT(0, 0, q);
}

/* The end points themselves map to themselves exactly, as do points on the segment with an
 * exact parameter: (2, 1.5) = a + (1/4)(b - a). */
static void test_points_on_segment(void)
{
    Segment s = segment(0, 0, 8, 6);
    Vec q = closest(0, 0, &s);
    EXPECT_VEC_EXACT(0, 0, q);
    q = closest(8, 6, &s);
    EXPECT_VEC_EXACT(8, 6, q);
    q = closest(2, 1.5, &s);
    EXPECT_VEC_NEAR(2, 2, 1.5, q);
}

/* Perpendicular exactly at an end point: p = (-3,4) gives lambda 0, the end a exactly. */
static void test_perpendicular_at_end(void)
{
    Segment s = segment(0, 0, 8, 6);
    Vec q = closest(-3, 4, &s);
    EXPECT_VEC_EXACT(0, 0, q);
}

/* A degenerate segment a == b = (2,3) returns that point for any p. */
static void test_degenerate(void)
{
    Segment s = segment(2, 3, 2, 3);
    Vec q = closest(10, -7, &s);
    EXPECT_VEC_EXACT(2, 3, q);
}

#ifdef TEST_FLOAT
#define HUGE_EXP 100
#else
#define HUGE_EXP 1000
#endif

/* Extreme lengths: the axis-aligned segment (0,0)-(s,0) with p = (s/2, s): foot (s/2, 0) for
 * s = 2^1000 and 2^-1000 (float 2^100, 2^-100), where |b - a|^2 would overflow or underflow. */
static void test_extreme_lengths(void)
{
    int i;
    for (i = -1; i <= 1; i += 2) {
        double sc = ldexp(1.0, i * HUGE_EXP);
        Segment s = segment(0, 0, sc, 0);
        Vec q = closest(0.5 * sc, sc, &s);
        EXPECT_VEC_EXACT(0.5 * sc, 0, q);
    }
}

/* No error channel: NaN in p or in the segment returns p bit for bit; a NULL segment gives
 * (0,0). */
static void test_nan_and_null(void)
{
    Segment s = segment(0, 0, 8, 6), bad = segment(0, NAN, 8, 6);
    Vec p = vec(NAN, 1), p2 = vec(3, 4), q = F(cc_closest_point_on_segment)(p, &s);
    TEST_ASSERT_EQUAL_MEMORY(&p, &q, sizeof q);
    q = F(cc_closest_point_on_segment)(p2, &bad);
    TEST_ASSERT_EQUAL_MEMORY(&p2, &q, sizeof q);
    q = F(cc_closest_point_on_segment)(p2, NULL);
    EXPECT_VEC_EXACT(0, 0, q);
}

/* Random points: the answer lies on the segment and (p - q) is perpendicular to it unless q
 * is an end point, where p projects beyond that end. */
static void test_random_properties(void)
{
    uint64_t seed = 777;
    int i;
    for (i = 0; i < 100000; i++) {
        Segment s = segment(rng_range(&seed, -10, 10), rng_range(&seed, -10, 10), rng_range(&seed, -10, 10),
                            rng_range(&seed, -10, 10));
        Vec p = vec(rng_range(&seed, -20, 20), rng_range(&seed, -20, 20)), q = F(cc_closest_point_on_segment)(p, &s);
        double ux = (double)s.b.x - s.a.x, uy = (double)s.b.y - s.a.y, len = hypot(ux, uy);
        double wx = (double)q.x - s.a.x, wy = (double)q.y - s.a.y;
        double along = (wx * ux + wy * uy) / len, off = (wx * uy - wy * ux) / len; /* q in segment coords */
        double pa = (((double)p.x - s.a.x) * ux + ((double)p.y - s.a.y) * uy) / len;
        double tol = 64 * EPS * 30;
        TEST_ASSERT_DOUBLE_WITHIN(tol, 0, off);
        TEST_ASSERT_TRUE(along >= -tol && along <= len + tol);
        if (pa <= 0)
            TEST_ASSERT_DOUBLE_WITHIN(tol, 0, along);
        else if (pa >= len)
            TEST_ASSERT_DOUBLE_WITHIN(tol, len, along);
        else
            TEST_ASSERT_DOUBLE_WITHIN(tol, pa, along);
    }
}

/* A segment 4 / EPS long, (0, -L)-(0, 0): the point (0.5, -3) by its end b has the foot (0, -3),
 * exactly, in either order of the ends (the projection is made from the nearer end, where the
 * parameter 3 / L is exact; from the far end 1 - 3 / L rounds by half an ulp of 1, which is 1 or
 * more along this segment). */
static void test_by_the_end_of_a_long_segment(void)
{
    double L = 4.0 / EPS;
    Segment ab = segment(0, -L, 0, 0), ba = segment(0, 0, 0, -L);
    Vec q = closest(0.5, -3, &ab);
    EXPECT_VEC_EXACT(0, -3, q);
    q = closest(0.5, -3, &ba);
    EXPECT_VEC_EXACT(0, -3, q);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_interior_and_beyond_ends);
    RUN_TEST(test_points_on_segment);
    RUN_TEST(test_perpendicular_at_end);
    RUN_TEST(test_degenerate);
    RUN_TEST(test_extreme_lengths);
    RUN_TEST(test_nan_and_null);
    RUN_TEST(test_random_properties);
    RUN_TEST(test_by_the_end_of_a_long_segment);
    return UNITY_END();
}
