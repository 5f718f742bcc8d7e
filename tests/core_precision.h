/* Binds the names the core tests use to one precision: double by default, float when the test
 * is compiled with -DTEST_FLOAT. Each suite is written once against these names and built twice
 * (tests/core.cmake), so cc_* and cc_*f meet the same specification, with tolerances scaled to
 * the precision's epsilon. */
#ifndef CORE_PRECISION_H
#define CORE_PRECISION_H

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "circlecollide.h"
#include "unity.h"

#ifdef TEST_FLOAT
typedef float Real;
typedef cc_vec2f Vec;
typedef cc_circlef Circle;
typedef cc_segmentf Segment;
typedef cc_contactf Contact;
#define EPS ((double)FLT_EPSILON)
#define PREC_NAME "float"
#define F(name) name##f /* F(cc_sweep) is cc_sweepf */
#define REAL_MAX ((double)FLT_MAX)
#else
typedef double Real;
typedef cc_vec2 Vec;
typedef cc_circle Circle;
typedef cc_segment Segment;
typedef cc_contact Contact;
#define EPS DBL_EPSILON
#define PREC_NAME "double"
#define F(name) name
#define REAL_MAX DBL_MAX
#endif

static inline Vec vec(double x, double y)
{
    Vec v;
    v.x = (Real)x;
    v.y = (Real)y;
    return v;
}

static inline Circle circle(double px, double py, double vx, double vy, double radius, double mass)
{
    Circle c;
    memset(&c, 0, sizeof c);
    c.pos = vec(px, py);
    c.vel = vec(vx, vy);
    c.radius = (Real)radius;
    c.mass = (Real)mass;
    return c;
}

static inline Segment segment(double ax, double ay, double bx, double by)
{
    Segment s;
    memset(&s, 0, sizeof s);
    s.a = vec(ax, ay);
    s.b = vec(bx, by);
    return s;
}

/* A contact full of a recognisable byte pattern: after CC_MISS or an error it must still hold it. */
static inline Contact sentinel_contact(void)
{
    Contact k;
    memset(&k, 0xA5, sizeof k);
    return k;
}

/* Tolerance of `ulps` units in the last place of the precision, relative to max(1, |scale|). */
static inline double ulps_of(double ulps, double scale)
{
    double s = fabs(scale);
    return ulps * EPS * (s > 1.0 ? s : 1.0);
}

/* A sweep's CC_HIT at t with normal (nx, ny) and point (px, py), depth 0, within `ulps`: the
 * checks of every hand-derived sweep case (circle-circle and circle-wall alike). */
static inline void expect_hit_contact(int result, const Contact *k, double t, double nx, double ny, double px,
                                      double py, double ulps)
{
    TEST_ASSERT_EQUAL_INT_MESSAGE(CC_HIT, result, "result");
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(ulps_of(ulps, t), t, k->t, "t");
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(ulps_of(ulps, 1.0), nx, k->normal.x, "normal.x");
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(ulps_of(ulps, 1.0), ny, k->normal.y, "normal.y");
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(ulps_of(ulps, px), px, k->point.x, "point.x");
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(ulps_of(ulps, py), py, k->point.y, "point.y");
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(0.0, 0.0, k->depth, "depth");
}

/* actual == expected within a few ulps of the precision (relative to max(1, |expected|)) */
#define EXPECT_NEAR(ulps, expected, actual)                                                        \
    TEST_ASSERT_DOUBLE_WITHIN(ulps_of((ulps), (double)(expected)), (double)(expected), (double)(actual))
/* bit-for-bit equal values (delta 0) */
#define EXPECT_EXACT(expected, actual) TEST_ASSERT_DOUBLE_WITHIN(0.0, (double)(expected), (double)(actual))
#define EXPECT_VEC_NEAR(ulps, ex, ey, v)                                                           \
    do {                                                                                           \
        EXPECT_NEAR(ulps, ex, (v).x);                                                              \
        EXPECT_NEAR(ulps, ey, (v).y);                                                              \
    } while (0)
#define EXPECT_VEC_EXACT(ex, ey, v)                                                                \
    do {                                                                                           \
        EXPECT_EXACT(ex, (v).x);                                                                   \
        EXPECT_EXACT(ey, (v).y);                                                                   \
    } while (0)

/* splitmix64: a tiny seeded generator, so that every random test is reproducible. */
static inline uint64_t rng_next(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
/* uniform in [0, 1) with 53 random bits */
static inline double rng_unit(uint64_t *s) { return (double)(rng_next(s) >> 11) * 0x1p-53; }
static inline double rng_range(uint64_t *s, double lo, double hi) { return lo + (hi - lo) * rng_unit(s); }
/* an integer in [0, n) */
static inline int rng_int(uint64_t *s, int n) { return (int)(rng_next(s) % (uint64_t)n); }

#endif
