/* Walls keep their side in SWEPT and DISCRETE (src/world/sides.c): a centre that crossed a wall
 * within a step is put back on the side it came from, whatever the speed. The table: a
 * walled 20 x 10 box, 80 circles of radius 0.4, steps of 0.05; at |v| dt about one radius the
 * push-out alone sent centres past a wall to its far side and six of them left for good in
 * 3,000 steps. Expected counts are derived beside each test. */
#include "unity.h"

#include "test_world_util.h"

#include <stdio.h>

void setUp(void) {}
void tearDown(void) {}

/* The table: a 20 x 10 box of four walls, 80 circles of radius 0.4 on a 10 x 8 lattice (spacing
 * 2 by 1.25: no overlaps), each moving at `speed` in a pseudo-random direction. Returns how many
 * centres are outside the box after each of `steps` steps of dt, summed over the steps. */
static long escapes(int mode, double speed, double dt, int steps, int *max_out)
{
    tw_mem m;
    cc_world_def d;
    cc_world *w;
    cc_segment box[4] = {{{0, 0}, {20, 0}}, {{20, 0}, {20, 10}}, {{20, 10}, {0, 10}}, {{0, 10}, {0, 0}}};
    cc_circle c[80];
    uint64_t seed = 36;
    long out = 0;
    int i, k, worst = 0;
    d = tw_def(mode, 80, 4);
    w = tw_make(&m, &d, 0);
    TEST_ASSERT_NOT_NULL(w);
    for (i = 0; i < 4; i++)
        TEST_ASSERT_EQUAL_INT(i, cc_world_add_segment(w, &box[i]));
    for (i = 0; i < 80; i++) {
        double a = 6.283185307179586 * tw_rand(&seed);
        c[i] = tw_circle(1.0 + 2.0 * (i % 10), 0.625 + 1.25 * (i / 10), speed * cos(a), speed * sin(a), 0.4, 1);
        TEST_ASSERT_EQUAL_INT(i, cc_world_add_circle(w, &c[i]));
    }
    for (k = 0; k < steps; k++) {
        int now = 0;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, dt));
        TEST_ASSERT_EQUAL_INT(80, cc_world_get_circles(w, NULL, c, 80));
        for (i = 0; i < 80; i++)
            now += !(c[i].pos.x > 0.0 && c[i].pos.x < 20.0 && c[i].pos.y > 0.0 && c[i].pos.y < 10.0);
        out += now;
        worst = now > worst ? now : worst;
    }
    *max_out = worst;
    tw_free(&m);
    return out;
}

/* At the speeds (|v| dt = 0.42, 1.05 radii) and far beyond (4 and 10 radii a step, the
 * centre past the wall's line by up to 3.6 after its step): no centre is ever outside, in
 * either mode, over 3,000 steps. */
static void test_the_table_holds_its_balls_at_any_speed(void)
{
    static const double per_step[] = {0.42, 1.6, 4.0};
    int mode, k;
    for (mode = CC_MODE_SWEPT; mode <= CC_MODE_DISCRETE; mode++)
        for (k = 0; k < 3; k++) {
            char what[64];
            int worst;
            long out = escapes(mode, per_step[k] / 0.05, 0.05, 3000, &worst);
            snprintf(what, sizeof what, "mode %d, |v| dt %.2f", mode, per_step[k]);
            TEST_ASSERT_EQUAL_INT_MESSAGE(0, worst, what);
            TEST_ASSERT_EQUAL_INT_MESSAGE(0, (int)out, what);
        }
}

/* One ball straight at a wall at x = 5 from x = 0 (radius 1, speed 1), steps of 3.7 in
 * DISCRETE: after the first step its centre is at 3.7 (touching nothing: 3.7 + 1 < 5); after the
 * second it would be at 7.4, 2.4 past the wall's line: it is put back a radius before the line,
 * at 4, and leaves at -1 (restitution 1). Without that it stayed at 7.4, past the wall for good. */
static void test_a_centre_past_the_line_comes_back(void)
{
    tw_mem m;
    cc_world_def d;
    cc_world *w;
    cc_circle ball = tw_circle(0, 0, 1, 0, 1, 1), got;
    cc_segment wall = tw_segment(5, -10, 5, 10);
    d = tw_def(CC_MODE_DISCRETE, 2, 1);
    w = tw_make(&m, &d, 0);
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &ball));
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_segment(w, &wall));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 3.7));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 3.7));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 4.0, got.pos.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, -1.0, got.vel.x);
    TEST_ASSERT_EQUAL_UINT64(1, tw_stats(w).collisions);
    tw_free(&m);
}

/* A ball into a corner of two walls (x = 0 and y = 0) along the diagonal, from (2, 2) at speed
 * (-3, -3), one DISCRETE step of 1: its centre would be at (-1, -1), past both lines. It is put
 * back across one wall, then (looking again) across the other: at (1, 1), a radius from each,
 * both velocity components reversed. */
static void test_a_corner_puts_back_across_both_walls(void)
{
    tw_mem m;
    cc_world_def d;
    cc_world *w;
    cc_circle ball = tw_circle(2, 2, -3, -3, 1, 1), got;
    cc_segment x0 = tw_segment(0, -10, 0, 10), y0 = tw_segment(-10, 0, 10, 0);
    d = tw_def(CC_MODE_DISCRETE, 2, 2);
    w = tw_make(&m, &d, 0);
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &ball));
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_segment(w, &x0));
    TEST_ASSERT_EQUAL_INT(1, cc_world_add_segment(w, &y0));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 1.0));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1.0, got.pos.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1.0, got.pos.y);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 3.0, got.vel.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 3.0, got.vel.y);
    tw_free(&m);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_the_table_holds_its_balls_at_any_speed);
    RUN_TEST(test_a_centre_past_the_line_comes_back);
    RUN_TEST(test_a_corner_puts_back_across_both_walls);
    return UNITY_END();
}
