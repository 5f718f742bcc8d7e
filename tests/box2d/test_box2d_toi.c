/* Cross-check of cc_sweep against Box2D 3.1's b2TimeOfImpact (the pyb2d3 wheel's libbox2d.a)
 * on 2 x 1e5 seeded random pairs of circles in pure translation.
 *
 * What Box2D computes (src/distance.c, v3.1): conservative advancement on the centre distance d(t)
 * of the two proxies, times as fractions of the sweep in [0, maxFraction]. It stops at the first
 * t where d(t) <= target + tol, target = max(slop, ra + rb - slop), tol = slop / 4, slop =
 * B2_LINEAR_SLOP = 0.005 length units; it never steps past d = target - tol. So Box2D reports the
 * moment the circles overlap by about one slop (+- slop/4), in float.
 *
 * Comparison 1 ("grown"): Box2D gets radii grown by slop/2 each, so its target is exactly our
 * R = ra + rb and its answer satisfies |d(t_b2) - R| <= tol. Expected: where both hit,
 * |d(t_b2) - R| <= tol (+ float rounding) and |t_b2 - t| ~ tol / closing speed; Box2D hits and we
 * miss only when our closest approach over [0, 1] lies in [R, R + tol] (the band Box2D counts
 * as contact); Box2D never misses a pair we hit; our CC_OVERLAP is Box2D's hit at fraction 0.
 *
 * Comparison 2 ("plain"): Box2D gets the true radii, target R - slop. Every Box2D hit is our
 * hit (or overlap), no earlier than ours; Box2D misses and we hit only when our closest
 * approach lies in [R - slop - tol, R): circles that touch but never overlap by a slop.
 *
 * Scales: centres in [-10, 10]^2, displacements over the sweep in [-10, 10]^2, radii in
 * [0.05, 2]: float rounding (~1e-5 here) stays far below tol = 1.25e-3. Inputs are floats, so
 * both libraries see identical numbers: our velocity is c2 - c1 computed exactly in double. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <box2d/collision.h>
#include <box2d/math_functions.h>

#include "circlecollide.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#define N_PAIRS 100000
#define SLOP 0.005 /* B2_LINEAR_SLOP at b2_lengthUnitsPerMeter = 1 */
#define TOL (0.25 * SLOP)

static uint64_t rng_state;
static uint64_t rng_next(void)
{
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
static double rng_range(double lo, double hi) { return lo + (hi - lo) * (double)(rng_next() >> 11) * 0x1p-53; }

typedef struct pair {
    float pa[2], pb[2], ca2[2], cb2[2]; /* start and end centres */
    float ra, rb;
} pair;

/* A third uniform, a third aimed at a random point within 1.2 R of a at a random fraction, a
 * third grazing: closest approach within R +- 2 tol, the slop band and either side of it. */
static pair random_pair(int kind)
{
    pair p;
    double dax = rng_range(-10, 10), day = rng_range(-10, 10), dbx, dby, R;
    p.ra = (float)rng_range(0.05, 2);
    p.rb = (float)rng_range(0.05, 2);
    R = (double)p.ra + p.rb;
    p.pa[0] = (float)rng_range(-10, 10);
    p.pa[1] = (float)rng_range(-10, 10);
    p.pb[0] = (float)rng_range(-10, 10);
    p.pb[1] = (float)rng_range(-10, 10);
    dbx = rng_range(-10, 10);
    dby = rng_range(-10, 10);
    if (kind > 0) {
        /* b passes the point e, at distance `miss` from a's centre at time f, moving relative
         * to a perpendicular to the offset e - a(f): its closest approach to a is `miss`, at f */
        double f = rng_range(0.1, 1.2), ang = rng_range(0, 6.283185307179586), speed = rng_range(1, 12);
        double miss = kind == 1 ? rng_range(0, 1.2) * R : R + rng_range(-2, 2) * TOL;
        double ex = p.pa[0] + dax * f + miss * cos(ang), ey = p.pa[1] + day * f + miss * sin(ang);
        dbx = dax - sin(ang) * speed;
        dby = day + cos(ang) * speed;
        p.pb[0] = (float)(ex - dbx * f);
        p.pb[1] = (float)(ey - dby * f);
    }
    p.ca2[0] = (float)(p.pa[0] + dax);
    p.ca2[1] = (float)(p.pa[1] + day);
    p.cb2[0] = (float)(p.pb[0] + dbx);
    p.cb2[1] = (float)(p.pb[1] + dby);
    return p;
}

static cc_circle our_circle(const float c1[2], const float c2[2], float r)
{
    cc_circle c;
    c.pos.x = c1[0];
    c.pos.y = c1[1];
    c.vel.x = (double)c2[0] - (double)c1[0]; /* exact: the difference of two floats fits a double */
    c.vel.y = (double)c2[1] - (double)c1[1];
    c.radius = r;
    c.mass = 1;
    return c;
}

static b2TOIOutput box2d_toi(const pair *p, float grow)
{
    b2TOIInput in;
    b2Vec2 origin = {0.0f, 0.0f};
    in.proxyA = b2MakeProxy(&origin, 1, p->ra + grow);
    in.proxyB = b2MakeProxy(&origin, 1, p->rb + grow);
    in.sweepA.localCenter = origin;
    in.sweepA.c1 = (b2Vec2){p->pa[0], p->pa[1]};
    in.sweepA.c2 = (b2Vec2){p->ca2[0], p->ca2[1]};
    in.sweepA.q1 = in.sweepA.q2 = b2Rot_identity;
    in.sweepB.localCenter = origin;
    in.sweepB.c1 = (b2Vec2){p->pb[0], p->pb[1]};
    in.sweepB.c2 = (b2Vec2){p->cb2[0], p->cb2[1]};
    in.sweepB.q1 = in.sweepB.q2 = b2Rot_identity;
    in.maxFraction = 1.0f;
    return b2TimeOfImpact(&in);
}

/* centre distance at t, and the closest approach over [0, 1], in double */
static double dist_at(const cc_circle *a, const cc_circle *b, double t)
{
    return hypot(b->pos.x - a->pos.x + (b->vel.x - a->vel.x) * t, b->pos.y - a->pos.y + (b->vel.y - a->vel.y) * t);
}
static double closest_approach(const cc_circle *a, const cc_circle *b)
{
    double dx = b->pos.x - a->pos.x, dy = b->pos.y - a->pos.y, vx = b->vel.x - a->vel.x, vy = b->vel.y - a->vel.y;
    double v2 = vx * vx + vy * vy, tc = v2 > 0 ? -(dx * vx + dy * vy) / v2 : 0;
    tc = tc < 0 ? 0 : (tc > 1 ? 1 : tc);
    return dist_at(a, b, tc);
}
/* rounding of Box2D's float arithmetic at this pair's scale (coordinates up to ~40) */
static double float_slack(const pair *p)
{
    double m = 0;
    int i;
    for (i = 0; i < 2; i++) {
        m = fmax(m, fmax(fabs((double)p->pa[i]), fabs((double)p->pb[i])));
        m = fmax(m, fmax(fabs((double)p->ca2[i]), fabs((double)p->cb2[i])));
    }
    return 32 * 1.1920929e-7 * (m + 1);
}

static int cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

static double dt_abs[N_PAIRS], dt_rel[N_PAIRS];

/* Comparison 1: radii grown by slop/2, Box2D's target is our R. */
static void test_grown_radii_agree_with_cc_sweep(void)
{
    int i, n_both = 0, n_overlap = 0, n_band = 0, n_sep = 0, n_failed = 0, bad_band = 0, bad_miss = 0;
    int bad_dist = 0, bad_overlap = 0, n_early = 0;
    double worst_early = 0, worst_dist = 0, med_abs, med_rel, max_abs, max_rel;
    rng_state = 20250101;
    for (i = 0; i < N_PAIRS; i++) {
        pair p = random_pair(i % 3);
        cc_circle a = our_circle(p.pa, p.ca2, p.ra), b = our_circle(p.pb, p.cb2, p.rb);
        double R = (double)p.ra + p.rb, eps = float_slack(&p), dmin = closest_approach(&a, &b);
        cc_contact k;
        int r = cc_sweep(&a, &b, 1.0, &k);
        b2TOIOutput o = box2d_toi(&p, (float)(0.5 * SLOP));
        TEST_ASSERT_TRUE(r >= 0);
        if (o.state == b2_toiStateFailed || o.state == b2_toiStateUnknown || o.state == b2_toiStateOverlapped) {
            n_failed++;
            continue;
        }
        if (o.state == b2_toiStateSeparated) {
            n_sep++;
            /* Box2D found no d <= R + tol in [0, 1]: we must not have found d = R there */
            bad_miss += r != CC_MISS;
            continue;
        }
        /* Box2D hit after a start apart (d(0) > R + tol): d(t_b2) within tol of R */
        if (r != CC_OVERLAP && o.fraction > 0.0f) {
            double e = fabs(dist_at(&a, &b, o.fraction) - R);
            worst_dist = fmax(worst_dist, e);
            bad_dist += e > TOL + eps;
        }
        if (r == CC_OVERLAP) {
            n_overlap++;
            bad_overlap += o.fraction != 0.0f;
        } else if (r == CC_MISS) {
            /* only inside the band: closest approach in [R, R + tol] */
            n_band++;
            bad_band += !(dmin >= R - eps && dmin <= R + TOL + eps);
        } else {
            double vx = b.vel.x - a.vel.x, vy = b.vel.y - a.vel.y;
            double px = b.pos.x - a.pos.x + vx * k.t, py = b.pos.y - a.pos.y + vy * k.t;
            double closing = -(px * vx + py * vy) / R; /* -d'(t) at our contact */
            double dt = (double)o.fraction - k.t;
            if (dt < 0) { /* d is convex, so d(t_b2d) - R >= closing |dt| there: ratio <= 1 */
                n_early++;
                worst_early = fmax(worst_early, (fabs(dt) * closing - float_slack(&p)) / TOL);
            }
            dt_abs[n_both] = fabs(dt);
            dt_rel[n_both] = fabs(dt) * closing / TOL; /* in units of the expected tol / closing */
            n_both++;
        }
    }
    qsort(dt_abs, (size_t)n_both, sizeof(double), cmp_double);
    qsort(dt_rel, (size_t)n_both, sizeof(double), cmp_double);
    med_abs = n_both ? dt_abs[n_both / 2] : 0;
    max_abs = n_both ? dt_abs[n_both - 1] : 0;
    med_rel = n_both ? dt_rel[n_both / 2] : 0;
    max_rel = n_both ? dt_rel[n_both - 1] : 0;
    printf("box2d grown radii: %d pairs: both hit %d, our overlap = Box2D hit at 0: %d, Box2D hit in the slop "
           "band where we miss: %d, both miss: %d, Box2D failed: %d\n",
           N_PAIRS, n_both, n_overlap, n_band, n_sep, n_failed);
    printf("box2d grown radii: |d(t_b2d) - R| max %.3g (tol %.3g); |t_b2d - t| median %.3g max %.3g; "
           "in units of tol/closing speed: median %.3f, p99 %.3f, max %.3f\n",
           worst_dist, TOL, med_abs, max_abs, med_rel, n_both ? dt_rel[n_both * 99 / 100] : 0.0, max_rel);
    printf("box2d grown radii: Box2D earlier than us in %d of %d, there |dt| <= %.3f tol/closing (convexity bound 1)\n",
           n_early, n_both, worst_early);
    printf("box2d grown radii: disagreements: Box2D missed our hit %d, band violations %d, distance violations %d, "
           "overlap not at 0: %d\n",
           bad_miss, bad_band, bad_dist, bad_overlap);
    TEST_ASSERT_EQUAL_INT(0, bad_miss);
    TEST_ASSERT_EQUAL_INT(0, bad_band);
    TEST_ASSERT_EQUAL_INT(0, bad_dist);
    TEST_ASSERT_EQUAL_INT(0, bad_overlap);
    TEST_ASSERT_EQUAL_INT(0, n_failed);
    /* enough of each kind for the figures to mean something */
    TEST_ASSERT_TRUE(n_both > N_PAIRS / 5 && n_sep > N_PAIRS / 5 && n_band > 100 && n_overlap > 100);
    /* Box2D stops with d within tol of R. Where it stops before our t, the convexity of d(t)
     * gives closing |dt| <= d(t_b2d) - R <= tol exactly (up to float rounding); after our t the
     * same holds to first order, and the curvature of d at grazing contacts allows a tail. */
    TEST_ASSERT_TRUE(worst_early <= 1.0);
    TEST_ASSERT_TRUE(med_rel <= 0.5);
    TEST_ASSERT_TRUE(max_rel <= 4.0);
}

/* Comparison 2: true radii, Box2D's target R - slop. */
static void test_plain_radii_misses_lie_in_the_band(void)
{
    int i, n_both = 0, n_b2_only = 0, n_ours_only = 0, n_sep = 0, n_failed = 0, bad_b2_only = 0, bad_ours_only = 0;
    int bad_order = 0;
    rng_state = 20250102;
    for (i = 0; i < N_PAIRS; i++) {
        pair p = random_pair(i % 3);
        cc_circle a = our_circle(p.pa, p.ca2, p.ra), b = our_circle(p.pb, p.cb2, p.rb);
        double R = (double)p.ra + p.rb, eps = float_slack(&p), dmin = closest_approach(&a, &b);
        cc_contact k;
        int r = cc_sweep(&a, &b, 1.0, &k);
        b2TOIOutput o = box2d_toi(&p, 0.0f);
        if (o.state != b2_toiStateHit && o.state != b2_toiStateSeparated) {
            n_failed++;
            continue;
        }
        if (o.state == b2_toiStateHit && r != CC_MISS) {
            n_both++;
            bad_order += r == CC_HIT && (double)o.fraction < k.t - 1e-6; /* Box2D goes deeper: later */
        } else if (o.state == b2_toiStateHit) {
            n_b2_only++; /* Box2D: d <= R - slop + tol somewhere; we saw no contact at all */
            bad_b2_only++;
        } else if (r != CC_MISS) {
            n_ours_only++; /* we touch, Box2D never overlaps by a slop: closest approach in the band */
            bad_ours_only += !(dmin >= R - SLOP - TOL - eps && dmin < R + eps);
        } else
            n_sep++;
    }
    printf("box2d plain radii: %d pairs: both hit %d, we hit and Box2D (target R - slop) misses %d, Box2D only %d, "
           "both miss %d, Box2D failed %d; outside the band %d, Box2D earlier than us %d\n",
           N_PAIRS, n_both, n_ours_only, n_b2_only, n_sep, n_failed, bad_ours_only, bad_order);
    TEST_ASSERT_EQUAL_INT(0, bad_b2_only);
    TEST_ASSERT_EQUAL_INT(0, bad_ours_only);
    TEST_ASSERT_EQUAL_INT(0, bad_order);
    TEST_ASSERT_EQUAL_INT(0, n_failed);
    TEST_ASSERT_TRUE(n_ours_only > 100);
}

int main(void)
{
    b2SetLengthUnitsPerMeter(1.0f); /* slop = 0.005 length units */
    UNITY_BEGIN();
    RUN_TEST(test_grown_radii_agree_with_cc_sweep);
    RUN_TEST(test_plain_radii_misses_lie_in_the_band);
    return UNITY_END();
}
