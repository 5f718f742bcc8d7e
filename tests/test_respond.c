/* cc_respond and cc_respond_segment (and float twins with -DTEST_FLOAT): hand-derived
 * impulses. With n from a to b and vn = (vb - va).n < 0, the contract's impulse gives
 *     va' = va + (1 + e) vn mb/(ma + mb) n,   vb' = vb - (1 + e) vn ma/(ma + mb) n,
 * each body scaled by the OTHER body's mass share (the tutorial formula swaps them). */
#include "core_precision.h"

void setUp(void) {}
void tearDown(void) {}

static Contact contact_n(double nx, double ny)
{
    Contact k;
    memset(&k, 0, sizeof k);
    k.normal = vec(nx, ny);
    return k;
}

/* Equal masses head-on, va = (1,0), vb = (-1,0), n = (1,0): vn = -2. e = 1 swaps the
 * velocities: va' = 1 + 2 (-2)/2 = -1, vb' = -1 + 2 = 1. e = 0: both stop (va' = 1 - 1 = 0). */
static void test_equal_masses(void)
{
    Contact k = contact_n(1, 0);
    Circle a = circle(0, 0, 1, 0, 1, 2), b = circle(2, 0, -1, 0, 1, 2);
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_respond)(&a, &b, &k, 1));
    EXPECT_VEC_EXACT(-1, 0, a.vel);
    EXPECT_VEC_EXACT(1, 0, b.vel);
    a.vel = vec(1, 0);
    b.vel = vec(-1, 0);
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_respond)(&a, &b, &k, 0));
    EXPECT_VEC_EXACT(0, 0, a.vel);
    EXPECT_VEC_EXACT(0, 0, b.vel);
}

/* Masses 1 and 3, va = (2,0) onto a still b, n = (1,0): vn = -2.
 * e = 1: va' = 2 + 2 (-2) 3/4 = -1, vb' = 0 - 2 (-2) 1/4 = 1 (the textbook 1-D elastic result
 * (m1 - m2)/(m1 + m2) 2 = -1 and 2 m1/(m1 + m2) 2 = 1); momentum 1 (-1) + 3 (1) = 2 as before;
 * energy (1 + 3)/2 = 2 as before. With the masses swapped in the formula, va' would be 1 and
 * vb' -3: this case catches that.
 * e = 1/2: va' = 2 + 1.5 (-2) 3/4 = -0.25, vb' = 1.5 (2) 1/4 = 0.75: relative normal velocity
 * 1 = -1/2 (-2). All exact. */
static void test_unequal_masses(void)
{
    Contact k = contact_n(1, 0);
    Circle a = circle(0, 0, 2, 0, 1, 1), b = circle(2, 0, 0, 0, 1, 3);
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_respond)(&a, &b, &k, 1));
    EXPECT_VEC_EXACT(-1, 0, a.vel);
    EXPECT_VEC_EXACT(1, 0, b.vel);
    a.vel = vec(2, 0);
    b.vel = vec(0, 0);
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_respond)(&a, &b, &k, 0.5));
    EXPECT_VEC_EXACT(-0.25, 0, a.vel);
    EXPECT_VEC_EXACT(0.75, 0, b.vel);
}

/* Oblique, equal masses, e = 1, n = (0.6,0.8), b still, va = (-1,7) = 5 n + 5 (-0.8,0.6):
 * normal part 5, tangential part (-4,3). vn = -5, so va' = va - 5 n = (-4,3) (the tangential
 * part, unchanged) and vb' = 5 n = (3,4). */
static void test_oblique_keeps_tangential(void)
{
    Contact k = contact_n(0.6, 0.8);
    Circle a = circle(0, 0, -1, 7, 1, 1), b = circle(1.2, 1.6, 0, 0, 1, 1);
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_respond)(&a, &b, &k, 1));
    EXPECT_VEC_NEAR(16, -4, 3, a.vel);
    EXPECT_VEC_NEAR(16, 3, 4, b.vel);
}

/* An immovable b (mass +INFINITY): a bounces as off a wall, va = (2,1), n = (1,0), e = 1:
 * va' = (2,1) + 2 (-2) 1 (1,0) = (-2,1); b untouched bit for bit. Immovable a: b bounces,
 * vb = (-3,0) -> (3,0), a untouched. */
static void test_immovable(void)
{
    Contact k = contact_n(1, 0);
    Circle a = circle(0, 0, 2, 1, 1, 1), b = circle(2, 0, 0, 0, 1, INFINITY), b0 = b;
    Circle c = circle(0, 0, 0, 0, 1, INFINITY), d = circle(2, 0, -3, 0, 1, 1), c0 = c;
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_respond)(&a, &b, &k, 1));
    EXPECT_VEC_EXACT(-2, 1, a.vel);
    TEST_ASSERT_EQUAL_MEMORY(&b0, &b, sizeof b);
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_respond)(&c, &d, &k, 1));
    EXPECT_VEC_EXACT(3, 0, d.vel);
    TEST_ASSERT_EQUAL_MEMORY(&c0, &c, sizeof c);
}

/* Not approaching along n: separating (vn = 2 > 0) or sliding (vn = 0): CC_MISS, no change. */
static void test_not_approaching(void)
{
    Contact k = contact_n(1, 0);
    Circle a = circle(0, 0, -1, 0, 1, 1), b = circle(2, 0, 1, 0, 1, 1), a0 = a, b0 = b;
    Circle c = circle(0, 0, 0, 1, 1, 1), d = circle(2, 0, 0, -1, 1, 1), c0 = c, d0 = d;
    TEST_ASSERT_EQUAL_INT(CC_MISS, F(cc_respond)(&a, &b, &k, 1));
    TEST_ASSERT_EQUAL_MEMORY(&a0, &a, sizeof a);
    TEST_ASSERT_EQUAL_MEMORY(&b0, &b, sizeof b);
    TEST_ASSERT_EQUAL_INT(CC_MISS, F(cc_respond)(&c, &d, &k, 1));
    TEST_ASSERT_EQUAL_MEMORY(&c0, &c, sizeof c);
    TEST_ASSERT_EQUAL_MEMORY(&d0, &d, sizeof d);
}

/* Extreme mass ratio 2^60 : 1: the light a (mass 1) bounces off the heavy b like a wall,
 * va = (1,0) -> 1 + 2 (-1) (1/(1 + 2^-60)) = -1 up to rounding; vb' = 2 * 2^-60 (tiny).
 * Momentum before 1, after -1 + 2^60 * 2 * 2^-60 = 1. */
static void test_extreme_mass_ratio(void)
{
    Contact k = contact_n(1, 0);
    Circle a = circle(0, 0, 1, 0, 1, 1), b = circle(2, 0, 0, 0, 1, 0x1p60);
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_respond)(&a, &b, &k, 1));
    EXPECT_NEAR(2, -1, a.vel.x);
    TEST_ASSERT_DOUBLE_WITHIN(4 * EPS * 0x1p-59, 0x1p-59, b.vel.x);
    EXPECT_NEAR(4, 1, (double)a.mass * a.vel.x + (double)b.mass * b.vel.x);
}

/* Wall below, n = (0,-1) (circle towards wall), v = (1,-2): v.n = 2 > 0, approaching.
 * v' = v - (1 + e)(v.n) n: e = 1 gives (1,-2) + (0,4) = (1,2); e = 0 gives (1,0); e = 1/2
 * gives (1,1). Moving away (1,2): CC_MISS, unchanged. */
static void test_respond_segment(void)
{
    Contact k = contact_n(0, -1);
    static const double e[3] = {1, 0, 0.5}, vy[3] = {2, 0, 1};
    int i;
    for (i = 0; i < 3; i++) {
        Circle c = circle(0, 1, 1, -2, 1, 1);
        TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_respond_segment)(&c, &k, (Real)e[i]));
        EXPECT_VEC_EXACT(1, vy[i], c.vel);
    }
    {
        Circle c = circle(0, 1, 1, 2, 1, 1), c0 = c;
        TEST_ASSERT_EQUAL_INT(CC_MISS, F(cc_respond_segment)(&c, &k, 1));
        TEST_ASSERT_EQUAL_MEMORY(&c0, &c, sizeof c);
    }
}

/* A wall's mass is not used: masses 1 and 1e6 bounce the same. */
static void test_respond_segment_mass_unused(void)
{
    Contact k = contact_n(0.6, 0.8);
    Circle c = circle(0, 0, 3, 4, 1, 1), d = circle(0, 0, 3, 4, 1, 1e6);
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_respond_segment)(&c, &k, 1));
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_respond_segment)(&d, &k, 1));
    TEST_ASSERT_EQUAL_MEMORY(&c.vel, &d.vel, sizeof c.vel);
    EXPECT_VEC_NEAR(16, -3, -4, c.vel); /* v = 5 n head-on: reverses */
}

/* Sweep, advance, respond: the head-on pair of test_sweep (t = 4), equal masses, e = 1:
 * after the impulse the circles leave each other, and a second sweep from the contact
 * finds nothing. */
static void test_sweep_then_respond(void)
{
    Circle a = circle(0, 0, 1, 0, 1, 1), b = circle(10, 0, -1, 0, 1, 1);
    Contact k, k2 = sentinel_contact(), before = k2;
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_sweep)(&a, &b, 10, &k));
    a.pos = vec((double)a.pos.x + (double)a.vel.x * k.t, (double)a.pos.y + (double)a.vel.y * k.t);
    b.pos = vec((double)b.pos.x + (double)b.vel.x * k.t, (double)b.pos.y + (double)b.vel.y * k.t);
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_respond)(&a, &b, &k, 1));
    EXPECT_VEC_EXACT(-1, 0, a.vel);
    EXPECT_VEC_EXACT(1, 0, b.vel);
    TEST_ASSERT_EQUAL_INT(CC_MISS, F(cc_sweep)(&a, &b, 10, &k2));
    TEST_ASSERT_EQUAL_MEMORY(&before, &k2, sizeof k2);
}

/* Masses near the largest finite number (the world fuzzer's D17 found the world's cluster
 * solver passing through the impulse m (1 + e) v_n, which overflows there): the pair response
 * goes through mass shares, never the impulse, so the velocities are finite and right.
 * REAL_MAX against an immovable b at speed 1: va' = -1; two masses REAL_MAX head on at e = 1
 * swap their velocities (m_a + m_b would overflow); REAL_MAX at 1 against REAL_MAX / 4 at -1
 * (vn = -2): 1 - 4 (1/5) = 0.2 and -1 + 4 (4/5) = 2.2; a subnormal mass against REAL_MAX
 * bounces as off a wall. */
static void test_masses_near_the_largest_number(void)
{
    Contact k = contact_n(1, 0);
    Circle a = circle(0, 0, 1, 0, 1, REAL_MAX), b = circle(2, 0, 0, 0, 1, INFINITY);
    Circle c = circle(0, 0, 1, 0, 1, REAL_MAX), d = circle(2, 0, -1, 0, 1, REAL_MAX);
    Circle p = circle(0, 0, 1, 0, 1, REAL_MAX), q = circle(2, 0, -1, 0, 1, 0.25 * REAL_MAX);
    Circle x = circle(0, 0, 1, 0, 1, 1e-40), y = circle(2, 0, 0, 0, 1, REAL_MAX);
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_respond)(&a, &b, &k, 1));
    EXPECT_VEC_NEAR(2, -1, 0, a.vel);
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_respond)(&c, &d, &k, 1));
    EXPECT_VEC_NEAR(2, -1, 0, c.vel);
    EXPECT_VEC_NEAR(2, 1, 0, d.vel);
    /* vn = -2, e = 1: p' = 1 + 2 (-2) (1/5) = 0.2, q' = -1 - 2 (-2) (4/5) = 2.2 */
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_respond)(&p, &q, &k, 1));
    EXPECT_VEC_NEAR(4, 0.2, 0, p.vel);
    EXPECT_VEC_NEAR(4, 2.2, 0, q.vel);
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_respond)(&x, &y, &k, 1));
    EXPECT_VEC_NEAR(2, -1, 0, x.vel);
    TEST_ASSERT_TRUE(isfinite((double)y.vel.x) && y.vel.x >= 0 && y.vel.y == 0);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_equal_masses);
    RUN_TEST(test_unequal_masses);
    RUN_TEST(test_oblique_keeps_tangential);
    RUN_TEST(test_immovable);
    RUN_TEST(test_not_approaching);
    RUN_TEST(test_extreme_mass_ratio);
    RUN_TEST(test_masses_near_the_largest_number);
    RUN_TEST(test_respond_segment);
    RUN_TEST(test_respond_segment_mass_unused);
    RUN_TEST(test_sweep_then_respond);
    return UNITY_END();
}
