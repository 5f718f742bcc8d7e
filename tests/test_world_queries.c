/* Queries and state (issue 14): casts derived by hand, overlap queries and casts against brute
 * force over random worlds (exact agreement), and the state hash. */
#include "unity.h"

#include "test_world_util.h"

#include <stdio.h>

void setUp(void) {}
void tearDown(void) {}

static cc_vec2 v2(double x, double y)
{
    cc_vec2 v;
    v.x = x;
    v.y = y;
    return v;
}

static cc_world *small(tw_mem *m, int max_circles, int max_segments)
{
    cc_world_def d;
    cc_world_def_init(&d);
    d.max_circles = max_circles;
    d.max_segments = max_segments;
    return tw_make(m, &d, 0);
}

/* ---- casts by hand ---------------------------------------------------------------------------- */

/* A ray along +x from the origin over 20 units, a circle of radius 1 at (10, 0) and a wall at
 * x = 5: the wall first, at t = 5/20; without the wall, the circle's surface at x = 9: t = 9/20.
 * A cast of radius 1 touches the wall with its centre at x = 4: t = 0.2, contact (5, 0). */
static void test_ray_and_circle_cast_along_x(void)
{
    tw_mem m;
    cc_world *w = small(&m, 64, 2);
    cc_circle c = tw_circle(10, 0, 0, 0, 1, 1);
    cc_segment wall = tw_segment(5, -3, 5, 3);
    cc_cast_hit h;
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &c));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.0));
    TEST_ASSERT_EQUAL_INT(CC_HIT, cc_world_cast_circle(w, v2(0, 0), 0.0, v2(20, 0), 0xFFFFFFFFu, &h));
    TEST_ASSERT_EQUAL_INT(0, h.circle);
    TEST_ASSERT_EQUAL_INT(-1, h.segment);
    TEST_ASSERT_EQUAL_DOUBLE(0.45, h.t);
    TEST_ASSERT_EQUAL_DOUBLE(9.0, h.point.x);
    TEST_ASSERT_EQUAL_DOUBLE(1.0, h.normal.x);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, h.normal.y);
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_segment(w, &wall));
    TEST_ASSERT_EQUAL_INT(CC_HIT, cc_world_cast_circle(w, v2(0, 0), 0.0, v2(20, 0), 0xFFFFFFFFu, &h));
    TEST_ASSERT_EQUAL_INT(-1, h.circle);
    TEST_ASSERT_EQUAL_INT(0, h.segment);
    TEST_ASSERT_EQUAL_DOUBLE(0.25, h.t);
    TEST_ASSERT_EQUAL_DOUBLE(5.0, h.point.x);
    TEST_ASSERT_EQUAL_DOUBLE(1.0, h.normal.x);
    TEST_ASSERT_EQUAL_INT(CC_HIT, cc_world_cast_circle(w, v2(0, 0), 1.0, v2(20, 0), 0xFFFFFFFFu, &h));
    TEST_ASSERT_EQUAL_INT(0, h.segment);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.2, h.t);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 5.0, h.point.x);
    /* short of everything: a miss, out untouched */
    memset(&h, 0x5A, sizeof h);
    {
        cc_cast_hit same;
        memset(&same, 0x5A, sizeof same);
        TEST_ASSERT_EQUAL_INT(CC_MISS, cc_world_cast_circle(w, v2(0, 0), 0.0, v2(4, 0), 0xFFFFFFFFu, &h));
        TEST_ASSERT_EQUAL_MEMORY(&same, &h, sizeof h);
    }
    tw_free(&m);
}

/* Grazing: a ray along y = 1 is tangent to the circle of radius 1 at (10, 0): tangent is not a
 * hit. Along y = 1 - 2^-20 it enters where x = 10 - sqrt(1 - (1 - 2^-20)^2). */
static void test_ray_grazing_a_circle(void)
{
    tw_mem m;
    cc_world *w = small(&m, 64, 0);
    cc_circle c = tw_circle(10, 0, 0, 0, 1, 1);
    cc_cast_hit h;
    double y = 1.0 - 0x1p-20, x = 10.0 - sqrt(1.0 - y * y);
    (void)cc_world_add_circle(w, &c);
    TEST_ASSERT_EQUAL_INT(CC_MISS, cc_world_cast_circle(w, v2(0, 1), 0.0, v2(20, 0), 0xFFFFFFFFu, &h));
    TEST_ASSERT_EQUAL_INT(CC_HIT, cc_world_cast_circle(w, v2(0, y), 0.0, v2(20, 0), 0xFFFFFFFFu, &h));
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, x / 20.0, h.t);
    tw_free(&m);
}

/* Starting inside a circle: an overlap at t = 0, the normal towards its centre; a cast that
 * does not move (d = 0) finds only overlaps. */
static void test_cast_starting_inside(void)
{
    tw_mem m;
    cc_world *w = small(&m, 64, 0);
    cc_circle c = tw_circle(10, 0, 0, 0, 1, 1);
    cc_cast_hit h;
    (void)cc_world_add_circle(w, &c);
    TEST_ASSERT_EQUAL_INT(CC_OVERLAP, cc_world_cast_circle(w, v2(10, 0.5), 0.0, v2(20, 0), 0xFFFFFFFFu, &h));
    TEST_ASSERT_EQUAL_INT(0, h.circle);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, h.t);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, h.normal.x);
    TEST_ASSERT_EQUAL_DOUBLE(-1.0, h.normal.y);
    TEST_ASSERT_EQUAL_INT(CC_OVERLAP, cc_world_cast_circle(w, v2(10, 0.5), 0.0, v2(0, 0), 0xFFFFFFFFu, &h));
    TEST_ASSERT_EQUAL_INT(CC_MISS, cc_world_cast_circle(w, v2(0, 0), 0.0, v2(0, 0), 0xFFFFFFFFu, &h));
    TEST_ASSERT_EQUAL_INT(CC_OVERLAP, cc_world_cast_circle(w, v2(8.5, 0), 0.75, v2(0, 0), 0xFFFFFFFFu, &h));
    tw_free(&m);
}

/* Masks and sensors: a circle of category 2 is passed by a cast of mask 1 and hit by one of mask
 * 2; a sensor in the way is never hit. Ties: two circles touched at the same t go to the lower
 * id; a circle and a wall at the same t to the circle. */
static void test_cast_masks_sensors_and_ties(void)
{
    tw_mem m;
    cc_world *w = small(&m, 64, 2);
    cc_circle near = tw_circle(5, 0, 0, 0, 1, 1), far = tw_circle(10, 0, 0, 0, 1, 1), pocket = tw_circle(2, 0, 0, 0, 1, INFINITY);
    cc_circle_props p;
    cc_cast_hit h;
    (void)cc_world_add_circle(w, &near); /* 0 */
    (void)cc_world_add_circle(w, &far);  /* 1 */
    (void)cc_world_add_circle(w, &pocket); /* 2 */
    p.struct_size = sizeof p;
    (void)cc_world_get_circle_props(w, 0, &p);
    p.category = 2u;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, 0, &p));
    (void)cc_world_get_circle_props(w, 2, &p);
    p.sensor = 1;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, 2, &p));
    TEST_ASSERT_EQUAL_INT(CC_HIT, cc_world_cast_circle(w, v2(-5, 0), 0.0, v2(20, 0), 1u, &h));
    TEST_ASSERT_EQUAL_INT(1, h.circle); /* 0 is of category 2, 2 is a sensor */
    TEST_ASSERT_EQUAL_INT(CC_HIT, cc_world_cast_circle(w, v2(-5, 0), 0.0, v2(20, 0), 2u, &h));
    TEST_ASSERT_EQUAL_INT(0, h.circle);
    tw_free(&m);
    /* ties: circles 0 and 1 at (5, -+1.2) of radius 1, a cast of radius 1 along y = 0 touches
     * both when its centre is at x = 5 - 1.6 (1.6^2 + 1.2^2 = 2^2), at the same time by symmetry:
     * the lower id. A cast that starts overlapping a circle and a wall at once: the circle. */
    w = small(&m, 64, 1);
    {
        cc_circle a = tw_circle(5, 1.2, 0, 0, 1, 1), b = tw_circle(5, -1.2, 0, 0, 1, 1);
        cc_segment wall = tw_segment(5, -10, 5, 10);
        (void)cc_world_add_circle(w, &b); /* 0, below */
        (void)cc_world_add_circle(w, &a); /* 1, above */
        TEST_ASSERT_EQUAL_INT(CC_HIT, cc_world_cast_circle(w, v2(0, 0), 1.0, v2(10, 0), 0xFFFFFFFFu, &h));
        TEST_ASSERT_EQUAL_INT(0, h.circle);
        TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.34, h.t);
        (void)cc_world_add_segment(w, &wall);
        TEST_ASSERT_EQUAL_INT(CC_OVERLAP, cc_world_cast_circle(w, v2(4.5, 1.0), 1.0, v2(10, 0), 0xFFFFFFFFu, &h));
        TEST_ASSERT_EQUAL_INT(1, h.circle); /* the one above, which it overlaps (0 it does not) */
        TEST_ASSERT_EQUAL_INT(-1, h.segment);
    }
    tw_free(&m);
}

static void test_query_errors(void)
{
    tw_mem m;
    cc_world *w = small(&m, 64, 0);
    int ids[4];
    cc_cast_hit h;
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_query_circle(NULL, v2(0, 0), 1, 1u, ids, 4));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_query_circle(w, v2(NAN, 0), 1, 1u, ids, 4));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_query_circle(w, v2(0, 0), -1, 1u, ids, 4));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_query_circle(w, v2(0, 0), 1, 1u, NULL, 4));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_query_circle(w, v2(0, 0), 1, 1u, ids, -1));
    TEST_ASSERT_EQUAL_INT(0, cc_world_query_circle(w, v2(0, 0), 1, 1u, NULL, 0));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_query_box(w, v2(1, 0), v2(0, 1), 1u, ids, 4));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_query_box(w, v2(0, 0), v2(INFINITY, 1), 1u, ids, 4));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_cast_circle(w, v2(0, 0), -1.0, v2(1, 0), 1u, &h));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_cast_circle(w, v2(0, 0), 1.0, v2(NAN, 0), 1u, &h));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_cast_circle(w, v2(0, 0), 1.0, v2(1, 0), 1u, NULL));
    TEST_ASSERT_EQUAL_UINT64(0, cc_world_hash(NULL));
    tw_free(&m);
}

/* ---- against brute force ------------------------------------------------------------------- */

static uint64_t g_rng = 88172645463325252u;
static double rnd(double lo, double hi)
{
    g_rng ^= g_rng << 13;
    g_rng ^= g_rng >> 7;
    g_rng ^= g_rng << 17;
    return lo + (hi - lo) * (double)(g_rng >> 11) * 0x1p-53;
}

/* A random world: n circles of radii 0.3-1.5 (some immovable, some sensors, categories 1 or 2)
 * in a box of walls, stepped for a while so that EXACT's grid is in use. */
static cc_world *random_world(tw_mem *m, int n, int mode, double L)
{
    cc_world_def d;
    cc_world *w;
    int k;
    cc_world_def_init(&d);
    d.max_circles = n + 8;
    d.max_segments = 8;
    d.mode = mode;
    w = tw_make(m, &d, 0);
    (void)cc_world_add_segment(w, &(cc_segment){{-L, -L}, {L, -L}});
    (void)cc_world_add_segment(w, &(cc_segment){{L, -L}, {L, L}});
    (void)cc_world_add_segment(w, &(cc_segment){{L, L}, {-L, L}});
    (void)cc_world_add_segment(w, &(cc_segment){{-L, L}, {-L, -L}});
    (void)cc_world_add_segment(w, &(cc_segment){{-0.3 * L, 0.2 * L}, {0.1 * L, 0.4 * L}});
    for (k = 0; k < n; k++) {
        cc_circle c = tw_circle(rnd(-L + 2, L - 2), rnd(-L + 2, L - 2), rnd(-1, 1), rnd(-1, 1), rnd(0.3, 1.5),
                                rnd(0, 1) < 0.1 ? INFINITY : rnd(0.5, 2));
        if (isinf(c.mass)) /* obstacles at rest: a kinematic one could pin a circle to a wall */
            c.vel = v2(0, 0);
        int id = cc_world_add_circle(w, &c);
        cc_circle_props p;
        p.struct_size = sizeof p;
        (void)cc_world_get_circle_props(w, id, &p);
        p.category = rnd(0, 1) < 0.5 ? 1u : 2u;
        p.sensor = rnd(0, 1) < 0.05;
        (void)cc_world_set_circle_props(w, id, &p);
    }
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 2.0));
    return w;
}

/* 2,000 disc queries and 2,000 box queries on each of five worlds (EXACT large and small, SWEPT,
 * DISCRETE, and EXACT before its first step): the same ids, in the same order, as testing every
 * circle by the contract's own rule; counts beyond a small capacity too. */
static void test_queries_against_brute_force(void)
{
    static const int modes[5] = {CC_MODE_EXACT, CC_MODE_EXACT, CC_MODE_SWEPT, CC_MODE_DISCRETE, CC_MODE_EXACT};
    static const int sizes[5] = {600, 20, 300, 300, 300};
    int v, q, total = 0;
    for (v = 0; v < 5; v++) {
        tw_mem m;
        double L = 2.0 * sqrt((double)sizes[v]);
        cc_world *w = random_world(&m, sizes[v], modes[v], L);
        cc_circle c[700];
        int ids[700], got[700], want[700], n, k;
        if (v == 4) { /* before the first step's rebuild: a circle added now is not in the grid yet */
            cc_circle extra = tw_circle(0, 0, 0, 0, 1, 1);
            cc_segment s = tw_segment(100, 100, 101, 101);
            (void)cc_world_add_segment(w, &s); /* the world waits for its rebuild */
            (void)cc_world_add_circle(w, &extra);
        }
        n = cc_world_get_circles(w, ids, c, 700);
        for (q = 0; q < 4000; q++, total++) {
            int box = q & 1, cap = q % 7 == 0 ? 3 : 700, count = 0, r;
            uint32_t mask = q % 5 == 0 ? 2u : 0xFFFFFFFFu;
            cc_vec2 lo = v2(rnd(-L, L), rnd(-L, L)), hi = v2(lo.x + rnd(0, 5), lo.y + rnd(0, 5));
            double rad = q % 11 == 0 ? 0.0 : rnd(0, 4);
            for (k = 0; k < n; k++) {
                cc_circle_props p;
                int in;
                p.struct_size = sizeof p;
                (void)cc_world_get_circle_props(w, ids[k], &p);
                if (!(p.category & mask))
                    continue;
                if (box) {
                    double dx = c[k].pos.x < lo.x ? lo.x - c[k].pos.x : c[k].pos.x > hi.x ? c[k].pos.x - hi.x : 0.0;
                    double dy = c[k].pos.y < lo.y ? lo.y - c[k].pos.y : c[k].pos.y > hi.y ? c[k].pos.y - hi.y : 0.0;
                    in = dx * dx + dy * dy <= c[k].radius * c[k].radius;
                } else {
                    double dx = c[k].pos.x - lo.x, dy = c[k].pos.y - lo.y, R = rad + c[k].radius;
                    in = dx * dx + dy * dy < R * R;
                }
                if (in)
                    want[count++] = ids[k]; /* ids come in increasing order */
            }
            r = box ? cc_world_query_box(w, lo, hi, mask, got, cap) : cc_world_query_circle(w, lo, rad, mask, got, cap);
            TEST_ASSERT_EQUAL_INT(count, r);
            if (count > 0)
                TEST_ASSERT_EQUAL_MEMORY(want, got, sizeof(int) * (size_t)(count < cap ? count : cap));
        }
        tw_free(&m);
    }
    printf("%d queries agree with brute force\n", total);
}

/* Casts against cc_sweep and cc_sweep_segment over every circle and wall (radius > 0): the same
 * hit, the same time bit for bit, the same normal. Long casts too (across the whole world). */
static void test_casts_against_brute_force(void)
{
    int v, q, total = 0, hits = 0;
    for (v = 0; v < 3; v++) {
        tw_mem m;
        int n = v == 0 ? 800 : v == 1 ? 20 : 300, mode = v == 2 ? CC_MODE_SWEPT : CC_MODE_EXACT;
        double L = 2.0 * sqrt((double)n);
        cc_world *w = random_world(&m, n, mode, L);
        cc_circle c[900];
        int ids[900], k;
        n = cc_world_get_circles(w, ids, c, 900);
        for (q = 0; q < 2000; q++, total++) {
            cc_vec2 p = v2(rnd(-L, L), rnd(-L, L)), d = v2(rnd(-1, 1) * (q % 3 ? 5.0 : 3 * L), rnd(-1, 1) * 5.0);
            double rad = rnd(0.01, q % 4 ? 1.0 : 6.0), best = HUGE_VAL;
            int best_c = -1, best_s = -1, best_touch = 1, r, s;
            cc_vec2 best_n = v2(0, 0);
            cc_circle cast = tw_circle(p.x, p.y, d.x, d.y, rad, 1);
            cc_cast_hit h;
            for (k = 0; k < n; k++) {
                cc_circle_props pp;
                cc_circle still = c[k];
                cc_contact t;
                pp.struct_size = sizeof pp;
                (void)cc_world_get_circle_props(w, ids[k], &pp);
                if (pp.sensor)
                    continue;
                still.vel = v2(0, 0);
                r = cc_sweep(&cast, &still, 1.0, &t);
                if (r == CC_OVERLAP)
                    t.t = 0.0;
                if ((r == CC_HIT || r == CC_OVERLAP) &&
                    (t.t < best || (t.t == best && (r == CC_OVERLAP) > !best_touch))) {
                    best = t.t, best_c = ids[k], best_s = -1, best_touch = r == CC_HIT, best_n = t.normal;
                }
            }
            for (s = 0; s < 5; s++) {
                cc_segment seg;
                cc_contact t;
                (void)cc_world_get_segment(w, s, &seg);
                r = cc_sweep_segment(&cast, &seg, 1.0, &t);
                if (r == CC_OVERLAP)
                    t.t = 0.0;
                if ((r == CC_HIT || r == CC_OVERLAP) && (t.t < best || (t.t == best && r == CC_OVERLAP && best_touch))) {
                    best = t.t, best_c = -1, best_s = s, best_touch = r == CC_HIT, best_n = t.normal;
                }
            }
            r = cc_world_cast_circle(w, p, rad, d, 0xFFFFFFFFu, &h);
            if (best > 1.0) {
                TEST_ASSERT_EQUAL_INT(CC_MISS, r);
                continue;
            }
            hits++;
            TEST_ASSERT_EQUAL_INT(best_touch ? CC_HIT : CC_OVERLAP, r);
            TEST_ASSERT_EQUAL_INT(best_c, h.circle);
            TEST_ASSERT_EQUAL_INT(best_s, h.segment);
            TEST_ASSERT_EQUAL_DOUBLE(best, h.t);
            if (best_touch) {
                TEST_ASSERT_EQUAL_DOUBLE(best_n.x, h.normal.x);
                TEST_ASSERT_EQUAL_DOUBLE(best_n.y, h.normal.y);
            }
        }
        tw_free(&m);
    }
    printf("%d casts agree with brute force (%d hits)\n", total, hits);
}

/* ---- the state hash -------------------------------------------------------------------------- */

static void test_hash_equal_states_equal_hashes(void)
{
    tw_mem m1, m2;
    cc_world *a = random_world(&m1, 200, CC_MODE_EXACT, 30.0), *b;
    uint64_t h = cc_world_hash(a);
    unsigned char *copy;
    TEST_ASSERT_TRUE(h != 0);
    TEST_ASSERT_EQUAL_UINT64(h, cc_world_hash(a)); /* reading changes nothing */
    /* a memcpy to other memory */
    copy = (unsigned char *)malloc(m1.bytes + 16);
    memcpy(copy + 8, m1.mem, m1.bytes);
    TEST_ASSERT_EQUAL_UINT64(h, cc_world_hash((cc_world *)(void *)(copy + 8)));
    free(copy);
    /* the same calls on another world */
    g_rng = 88172645463325252u;
    a = (tw_free(&m1), random_world(&m1, 200, CC_MODE_EXACT, 30.0));
    g_rng = 88172645463325252u;
    b = random_world(&m2, 200, CC_MODE_EXACT, 30.0);
    TEST_ASSERT_EQUAL_UINT64(cc_world_hash(a), cc_world_hash(b));
    tw_free(&m1);
    tw_free(&m2);
}

/* One bit of anything: a position, a velocity, a property, a wall's property, the time. */
static void test_hash_one_bit_apart(void)
{
    tw_mem m;
    cc_world *w = small(&m, 64, 1);
    cc_circle c = tw_circle(1, 2, 3, 4, 1, 1);
    cc_segment s = tw_segment(50, 0, 50, 10);
    cc_circle_props p;
    cc_segment_props q;
    uint64_t h0, h;
    (void)cc_world_add_circle(w, &c);
    (void)cc_world_add_segment(w, &s);
    h0 = cc_world_hash(w);
    c.pos.x = nextafter(1.0, 2.0);
    (void)cc_world_set_circle(w, 0, &c);
    h = cc_world_hash(w);
    TEST_ASSERT_TRUE(h != h0);
    c.pos.x = 1.0;
    (void)cc_world_set_circle(w, 0, &c);
    TEST_ASSERT_EQUAL_UINT64(h0, cc_world_hash(w)); /* back: the same state */
    c.vel.y = nextafter(4.0, 5.0);
    (void)cc_world_set_circle(w, 0, &c);
    TEST_ASSERT_TRUE(cc_world_hash(w) != h0);
    c.vel.y = 4.0;
    (void)cc_world_set_circle(w, 0, &c);
    p.struct_size = sizeof p;
    (void)cc_world_get_circle_props(w, 0, &p);
    p.restitution = nextafter(1.0, 0.0);
    (void)cc_world_set_circle_props(w, 0, &p);
    TEST_ASSERT_TRUE(cc_world_hash(w) != h0);
    p.restitution = 1.0;
    (void)cc_world_set_circle_props(w, 0, &p);
    TEST_ASSERT_EQUAL_UINT64(h0, cc_world_hash(w));
    q.struct_size = sizeof q;
    (void)cc_world_get_segment_props(w, 0, &q);
    q.mask ^= 1u << 31;
    (void)cc_world_set_segment_props(w, 0, &q);
    TEST_ASSERT_TRUE(cc_world_hash(w) != h0);
    q.mask ^= 1u << 31;
    (void)cc_world_set_segment_props(w, 0, &q);
    TEST_ASSERT_EQUAL_UINT64(h0, cc_world_hash(w));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0x1p-40)); /* the time, and the circle with it */
    TEST_ASSERT_TRUE(cc_world_hash(w) != h0);
    tw_free(&m);
}

/* Lock-step: two worlds fed the same inputs keep equal hashes, step after step, over 1e5
 * collisions (the gas of 400 circles in a box). */
static void test_hash_lock_step(void)
{
    tw_mem m1, m2;
    cc_world *a, *b;
    int steps = 0;
    g_rng = 1234567;
    a = random_world(&m1, 400, CC_MODE_EXACT, 25.0);
    g_rng = 1234567;
    b = random_world(&m2, 400, CC_MODE_EXACT, 25.0);
    while (tw_stats(a).collisions < 100000) {
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(a, 0.05));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(b, 0.05));
        TEST_ASSERT_EQUAL_UINT64(cc_world_hash(a), cc_world_hash(b));
        steps++;
    }
    printf("lock-step: %d steps, %llu collisions, equal hashes\n", steps, (unsigned long long)tw_stats(a).collisions);
    tw_free(&m1);
    tw_free(&m2);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_ray_and_circle_cast_along_x);
    RUN_TEST(test_ray_grazing_a_circle);
    RUN_TEST(test_cast_starting_inside);
    RUN_TEST(test_cast_masks_sensors_and_ties);
    RUN_TEST(test_query_errors);
    RUN_TEST(test_queries_against_brute_force);
    RUN_TEST(test_casts_against_brute_force);
    RUN_TEST(test_hash_equal_states_equal_hashes);
    RUN_TEST(test_hash_one_bit_apart);
    RUN_TEST(test_hash_lock_step);
    return UNITY_END();
}
