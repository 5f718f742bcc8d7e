/* SWEPT and DISCRETE: the cheaper modes and what they give up. DISCRETE tunnels at speed and
 * SWEPT misses an impact that follows another within one step; both keep energy and walls. The
 * same scenes in EXACT (test_world_exact.c) lose nothing. */
#include "unity.h"

#include "test_world_util.h"

#include <stdio.h>

void setUp(void) {}
void tearDown(void) {}

static cc_world *world(tw_mem *m, int mode, int cap, int segs)
{
    cc_world_def d;
    cc_world_def_init(&d);
    d.mode = mode;
    d.max_circles = cap;
    d.max_segments = segs;
    return tw_make(m, &d, 0);
}

static uint64_t collisions(const cc_world *w)
{
    cc_world_stats s;
    s.struct_size = sizeof s;
    (void)cc_world_get_stats(w, &s);
    return s.collisions;
}

/* A bullet of radius 0.1 at speed 1e4 and a thin wall at x = 10, one step of 1. */
static double bullet_after_wall(int mode)
{
    tw_mem m;
    cc_world *w = world(&m, mode, 1, 1);
    cc_segment wall;
    cc_circle bullet = tw_circle(0, 0, 1e4, 0, 0.1, 1), got;
    wall.a.x = 10;
    wall.a.y = -1;
    wall.b.x = 10;
    wall.b.y = 1;
    (void)cc_world_add_segment(w, &wall);
    (void)cc_world_add_circle(w, &bullet);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 1.0));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
    tw_free(&m);
    return got.pos.x;
}

/* Walls keep their side in every mode, each in its way: DISCRETE moves the bullet to x = 1e4,
 * finds its centre crossed the wall and puts it back a radius before the wall's line, at 9.9
 * (moving back at 1e4 from there, next step); SWEPT and EXACT find the impact at x = 9.9 and
 * send it back to 9.9 - 1e4 (1 - 9.9e-4). */
static void test_discrete_tunnels_swept_does_not(void)
{
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 9.9, bullet_after_wall(CC_MODE_DISCRETE));
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, 9.9 - 1e4 * (1.0 - 9.9e-4), bullet_after_wall(CC_MODE_SWEPT));
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, 9.9 - 1e4 * (1.0 - 9.9e-4), bullet_after_wall(CC_MODE_EXACT));
}

/* DISCRETE head-on: unit circles at 0 and 3 closing at speed 2; after dt = 1 they sit at 1 and
 * 2, overlapping by 1: each is pushed back 0.5 (equal masses) and they exchange velocities. */
static void test_discrete_push_apart(void)
{
    tw_mem m;
    cc_world *w = world(&m, CC_MODE_DISCRETE, 2, 0);
    cc_circle a = tw_circle(0, 0, 1, 0, 1, 1), b = tw_circle(3, 0, -1, 0, 1, 1), got;
    (void)cc_world_add_circle(w, &a);
    (void)cc_world_add_circle(w, &b);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 1.0));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
    TEST_ASSERT_EQUAL_DOUBLE(0.5, got.pos.x);
    TEST_ASSERT_EQUAL_DOUBLE(-1.0, got.vel.x);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 1, &got));
    TEST_ASSERT_EQUAL_DOUBLE(2.5, got.pos.x);
    TEST_ASSERT_EQUAL_DOUBLE(1.0, got.vel.x);
    TEST_ASSERT_EQUAL_UINT64(1, collisions(w));
    tw_free(&m);
}

/* A ball A (x = 2, speed -1, radius 1) bounces off the wall x = 0 at t = 1 and would then reach
 * ball B (at rest at x = 4.5) at t = 2.5, when the centres are 2 apart (A at 2.5). In one step
 * of 3, EXACT finds both impacts: A stops at 2.5 and B leaves at speed 1, reaching 5. SWEPT
 * resolves only impacts predicted at the start of the step: A ends at 3 overlapping B by 0.5;
 * its next step pushes them apart and resolves the contact. */
static void wall_then_ball(int mode, cc_circle *a, cc_circle *b, uint64_t *n)
{
    tw_mem m;
    cc_world *w = world(&m, mode, 2, 1);
    cc_segment wall;
    cc_circle ca = tw_circle(2, 0, -1, 0, 1, 1), cb = tw_circle(4.5, 0, 0, 0, 1, 1);
    wall.a.x = 0;
    wall.a.y = -5;
    wall.b.x = 0;
    wall.b.y = 5;
    (void)cc_world_add_segment(w, &wall);
    (void)cc_world_add_circle(w, &ca);
    (void)cc_world_add_circle(w, &cb);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 3.0));
    (void)cc_world_get_circle(w, 0, a);
    (void)cc_world_get_circle(w, 1, b);
    *n = collisions(w);
    if (mode == CC_MODE_SWEPT) {
        cc_circle a2, b2;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.0));
        (void)cc_world_get_circle(w, 0, &a2);
        (void)cc_world_get_circle(w, 1, &b2);
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, 2.0, b2.pos.x - a2.pos.x); /* pushed apart: 0.25 each */
        TEST_ASSERT_EQUAL_DOUBLE(2.75, a2.pos.x);
        TEST_ASSERT_EQUAL_DOUBLE(0.0, a2.vel.x); /* A approached B: velocities exchanged */
        TEST_ASSERT_EQUAL_DOUBLE(1.0, b2.vel.x);
    }
    tw_free(&m);
}

static void test_swept_misses_second_impact(void)
{
    cc_circle a, b;
    uint64_t n;
    wall_then_ball(CC_MODE_EXACT, &a, &b, &n);
    TEST_ASSERT_EQUAL_UINT64(2, n);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 2.5, a.pos.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 5.0, b.pos.x);
    wall_then_ball(CC_MODE_SWEPT, &a, &b, &n);
    TEST_ASSERT_EQUAL_UINT64(1, n);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 3.0, a.pos.x);
    TEST_ASSERT_EQUAL_DOUBLE(4.5, b.pos.x);
}

/* A gas in a box for 300 steps of 0.1 (speeds <= 1.4, radius 1): energy kept (e = 1; the
 * push-apart moves positions only), nobody leaves the box. */
static void gas(int mode)
{
    enum { N = 300 };
    static cc_circle c[N];
    tw_mem m;
    cc_world *w = world(&m, mode, N, 4);
    double L = tw_fill_box(w, N, 1.0, 0.3, 99), e0;
    int k;
    TEST_ASSERT_EQUAL_INT(N, cc_world_get_circles(w, NULL, c, N));
    e0 = tw_sum(c, N).energy;
    for (k = 0; k < 300; k++)
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.1));
    TEST_ASSERT_EQUAL_INT(N, cc_world_get_circles(w, NULL, c, N));
    TEST_ASSERT_DOUBLE_WITHIN(1e-12 * e0, e0, tw_sum(c, N).energy);
    TEST_ASSERT_EQUAL_INT(0, tw_escapes(c, N, L, 0.05));
    TEST_ASSERT_TRUE(collisions(w) > 1000);
    printf("%s gas: %llu collisions, max overlap now %.3g\n", mode == CC_MODE_SWEPT ? "swept" : "discrete",
           (unsigned long long)collisions(w), tw_max_rel_overlap(c, N, 1.0));
    TEST_ASSERT_TRUE(tw_canary_ok(&m));
    tw_free(&m);
}

static void test_swept_gas(void) { gas(CC_MODE_SWEPT); }
static void test_discrete_gas(void) { gas(CC_MODE_DISCRETE); }

/* SWEPT with a fast body among slow ones: it looks over the cells its path covers and finds
 * its first impact far along it (a target 500 cells away). */
static void test_swept_fast_body_far_target(void)
{
    enum { N = 100 };
    tw_mem m;
    cc_world *w = world(&m, CC_MODE_SWEPT, N, 0);
    cc_circle c, got;
    int i, bullet, target;
    for (i = 0; i < N - 2; i++) { /* a row of slow circles far below the bullet's path */
        c = tw_circle(3.0 * i, -50, 0.01, 0, 1, 1);
        (void)cc_world_add_circle(w, &c);
    }
    c = tw_circle(0, 0, 1000, 0, 1, 1);
    bullet = cc_world_add_circle(w, &c);
    c = tw_circle(1000, 0, 0, 0, 1, 1);
    target = cc_world_add_circle(w, &c);
    /* contact when the centres are 2 apart: x = 998 at t = 0.998; the bullet stops there */
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 1.0));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, bullet, &got));
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 998.0, got.pos.x);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, got.vel.x);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, target, &got));
    TEST_ASSERT_EQUAL_DOUBLE(1000.0, got.vel.x);
    tw_free(&m);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_discrete_tunnels_swept_does_not);
    RUN_TEST(test_discrete_push_apart);
    RUN_TEST(test_swept_misses_second_impact);
    RUN_TEST(test_swept_gas);
    RUN_TEST(test_discrete_gas);
    RUN_TEST(test_swept_fast_body_far_target);
    return UNITY_END();
}
