/* Rolling to rest (1.1): cc_sweep_rolling's argument checks on ordinary pairs. Most pairs (both
 * circles moving at ordinary speeds and decelerating, or one of them exactly at rest) take a
 * path that checks the arguments through the tests it makes anyway (src/rolling.inc,
 * cc_sweep_rolling) instead of cc__roll_pair_checked's full checks. Each argument of such a pair
 * is made invalid in turn, with every kind of bad value: the answer must be CC_ERR_INVALID, with
 * the output and the inputs untouched, as for any other pair. Built twice (double and, with
 * -DTEST_FLOAT, the float twin), as the core suites. */
#include "core_precision.h"

#include <stdio.h>

void setUp(void) {}
void tearDown(void) {}

/* the three ordinary shapes: both rolling (towards each other: a hit), b at rest, a at rest */
static void pair_of_shape(int shape, Circle *a, Circle *b)
{
    *a = circle(0, 0, shape == 2 ? 0 : 1, shape == 2 ? 0 : 0.5, 0.5, 1);
    *b = circle(3, 0.25, shape == 1 ? 0 : -1, 0, 0.4, 2);
}

static int call(const Circle *a, double da, const Circle *b, double db, double t_max, Contact *k)
{
    return F(cc_sweep_rolling)(a, (Real)da, b, (Real)db, (Real)t_max, k);
}

/* the pair with one argument changed: CC_ERR_INVALID, nothing written, nothing changed */
static void expect_refused(const Circle *a, double da, const Circle *b, double db, double t_max, const char *what)
{
    Contact k = sentinel_contact(), before = k;
    Circle a0 = *a, b0 = *b;
    char msg[96];
    snprintf(msg, sizeof msg, "%s (%s)", what, PREC_NAME);
    TEST_ASSERT_EQUAL_INT_MESSAGE(CC_ERR_INVALID, call(a, da, b, db, t_max, &k), msg);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&before, &k, sizeof k, msg);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&a0, a, sizeof a0, msg);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&b0, b, sizeof b0, msg);
}

static Real *field(Circle *c, int i)
{
    switch (i) {
    case 0: return &c->pos.x;
    case 1: return &c->pos.y;
    case 2: return &c->vel.x;
    case 3: return &c->vel.y;
    case 4: return &c->radius;
    default: return &c->mass;
    }
}

static void test_each_bad_argument_of_an_ordinary_pair(void)
{
    static const char *names[] = {"pos.x", "pos.y", "vel.x", "vel.y", "radius", "mass"};
    const double nan_ = (double)NAN, inf = (double)INFINITY;
    const double any_bad[] = {nan_, inf, -inf};
    const double sign_bad[] = {0.0, -1.0, -0.0}; /* radius and mass must be > 0 */
    const double decel_bad[] = {-1.0, nan_, inf, -inf, -0x1p-149};
    int shape, which, i, j;
    for (shape = 0; shape < 3; shape++) {
        Circle a, b;
        Contact k = sentinel_contact();
        char what[96];
        int r;
        pair_of_shape(shape, &a, &b);
        r = call(&a, 0.3, &b, 0.2, 10, &k);
        TEST_ASSERT_TRUE_MESSAGE(r == CC_HIT || r == CC_MISS, "the valid pair is answered");
        if (shape == 0)
            TEST_ASSERT_EQUAL_INT_MESSAGE(CC_HIT, r, "the rolling pair meets");
        for (which = 0; which < 2; which++) {
            for (i = 0; i < 6; i++) {
                for (j = 0; j < 3 + (i >= 4 ? 3 : 0); j++) {
                    Circle a1 = a, b1 = b;
                    Real *x = field(which ? &b1 : &a1, i);
                    *x = (Real)(j < 3 ? any_bad[j] : sign_bad[j - 3]);
                    if (i == 5 && j == 1)
                        continue; /* an infinite mass is valid (immovable) */
                    snprintf(what, sizeof what, "shape %d, %c.%s = %g", shape, which ? 'b' : 'a', names[i], (double)*x);
                    expect_refused(&a1, 0.3, &b1, 0.2, 10, what);
                }
            }
            for (j = 0; j < (int)(sizeof decel_bad / sizeof decel_bad[0]); j++) {
                snprintf(what, sizeof what, "shape %d, decel_%c = %g", shape, which ? 'b' : 'a', decel_bad[j]);
                expect_refused(&a, which ? 0.3 : decel_bad[j], &b, which ? decel_bad[j] : 0.2, 10, what);
            }
        }
        snprintf(what, sizeof what, "shape %d, t_max = -1", shape);
        expect_refused(&a, 0.3, &b, 0.2, -1, what);
        snprintf(what, sizeof what, "shape %d, t_max = NaN", shape);
        expect_refused(&a, 0.3, &b, 0.2, nan_, what);
        {   /* and what is valid stays valid: an immovable circle, an unbounded t_max */
            Circle a1 = a;
            a1.mass = (Real)inf;
            k = sentinel_contact();
            r = call(&a1, 0.3, &b, 0.2, inf, &k);
            TEST_ASSERT_TRUE_MESSAGE(r == CC_HIT || r == CC_MISS, "infinite mass and t_max are valid");
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_each_bad_argument_of_an_ordinary_pair);
    return UNITY_END();
}
