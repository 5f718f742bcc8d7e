/* cc_detect_static and cc_separate (and their float twins with -DTEST_FLOAT): hand-derived
 * static overlap contacts and push-apart shares. Most cases use the 3-4-5 pair
 * a = (0,0) r 3, b = (3,4) r 3: d = 5 < R = 6, depth 1, normal n = (0.6,0.8). */
#include "core_precision.h"

void setUp(void) {}
void tearDown(void) {}

static double dist(const Circle *a, const Circle *b)
{
    return hypot((double)b->pos.x - (double)a->pos.x, (double)b->pos.y - (double)a->pos.y);
}

/* Overlap 3-4-5: depth 1, normal (0.6,0.8), point midway between the deepest points
 * pa + 3n = (1.8,2.4) and pb - 3n = (1.2,1.6): (1.5, 2). t = 0. */
static void test_detect_overlap(void)
{
    Circle a = circle(0, 0, 7, 7, 3, 1), b = circle(3, 4, -7, 1, 3, 2);
    Contact k = sentinel_contact();
    TEST_ASSERT_EQUAL_INT(CC_OVERLAP, F(cc_detect_static)(&a, &b, &k));
    EXPECT_EXACT(0, k.t);
    EXPECT_NEAR(4, 1, k.depth);
    EXPECT_VEC_NEAR(4, 0.6, 0.8, k.normal);
    EXPECT_VEC_NEAR(4, 1.5, 2, k.point);
}

/* Different radii: a (0,0) r 1, b (0,3) r 4: depth 5 - 3 = 2, normal (0,1), deepest points
 * (0,1) and (0,-1), midway (0,0). Exact. */
static void test_detect_different_radii(void)
{
    Circle a = circle(0, 0, 0, 0, 1, 1), b = circle(0, 3, 0, 0, 4, 1);
    Contact k = sentinel_contact();
    TEST_ASSERT_EQUAL_INT(CC_OVERLAP, F(cc_detect_static)(&a, &b, &k));
    EXPECT_EXACT(2, k.depth);
    EXPECT_VEC_EXACT(0, 1, k.normal);
    EXPECT_VEC_EXACT(0, 0, k.point);
}

/* Touching exactly (d = R = 6 at (6,0)) is not overlapping; apart neither; out untouched. */
static void test_detect_touching_and_apart(void)
{
    Circle a = circle(0, 0, 0, 0, 3, 1), touch = circle(6, 0, 0, 0, 3, 1), apart = circle(3, 8, 0, 0, 3, 1);
    Contact k = sentinel_contact(), before = k;
    TEST_ASSERT_EQUAL_INT(CC_MISS, F(cc_detect_static)(&a, &touch, &k));
    TEST_ASSERT_EQUAL_INT(CC_MISS, F(cc_detect_static)(&a, &apart, &k));
    TEST_ASSERT_EQUAL_MEMORY(&before, &k, sizeof k);
}

/* Concentric a (1,2) r 1, b (1,2) r 2: normal (+1,0), depth 3, point a + (0 + 1 - 2)/2 (1,0) =
 * (0.5, 2). out may be NULL: the answer is still CC_OVERLAP. */
static void test_detect_concentric_and_null_out(void)
{
    Circle a = circle(1, 2, 0, 0, 1, 1), b = circle(1, 2, 0, 0, 2, 1);
    Contact k = sentinel_contact();
    TEST_ASSERT_EQUAL_INT(CC_OVERLAP, F(cc_detect_static)(&a, &b, &k));
    EXPECT_EXACT(3, k.depth);
    EXPECT_VEC_EXACT(1, 0, k.normal);
    EXPECT_VEC_EXACT(0.5, 2, k.point);
    TEST_ASSERT_EQUAL_INT(CC_OVERLAP, F(cc_detect_static)(&a, &b, NULL));
}

#ifdef TEST_FLOAT
#define FAR_OFFSET 0x1p20
#else
#define FAR_OFFSET 0x1p50
#endif

/* The 3-4-5 pair moved to (X, X): the difference (3,4) is exact, so depth 1 and normal
 * (0.6,0.8) as at the origin; the point (X + 1.5, X + 2) up to the rounding at X. */
static void test_detect_far_from_origin(void)
{
    double X = FAR_OFFSET;
    Circle a = circle(X, X, 0, 0, 3, 1), b = circle(X + 3, X + 4, 0, 0, 3, 1);
    Contact k = sentinel_contact();
    TEST_ASSERT_EQUAL_INT(CC_OVERLAP, F(cc_detect_static)(&a, &b, &k));
    EXPECT_NEAR(4, 1, k.depth);
    EXPECT_VEC_NEAR(4, 0.6, 0.8, k.normal);
    EXPECT_VEC_NEAR(1, X + 1.5, X + 2, k.point);
}

/* Push the 3-4-5 pair apart by depth 1 along n, shares inverse to mass: a takes
 * mb / (ma + mb), b takes ma / (ma + mb). Equal masses: 1/2 each, a to -0.5 n = (-0.3,-0.4),
 * b to (3,4) + 0.5 n = (3.3,4.4). Masses 1 and 3: a takes 3/4, (-0.45,-0.6); b takes 1/4,
 * (3.15,4.2). Afterwards the distance is R = 6 and the velocities are untouched. */
static void test_separate_shares(void)
{
    static const double mb[2] = {1, 3};
    static const double ax[2] = {-0.3, -0.45}, ay[2] = {-0.4, -0.6}, bx[2] = {3.3, 3.15}, by[2] = {4.4, 4.2};
    int i;
    for (i = 0; i < 2; i++) {
        Circle a = circle(0, 0, 1, 2, 3, 1), b = circle(3, 4, 3, 4, 3, mb[i]);
        TEST_ASSERT_EQUAL_INT(CC_OVERLAP, F(cc_separate)(&a, &b));
        EXPECT_VEC_NEAR(8, ax[i], ay[i], a.pos);
        EXPECT_VEC_NEAR(8, bx[i], by[i], b.pos);
        EXPECT_NEAR(8, 6, dist(&a, &b));
        EXPECT_VEC_EXACT(1, 2, a.vel);
        EXPECT_VEC_EXACT(3, 4, b.vel);
    }
}

/* An immovable circle (mass +INFINITY) stays put bit for bit; the other moves the whole depth:
 * a to -n = (-0.6,-0.8) when b is immovable, b to (3,4) + n = (3.6,4.8) when a is. */
static void test_separate_immovable(void)
{
    Circle a = circle(0, 0, 0, 0, 3, 1), b = circle(3, 4, 0, 0, 3, INFINITY), b0 = b;
    Circle c = circle(0, 0, 0, 0, 3, INFINITY), d = circle(3, 4, 0, 0, 3, 5), c0 = c;
    TEST_ASSERT_EQUAL_INT(CC_OVERLAP, F(cc_separate)(&a, &b));
    EXPECT_VEC_NEAR(8, -0.6, -0.8, a.pos);
    TEST_ASSERT_EQUAL_MEMORY(&b0, &b, sizeof b);
    TEST_ASSERT_EQUAL_INT(CC_OVERLAP, F(cc_separate)(&c, &d));
    EXPECT_VEC_NEAR(8, 3.6, 4.8, d.pos);
    TEST_ASSERT_EQUAL_MEMORY(&c0, &c, sizeof c);
}

/* Concentric equal circles r 1 at (1,2): depth 2 along +x, 1 each: a to (0,2), b to (2,2). */
static void test_separate_concentric(void)
{
    Circle a = circle(1, 2, 0, 0, 1, 1), b = circle(1, 2, 0, 0, 1, 1);
    TEST_ASSERT_EQUAL_INT(CC_OVERLAP, F(cc_separate)(&a, &b));
    EXPECT_VEC_EXACT(0, 2, a.pos);
    EXPECT_VEC_EXACT(2, 2, b.pos);
}

/* Not overlapping (touching, or apart): CC_MISS and nothing changes. */
static void test_separate_no_overlap(void)
{
    Circle a = circle(0, 0, 1, 1, 3, 1), b = circle(6, 0, 2, 2, 3, 1), a0 = a, b0 = b;
    TEST_ASSERT_EQUAL_INT(CC_MISS, F(cc_separate)(&a, &b));
    TEST_ASSERT_EQUAL_MEMORY(&a0, &a, sizeof a);
    TEST_ASSERT_EQUAL_MEMORY(&b0, &b, sizeof b);
    b.pos.x = 7;
    b0 = b;
    TEST_ASSERT_EQUAL_INT(CC_MISS, F(cc_separate)(&a, &b));
    TEST_ASSERT_EQUAL_MEMORY(&a0, &a, sizeof a);
    TEST_ASSERT_EQUAL_MEMORY(&b0, &b, sizeof b);
}

/* Random overlapping pairs: after cc_separate the distance is R up to rounding, and the
 * mass-weighted centre (ma pa + mb pb) / (ma + mb) has not moved. */
static void test_separate_random(void)
{
    uint64_t seed = 12345;
    int i;
    for (i = 0; i < 20000; i++) {
        double ra = rng_range(&seed, 0.1, 5), rb = rng_range(&seed, 0.1, 5);
        double ang = rng_range(&seed, 0, 6.283185307179586), d = rng_range(&seed, 0.01, 0.99) * (ra + rb);
        double ma = rng_range(&seed, 0.1, 10), mb = rng_range(&seed, 0.1, 10);
        Circle a = circle(rng_range(&seed, -10, 10), rng_range(&seed, -10, 10), 0, 0, ra, ma), b = a;
        double cx, cy, R;
        b.pos = vec((double)a.pos.x + d * cos(ang), (double)a.pos.y + d * sin(ang));
        b.radius = (Real)rb;
        b.mass = (Real)mb;
        R = (double)a.radius + (double)b.radius;
        if (!(dist(&a, &b) < R))
            continue;
        cx = ((double)a.mass * a.pos.x + (double)b.mass * b.pos.x) / ((double)a.mass + (double)b.mass);
        cy = ((double)a.mass * a.pos.y + (double)b.mass * b.pos.y) / ((double)a.mass + (double)b.mass);
        TEST_ASSERT_EQUAL_INT(CC_OVERLAP, F(cc_separate)(&a, &b));
        TEST_ASSERT_DOUBLE_WITHIN(64 * EPS * (R + 20), R, dist(&a, &b));
        TEST_ASSERT_DOUBLE_WITHIN(64 * EPS * (R + 20),
                                  cx, ((double)a.mass * a.pos.x + (double)b.mass * b.pos.x) / ((double)a.mass + (double)b.mass));
        TEST_ASSERT_DOUBLE_WITHIN(64 * EPS * (R + 20),
                                  cy, ((double)a.mass * a.pos.y + (double)b.mass * b.pos.y) / ((double)a.mass + (double)b.mass));
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_detect_overlap);
    RUN_TEST(test_detect_different_radii);
    RUN_TEST(test_detect_touching_and_apart);
    RUN_TEST(test_detect_concentric_and_null_out);
    RUN_TEST(test_detect_far_from_origin);
    RUN_TEST(test_separate_shares);
    RUN_TEST(test_separate_immovable);
    RUN_TEST(test_separate_concentric);
    RUN_TEST(test_separate_no_overlap);
    RUN_TEST(test_separate_random);
    return UNITY_END();
}
