/* cc_world_step's check of what a step may reach (src/world/step.c): the range rule (a step whose
 * straight paths pass 2^1017 is refused, world fuzzer D1) and SWEPT's half period (D8), decided
 * by the world's bounds w->reach and w->speed in O(1) when they show the step safe, by the pass
 * over every circle otherwise. The refusals themselves are tests/test_world_fuzz_defects.c's;
 * here: a speed doubled by an impact inside a step is seen by the next step's check (the bounds
 * are kept where impulses are applied), loose bounds (a circle slowed, moved back or removed)
 * still let the pass accept, a copied world keeps its bounds, the quick test is what decides a
 * world at rest, and, over random scenes in every mode, the bounds hold every circle after every
 * call. */
#include "unity.h"

#include "test_world_util.h"
#include "world/world_internal.h"

void setUp(void) {}
void tearDown(void) {}

static cc_world *make(tw_mem *m, int mode, double period, int max_circles)
{
    cc_world_def d;
    cc_world *w;
    cc_world_def_init(&d);
    d.mode = mode;
    d.max_circles = max_circles;
    d.max_segments = 4;
    d.restitution = 1.0;
    d.period.x = d.period.y = period;
    w = tw_make(m, &d, 0);
    TEST_ASSERT_NOT_NULL(w);
    return w;
}

/* What the pass reads, for every live circle: max over the axes of |p| + |v| (now - t), and
 * |vx| + |vy|; the bounds must be at least these (to the rounding step.c allows for: 2^-40 here). */
static void check_bounds(const cc_world *w)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
    int j;
    for (j = 0; j < w->id_end; j++) {
        double ago, x, y;
        if (!(C[j].flags & CC__ALIVE))
            continue;
        ago = w->now > B[j].t ? w->now - B[j].t : 0.0;
        x = fabs(B[j].px) + fabs(B[j].vx) * ago;
        y = fabs(B[j].py) + fabs(B[j].vy) * ago;
        TEST_ASSERT_TRUE(x <= w->reach * (1.0 + 0x1p-40) && y <= w->reach * (1.0 + 0x1p-40));
        TEST_ASSERT_TRUE(fabs(B[j].vx) + fabs(B[j].vy) <= w->speed);
    }
}

/* A kinematic circle (infinite mass) at speed v strikes a light one at rest, which leaves at 2v
 * (restitution 1). The next step is one that the kinematic circle's speed allows (v dt =
 * 0.625 * 2^1017: below the quick test's 0.75 * 2^1017) but the struck circle's does not (2 v dt
 * = 1.25 * 2^1017): refused, nothing changed; a copy of the world (memcpy) refuses it too; a
 * step half as long is made. Every mode (DISCRETE: the impact is the overlap at the end of the
 * first step). v = 2^400 keeps the impact's squares finite ("Range" in the header). */
static void test_a_speed_doubled_by_an_impact_is_seen_by_the_next_step(void)
{
    int mode;
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++) {
        tw_mem m, m2;
        cc_world *w, *w2;
        cc_circle k = tw_circle(-3.0, 0.0, 0x1p400, 0.0, 1.0, INFINITY), l = tw_circle(0.0, 0.0, 0.0, 0.0, 1.0, 1.0), o;
        uint64_t h;
        double t;
        w = make(&m, mode, 0.0, 4);
        TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &k));
        TEST_ASSERT_EQUAL_INT(1, cc_world_add_circle(w, &l));
        /* the kinematic circle moves 2 in this step: contact after 1, at t = 2^-400 */
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0x1p-399));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 1, &o));
        TEST_ASSERT_TRUE(o.vel.x > 0x1.fp400 && o.vel.x < 0x1.1p401); /* 2v */
        h = cc_world_hash(w);
        t = cc_world_time(w);
        TEST_ASSERT_EQUAL_INT(tw_code(CC_ERR_RANGE), cc_world_step(w, 0.625 * 0x1p617));
        TEST_ASSERT_TRUE(h == cc_world_hash(w));
        TEST_ASSERT_EQUAL_DOUBLE(t, cc_world_time(w));
        /* a copy holds its bounds in its own memory */
        memset(&m2, 0, sizeof m2);
        m2.raw = (unsigned char *)malloc(m.bytes + 16);
        TEST_ASSERT_NOT_NULL(m2.raw);
        m2.mem = m2.raw + ((16u - ((size_t)m2.raw & 15u)) & 15u);
        memcpy(m2.mem, m.mem, m.bytes);
        w2 = (cc_world *)(void *)m2.mem;
        TEST_ASSERT_EQUAL_INT(tw_code(CC_ERR_RANGE), cc_world_step(w2, 0.625 * 0x1p617));
        TEST_ASSERT_TRUE(h == cc_world_hash(w2));
        free(m2.raw);
        /* 2 v dt = 0.625 * 2^1017: made, the struck circle far out and finite */
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.3125 * 0x1p617));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 1, &o));
        TEST_ASSERT_TRUE(isfinite(o.pos.x) && o.pos.x > 0x1p1015);
        tw_free(&m);
    }
}

/* Steps add up: a circle at speed 2^1000 makes three steps of 2^15 (2^1015 each, to 0.75 *
 * 2^1017), each within the quick test's limit on its own; the fourth would reach 2^1017 itself:
 * refused, nothing changed. Every mode. */
static void test_steps_add_up_to_the_limit(void)
{
    int mode, i;
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++) {
        tw_mem m;
        cc_world *w = make(&m, mode, 0.0, 4);
        cc_circle c = tw_circle(0.0, 0.0, 0x1p1000, 0.0, 1.0, 1.0), o;
        uint64_t h;
        TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &c));
        for (i = 0; i < 3; i++)
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0x1p15));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &o));
        TEST_ASSERT_EQUAL_DOUBLE(0x1.8p1016, o.pos.x);
        h = cc_world_hash(w);
        TEST_ASSERT_EQUAL_INT(tw_code(CC_ERR_RANGE), cc_world_step(w, 0x1p15));
        TEST_ASSERT_TRUE(h == cc_world_hash(w));
        TEST_ASSERT_EQUAL_DOUBLE(0x1.8p16, cc_world_time(w));
        tw_free(&m);
    }
}

/* The same for SWEPT's half period (periods 100 x 100): the kinematic circle at speed 10 strikes
 * the light one, which leaves at 20; a step of 3 carries the kinematic circle 30 (below 50) but
 * the struck one 60: refused; a step of 2 (40) is made. */
static void test_a_speed_doubled_by_an_impact_is_seen_by_the_half_period_rule(void)
{
    tw_mem m;
    cc_world *w = make(&m, CC_MODE_SWEPT, 100.0, 4);
    cc_circle k = tw_circle(10.0, 50.0, 10.0, 0.0, 1.0, INFINITY), l = tw_circle(13.0, 50.0, 0.0, 0.0, 1.0, 1.0), o;
    uint64_t h;
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &k));
    TEST_ASSERT_EQUAL_INT(1, cc_world_add_circle(w, &l));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.2)); /* contact at t = 0.1 */
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 1, &o));
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 20.0, o.vel.x);
    h = cc_world_hash(w);
    TEST_ASSERT_EQUAL_INT(tw_code(CC_ERR_RANGE), cc_world_step(w, 3.0));
    TEST_ASSERT_TRUE(h == cc_world_hash(w));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 2.0));
    tw_free(&m);
}

/* Loose bounds: a circle that was fast (2^600) and was set at rest, and one that was far out
 * (1.5625 * 2^1016, beyond the quick test's limit) and was removed, leave the bounds above what
 * the quick test accepts; the pass looks, accepts, and measures them again (tight: the next step
 * is decided by the quick test). Every mode, open and periodic. The one circle left moves at
 * 1e-300: a step of 2^500 carries it a little (EXACT would count 2^500 cell crossings at speed 1). */
static void test_loose_bounds_leave_the_decision_to_the_pass(void)
{
    int mode, per;
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++)
        for (per = 0; per < 2; per++) {
            tw_mem m;
            cc_world *w = make(&m, mode, per ? 40.0 : 0.0, 8);
            cc_circle a = tw_circle(5.0, 5.0, 1e-300, 0.5e-300, 0.5, 1.0), fast = tw_circle(10.0, 10.0, 0x1p600, 0.0, 0.5, 1.0),
                      far = tw_circle(0x1.9p1016, 10.0, 0.0, 0.0, 0.5, 1.0), o;
            int fid;
            double dt;
            uint64_t ticks, events;
            TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &a));
            TEST_ASSERT_EQUAL_INT(1, cc_world_add_circle(w, &fast));
            fast.vel.x = 0.0;
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle(w, 1, &fast));
            fid = cc_world_add_circle(w, &far);
            TEST_ASSERT_EQUAL_INT(2, fid);
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_remove_circle(w, fid));
            /* loose (a periodic world keeps the far circle's image within the period from the
             * moment it is put: only its speed bound is loose there) */
            TEST_ASSERT_TRUE(w->speed >= 0x1p600 && (per || w->reach >= 0x1.9p1016));
            /* 2^600 * 2^500 is Inf (in periodic SWEPT, 2^600 * 1 passes half a period) */
            dt = mode == CC_MODE_SWEPT && per ? 1.0 : 0x1p500;
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, dt));
            TEST_ASSERT_EQUAL_DOUBLE(dt, cc_world_time(w));
            /* measured by the pass (the bounds alone never shrink): tight */
            TEST_ASSERT_TRUE(w->speed == 1.5e-300 && w->reach < 100.0);
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &o));
            TEST_ASSERT_TRUE(isfinite(o.pos.x) && isfinite(o.pos.y));
            ticks = w->reach_ticks;
            events = tw_stats(w).events;
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, dt));
            /* decided by the bounds: the pass would have counted from 0 again */
            TEST_ASSERT_TRUE(ticks > 0 && w->reach_ticks == ticks + 1 + (tw_stats(w).events - events));
            check_bounds(w);
            tw_free(&m);
        }
}

/* A world of circles at rest steps without the pass: the quick test decides every step (the
 * pass runs once, for the first step, only if the bounds were loose: here they are not). */
static void test_a_world_at_rest_steps_without_the_pass(void)
{
    tw_mem m;
    cc_world *w = make(&m, CC_MODE_EXACT, 0.0, 400);
    int i;
    for (i = 0; i < 400; i++) {
        cc_circle c = tw_circle(3.0 * (i % 20), 3.0 * (i / 20), 0.0, 0.0, 1.0, 1.0);
        TEST_ASSERT_EQUAL_INT(i, cc_world_add_circle(w, &c));
    }
    for (i = 0; i < 100; i++)
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.001));
    TEST_ASSERT_EQUAL_INT(100, w->reach_ticks);
    TEST_ASSERT_TRUE(w->reach == 57.0 && w->speed == 0.0);
    tw_free(&m);
}

/* Random scenes in every mode, open and periodic, with walls, kinematic circles, rolling
 * friction, impacts and push-aparts, circles set, removed and added between steps, and steps
 * long and short: after every call the bounds hold every live circle. */
static void test_the_bounds_hold_every_circle_after_every_call(void)
{
    uint64_t seed = 12345, collisions = 0;
    int scene;
    for (scene = 0; scene < 240; scene++) {
        int mode = scene % 3, per = (scene / 3) % 2, roll = (scene / 6) % 2, n = 6 + (int)(tw_rand(&seed) * 20.0), i, s;
        double L = 20.0;
        tw_mem m;
        cc_world_def d;
        cc_world *w;
        cc_world_def_init(&d);
        d.mode = mode;
        d.max_circles = 32 + 8 * (scene % 4 == 0 ? 10 : 0); /* some with a grid, some without */
        d.max_segments = 4;
        d.restitution = tw_rand(&seed) < 0.5 ? 1.0 : 0.7;
        d.rolling_decel = roll ? 0.3 : 0.0;
        d.period.x = d.period.y = per ? L : 0.0;
        w = tw_make(&m, &d, 0);
        TEST_ASSERT_NOT_NULL(w);
        if (!per) {
            cc_segment walls[4];
            walls[0] = tw_segment(0, 0, L, 0), walls[1] = tw_segment(L, 0, L, L);
            walls[2] = tw_segment(L, L, 0, L), walls[3] = tw_segment(0, L, 0, 0);
            for (i = 0; i < 4; i++)
                TEST_ASSERT_EQUAL_INT(i, cc_world_add_segment(w, &walls[i]));
        }
        for (i = 0; i < n; i++) {
            double r = 0.3 + 0.5 * tw_rand(&seed), sp = tw_rand(&seed) < 0.2 ? 40.0 : 4.0;
            cc_circle c = tw_circle(1.5 + (L - 3.0) * tw_rand(&seed), 1.5 + (L - 3.0) * tw_rand(&seed),
                                    sp * (2.0 * tw_rand(&seed) - 1.0), sp * (2.0 * tw_rand(&seed) - 1.0), r,
                                    tw_rand(&seed) < 0.1 ? INFINITY : 0.05 + 3.0 * tw_rand(&seed));
            TEST_ASSERT_TRUE(cc_world_add_circle(w, &c) >= 0); /* overlaps allowed: pushed apart */
            check_bounds(w);
        }
        for (s = 0; s < 40; s++) {
            double u = tw_rand(&seed), dt = u < 0.3 ? 0.002 : u < 0.9 ? 0.05 : 0.6;
            int id = (int)(tw_rand(&seed) * n), rc = cc_world_step(w, dt);
            TEST_ASSERT_TRUE(rc == CC_OK || rc == CC_EVENT_LIMIT || (mode == CC_MODE_SWEPT && per && rc == tw_code(CC_ERR_RANGE)));
            check_bounds(w);
            u = tw_rand(&seed);
            if (u < 0.15) { /* set: somewhere else, another speed (a kinematic circle too) */
                cc_circle c;
                if (cc_world_get_circle(w, id, &c) == CC_OK) {
                    c.pos.x = 1.5 + (L - 3.0) * tw_rand(&seed);
                    c.vel.x = 30.0 * (2.0 * tw_rand(&seed) - 1.0);
                    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle(w, id, &c));
                }
            } else if (u < 0.2) {
                (void)cc_world_remove_circle(w, id);
            } else if (u < 0.25) {
                cc_circle c = tw_circle(L * tw_rand(&seed), L * tw_rand(&seed), 10.0 * tw_rand(&seed), -5.0, 0.4, 1.0);
                (void)cc_world_add_circle(w, &c);
            } else if (u < 0.3 && roll) { /* another deceleration from now */
                cc_circle_props p;
                p.struct_size = sizeof p;
                if (cc_world_get_circle_props(w, id, &p) == CC_OK) {
                    p.rolling_decel = 2.0 * tw_rand(&seed);
                    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, id, &p));
                }
            }
            check_bounds(w);
        }
        collisions += tw_stats(w).collisions;
        tw_free(&m);
    }
    TEST_ASSERT_TRUE(collisions > 5000); /* impulses (and push-aparts) were there to be noted */
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_a_speed_doubled_by_an_impact_is_seen_by_the_next_step);
    RUN_TEST(test_steps_add_up_to_the_limit);
    RUN_TEST(test_a_speed_doubled_by_an_impact_is_seen_by_the_half_period_rule);
    RUN_TEST(test_loose_bounds_leave_the_decision_to_the_pass);
    RUN_TEST(test_a_world_at_rest_steps_without_the_pass);
    RUN_TEST(test_the_bounds_hold_every_circle_after_every_call);
    return UNITY_END();
}
