/* Rolling to rest in the world (issue 12): positions p(t) = p0 + v t (1 - k t), k = decel / (2|v|),
 * until the stop at 1 / (2k). Every expected number is derived beside its test. */
#include "unity.h"

#include "test_world_util.h"

#include <math.h>
#include <stddef.h>

void setUp(void) {}
void tearDown(void) {}

static double g_t[8];
static int g_n;

static void on_contact(const cc_contact_event *e, void *user)
{
    (void)user;
    if (g_n < 8)
        g_t[g_n] = e->t;
    g_n++;
}

static cc_world *world(tw_mem *m, int mode, double decel)
{
    cc_world_def d;
    cc_world_def_init(&d);
    d.mode = mode;
    d.max_circles = 8;
    d.rolling_decel = decel;
    d.on_contact = on_contact;
    g_n = 0;
    return tw_make(m, &d, 0);
}

static cc_circle get(const cc_world *w, int id)
{
    cc_circle c;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, id, &c));
    return c;
}

/* Speed 2, decel 0.5: stops at t = v / a = 4, after v^2 / (2a) = 4; at t = 1: x = 2 - 0.25 =
 * 1.75, v = 2 - 0.5 = 1.5. Exactly: these are sums of powers of two. */
static void test_a_ball_rolls_to_rest_where_the_formula_says(void)
{
    int mode;
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++) {
        tw_mem m;
        cc_world *w = world(&m, mode, 0.5);
        cc_circle a = {{0.0, 0.0}, {2.0, 0.0}, 0.25, 1.0}, c;
        TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &a));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 1.0));
        c = get(w, 0);
        TEST_ASSERT_EQUAL_DOUBLE(1.75, c.pos.x);
        TEST_ASSERT_EQUAL_DOUBLE(1.5, c.vel.x);
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 9.0));
        c = get(w, 0);
        TEST_ASSERT_EQUAL_DOUBLE(4.0, c.pos.x);
        TEST_ASSERT_EQUAL_DOUBLE(0.0, c.vel.x);
        TEST_ASSERT_EQUAL_DOUBLE(0.0, c.pos.y);
        tw_free(&m);
    }
}

/* Found by the bindings (bug A of the first cut): a rolling ball into one at rest. Radii 0.1,
 * a from 0 at 2, decel 0.4: x(t) = 2t - 0.2t^2 reaches 0.8 (touching b at 1) at
 * t = (2 - sqrt(3.36)) / 0.4, at speed sqrt(3.36). Equal masses, e = 1: a stops there, b leaves
 * at sqrt(3.36) and rolls sqrt(3.36)^2 / 0.8 = 4.2 further, to 5.2. */
static void test_a_rolling_ball_strikes_one_at_rest(void)
{
    tw_mem m;
    cc_world *w = world(&m, CC_MODE_EXACT, 0.4);
    cc_circle a = {{0.0, 0.0}, {2.0, 0.0}, 0.1, 1.0}, b = {{1.0, 0.0}, {0.0, 0.0}, 0.1, 1.0};
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &a));
    TEST_ASSERT_EQUAL_INT(1, cc_world_add_circle(w, &b));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 20.0));
    TEST_ASSERT_EQUAL_INT(1, g_n);
    TEST_ASSERT_DOUBLE_WITHIN(1e-13, (2.0 - sqrt(3.36)) / 0.4, g_t[0]);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.8, get(w, 0).pos.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 5.2, get(w, 1).pos.x);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, get(w, 1).vel.x);
    tw_free(&m);
}

/* Stopping short by 1e-9 of touching: no contact; reaching 1e-9 past touching: one. a stops at
 * x = 4 (speed 2, decel 0.5); b's surface is 4 + 0.5 (two radii of 0.25) +- 1e-9 away. */
static void test_a_stop_just_short_and_just_long(void)
{
    int k;
    for (k = 0; k < 2; k++) {
        tw_mem m;
        cc_world *w = world(&m, CC_MODE_EXACT, 0.5);
        cc_circle a = {{0.0, 0.0}, {2.0, 0.0}, 0.25, 1.0}, b = {{4.5 + (k ? -1e-9 : 1e-9), 0.0}, {0.0, 0.0}, 0.25, 1.0};
        TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &a));
        TEST_ASSERT_EQUAL_INT(1, cc_world_add_circle(w, &b));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 10.0));
        TEST_ASSERT_EQUAL_INT(k, g_n);
        tw_free(&m);
    }
}

/* Found by the bindings (bug B of the first cut): a deceleration set through the props takes
 * effect in every mode, before the first step too: speed 2, decel 4 stops after 4/8 = 0.5. */
static void test_a_deceleration_set_through_the_props_takes_effect(void)
{
    int mode, warm;
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++)
        for (warm = 0; warm < 2; warm++) {
            tw_mem m;
            cc_world *w = world(&m, mode, 0.0);
            cc_circle a = {{0.0, 0.0}, {2.0, 0.0}, 0.25, 1.0};
            cc_circle_props p;
            TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &a));
            if (warm)
                TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.0));
            p.struct_size = sizeof p;
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle_props(w, 0, &p));
            p.rolling_decel = 4.0;
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, 0, &p));
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 1.0));
            TEST_ASSERT_EQUAL_DOUBLE(0.5, get(w, 0).pos.x);
            tw_free(&m);
        }
}

/* An immovable (kinematic) circle is driven, not rolling: it keeps its velocity. */
static void test_a_kinematic_circle_does_not_decelerate(void)
{
    tw_mem m;
    cc_world *w = world(&m, CC_MODE_EXACT, 0.5);
    cc_circle k = {{0.0, 0.0}, {2.0, 0.0}, 0.25, HUGE_VAL};
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &k));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 10.0));
    TEST_ASSERT_EQUAL_DOUBLE(20.0, get(w, 0).pos.x);
    TEST_ASSERT_EQUAL_DOUBLE(2.0, get(w, 0).vel.x);
    tw_free(&m);
}

/* A wall in the way: speed 2, decel 0.5, radius 0.25, wall at x = 3.25: the surface reaches it
 * when 2t - 0.25t^2 = 3, t = 2 (the smaller root of t^2 - 8t + 12), at speed 1; e = 1 sends it
 * back at 1, which rolls 1 / (2 * 0.5) = 1 further: rests at x = 2. */
static void test_a_rolling_ball_off_a_wall(void)
{
    tw_mem m;
    cc_world_def d;
    cc_world *w;
    cc_circle a = {{0.0, 0.0}, {2.0, 0.0}, 0.25, 1.0};
    cc_segment s = {{3.25, -5.0}, {3.25, 5.0}};
    cc_world_def_init(&d);
    d.max_circles = 4;
    d.max_segments = 1;
    d.rolling_decel = 0.5;
    d.on_contact = on_contact;
    g_n = 0;
    w = tw_make(&m, &d, 0);
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_segment(w, &s));
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &a));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 10.0));
    TEST_ASSERT_EQUAL_INT(1, g_n);
    TEST_ASSERT_DOUBLE_WITHIN(1e-14, 2.0, g_t[0]);
    TEST_ASSERT_DOUBLE_WITHIN(1e-13, 2.0, get(w, 0).pos.x);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, get(w, 0).vel.x);
    tw_free(&m);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_a_ball_rolls_to_rest_where_the_formula_says);
    RUN_TEST(test_a_rolling_ball_strikes_one_at_rest);
    RUN_TEST(test_a_stop_just_short_and_just_long);
    RUN_TEST(test_a_deceleration_set_through_the_props_takes_effect);
    RUN_TEST(test_a_kinematic_circle_does_not_decelerate);
    RUN_TEST(test_a_rolling_ball_off_a_wall);
    return UNITY_END();
}
