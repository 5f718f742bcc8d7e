/* Simultaneous impacts in the world (EXACT mode): the scenes of issue 5 run through cc_world.
 * Impacts at one instant, and bodies touching at that instant, form one cluster resolved by
 * the simultaneous-impact model (docs/SIMULTANEOUS.md); expected values are derived beside each
 * check. */
#include "unity.h"

#include "test_world_util.h"

#include <stdio.h>

void setUp(void) {}
void tearDown(void) {}

static cc_world *world(tw_mem *m, int cap, int segs, double e)
{
    cc_world_def d;
    cc_world_def_init(&d);
    d.max_circles = cap;
    d.max_segments = segs;
    d.restitution = e;
    d.mode = CC_MODE_EXACT;
    return tw_make(m, &d, 0);
}

static cc_circle get(const cc_world *w, int id)
{
    cc_circle c;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, id, &c));
    return c;
}

/* ---- Newton's cradle -------------------------------------------------------------------- */

/* n balls of radius 1 and mass 1: n - 1 touching at x = 0, 2, ..., 2(n-2) and a striker at
 * x = -6 moving at +1, which touches the row at t = 4 (gap 6 - 2). At t = 10 the last ball has
 * left at speed 1 and travelled 6, the striker rests at x = -2 and the others where they were;
 * n - 1 impulses of m * 1 each. */
static void test_cradle(void)
{
    int n, i;
    for (n = 2; n <= 10; ++n) {
        tw_mem m;
        cc_world *w = world(&m, 16, 0, 1.0);
        cc_circle c;
        TEST_ASSERT_NOT_NULL(w);
        c = tw_circle(-6.0, 0.0, 1.0, 0.0, 1.0, 1.0);
        TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &c));
        for (i = 0; i + 1 < n; ++i) {
            c = tw_circle(2.0 * i, 0.0, 0.0, 0.0, 1.0, 1.0);
            TEST_ASSERT_EQUAL_INT(i + 1, cc_world_add_circle(w, &c));
        }
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 10.0));
        for (i = 0; i < n; ++i) {
            c = get(w, i);
            TEST_ASSERT_DOUBLE_WITHIN(1e-12, i == n - 1 ? 1.0 : 0.0, c.vel.x);
            TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.0, c.vel.y);
            double x = i == 0 ? -2.0 : i == n - 1 ? 2.0 * (n - 2) + 6.0 : 2.0 * (i - 1);
            TEST_ASSERT_DOUBLE_WITHIN(1e-11, x, c.pos.x);
        }
        TEST_ASSERT_EQUAL_UINT64(n - 1, tw_stats(w).collisions);
        TEST_ASSERT_TRUE(tw_canary_ok(&m));
        tw_free(&m);
    }
}

/* ---- the 15-ball rack ------------------------------------------------------------------- */

/* Radius 1, unit masses. Row k (0..4) at x = k sqrt(3), balls at y = 2j - k (j = 0..k); the cue
 * ball starts at (-3, 0) moving +1 and touches the apex at t = 1. ids: cue first, then the rack
 * row by row, unless `order` permutes the additions. */
#define RACK 16
static void rack_state(cc_circle *c)
{
    const double r3 = sqrt(3.0);
    int k, j, i = 1;
    c[0] = tw_circle(-3.0, 0.0, 1.0, 0.0, 1.0, 1.0);
    for (k = 0; k < 5; ++k)
        for (j = 0; j <= k; ++j)
            c[i++] = tw_circle(k * r3, 2.0 * j - k, 0.0, 0.0, 1.0, 1.0);
}

/* Runs the rack to time t with the balls added in the order order[0..16) (ball order[i] gets id
 * i); out[b] is ball b's state at t, by physical identity. */
static void run_rack(double e, double t, const int *order, cc_circle *out, cc_world_stats *st)
{
    cc_circle c[RACK];
    int ids[RACK], i;
    tw_mem m;
    cc_world *w = world(&m, 32, 0, e);
    TEST_ASSERT_NOT_NULL(w);
    rack_state(c);
    for (i = 0; i < RACK; ++i)
        ids[order[i]] = cc_world_add_circle(w, &c[order[i]]);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, t));
    for (i = 0; i < RACK; ++i)
        out[i] = get(w, ids[i]);
    if (st != NULL)
        *st = tw_stats(w);
    TEST_ASSERT_TRUE(tw_canary_ok(&m));
    tw_free(&m);
}

static const int identity[RACK] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};

/* ball index of the mirror image (y -> -y) of rack ball i: row k, slot j <-> slot k - j */
static int mirror(int i)
{
    int k = 0, first = 1;
    if (i == 0)
        return 0;
    while (i >= first + k + 1) {
        first += k + 1;
        ++k;
    }
    return first + (k - (i - first));
}

static void check_rack(double e)
{
    cc_circle c[RACK], c0[RACK];
    cc_world_stats st;
    tw_totals before, after;
    int i, moving = 0;
    char msg[80];
    rack_state(c0);
    before = tw_sum(c0, RACK);
    /* t = 1.5: half a time unit after the impact, the break under way */
    run_rack(e, 1.5, identity, c, &st);
    after = tw_sum(c, RACK);
    printf("rack e=%.1f: %llu impulses, %llu events\n", e, (unsigned long long)st.collisions,
           (unsigned long long)st.events);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, before.px, after.px);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, before.py, after.py);
    if (e == 1.0)
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, before.energy, after.energy);
    else
        TEST_ASSERT_TRUE(after.energy < before.energy);
    for (i = 0; i < RACK; ++i) {
        int j = mirror(i);
        sprintf(msg, "ball %d and its mirror %d", i, j);
        TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-9, c[i].pos.x, c[j].pos.x, msg);
        TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-9, -c[i].pos.y, c[j].pos.y, msg);
        TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-9, c[i].vel.x, c[j].vel.x, msg);
        TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-9, -c[i].vel.y, c[j].vel.y, msg);
    }
    /* the back row (balls 11..15) is driven away from the pack */
    for (i = 11; i < RACK; ++i)
        if (c[i].vel.x > 1e-3)
            ++moving;
    TEST_ASSERT_EQUAL_INT(5, moving);
    TEST_ASSERT_TRUE(st.max_overlap < 1e-10); /* the documented overlap tolerance */
}

static void test_rack_break_elastic(void) { check_rack(1.0); }
static void test_rack_break_restitution_0_9(void) { check_rack(0.9); }

/* Independence of the order in which the bodies were added: the rack added in three other
 * orders gives the same state ball by ball, to rounding, long after the break (t = 20, with the
 * secondary collisions of the scattering balls). */
static void test_rack_order_of_adding(void)
{
    static const int orders[3][RACK] = {{15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0},
                                        {5, 11, 0, 3, 14, 8, 1, 12, 6, 9, 15, 2, 7, 13, 4, 10},
                                        {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 0}};
    cc_circle ref[RACK], other[RACK];
    int t, i;
    run_rack(0.9, 20.0, identity, ref, NULL);
    for (t = 0; t < 3; ++t) {
        run_rack(0.9, 20.0, orders[t], other, NULL);
        for (i = 0; i < RACK; ++i) {
            TEST_ASSERT_DOUBLE_WITHIN(1e-9, ref[i].pos.x, other[i].pos.x);
            TEST_ASSERT_DOUBLE_WITHIN(1e-9, ref[i].pos.y, other[i].pos.y);
            TEST_ASSERT_DOUBLE_WITHIN(1e-9, ref[i].vel.x, other[i].vel.x);
            TEST_ASSERT_DOUBLE_WITHIN(1e-9, ref[i].vel.y, other[i].vel.y);
        }
    }
}

/* ---- two impacts at one instant on one body --------------------------------------------- */

/* B rests at the origin; A and C (unit masses, radius 1) come at it from the directions +60 and
 * -60 degrees, mirror images of each other, and touch it at the same instant t = 3. One cluster
 * with two contacts: the outcome is mirror-symmetric (B moves along -x only) and keeps momentum
 * and energy, which no pairwise order does (the first pair resolved would push B off the
 * axis before the second). */
static void test_two_impacts_at_one_instant(void)
{
    const double c60 = 0.5, s60 = sqrt(3.0) / 2.0;
    tw_mem m;
    cc_world *w = world(&m, 8, 0, 1.0);
    cc_circle c[3];
    tw_totals before, after;
    int i;
    c[0] = tw_circle(0.0, 0.0, 0.0, 0.0, 1.0, 1.0);
    c[1] = tw_circle(5.0 * c60, 5.0 * s60, -c60, -s60, 1.0, 1.0);
    c[2] = tw_circle(5.0 * c60, -5.0 * s60, -c60, s60, 1.0, 1.0);
    before = tw_sum(c, 3);
    for (i = 0; i < 3; ++i)
        TEST_ASSERT_EQUAL_INT(i, cc_world_add_circle(w, &c[i]));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 4.0));
    for (i = 0; i < 3; ++i)
        c[i] = get(w, i);
    after = tw_sum(c, 3);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.0, c[0].vel.y);
    TEST_ASSERT_TRUE(c[0].vel.x < -0.1);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, c[1].vel.x, c[2].vel.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, -c[1].vel.y, c[2].vel.y);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, before.px, after.px);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, before.py, after.py);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, before.energy, after.energy);
    TEST_ASSERT_EQUAL_UINT64(2, tw_stats(w).collisions);
    tw_free(&m);
}

/* The same two impacts, turned by 37 degrees, far from the origin and late: the scene's axis
 * is u = (cos 37, sin 37), shifted to (3e4, -2e4), and the circles start 1000 further out so
 * that the impacts come at t = 1003. Turned, the two impacts are no longer mirror images in
 * floating point: their predicted times and positions differ by rounding (ulps of 3e4 and of
 * 1e3). They still meet the touching tolerance and form one cluster, so the outcome is
 * symmetric about the axis to rounding. */
static void test_two_impacts_turned_far_and_late(void)
{
    const double c60 = 0.5, s60 = sqrt(3.0) / 2.0, X = 3e4, Y = -2e4, D = 1005.0;
    const double deg = 3.14159265358979323846 / 180.0, ux = cos(37.0 * deg), uy = sin(37.0 * deg);
    const double px = -uy, py = ux; /* perpendicular to the axis */
    tw_mem m;
    cc_world *w = world(&m, 8, 0, 1.0);
    cc_circle c[3];
    double da, dc;
    int i;
    c[0] = tw_circle(X, Y, 0.0, 0.0, 1.0, 1.0);
    const double ax = c60 * ux + s60 * px, ay = c60 * uy + s60 * py; /* from B towards A */
    const double cx = c60 * ux - s60 * px, cy = c60 * uy - s60 * py; /* from B towards C */
    c[1] = tw_circle(X + D * ax, Y + D * ay, -ax, -ay, 1.0, 1.0);
    c[2] = tw_circle(X + D * cx, Y + D * cy, -cx, -cy, 1.0, 1.0);
    for (i = 0; i < 3; ++i)
        TEST_ASSERT_EQUAL_INT(i, cc_world_add_circle(w, &c[i]));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 1004.0));
    for (i = 0; i < 3; ++i)
        c[i] = get(w, i);
    /* B along -u only; A and C mirror images about the axis, in velocity and in position */
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 0.0, c[0].vel.x * px + c[0].vel.y * py);
    TEST_ASSERT_TRUE(c[0].vel.x * ux + c[0].vel.y * uy < -0.1);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, c[1].vel.x * ux + c[1].vel.y * uy,
                              c[2].vel.x * ux + c[2].vel.y * uy);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, -(c[1].vel.x * px + c[1].vel.y * py),
                              c[2].vel.x * px + c[2].vel.y * py);
    da = (c[1].pos.x - X) * px + (c[1].pos.y - Y) * py;
    dc = (c[2].pos.x - X) * px + (c[2].pos.y - Y) * py;
    TEST_ASSERT_DOUBLE_WITHIN(1e-8, -da, dc);
    TEST_ASSERT_EQUAL_UINT64(2, tw_stats(w).collisions);
    tw_free(&m);
}

/* A chain with a gap: A (mass 2) at x = -4 moving +1 hits B (x = 0) at t = 2: A 1/3, B 4/3.
 * B closes the gap of 0.5 to C (x = 2.5) by t = 2.375 and stops there (equal masses), A being
 * at -1.875. A must find the stopped B (a body at rest predicts nothing): the gap of 0.375
 * closes at 1/3 by t = 3.5, A at -1.5, B at 0.5; then A 1/9, B 4/9. At t = 5: A at
 * -1.5 + 1.5/9, B at 0.5 + 1.5 * 4/9. (Before the fix in exact.c, A passed through B.) */
static void test_chain_with_a_gap(void)
{
    tw_mem m;
    cc_world *w = world(&m, 4, 0, 1.0);
    cc_circle a = tw_circle(-4.0, 0.0, 1.0, 0.0, 1.0, 2.0), b = tw_circle(0.0, 0.0, 0.0, 0.0, 1.0, 1.0),
              c = tw_circle(2.5, 0.0, 0.0, 0.0, 1.0, 1.0);
    (void)cc_world_add_circle(w, &a);
    (void)cc_world_add_circle(w, &b);
    (void)cc_world_add_circle(w, &c);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 5.0));
    a = get(w, 0);
    b = get(w, 1);
    c = get(w, 2);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1.0 / 9.0, a.vel.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 4.0 / 9.0, b.vel.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 4.0 / 3.0, c.vel.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, -1.5 + 1.5 / 9.0, a.pos.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.5 + 1.5 * 4.0 / 9.0, b.pos.x);
    TEST_ASSERT_EQUAL_UINT64(3, tw_stats(w).collisions);
    tw_free(&m);
}

/* ---- walls, masses, immovable bodies ---------------------------------------------------- */

/* Walls along x = 0 and y = 0; a ball of radius 1 at (5, 5) moving (-1, -1) touches both at
 * once at t = 4 in the corner at (1, 1), and comes back along its incoming line at e times its
 * speed: at t = 10 it is at (1 + 6e, 1 + 6e) moving (e, e). */
static void test_corner_at_45_degrees(void)
{
    const double es[2] = {1.0, 0.9};
    int k;
    for (k = 0; k < 2; ++k) {
        const double e = es[k];
        tw_mem m;
        cc_world *w = world(&m, 4, 2, e);
        cc_segment s1 = tw_segment(0.0, 0.0, 0.0, 20.0), s2 = tw_segment(0.0, 0.0, 20.0, 0.0);
        cc_circle c = tw_circle(5.0, 5.0, -1.0, -1.0, 1.0, 1.0);
        TEST_ASSERT_EQUAL_INT(0, cc_world_add_segment(w, &s1));
        TEST_ASSERT_EQUAL_INT(1, cc_world_add_segment(w, &s2));
        TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &c));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 10.0));
        c = get(w, 0);
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, e, c.vel.x);
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, e, c.vel.y);
        TEST_ASSERT_DOUBLE_WITHIN(1e-11, 1.0 + 6.0 * e, c.pos.x);
        TEST_ASSERT_DOUBLE_WITHIN(1e-11, 1.0 + 6.0 * e, c.pos.y);
        TEST_ASSERT_EQUAL_UINT64(2, tw_stats(w).collisions);
        tw_free(&m);
    }
}

/* A (mass 2) at x = -4 moving +1 reaches B (mass 1, at x = 0) at t = 2; B touches C (mass 1,
 * x = 2). The model's rounds (docs/SIMULTANEOUS.md, tests/test_cluster.c): A-B gives 1/3 and
 * 4/3, B-C hands 4/3 on to C, A-B again gives 1/9 and 4/9: final velocities 1/9, 4/9, 4/3
 * (momentum 2, energy 1 kept). */
static void test_unequal_masses(void)
{
    tw_mem m;
    cc_world *w = world(&m, 4, 0, 1.0);
    cc_circle a = tw_circle(-4.0, 0.0, 1.0, 0.0, 1.0, 2.0), b = tw_circle(0.0, 0.0, 0.0, 0.0, 1.0, 1.0),
              c = tw_circle(2.0, 0.0, 0.0, 0.0, 1.0, 1.0);
    (void)cc_world_add_circle(w, &a);
    (void)cc_world_add_circle(w, &b);
    (void)cc_world_add_circle(w, &c);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 2.5));
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1.0 / 9.0, get(w, 0).vel.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 4.0 / 9.0, get(w, 1).vel.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 4.0 / 3.0, get(w, 2).vel.x);
    tw_free(&m);
}

/* B (unit mass, radius 1) at the origin touches a wall along x = -1 and an immovable circle O at
 * (0, 2); A (unit mass) comes from the lower right along the direction (-1, 1)/sqrt(2) at speed
 * 1 and touches B at t = 2 at (2h, -2h), h = 1/sqrt(2). Resolved together (tests/test_cluster.c
 * derives it): A goes back along its incoming line at speed 1, B stops, O does not move. At t = 5
 * A is at (5h, -5h). */
static void test_immovable_circle_and_wall(void)
{
    const double h = 1.0 / sqrt(2.0);
    tw_mem m;
    cc_world *w = world(&m, 4, 1, 1.0);
    cc_segment s = tw_segment(-1.0, -10.0, -1.0, 10.0);
    cc_circle b = tw_circle(0.0, 0.0, 0.0, 0.0, 1.0, 1.0), got;
    cc_circle o = tw_circle(0.0, 2.0, 0.0, 0.0, 1.0, INFINITY); /* immovable */
    cc_circle a = tw_circle(4.0 * h, -4.0 * h, -h, h, 1.0, 1.0);
    (void)cc_world_add_segment(w, &s);
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &b));
    TEST_ASSERT_EQUAL_INT(1, cc_world_add_circle(w, &o));
    TEST_ASSERT_EQUAL_INT(2, cc_world_add_circle(w, &a));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 5.0));
    got = get(w, 0);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.0, got.vel.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.0, got.vel.y);
    TEST_ASSERT_DOUBLE_WITHIN(1e-11, 0.0, got.pos.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-11, 0.0, got.pos.y);
    got = get(w, 1);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, got.pos.x);
    TEST_ASSERT_EQUAL_DOUBLE(2.0, got.pos.y);
    got = get(w, 2);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, h, got.vel.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, -h, got.vel.y);
    TEST_ASSERT_DOUBLE_WITHIN(1e-11, 5.0 * h, got.pos.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-11, -5.0 * h, got.pos.y);
    tw_free(&m);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_cradle);
    RUN_TEST(test_rack_break_elastic);
    RUN_TEST(test_rack_break_restitution_0_9);
    RUN_TEST(test_rack_order_of_adding);
    RUN_TEST(test_two_impacts_at_one_instant);
    RUN_TEST(test_two_impacts_turned_far_and_late);
    RUN_TEST(test_chain_with_a_gap);
    RUN_TEST(test_corner_at_45_degrees);
    RUN_TEST(test_unequal_masses);
    RUN_TEST(test_immovable_circle_and_wall);
    return UNITY_END();
}
