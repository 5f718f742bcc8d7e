/* Per-body properties (issue 13): restitution per side and how it mixes, filters, sensors, the
 * props handshake, and that a world whose bodies keep their defaults runs as before. Expected
 * numbers are derived beside each test. */
#include "unity.h"

#include "test_world_util.h"

#include <stddef.h>
#include <stdio.h>

void setUp(void) {}
void tearDown(void) {}

static cc_world *world(tw_mem *m, int mode, int max_circles, int max_segments, int mix)
{
    cc_world_def d;
    cc_world_def_init(&d);
    d.mode = mode;
    d.max_circles = max_circles;
    d.max_segments = max_segments;
    d.restitution_mix = mix;
    return tw_make(m, &d, 0);
}

static cc_circle_props circle_props(const cc_world *w, int id)
{
    cc_circle_props p;
    p.struct_size = sizeof p;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle_props(w, id, &p));
    return p;
}

static cc_segment_props segment_props(const cc_world *w, int id)
{
    cc_segment_props p;
    p.struct_size = sizeof p;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_segment_props(w, id, &p));
    return p;
}

static void run(cc_world *w, double t, int mode)
{
    int k, n = mode == CC_MODE_EXACT ? 1 : (int)(t / 0.01 + 0.5);
    for (k = 0; k < n; k++)
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, t / n));
}

/* A ball of restitution 0.5 (r 1, at the origin, speed 1 along +x) against a wall at x = 5 of
 * restitution 0.8: it touches at t = 4 and leaves at -e, with e = min 0.5, max 0.8, product
 * 0.4, mean 0.65. In every mode. */
static void test_ball_against_wall_under_each_mix(void)
{
    static const double expect[4] = {0.5, 0.8, 0.4, 0.65};
    int mix, mode;
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++)
        for (mix = CC_MIX_MIN; mix <= CC_MIX_MEAN; mix++) {
            tw_mem m;
            cc_world *w = world(&m, mode, 4, 1, mix);
            cc_circle ball = tw_circle(0, 0, 1, 0, 1, 1), got;
            cc_segment wall = tw_segment(5, -10, 5, 10);
            cc_circle_props bp;
            cc_segment_props wp;
            char what[64];
            snprintf(what, sizeof what, "mode %d, mix %d", mode, mix);
            TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &ball));
            TEST_ASSERT_EQUAL_INT(0, cc_world_add_segment(w, &wall));
            bp = circle_props(w, 0);
            bp.restitution = 0.5;
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, 0, &bp));
            wp = segment_props(w, 0);
            wp.restitution = 0.8;
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_segment_props(w, 0, &wp));
            run(w, 6.0, mode);
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
            TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-12, -expect[mix], got.vel.x, what);
            tw_free(&m);
        }
}

/* Two balls of restitution 0.9 and 0.5 head-on (equal masses, speeds 1 and -1) under MIN: e =
 * 0.5, so each leaves at -e times its speed: -0.5 and 0.5. */
static void test_two_balls_take_the_mixed_restitution(void)
{
    tw_mem m;
    cc_world *w = world(&m, CC_MODE_EXACT, 4, 0, CC_MIX_MIN);
    cc_circle a = tw_circle(-5, 0, 1, 0, 1, 1), b = tw_circle(5, 0, -1, 0, 1, 1), got;
    cc_circle_props p;
    (void)cc_world_add_circle(w, &a);
    (void)cc_world_add_circle(w, &b);
    p = circle_props(w, 0);
    p.restitution = 0.9;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, 0, &p));
    p.restitution = 0.5;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, 1, &p));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 10.0));
    (void)cc_world_get_circle(w, 0, &got);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, -0.5, got.vel.x);
    (void)cc_world_get_circle(w, 1, &got);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.5, got.vel.x);
    tw_free(&m);
}

/* Circles whose masks exclude each other pass through: a (category 1, mask without bit 2) and b
 * (category 2): b's category meets nothing of a's mask. a runs through b at rest, unchanged; c,
 * added onto a with the same filter as b, is not pushed apart. A circle whose mask excludes a
 * wall's category passes through the wall. Every mode. */
static void test_filtered_pairs_pass_through(void)
{
    int mode;
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++) {
        tw_mem m;
        cc_world *w = world(&m, mode, 64, 1, CC_MIX_MIN);
        cc_circle a = tw_circle(0, 0, 1, 0, 1, 1), b = tw_circle(5, 0, 0, 0, 1, 1), c, got;
        cc_segment wall = tw_segment(12, -10, 12, 10);
        cc_circle_props p;
        cc_segment_props q;
        (void)cc_world_add_circle(w, &a);
        (void)cc_world_add_circle(w, &b);
        (void)cc_world_add_segment(w, &wall);
        p = circle_props(w, 0);
        p.mask = ~2u;
        p.category = 1u;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, 0, &p));
        p = circle_props(w, 1);
        p.category = 2u;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, 1, &p));
        q = segment_props(w, 0);
        q.category = 4u;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_segment_props(w, 0, &q));
        p = circle_props(w, 0);
        p.mask = ~(2u | 4u);
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, 0, &p));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.0));
        c = tw_circle(0, 50, 0, 0, 1, 1); /* added away from everything, filtered, then set onto a */
        TEST_ASSERT_EQUAL_INT(2, cc_world_add_circle(w, &c));
        p = circle_props(w, 2);
        p.category = 2u;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, 2, &p));
        c.pos.y = 0.0;
        c.pos.x = 0.5; /* overlaps a by 1.5 */
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle(w, 2, &c));
        run(w, 20.0, mode);
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, 20.0, got.pos.x); /* through b and through the wall */
        TEST_ASSERT_DOUBLE_WITHIN(1e-15, 1.0, got.vel.x);
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 1, &got));
        TEST_ASSERT_EQUAL_DOUBLE(5.0, got.pos.x);
        TEST_ASSERT_EQUAL_DOUBLE(0.0, got.vel.x);
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 2, &got));
        TEST_ASSERT_EQUAL_DOUBLE(0.5, got.pos.x); /* never pushed */
        TEST_ASSERT_EQUAL_UINT64(0, tw_stats(w).collisions);
        tw_free(&m);
    }
}

/* ---- sensors ---------------------------------------------------------------------------------- */

typedef struct sensed {
    int n;
    cc_sensor_event e[16];
} sensed;

static void on_sensor(const cc_sensor_event *e, void *user)
{
    sensed *s = (sensed *)user;
    if (s->n < 16)
        s->e[s->n] = *e;
    s->n++;
}

static cc_world *sensor_world(tw_mem *m, int mode, sensed *log)
{
    cc_world_def d;
    cc_world_def_init(&d);
    d.mode = mode;
    d.max_circles = 64;
    d.max_segments = 4;
    d.on_sensor = on_sensor;
    d.user = log;
    memset(log, 0, sizeof *log);
    return tw_make(m, &d, 0);
}

static void make_sensor(cc_world *w, int id)
{
    cc_circle_props p = circle_props(w, id);
    p.sensor = 1;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, id, &p));
    TEST_ASSERT_EQUAL_INT(1, circle_props(w, id).sensor);
}

static void expect_event(const sensed *s, int k, int sensor, int visitor, int begin, double t, double tol)
{
    char what[64];
    snprintf(what, sizeof what, "sensor event %d of %d", k, s->n);
    TEST_ASSERT_TRUE_MESSAGE(k < s->n, what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(sensor, s->e[k].sensor, what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(visitor, s->e[k].visitor, what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(begin, s->e[k].begin, what);
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(tol, t, s->e[k].t, what);
}

/* A sensor of radius 2 at (10, 0); visitors of radius 1 (R = 3):
 * - v0 from (0, 0) at speed 1 along +x: begins at x = 7 (t = 7), ends at x = 13 (t = 13);
 * - v1 from (0, 2), the same: |x - 10|^2 + 4 < 9 while |x - 10| < sqrt 5: t = 10 -+ sqrt 5;
 * - v2 as v0 but filtered out, v3 a second sensor crossing it: nothing.
 * EXACT reports the exact times, in time order. */
static void test_sensor_times_exact(void)
{
    tw_mem m;
    sensed log;
    cc_world *w = sensor_world(&m, CC_MODE_EXACT, &log);
    cc_circle s = tw_circle(10, 0, 0, 0, 2, INFINITY), v0 = tw_circle(0, 0, 1, 0, 1, 1),
              v1 = tw_circle(0, 2, 1, 0, 1, 1), v2 = tw_circle(0, -30, 1, 0, 1, 1), v3 = tw_circle(0, 30, 1, 0, 1, 1);
    cc_circle_props p;
    double r5 = sqrt(5.0);
    (void)cc_world_add_circle(w, &s);
    (void)cc_world_add_circle(w, &v0);
    (void)cc_world_add_circle(w, &v1);
    v2.pos.y = 0.0; /* crosses the sensor too, but filtered */
    v2.pos.x = -1.0;
    v2.vel.x = 1.0;
    (void)cc_world_add_circle(w, &v2);
    make_sensor(w, 0);
    p = circle_props(w, 3);
    p.category = 8u;
    p.mask = 8u;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, 3, &p)); /* the sensor's category 1 is not in it */
    v3.pos = tw_circle(10, -20, 0, 1, 2, 1).pos;
    v3.vel.x = 0.0;
    v3.vel.y = 1.0;
    (void)cc_world_add_circle(w, &v3); /* along x = 10 from y = -20: through the sensor */
    make_sensor(w, 4);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 30.0));
    TEST_ASSERT_EQUAL_INT(4, log.n);
    expect_event(&log, 0, 0, 1, 1, 7.0, 1e-12);
    expect_event(&log, 1, 0, 2, 1, 10.0 - r5, 1e-12);
    expect_event(&log, 2, 0, 2, 0, 10.0 + r5, 1e-12);
    expect_event(&log, 3, 0, 1, 0, 13.0, 1e-12);
    tw_free(&m);
}

/* A moving sensor and a resting visitor: the sensor (radius 2) from (20, 0) at speed -1, the
 * visitor (radius 1) at the origin: |20 - t| < 3 for t in (17, 23). */
static void test_moving_sensor_finds_resting_visitor(void)
{
    tw_mem m;
    sensed log;
    cc_world *w = sensor_world(&m, CC_MODE_EXACT, &log);
    cc_circle s = tw_circle(20, 0, -1, 0, 2, INFINITY), v = tw_circle(0, 0, 0, 0, 1, 1);
    (void)cc_world_add_circle(w, &s);
    (void)cc_world_add_circle(w, &v);
    make_sensor(w, 0);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 40.0));
    TEST_ASSERT_EQUAL_INT(2, log.n);
    expect_event(&log, 0, 0, 1, 1, 17.0, 1e-12);
    expect_event(&log, 1, 0, 1, 0, 23.0, 1e-12);
    tw_free(&m);
}

/* A visitor that starts inside, leaves, bounces off a wall and comes back: the sensor (radius 2)
 * at the origin, the visitor (radius 1) at (1, 0) moving +x at 1, a wall at x = 10. Begin at
 * once (the add, t = 0); end at x = 3 (t = 2); the wall is touched at x = 9 (t = 8), the
 * visitor returns at -1 and re-enters at x = 3 (t = 14), then crosses to x = -3 (t = 20). */
static void test_visitor_starting_inside_leaves_and_returns(void)
{
    tw_mem m;
    sensed log;
    cc_world *w = sensor_world(&m, CC_MODE_EXACT, &log);
    cc_circle s = tw_circle(0, 0, 0, 0, 2, INFINITY), v = tw_circle(1, 0, 1, 0, 1, 1);
    cc_segment wall = tw_segment(10, -10, 10, 10);
    (void)cc_world_add_segment(w, &wall);
    (void)cc_world_add_circle(w, &s);
    make_sensor(w, 0);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.0));
    (void)cc_world_add_circle(w, &v);
    TEST_ASSERT_EQUAL_INT(1, log.n);
    expect_event(&log, 0, 0, 1, 1, 0.0, 0.0);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 25.0));
    TEST_ASSERT_EQUAL_INT(4, log.n);
    expect_event(&log, 1, 0, 1, 0, 2.0, 1e-12);
    expect_event(&log, 2, 0, 1, 1, 14.0, 1e-12);
    expect_event(&log, 3, 0, 1, 0, 20.0, 1e-12);
    /* removed while inside a sensor: nothing more is reported */
    {
        cc_circle back = tw_circle(0, 0, 0, 0, 1, 1);
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle(w, 1, &back));
        TEST_ASSERT_EQUAL_INT(5, log.n);
        expect_event(&log, 4, 0, 1, 1, 25.0, 0.0);
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_remove_circle(w, 1));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 10.0));
        TEST_ASSERT_EQUAL_INT(5, log.n);
    }
    tw_free(&m);
}

/* A pocket of radius 2 swallows the balls (radius 0.5) whose centres enter it: a sensor of
 * radius 2 - 0.5 = 1.5 at (0, 10), which a ball overlaps while its centre is within 1.5 + 0.5 =
 * 2 of the pocket's. Balls from below, upwards, at x offsets 0, 1.9, 1.99, 2.01 and 2.1: the
 * first three centres pass within 2 of the pocket's centre, the others do not.
 * Balls are far apart in x order so that they never meet (offsets are their own columns). In
 * SWEPT and DISCRETE with steps of 0.05 the same balls are reported. */
static void test_pocket_swallows_exactly_the_centres_that_enter(void)
{
    static const double offset[5] = {0.0, 1.9, 1.99, 2.01, 2.1};
    int mode;
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++) {
        tw_mem m;
        sensed log;
        int k, seen[5] = {0, 0, 0, 0, 0};
        cc_world *w = sensor_world(&m, mode, &log);
        cc_circle pocket = tw_circle(0, 10, 0, 0, 1.5, INFINITY);
        cc_circle_props p;
        (void)cc_world_add_circle(w, &pocket);
        make_sensor(w, 0);
        for (k = 0; k < 5; k++) {
            /* each ball in its own world column: filters keep the balls from meeting one another */
            cc_circle b = tw_circle(offset[k], -10.0 * k, 0, 1, 0.5, 1);
            (void)cc_world_add_circle(w, &b);
            p = circle_props(w, k + 1);
            p.category = 1u | (2u << k);
            p.mask = 1u;
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, k + 1, &p));
        }
        run(w, 70.0, mode);
        for (k = 0; k < log.n && k < 16; k++)
            if (log.e[k].begin)
                seen[log.e[k].visitor - 1]++;
        TEST_ASSERT_EQUAL_INT(1, seen[0]);
        TEST_ASSERT_EQUAL_INT(1, seen[1]);
        TEST_ASSERT_EQUAL_INT(1, seen[2]);
        TEST_ASSERT_EQUAL_INT(0, seen[3]);
        TEST_ASSERT_EQUAL_INT(0, seen[4]);
        TEST_ASSERT_EQUAL_INT(6, log.n); /* three begins and their ends */
        tw_free(&m);
    }
}

/* A sensor takes and gives no impulses and touches no wall: a moving sensor runs through a
 * resting circle and a wall unchanged, and the circle stays put. */
static void test_sensor_takes_no_impulse(void)
{
    tw_mem m;
    sensed log;
    cc_world *w = sensor_world(&m, CC_MODE_EXACT, &log);
    cc_circle s = tw_circle(0, 0, 1, 0, 1, 1), c = tw_circle(5, 0, 0, 0, 1, 1), got;
    cc_segment wall = tw_segment(10, -5, 10, 5);
    (void)cc_world_add_segment(w, &wall);
    (void)cc_world_add_circle(w, &s);
    (void)cc_world_add_circle(w, &c);
    make_sensor(w, 0);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 20.0));
    (void)cc_world_get_circle(w, 0, &got);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 20.0, got.pos.x);
    (void)cc_world_get_circle(w, 1, &got);
    TEST_ASSERT_EQUAL_DOUBLE(5.0, got.pos.x);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, got.vel.x);
    TEST_ASSERT_EQUAL_UINT64(0, tw_stats(w).collisions);
    TEST_ASSERT_EQUAL_INT(2, log.n); /* it passed through c: begin at t = 3, end at t = 7 */
    expect_event(&log, 0, 0, 1, 1, 3.0, 1e-12);
    expect_event(&log, 1, 0, 1, 0, 7.0, 1e-12);
    tw_free(&m);
}

/* ---- simultaneous impacts with different restitutions ---------------------------------------- */

/* A ball (restitution 1) at 45 degrees into the corner of two cushions of 0.75 and 0.6, touching
 * both at once: the cluster takes the smallest, 0.6, and the ball returns along its incoming
 * line at 0.6 of its speed: (-1, -1) becomes (0.6, 0.6). */
static void test_corner_of_two_cushions(void)
{
    tw_mem m;
    cc_world *w = world(&m, CC_MODE_EXACT, 4, 2, CC_MIX_MIN);
    cc_circle ball = tw_circle(5, 5, -1, -1, 1, 1), got;
    cc_segment left = tw_segment(0, -1, 0, 20), bottom = tw_segment(-1, 0, 20, 0);
    cc_segment_props q;
    (void)cc_world_add_circle(w, &ball);
    (void)cc_world_add_segment(w, &left);
    (void)cc_world_add_segment(w, &bottom);
    q = segment_props(w, 0);
    q.restitution = 0.75;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_segment_props(w, 0, &q));
    q.restitution = 0.6;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_segment_props(w, 1, &q));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 5.0)); /* both touched at t = 4 */
    (void)cc_world_get_circle(w, 0, &got);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.6, got.vel.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.6, got.vel.y);
    tw_free(&m);
}

/* A cue ball into a touching rack of 15 with balls of 0.95 and cushions of 0.75 far away: every
 * contact of the cluster is ball-ball, so it is resolved at 0.95, bit for bit as a world whose
 * def.restitution is 0.95. */
static void test_rack_of_one_material(void)
{
    tw_mem m1, m2;
    cc_world_def d;
    cc_world *a, *b;
    cc_circle ca[16], cb[16];
    int k, row, n = 0;
    cc_world_def_init(&d);
    d.max_circles = 64;
    d.max_segments = 4;
    a = tw_make(&m1, &d, 0);
    d.restitution = 0.95;
    b = tw_make(&m2, &d, 0);
    for (row = 0; row < 5; row++)
        for (k = 0; k <= row; k++, n++) {
            cc_circle c = tw_circle(10.0 + row * sqrt(3.0), (k - 0.5 * row) * 2.0, 0, 0, 1, 1);
            (void)cc_world_add_circle(a, &c);
            (void)cc_world_add_circle(b, &c);
        }
    {
        cc_circle cue = tw_circle(0, 0, 10, 0, 1, 1);
        cc_segment far[2];
        far[0] = tw_segment(-100, -100, 100, -100);
        far[1] = tw_segment(-100, 100, 100, 100);
        (void)cc_world_add_circle(a, &cue);
        (void)cc_world_add_circle(b, &cue);
        for (k = 0; k < 2; k++) {
            cc_segment_props q;
            (void)cc_world_add_segment(a, &far[k]);
            (void)cc_world_add_segment(b, &far[k]);
            q = segment_props(a, k);
            q.restitution = 0.75;
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_segment_props(a, k, &q));
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_segment_props(b, k, &q));
        }
        n++;
    }
    for (k = 0; k < n; k++) {
        cc_circle_props p = circle_props(a, k);
        p.restitution = 0.95;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(a, k, &p));
    }
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(a, 1.5));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(b, 1.5));
    TEST_ASSERT_EQUAL_INT(n, cc_world_get_circles(a, NULL, ca, 16));
    TEST_ASSERT_EQUAL_INT(n, cc_world_get_circles(b, NULL, cb, 16));
    TEST_ASSERT_EQUAL_MEMORY(cb, ca, sizeof ca[0] * (size_t)n);
    TEST_ASSERT_TRUE(tw_stats(a).collisions >= 15);
    tw_free(&m1);
    tw_free(&m2);
}

/* ---- the handshake, errors, and worlds that set nothing ---------------------------------------- */

static void test_props_defaults_and_handshake(void)
{
    tw_mem m;
    cc_world_def d;
    cc_world *w;
    cc_circle c = tw_circle(0, 0, 0, 0, 1, 1);
    cc_circle_props p, before;
    unsigned char buf[sizeof(cc_circle_props)];
    size_t size;
    cc_world_def_init(&d);
    d.restitution = 0.7;
    d.rolling_decel = 0.25;
    d.max_circles = 70;
    w = tw_make(&m, &d, 0);
    (void)cc_world_add_circle(w, &c);
    p = circle_props(w, 0);
    TEST_ASSERT_EQUAL_DOUBLE(0.7, p.restitution);
    TEST_ASSERT_EQUAL_DOUBLE(0.25, p.rolling_decel);
    TEST_ASSERT_EQUAL_UINT64(1, p.category);
    TEST_ASSERT_EQUAL_UINT64(0xFFFFFFFFu, p.mask);
    TEST_ASSERT_EQUAL_INT(0, p.sensor);
    /* get: only whole fields within struct_size are written */
    for (size = offsetof(cc_circle_props, restitution) + sizeof(double); size <= sizeof p; size++) {
        size_t end = offsetof(cc_circle_props, restitution) + sizeof(double), k;
        if (size >= offsetof(cc_circle_props, rolling_decel) + sizeof(double))
            end = offsetof(cc_circle_props, rolling_decel) + sizeof(double);
        if (size >= offsetof(cc_circle_props, category) + sizeof(uint32_t))
            end = offsetof(cc_circle_props, category) + sizeof(uint32_t);
        if (size >= offsetof(cc_circle_props, mask) + sizeof(uint32_t))
            end = offsetof(cc_circle_props, mask) + sizeof(uint32_t);
        if (size >= offsetof(cc_circle_props, sensor) + sizeof(int))
            end = offsetof(cc_circle_props, sensor) + sizeof(int);
        memset(buf, 0xEE, sizeof buf);
        memcpy(buf, &size, sizeof size);
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle_props(w, 0, (cc_circle_props *)(void *)buf));
        for (k = end; k < sizeof buf; k++)
            TEST_ASSERT_EQUAL_INT(0xEE, buf[k]);
    }
    /* set: a struct cut after restitution leaves the rest as it is */
    before = circle_props(w, 0);
    p = before;
    p.struct_size = offsetof(cc_circle_props, restitution) + sizeof(double);
    p.restitution = 0.3;
    p.mask = 0; /* beyond struct_size: not read */
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, 0, &p));
    p = circle_props(w, 0);
    TEST_ASSERT_EQUAL_DOUBLE(0.3, p.restitution);
    TEST_ASSERT_EQUAL_UINT64(before.mask, p.mask);
    /* errors change nothing */
    p.struct_size = 4;
    TEST_ASSERT_EQUAL_INT(CC_ERR_VERSION, cc_world_set_circle_props(w, 0, &p));
    TEST_ASSERT_EQUAL_INT(CC_ERR_VERSION, cc_world_get_circle_props(w, 0, &p));
    p = circle_props(w, 0);
    p.restitution = 1.5;
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_set_circle_props(w, 0, &p));
    p.restitution = NAN;
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_set_circle_props(w, 0, &p));
    p.restitution = 0.5;
    p.rolling_decel = -1.0;
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_set_circle_props(w, 0, &p));
    p.rolling_decel = INFINITY;
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_set_circle_props(w, 0, &p));
    TEST_ASSERT_EQUAL_DOUBLE(0.3, circle_props(w, 0).restitution);
    TEST_ASSERT_EQUAL_INT(CC_ERR_NOT_FOUND, cc_world_set_circle_props(w, 5, &before));
    TEST_ASSERT_EQUAL_INT(CC_ERR_NOT_FOUND, cc_world_get_circle_props(w, -1, &p));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_set_circle_props(NULL, 0, &before));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_set_circle_props(w, 0, NULL));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_get_circle_props(w, 0, NULL));
    /* sensors: CC_MAX_SENSORS of them, then CC_ERR_FULL; freed by turning one back */
    {
        int k;
        for (k = 1; k <= CC_MAX_SENSORS + 1; k++) {
            cc_circle far = tw_circle(10.0 * k, 100, 0, 0, 1, 1);
            TEST_ASSERT_EQUAL_INT(k, cc_world_add_circle(w, &far));
        }
        p = circle_props(w, 1);
        p.sensor = 1;
        for (k = 1; k <= CC_MAX_SENSORS; k++)
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, k, &p));
        TEST_ASSERT_EQUAL_INT(CC_ERR_FULL, cc_world_set_circle_props(w, CC_MAX_SENSORS + 1, &p));
        TEST_ASSERT_EQUAL_INT(0, circle_props(w, CC_MAX_SENSORS + 1).sensor);
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_remove_circle(w, 3));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, CC_MAX_SENSORS + 1, &p));
    }
    TEST_ASSERT_TRUE(tw_canary_ok(&m));
    tw_free(&m);
}

/* Called from a callback, the setters are refused and change nothing. */
static cc_world *g_w;
static int g_refused;
static void setter_in_callback(const cc_contact_event *e, void *user)
{
    cc_circle_props p;
    cc_segment_props q;
    (void)user;
    p.struct_size = sizeof p;
    q.struct_size = sizeof q;
    (void)cc_world_get_circle_props(g_w, e->a, &p);
    p.restitution = 0.1;
    g_refused += cc_world_set_circle_props(g_w, e->a, &p) == tw_code(CC_ERR_BUSY);
    (void)cc_world_get_segment_props(g_w, 0, &q);
    g_refused += cc_world_set_segment_props(g_w, 0, &q) == tw_code(CC_ERR_BUSY);
}

static void test_setters_refused_from_callback(void)
{
    tw_mem m;
    cc_world_def d;
    cc_circle a = tw_circle(0, 0, 1, 0, 1, 1);
    cc_segment wall = tw_segment(5, -5, 5, 5);
    cc_world_def_init(&d);
    d.max_segments = 1;
    d.on_contact = setter_in_callback;
    g_w = tw_make(&m, &d, 0);
    g_refused = 0;
    (void)cc_world_add_circle(g_w, &a);
    (void)cc_world_add_segment(g_w, &wall);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(g_w, 10.0));
    TEST_ASSERT_EQUAL_INT(2, g_refused);
    TEST_ASSERT_EQUAL_DOUBLE(1.0, circle_props(g_w, 0).restitution);
    tw_free(&m);
}

/* def.restitution is a side's default, mixed like any value a side is given: with e = 0.9 on
 * every side (nothing set), a contact gets mix(0.9, 0.9): 0.9 under MIN, MAX and MEAN (each
 * gives back a value mixed with itself, exactly: 0.5 * (e + e) = e), and 0.9 * 0.9 under
 * PRODUCT (0.81 as doubles). Two probes in every mode: a ball (r 1, speed 1 along +x) into a wall
 * at x = 5 leaves at -e; two equal balls head-on at +-1 leave at -+e. A world whose sides are
 * given 0.9 explicitly (0.5 first, then 0.9, so that its contacts are mixed side by side) runs
 * bit for bit as the one that kept the default, in every mix: a default is nothing but its value. */
static void test_default_restitution_is_mixed_like_any_side(void)
{
    int mix, mode, given;
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++)
        for (mix = CC_MIX_MIN; mix <= CC_MIX_MEAN; mix++) {
            double e = mix == CC_MIX_PRODUCT ? 0.9 * 0.9 : 0.9;
            cc_circle first[3];
            for (given = 0; given < 2; given++) {
                tw_mem m;
                cc_world_def d;
                cc_world *w;
                cc_circle got[3];
                char what[80];
                int k;
                cc_world_def_init(&d);
                d.mode = mode;
                d.max_circles = 4;
                d.max_segments = 1;
                d.restitution = 0.9;
                d.restitution_mix = mix;
                w = tw_make(&m, &d, 0);
                snprintf(what, sizeof what, "mode %d, mix %d, given %d", mode, mix, given);
                TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &(cc_circle){{0, 0}, {1, 0}, 1, 1}));
                TEST_ASSERT_EQUAL_INT(0, cc_world_add_segment(w, &(cc_segment){{5, -10}, {5, 10}}));
                TEST_ASSERT_EQUAL_INT(1, cc_world_add_circle(w, &(cc_circle){{-5, 20}, {1, 0}, 1, 1}));
                TEST_ASSERT_EQUAL_INT(2, cc_world_add_circle(w, &(cc_circle){{5, 20}, {-1, 0}, 1, 1}));
                if (given) { /* 0.5 first: a world once given another restitution mixes per side */
                    cc_segment_props q = segment_props(w, 0);
                    q.restitution = 0.5;
                    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_segment_props(w, 0, &q));
                    q.restitution = 0.9;
                    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_segment_props(w, 0, &q));
                    for (k = 0; k < 3; k++) {
                        cc_circle_props p = circle_props(w, k);
                        p.restitution = 0.5;
                        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, k, &p));
                        p.restitution = 0.9;
                        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, k, &p));
                    }
                }
                run(w, 6.0, mode); /* the wall at t = 4, the pair at t = 4 */
                TEST_ASSERT_EQUAL_INT(3, cc_world_get_circles(w, NULL, got, 3));
                TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-12, -e, got[0].vel.x, what);
                TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-12, -e, got[1].vel.x, what);
                TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-12, e, got[2].vel.x, what);
                if (given)
                    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(first, got, sizeof got, what);
                else
                    memcpy(first, got, sizeof got);
                tw_free(&m);
            }
        }
}

/* Properties set to what they already are change nothing, bit for bit; and a world that uses a
 * feature elsewhere (a sensor far away, filters that admit everything) runs the other circles'
 * events bit for bit as before: the gas of test_world_util's kind, 200 circles in a box. */
static void test_unused_properties_change_no_bit(void)
{
    int variant;
    cc_circle ref[200], got[200];
    int n = 0;
    for (variant = 0; variant < 3; variant++) {
        tw_mem m;
        cc_world_def d;
        cc_world *w;
        uint64_t s = 12345;
        int k;
        cc_world_def_init(&d);
        d.max_circles = 256;
        d.max_segments = 4;
        w = tw_make(&m, &d, 0);
        (void)cc_world_add_segment(w, &(cc_segment){{-60, -60}, {60, -60}});
        (void)cc_world_add_segment(w, &(cc_segment){{60, -60}, {60, 60}});
        (void)cc_world_add_segment(w, &(cc_segment){{60, 60}, {-60, 60}});
        (void)cc_world_add_segment(w, &(cc_segment){{-60, 60}, {-60, -60}});
        for (k = 0; k < 200; k++) {
            double x = -55.0 + 110.0 * (double)((s = s * 6364136223846793005u + 1442695040888963407u) >> 11) * 0x1p-53;
            double y = -55.0 + 110.0 * (double)((s = s * 6364136223846793005u + 1442695040888963407u) >> 11) * 0x1p-53;
            double a = 6.283185307179586 * (double)((s = s * 6364136223846793005u + 1442695040888963407u) >> 11) * 0x1p-53;
            cc_circle c = tw_circle(x, y, cos(a), sin(a), 1, 1);
            (void)cc_world_add_circle(w, &c); /* overlaps are pushed apart at the first step */
        }
        if (variant == 1) /* every circle given its own defaults */
            for (k = 0; k < 200; k++) {
                cc_circle_props p = circle_props(w, k);
                TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, k, &p));
            }
        if (variant == 2) { /* a sensor far away, and filters that admit everything */
            cc_circle far = tw_circle(1000, 1000, 0, 0, 1, INFINITY);
            cc_circle_props p;
            TEST_ASSERT_EQUAL_INT(200, cc_world_add_circle(w, &far));
            make_sensor(w, 200);
            p = circle_props(w, 0);
            p.category = 3u;
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, 0, &p));
        }
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 50.0));
        n = cc_world_get_circles(w, NULL, variant == 0 ? ref : got, 200); /* ids 0..199 */
        TEST_ASSERT_EQUAL_INT(variant == 2 ? 201 : 200, n);
        if (variant > 0)
            TEST_ASSERT_EQUAL_MEMORY(ref, got, sizeof ref);
        tw_free(&m);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_ball_against_wall_under_each_mix);
    RUN_TEST(test_two_balls_take_the_mixed_restitution);
    RUN_TEST(test_filtered_pairs_pass_through);
    RUN_TEST(test_sensor_times_exact);
    RUN_TEST(test_moving_sensor_finds_resting_visitor);
    RUN_TEST(test_visitor_starting_inside_leaves_and_returns);
    RUN_TEST(test_pocket_swallows_exactly_the_centres_that_enter);
    RUN_TEST(test_sensor_takes_no_impulse);
    RUN_TEST(test_corner_of_two_cushions);
    RUN_TEST(test_rack_of_one_material);
    RUN_TEST(test_props_defaults_and_handshake);
    RUN_TEST(test_setters_refused_from_callback);
    RUN_TEST(test_unused_properties_change_no_bit);
    RUN_TEST(test_default_restitution_is_mixed_like_any_side);
    return UNITY_END();
}
