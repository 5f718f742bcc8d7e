/* EXACT mode: every collision in time order. Closed-form scenes (a head-on pair, Galperin's
 * billiard), conservation laws and the no-overlap/no-escape invariants over many collisions,
 * determinism independent of addresses, tunnelling, overlaps made by the caller, and the
 * inelastic-collapse remedies (rest_speed and the event cap). */
#include "unity.h"

#include "test_world_util.h"

#include <stdio.h>

void setUp(void) {}
void tearDown(void) {}

/* Documented overlap tolerance: ~1e-12 of the radius sum for these scenes (coordinates within
 * ~1e3 radii of the origin); the tests allow 1e-10. */
#define TW_OVERLAP_TOL 1e-10

static cc_world *world(tw_mem *m, int cap, int segs, double e)
{
    cc_world_def d;
    cc_world_def_init(&d);
    d.max_circles = cap;
    d.max_segments = segs;
    d.restitution = e;
    d.max_events = 10000000u; /* whole runs in one call (Galperin's billiard, a gas for 200) */
    return tw_make(m, &d, 0);
}

static cc_contact_event g_events[8];
static int g_n;
static void record(const cc_contact_event *e, void *user)
{
    (void)user;
    if (g_n < 8)
        g_events[g_n] = *e;
    g_n++;
}

/* Two unit circles at x = 0 and x = 10 moving towards each other at speed 1: the gap of 8
 * closes at relative speed 2, so they touch at t = 4 at x = 4 and x = 6, contact point (5, 0),
 * normal +x. Masses 1 and 3, e = 1: va' = ((1-3) 1 + 2*3*(-1)) / 4 = -2,
 * vb' = ((3-1)(-1) + 2*1*1) / 4 = 0; impulse = 1 * |(-2) - 1| = 3. */
static void test_head_on_pair(void)
{
    cc_world_def d;
    tw_mem m;
    cc_world *w;
    cc_circle a = tw_circle(0, 0, 1, 0, 1, 1), b = tw_circle(10, 0, -1, 0, 1, 3), got;
    cc_world_def_init(&d);
    d.max_circles = 2;
    d.on_contact = record;
    w = tw_make(&m, &d, 0);
    g_n = 0;
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &a));
    TEST_ASSERT_EQUAL_INT(1, cc_world_add_circle(w, &b));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 3.0));
    TEST_ASSERT_EQUAL_INT(0, g_n);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 2.0));
    TEST_ASSERT_EQUAL_INT(1, g_n);
    TEST_ASSERT_EQUAL_INT(0, g_events[0].a);
    TEST_ASSERT_EQUAL_INT(1, g_events[0].b);
    TEST_ASSERT_EQUAL_INT(-1, g_events[0].segment);
    TEST_ASSERT_EQUAL_DOUBLE(4.0, g_events[0].t);
    TEST_ASSERT_EQUAL_DOUBLE(5.0, g_events[0].point.x);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, g_events[0].point.y);
    TEST_ASSERT_EQUAL_DOUBLE(1.0, g_events[0].normal.x);
    TEST_ASSERT_EQUAL_DOUBLE(3.0, g_events[0].impulse);
    /* at t = 5: a at 4 - 2 = 2, b still at 6 */
    TEST_ASSERT_EQUAL_DOUBLE(5.0, cc_world_time(w));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
    TEST_ASSERT_EQUAL_DOUBLE(2.0, got.pos.x);
    TEST_ASSERT_EQUAL_DOUBLE(-2.0, got.vel.x);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 1, &got));
    TEST_ASSERT_EQUAL_DOUBLE(6.0, got.pos.x);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, got.vel.x);
    TEST_ASSERT_EQUAL_UINT64(1, tw_stats(w).collisions);
    tw_free(&m);
}

/* A wall: a circle of radius 1 at x = 5 moving at -2 towards the segment x = 0 touches it at
 * t = (5 - 1) / 2 = 2, point (0, 0), normal -x; impulse m |dv| = 1 * 4. */
static void test_wall_bounce(void)
{
    cc_world_def d;
    tw_mem m;
    cc_world *w;
    cc_circle a = tw_circle(5, 0, -2, 0, 1, 1), got;
    cc_segment s = tw_segment(0, -5, 0, 5);
    cc_world_def_init(&d);
    d.max_circles = 1;
    d.max_segments = 1;
    d.on_contact = record;
    w = tw_make(&m, &d, 0);
    g_n = 0;
    (void)cc_world_add_segment(w, &s);
    (void)cc_world_add_circle(w, &a);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 3.0));
    TEST_ASSERT_EQUAL_INT(1, g_n);
    TEST_ASSERT_EQUAL_INT(-1, g_events[0].b);
    TEST_ASSERT_EQUAL_INT(0, g_events[0].segment);
    TEST_ASSERT_EQUAL_DOUBLE(2.0, g_events[0].t);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, g_events[0].point.x);
    TEST_ASSERT_EQUAL_DOUBLE(-1.0, g_events[0].normal.x);
    TEST_ASSERT_EQUAL_DOUBLE(4.0, g_events[0].impulse);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
    TEST_ASSERT_EQUAL_DOUBLE(3.0, got.pos.x); /* back from x = 1 at speed 2 for 1 */
    tw_free(&m);
}

/* Galperin's billiard: a light circle between a wall and a heavy circle (mass ratio 100^k)
 * moving towards it, e = 1, collides floor(pi 10^k) times in all, counting the wall hits. */
static uint64_t galperin(double ratio)
{
    tw_mem m;
    cc_world *w = world(&m, 2, 1, 1.0);
    cc_segment s = tw_segment(0, -10, 0, 10);
    cc_circle light = tw_circle(2, 0, 0, 0, 1, 1), heavy = tw_circle(5, 0, -1, 0, 1, ratio);
    uint64_t n;
    (void)cc_world_add_segment(w, &s);
    (void)cc_world_add_circle(w, &light);
    (void)cc_world_add_circle(w, &heavy);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 1e3));
    n = tw_stats(w).collisions;
    tw_free(&m);
    return n;
}

static void test_galperin_pi(void)
{
    TEST_ASSERT_EQUAL_UINT64(3, galperin(1.0));
    TEST_ASSERT_EQUAL_UINT64(31, galperin(1e2));
    TEST_ASSERT_EQUAL_UINT64(314, galperin(1e4));
    TEST_ASSERT_EQUAL_UINT64(3141, galperin(1e6));
    TEST_ASSERT_EQUAL_UINT64(314159, galperin(1e10));
}

/* A gas in a box, e = 1: kinetic energy conserved to rounding, nothing escapes, no pair
 * overlaps beyond the tolerance, at every one of 20 steps. Momentum is not conserved (walls). */
static void test_box_gas_invariants(void)
{
    enum { N = 400 };
    tw_mem m;
    cc_world *w = world(&m, N, 4, 1.0);
    static cc_circle c[N];
    double L = tw_fill_box(w, N, 1.0, 0.3, 11), e0;
    int k;
    TEST_ASSERT_EQUAL_INT(N, cc_world_get_circles(w, NULL, c, N));
    e0 = tw_sum(c, N).energy;
    for (k = 0; k < 20; k++) {
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 10.0));
        TEST_ASSERT_EQUAL_INT(N, cc_world_get_circles(w, NULL, c, N));
        TEST_ASSERT_DOUBLE_WITHIN(1e-12 * e0, e0, tw_sum(c, N).energy);
        TEST_ASSERT_EQUAL_INT(0, tw_escapes(c, N, L, TW_OVERLAP_TOL));
        TEST_ASSERT_TRUE(tw_max_rel_overlap(c, N, 1.0) < TW_OVERLAP_TOL);
    }
    /* 400 circles at speed ~0.8 and mean free path ~3 radii: thousands of collisions */
    TEST_ASSERT_TRUE(tw_stats(w).collisions > 20000);
    TEST_ASSERT_TRUE(tw_stats(w).max_overlap < 2.0 * TW_OVERLAP_TOL);
    printf("box gas: %llu collisions, %llu events, max overlap %.3g\n", (unsigned long long)tw_stats(w).collisions,
           (unsigned long long)tw_stats(w).events, tw_stats(w).max_overlap);
    tw_free(&m);
}

/* Without walls momentum is conserved too: circles of different masses and radii thrown at a
 * common centre collide many times and fly apart. */
static void test_momentum_and_energy(void)
{
    enum { N = 300 };
    tw_mem m;
    cc_world *w = world(&m, N, 0, 1.0);
    static cc_circle c[N];
    uint64_t seed = 5;
    tw_totals t0, t1;
    int i;
    for (i = 0; i < N; i++) {
        double ang = 6.283185307179586 * tw_rand(&seed), rad = 30.0 + 30.0 * tw_rand(&seed);
        cc_circle k = tw_circle(rad * cos(ang), rad * sin(ang), -cos(ang) * (1 + tw_rand(&seed)),
                             -sin(ang) * (1 + tw_rand(&seed)), 0.5 + 0.5 * tw_rand(&seed), 0.5 + 4 * tw_rand(&seed));
        (void)cc_world_add_circle(w, &k);
    }
    TEST_ASSERT_EQUAL_INT(N, cc_world_get_circles(w, NULL, c, N));
    TEST_ASSERT_TRUE(tw_max_rel_overlap(c, N, 1.0) > 0.0 || 1); /* random placement may overlap */
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.0)); /* overlaps of the placement resolved */
    TEST_ASSERT_EQUAL_INT(N, cc_world_get_circles(w, NULL, c, N));
    t0 = tw_sum(c, N);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 200.0));
    TEST_ASSERT_EQUAL_INT(N, cc_world_get_circles(w, NULL, c, N));
    t1 = tw_sum(c, N);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12 * t0.energy, t0.energy, t1.energy);
    TEST_ASSERT_DOUBLE_WITHIN(1e-11 * t0.energy, t0.px, t1.px);
    TEST_ASSERT_DOUBLE_WITHIN(1e-11 * t0.energy, t0.py, t1.py);
    TEST_ASSERT_TRUE(tw_max_rel_overlap(c, N, 1.0) < TW_OVERLAP_TOL);
    TEST_ASSERT_TRUE(tw_stats(w).collisions > 1000);
    tw_free(&m);
}

/* Runs a box gas for a while and returns its final circles in c. */
static void run_box(cc_world *w, cc_circle *c, int n)
{
    int k;
    (void)tw_fill_box(w, n, 1.0, 0.35, 3);
    for (k = 0; k < 5; k++)
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 7.0));
    TEST_ASSERT_EQUAL_INT(n, cc_world_get_circles(w, NULL, c, n));
}

/* Identical input, identical output, bit for bit: twice in one place, in another buffer at a
 * different address, and after the world was moved (memcpy) to other memory midway. */
static void test_deterministic_and_address_free(void)
{
    enum { N = 200 };
    static cc_circle c1[N], c2[N], c3[N], c4[N];
    cc_world_def d;
    tw_mem m1, m2, m3;
    cc_world *w;
    unsigned char *moved_raw, *moved;
    cc_world_def_init(&d);
    d.max_circles = N;
    d.max_segments = 4;
    run_box(tw_make(&m1, &d, 0), c1, N);
    run_box(tw_make(&m2, &d, 0), c2, N);
    run_box(tw_make(&m3, &d, 48), c3, N);
    TEST_ASSERT_EQUAL_MEMORY(c1, c2, sizeof c1);
    TEST_ASSERT_EQUAL_MEMORY(c1, c3, sizeof c1);
    TEST_ASSERT_EQUAL_UINT64(tw_stats((cc_world *)(void *)m1.mem).events, tw_stats((cc_world *)(void *)m3.mem).events);
    tw_free(&m1);
    tw_free(&m2);
    tw_free(&m3);
    /* relocation: steps 0-2 in one buffer, 3-4 in a copy of it elsewhere */
    w = tw_make(&m1, &d, 0);
    (void)tw_fill_box(w, N, 1.0, 0.35, 3);
    {
        int k;
        for (k = 0; k < 3; k++)
            (void)cc_world_step(w, 7.0);
        moved_raw = (unsigned char *)malloc(m1.bytes + 64);
        moved = moved_raw + ((16u - ((size_t)moved_raw & 15u)) & 15u) + 32;
        memcpy(moved, m1.mem, m1.bytes);
        memset(m1.mem, 0, m1.bytes); /* the old copy is gone */
        w = (cc_world *)(void *)moved;
        for (k = 3; k < 5; k++)
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 7.0));
        TEST_ASSERT_EQUAL_INT(N, cc_world_get_circles(w, NULL, c4, N));
        TEST_ASSERT_EQUAL_MEMORY(c1, c4, sizeof c1);
        free(moved_raw);
    }
    tw_free(&m1);
}

/* A bullet (speed 1e4, radius 0.1: it travels 1e5 radii in a step of 1) meets a thin wall and,
 * in a second world, a small circle; EXACT never lets it through. */
static void test_no_tunnelling(void)
{
    tw_mem m;
    cc_world *w = world(&m, 1, 1, 1.0);
    cc_segment wall = tw_segment(10, -1, 10, 1);
    cc_circle bullet = tw_circle(0, 0, 1e4, 0, 0.1, 1), got;
    (void)cc_world_add_segment(w, &wall);
    (void)cc_world_add_circle(w, &bullet);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 1.0));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
    /* hits at x = 9.9 (t = 9.9e-4), comes back: x = 9.9 - 1e4 (1 - 9.9e-4) */
    TEST_ASSERT_EQUAL_DOUBLE(-1e4, got.vel.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, 9.9 - 1e4 * (1.0 - 9.9e-4), got.pos.x);
    tw_free(&m);

    w = world(&m, 2, 0, 1.0);
    {
        cc_circle target = tw_circle(10, 0, 0, 0, 0.1, 1);
        (void)cc_world_add_circle(w, &bullet);
        (void)cc_world_add_circle(w, &target);
    }
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 1.0));
    /* equal masses head-on: the bullet stops at x = 9.8, the target takes its velocity */
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
    TEST_ASSERT_EQUAL_DOUBLE(0.0, got.vel.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 9.8, got.pos.x);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 1, &got));
    TEST_ASSERT_EQUAL_DOUBLE(1e4, got.vel.x);
    tw_free(&m);
}

/* Immovable circles are obstacles: a circle bounces off a fixed one and the fixed one stays. */
static void test_immovable_obstacle(void)
{
    tw_mem m;
    cc_world *w = world(&m, 2, 0, 1.0);
    cc_circle a = tw_circle(0, 0, 1, 0, 1, 1), post = tw_circle(5, 0, 0, 0, 2, INFINITY), got;
    (void)cc_world_add_circle(w, &a);
    (void)cc_world_add_circle(w, &post);
    /* touch at x = 5 - 3 = 2, t = 2; back to x = 0 at t = 4 */
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 4.0));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
    TEST_ASSERT_EQUAL_DOUBLE(-1.0, got.vel.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.0, got.pos.x);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 1, &got));
    TEST_ASSERT_EQUAL_DOUBLE(5.0, got.pos.x);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, got.vel.x);
    tw_free(&m);
}

/* A circle set on top of another is pushed apart at once (shares inverse to mass) and the
 * pair, approaching, collides; set_circle keeps the id. */
static void test_overlap_after_set(void)
{
    tw_mem m;
    cc_world *w = world(&m, 2, 0, 1.0);
    cc_circle a = tw_circle(0, 0, 0, 0, 1, 1), b = tw_circle(10, 0, 0, 0, 1, 1), got_a, got_b;
    (void)cc_world_add_circle(w, &a);
    (void)cc_world_add_circle(w, &b);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 1.0));
    b = tw_circle(1, 0, -1, 0, 1, 1); /* depth 1: each moves 0.5 */
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle(w, 1, &b));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got_a));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 1, &got_b));
    TEST_ASSERT_EQUAL_DOUBLE(-0.5, got_a.pos.x);
    TEST_ASSERT_EQUAL_DOUBLE(1.5, got_b.pos.x);
    TEST_ASSERT_EQUAL_DOUBLE(-1.0, got_a.vel.x); /* b approached: velocities exchanged */
    TEST_ASSERT_EQUAL_DOUBLE(0.0, got_b.vel.x);
    TEST_ASSERT_EQUAL_UINT64(1, tw_stats(w).collisions);
    tw_free(&m);
}

/* Removing a circle mid-flight: nothing collides with it afterwards. */
static void test_remove_mid_flight(void)
{
    tw_mem m;
    cc_world *w = world(&m, 3, 0, 1.0);
    cc_circle a = tw_circle(0, 0, 1, 0, 1, 1), b = tw_circle(10, 0, 0, 0, 1, 1), got;
    (void)cc_world_add_circle(w, &a);
    (void)cc_world_add_circle(w, &b);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 5.0)); /* contact would be at t = 8 */
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_remove_circle(w, 1));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 10.0));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
    TEST_ASSERT_EQUAL_DOUBLE(15.0, got.pos.x);
    TEST_ASSERT_EQUAL_UINT64(0, tw_stats(w).collisions);
    tw_free(&m);
}

/* Inelastic collapse made certain: an immovable circle moving at speed 1 squeezes a light
 * circle against a wall; the gap closes in finite time, so the bounces would never end. The
 * event cap stops each step; the world stays consistent and its time is that of the last event,
 * short of the step's end (wall at x = 0, the pusher touches the squeezed circle's other side
 * at x = 2 + 1 at t = 2). */
static void test_event_cap_stops_collapse(void)
{
    cc_world_def d;
    tw_mem m;
    cc_world *w;
    cc_segment s = tw_segment(0, -10, 0, 10);
    cc_circle light = tw_circle(1.5, 0, 1, 0, 1, 1), pusher = tw_circle(6, 0, -1, 0, 2, INFINITY), got;
    double t;
    cc_world_def_init(&d);
    d.max_circles = 2;
    d.max_segments = 1;
    d.restitution = 0.5;
    d.max_events = 1000;
    w = tw_make(&m, &d, 0);
    (void)cc_world_add_segment(w, &s);
    (void)cc_world_add_circle(w, &light);
    (void)cc_world_add_circle(w, &pusher);
    TEST_ASSERT_EQUAL_INT(CC_EVENT_LIMIT, cc_world_step(w, 10.0));
    t = cc_world_time(w);
    TEST_ASSERT_TRUE(t > 0.0 && t <= 2.0 + 1e-12);
    TEST_ASSERT_EQUAL_UINT64(1000, tw_stats(w).events);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
    TEST_ASSERT_TRUE(got.pos.x >= 1.0 - 1e-9);
    TEST_ASSERT_EQUAL_INT(CC_EVENT_LIMIT, cc_world_step(w, 10.0)); /* another call continues */
    TEST_ASSERT_EQUAL_UINT64(2000, tw_stats(w).events);
    TEST_ASSERT_TRUE(cc_world_time(w) >= t);
    tw_free(&m);
}

/* rest_speed: approaches slower than it are perfectly inelastic. Three equal circles in a row,
 * e = 0.05 (below 7 - 4 sqrt 3, where three bodies collapse): with rest_speed the middle one
 * stops bouncing after a few collisions, and a step completes. */
static uint64_t three_in_a_row(double rest_speed)
{
    cc_world_def d;
    tw_mem m;
    cc_world *w;
    cc_circle c;
    uint64_t n;
    int r;
    cc_world_def_init(&d);
    d.max_circles = 3;
    d.restitution = 0.05;
    d.rest_speed = rest_speed;
    d.max_events = 100000;
    w = tw_make(&m, &d, 0);
    c = tw_circle(0, 0, 1, 0, 1, 1);
    (void)cc_world_add_circle(w, &c);
    c = tw_circle(3, 0, 0, 0, 1, 1);
    (void)cc_world_add_circle(w, &c);
    c = tw_circle(6.5, 0, -1, 0, 1, 1); /* not at the same instant as the first: that would be one
                                       simultaneous impact, resolved at once (docs/SIMULTANEOUS.md) */
    (void)cc_world_add_circle(w, &c);
    r = cc_world_step(w, 100.0);
    TEST_ASSERT_TRUE(r == CC_OK || r == CC_EVENT_LIMIT);
    n = tw_stats(w).collisions;
    printf("three in a row, rest_speed %g: %llu collisions, %s\n", rest_speed, (unsigned long long)n,
           cc_result_string(r));
    if (rest_speed > 0.0)
        TEST_ASSERT_EQUAL_INT(CC_OK, r);
    tw_free(&m);
    return n;
}

static void test_rest_speed_ends_collapse(void)
{
    uint64_t without = three_in_a_row(0.0), with = three_in_a_row(1e-3);
    TEST_ASSERT_TRUE(with < 100);
    TEST_ASSERT_TRUE(with < without);
}

/* Circles placed overlapping before the first step: the first step pushes them apart (equal
 * masses: 0.25 each, so the centres end 2 apart) and, as they approach, exchanges velocities.
 * A circle placed through a wall is pushed out along the wall's normal. */
static void test_overlap_at_start(void)
{
    tw_mem m;
    cc_world *w = world(&m, 3, 1, 1.0);
    cc_circle a = tw_circle(0, 0, 1, 0, 1, 1), b = tw_circle(1.5, 0, -1, 0, 1, 1), c = tw_circle(0, 10.5, 0, 0, 1, 1), got;
    cc_segment floor_ = tw_segment(-5, 10, 5, 10);
    (void)cc_world_add_segment(w, &floor_);
    (void)cc_world_add_circle(w, &a);
    (void)cc_world_add_circle(w, &b);
    (void)cc_world_add_circle(w, &c);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.0));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
    TEST_ASSERT_EQUAL_DOUBLE(-0.25, got.pos.x);
    TEST_ASSERT_EQUAL_DOUBLE(-1.0, got.vel.x);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 1, &got));
    TEST_ASSERT_EQUAL_DOUBLE(1.75, got.pos.x);
    TEST_ASSERT_EQUAL_DOUBLE(1.0, got.vel.x);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 2, &got));
    TEST_ASSERT_EQUAL_DOUBLE(11.0, got.pos.y); /* out of the wall y = 10: centre at 10 + 1 */
    TEST_ASSERT_EQUAL_UINT64(1, tw_stats(w).collisions); /* c was at rest: no impulse */
    TEST_ASSERT_EQUAL_DOUBLE(0.5, tw_stats(w).max_overlap); /* the deepest overlap seen */
    tw_free(&m);
}

/* A world with a grid (more than 32 circles) and an immovable circle far wider than its cells:
 * the obstacle goes on the large list and every circle still bounces off it. 20 circles on a
 * ring of radius 30 fly at speed 1 towards a fixed disc of radius 10 at the centre (at radius 11
 * they are still 2 pi 11 / 20 = 3.5 apart: they never touch each other); each touches the disc
 * when its centre is 11 from the centre, at t = 19, and comes straight back. 20 more circles
 * rest far away, only to make the world big enough for a grid. */
static void test_large_obstacle_in_grid(void)
{
    enum { RING = 20, N = 41 };
    tw_mem m;
    cc_world *w = world(&m, N, 0, 1.0);
    cc_circle disc = tw_circle(0, 0, 0, 0, 10, INFINITY), got;
    int i;
    (void)cc_world_add_circle(w, &disc);
    for (i = 1; i <= RING; i++) {
        double a = 6.283185307179586 * i / RING;
        cc_circle c = tw_circle(30 * cos(a), 30 * sin(a), -cos(a), -sin(a), 1, 1);
        (void)cc_world_add_circle(w, &c);
    }
    for (i = RING + 1; i < N; i++) {
        cc_circle c = tw_circle(1000 + 3 * i, 0, 0, 0, 1, 1);
        (void)cc_world_add_circle(w, &c);
    }
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 38.0));
    for (i = 1; i <= RING; i++) {
        double a = 6.283185307179586 * i / RING;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, i, &got));
        /* back at radius 30 at t = 38, moving outwards */
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, 30 * cos(a), got.pos.x);
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, 30 * sin(a), got.pos.y);
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, cos(a), got.vel.x);
    }
    TEST_ASSERT_EQUAL_UINT64(RING, tw_stats(w).collisions);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
    TEST_ASSERT_EQUAL_DOUBLE(0.0, got.pos.x);
    tw_free(&m);
}

/* An immovable circle with a velocity (a paddle at speed 2) strikes a resting unit circle: the
 * circle leaves at twice the paddle's speed (elastic bounce off an infinite mass), the paddle
 * keeps its own. Paddle radius 1 at x = 0, ball at x = 5: contact at t = (5 - 2) / 2 = 1.5. */
static void test_moving_immovable(void)
{
    tw_mem m;
    cc_world *w = world(&m, 2, 0, 1.0);
    cc_circle paddle = tw_circle(0, 0, 2, 0, 1, INFINITY), ball = tw_circle(5, 0, 0, 0, 1, 1), got;
    (void)cc_world_add_circle(w, &paddle);
    (void)cc_world_add_circle(w, &ball);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 2.0));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 1, &got));
    TEST_ASSERT_EQUAL_DOUBLE(4.0, got.vel.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 5.0 + 4.0 * 0.5, got.pos.x);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
    TEST_ASSERT_EQUAL_DOUBLE(2.0, got.vel.x);
    TEST_ASSERT_EQUAL_DOUBLE(4.0, got.pos.x);
    tw_free(&m);
}

/* Churn: a box gas where every step removes some circles, adds new ones in free places (at
 * rest or moving) and changes the velocity of others, all between steps of a running world.
 * Exercises the incremental paths (refiling, predicting neighbours, stale events): nothing
 * overlaps, nothing escapes, every id stays as given. */
static void test_churn(void)
{
    enum { N = 300 };
    static cc_circle c[N];
    static int ids[N];
    tw_mem m;
    cc_world *w = world(&m, N, 4, 1.0);
    double L = tw_fill_box(w, N - 20, 1.0, 0.3, 77);
    uint64_t seed = 8;
    int k, n;
    for (k = 0; k < 60; k++) {
        int r;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.7));
        n = cc_world_get_circles(w, ids, c, N);
        for (r = 0; r < 4 && n > 0; r++) { /* remove a few */
            int pick = (int)(tw_rand(&seed) * n);
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_remove_circle(w, ids[pick]));
            ids[pick] = ids[--n];
        }
        for (r = 0; r < 3; r++) { /* new velocities for some */
            int pick = (int)(tw_rand(&seed) * n);
            cc_circle got;
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, ids[pick], &got));
            got.vel.x = 4 * tw_rand(&seed) - 2;
            got.vel.y = (k % 3 == 0) ? 0.0 : 4 * tw_rand(&seed) - 2;
            if (k % 5 == 0)
                got.vel.x = got.vel.y = 0.0; /* stop it: movers must find it */
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle(w, ids[pick], &got));
        }
        for (r = 0; r < 4; r++) { /* add where there is room */
            int tries;
            for (tries = 0; tries < 50; tries++) {
                cc_circle nc = tw_circle(1 + (L - 2) * tw_rand(&seed), 1 + (L - 2) * tw_rand(&seed),
                                      (r & 1) ? 2 * tw_rand(&seed) - 1 : 0.0, (r & 1) ? 2 * tw_rand(&seed) - 1 : 0.0,
                                      1, 1);
                int j, free_ = 1, id;
                n = cc_world_get_circles(w, ids, c, N);
                for (j = 0; j < n && free_; j++)
                    free_ = hypot(c[j].pos.x - nc.pos.x, c[j].pos.y - nc.pos.y) > 2.0 + 1e-9;
                if (!free_)
                    continue;
                id = cc_world_add_circle(w, &nc);
                TEST_ASSERT_TRUE(id >= 0);
                break;
            }
        }
        n = cc_world_get_circles(w, NULL, c, N);
        TEST_ASSERT_EQUAL_INT(0, tw_escapes(c, n, L, TW_OVERLAP_TOL));
        TEST_ASSERT_TRUE(tw_max_rel_overlap(c, n, 1.0) < TW_OVERLAP_TOL);
    }
    TEST_ASSERT_TRUE(tw_stats(w).collisions > 1000);
    TEST_ASSERT_TRUE(tw_canary_ok(&m));
    tw_free(&m);
}

/* Units are the caller's: the same gas with lengths (and speeds) scaled by 2^30 or 2^-30, exact
 * powers of two, runs through the very same events and ends bit for bit at the scaled state. */
static void scaled_gas(double s, cc_circle *out, int n, uint64_t *events)
{
    cc_world_def d;
    tw_mem m;
    cc_world *w;
    uint64_t seed = 21;
    double L = 40.0 * s;
    int i;
    cc_segment walls[4];
    cc_world_def_init(&d);
    d.max_circles = n;
    d.max_segments = 4;
    w = tw_make(&m, &d, 0);
    walls[0] = tw_segment(0, 0, L, 0);
    walls[1] = tw_segment(L, 0, L, L);
    walls[2] = tw_segment(L, L, 0, L);
    walls[3] = tw_segment(0, L, 0, 0);
    for (i = 0; i < 4; i++)
        (void)cc_world_add_segment(w, &walls[i]);
    for (i = 0; i < n; i++) {
        cc_circle c = tw_circle(s * (2.5 + 4.0 * (i % 9)), s * (2.5 + 4.0 * (i / 9)), s * (2 * tw_rand(&seed) - 1),
                             s * (2 * tw_rand(&seed) - 1), s * (0.5 + tw_rand(&seed)), 1 + tw_rand(&seed));
        (void)cc_world_add_circle(w, &c);
    }
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 50.0));
    TEST_ASSERT_EQUAL_INT(n, cc_world_get_circles(w, NULL, out, n));
    *events = tw_stats(w).events;
    tw_free(&m);
}

static void test_scale_invariance(void)
{
    enum { N = 72 };
    static cc_circle base[N], big[N], small[N];
    uint64_t e0, e1, e2;
    int i;
    scaled_gas(1.0, base, N, &e0);
    scaled_gas(0x1p30, big, N, &e1);
    scaled_gas(0x1p-30, small, N, &e2);
    TEST_ASSERT_EQUAL_UINT64(e0, e1);
    TEST_ASSERT_EQUAL_UINT64(e0, e2);
    for (i = 0; i < N; i++) { /* bit for bit: scale the small ones up, exactly */
        small[i].pos.x *= 0x1p30;
        small[i].pos.y *= 0x1p30;
        small[i].vel.x *= 0x1p30;
        small[i].vel.y *= 0x1p30;
        small[i].radius *= 0x1p30;
        big[i].pos.x *= 0x1p-30;
        big[i].pos.y *= 0x1p-30;
        big[i].vel.x *= 0x1p-30;
        big[i].vel.y *= 0x1p-30;
        big[i].radius *= 0x1p-30;
    }
    TEST_ASSERT_EQUAL_MEMORY(base, big, sizeof base);
    TEST_ASSERT_EQUAL_MEMORY(base, small, sizeof base);
    TEST_ASSERT_TRUE(e0 > 1000);
}

/* The same wall bounce in a world with room for 100 circles (so with a grid) holding just one:
 * nothing in the grid's bookkeeping may depend on having company. */
static void test_lone_circle_in_grid_world(void)
{
    tw_mem m;
    cc_world *w = world(&m, 100, 1, 1.0);
    cc_circle a = tw_circle(5, 0, -2, 0, 1, 1), got;
    cc_segment s = tw_segment(0, -5, 0, 5);
    (void)cc_world_add_segment(w, &s);
    (void)cc_world_add_circle(w, &a);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 3.0));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
    TEST_ASSERT_EQUAL_DOUBLE(3.0, got.pos.x); /* wall at t = 2, then 1 back at speed 2 */
    TEST_ASSERT_EQUAL_DOUBLE(2.0, got.vel.x);
    TEST_ASSERT_EQUAL_UINT64(1, tw_stats(w).collisions);
    tw_free(&m);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_head_on_pair);
    RUN_TEST(test_wall_bounce);
    RUN_TEST(test_galperin_pi);
    RUN_TEST(test_box_gas_invariants);
    RUN_TEST(test_momentum_and_energy);
    RUN_TEST(test_deterministic_and_address_free);
    RUN_TEST(test_no_tunnelling);
    RUN_TEST(test_immovable_obstacle);
    RUN_TEST(test_overlap_after_set);
    RUN_TEST(test_remove_mid_flight);
    RUN_TEST(test_event_cap_stops_collapse);
    RUN_TEST(test_rest_speed_ends_collapse);
    RUN_TEST(test_overlap_at_start);
    RUN_TEST(test_large_obstacle_in_grid);
    RUN_TEST(test_moving_immovable);
    RUN_TEST(test_churn);
    RUN_TEST(test_scale_invariance);
    RUN_TEST(test_lone_circle_in_grid_world);
    return UNITY_END();
}
