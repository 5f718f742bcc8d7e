/* Periodic boxes (issue 15), derived by hand: a circle through the period's edge, an impact
 * across it, positions kept within the period, unwrapped positions, channels, the virial and the
 * wall impulse, queries across the edge, validation; in every mode where it applies. */
#include "unity.h"

#include "test_world_util.h"

#include <stdio.h>

void setUp(void) {}
void tearDown(void) {}

static cc_world *periodic(tw_mem *m, int mode, double px, double py, int max_circles, int max_segments)
{
    cc_world_def d;
    d = tw_def(mode, max_circles, max_segments);
    d.period.x = px;
    d.period.y = py;
    d.max_events = 10000000u; /* some steps cross 5e4 cells or run whole gases in one call */
    return tw_make(m, &d, 0);
}

/* A circle of radius 0.5 at x = 9 in a period of 10, moving +1: at t = 2.5 it is at 11.5, shown
 * as 1.5, unwrapped 11.5; after 1000 periods (t = 10002.5) at 1.5 again, unwrapped 10011.5. */
static void test_through_the_edge(void)
{
    int mode;
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++) {
        tw_mem m;
        cc_world *w = periodic(&m, mode, 10.0, 0.0, 8, 0);
        cc_circle c = tw_circle(9, 3, 1, 0, 0.5, 1), got;
        cc_vec2 u;
        int k;
        TEST_ASSERT_NOT_NULL(w);
        TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &c));
        for (k = 0; k < 25; k++)
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.1));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1.5, got.pos.x);
        TEST_ASSERT_EQUAL_DOUBLE(3.0, got.pos.y);
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_unwrapped(w, 0, &u));
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, 11.5, u.x);
        if (mode == CC_MODE_SWEPT) { /* SWEPT refuses a step of half a period (world fuzzer D8) */
            uint64_t h = cc_world_hash(w);
            TEST_ASSERT_EQUAL_INT(tw_code(CC_ERR_RANGE), cc_world_step(w, 10000.0));
            TEST_ASSERT_TRUE(h == cc_world_hash(w));
            for (k = 0; k < 4000; k++)
                TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 2.5));
        } else {
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 10000.0));
        }
        (void)cc_world_get_circle(w, 0, &got);
        TEST_ASSERT_TRUE(got.pos.x >= 0.0 && got.pos.x < 10.0);
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, 1.5, got.pos.x);
        (void)cc_world_get_unwrapped(w, 0, &u);
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, 10011.5, u.x);
        tw_free(&m);
    }
}

/* A circle set far outside the period is taken to its image exactly: x - n P, what fmod gives
 * (the library computes it by long division with powers of two, as its embedded build calls no
 * fmod), from 1e-300 to 1e300 and negative, and the unwrapped position keeps x. */
static void test_far_positions_wrap_exactly(void)
{
    static const double xs[] = {1e-300, 9.999999999999998, 10.0, 10.000000000000002, -1e-300, -0.1, -10.0,
                                123456.789, -987654321.123, 3.0e15 + 7.0, 1e300, -1e300, 7.0 * 0x1p60};
    tw_mem m;
    cc_world *w = periodic(&m, CC_MODE_EXACT, 10.0, 0.7, 8, 0);
    size_t k;
    TEST_ASSERT_NOT_NULL(w);
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &(cc_circle){{1.0, 0.25}, {0.0, 0.0}, 0.1, 1.0}));
    for (k = 0; k < sizeof xs / sizeof xs[0]; k++) {
        cc_circle c = tw_circle(xs[k], -xs[k], 0, 0, 0.1, 1), got;
        double ex = fmod(xs[k], 10.0), ey = fmod(-xs[k], 0.7);
        ex = ex < 0.0 ? ex + 10.0 : ex;
        ey = ey < 0.0 ? ey + 0.7 : ey;
        ex = ex >= 10.0 ? 0.0 : ex; /* a tiny negative remainder rounds up to the period: 0 */
        ey = ey >= 0.7 ? 0.0 : ey;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle(w, 0, &c));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
        TEST_ASSERT_EQUAL_DOUBLE(ex, got.pos.x);
        TEST_ASSERT_EQUAL_DOUBLE(ey, got.pos.y);
    }
    tw_free(&m);
}

/* Found by the world fuzzer (tests/fuzz/world_defects/): a period of more than 2^31 cells
 * (period 20, a circle of radius 1e-9) made the cell count's conversion undefined (D4): the cells
 * are widened to period / 2^30; a query centred periods away from the box missed circles (D6):
 * its centre is taken to its image first. */
static void test_tiny_cells_and_far_query_centres(void)
{
    int mode;
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++) {
        tw_mem m;
        cc_world *w = periodic(&m, mode, 20.0, 20.0, 8, 0);
        cc_circle tiny = tw_circle(1, 1, 1, 0, 1e-9, 1), big = tw_circle(5, 5, 0, 0, 1, 1), got;
        int ids[4];
        TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &tiny));
        /* cells of 20 / 2^30: 1e-3 crosses some 5e4 of them (EXACT), within the event cap */
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 1e-3));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1.001, got.pos.x);
        TEST_ASSERT_EQUAL_INT(1, cc_world_add_circle(w, &big));
        /* (5, 5) seen from (5 - 3 * 20, 5 + 40) and from (5.5 + 1e6 * 20, 5): the same circle */
        TEST_ASSERT_EQUAL_INT(1, cc_world_query_circle(w, (cc_vec2){5.0 - 60.0, 5.0 + 40.0}, 0.5, 0xFFFFFFFFu, ids, 4));
        TEST_ASSERT_EQUAL_INT(1, ids[0]);
        TEST_ASSERT_EQUAL_INT(1, cc_world_query_circle(w, (cc_vec2){5.5 + 2e7, 5.0}, 0.0, 0xFFFFFFFFu, ids, 4));
        tw_free(&m);
    }
}

/* Across the edge: a at x = 9, b at x = 1 (through the edge 2 apart), radii 0.5, a moving +1 at
 * b at rest, equal masses, elastic: they touch when 1 apart, at t = 1 (a at 10, shown as 0), a
 * stops and b leaves at +1. At t = 3: a at 0, b at 3. The impact is predicted before a crosses
 * the edge and kept through the crossing (EXACT). */
static void test_impact_across_the_edge(void)
{
    int mode;
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++) {
        tw_mem m;
        cc_world *w = periodic(&m, mode, 10.0, 10.0, 8, 0);
        cc_circle a = tw_circle(9, 5, 1, 0, 0.5, 1), b = tw_circle(1, 5, 0, 0, 0.5, 1), got;
        int k;
        (void)cc_world_add_circle(w, &a);
        (void)cc_world_add_circle(w, &b);
        for (k = 0; k < 300; k++)
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.01));
        (void)cc_world_get_circle(w, 0, &got);
        TEST_ASSERT_DOUBLE_WITHIN(mode == CC_MODE_EXACT ? 1e-12 : 0.02, 0.0, fmod(got.pos.x + 5.0, 10.0) - 5.0);
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.0, got.vel.x);
        (void)cc_world_get_circle(w, 1, &got);
        TEST_ASSERT_DOUBLE_WITHIN(mode == CC_MODE_EXACT ? 1e-12 : 0.02, 3.0, got.pos.x);
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1.0, got.vel.x);
        TEST_ASSERT_EQUAL_UINT64(1, tw_stats(w).collisions);
        tw_free(&m);
    }
}

/* The virial and the wall impulse. Two unit masses head-on at +-1 (radii 1): the impulse is
 * m |dv| = 2, the centres 2 apart: virial 4. A ball of mass 2 at speed 3 into a wall: impulse
 * 2 * 6 = 12. */
static void test_virial_and_wall_impulse(void)
{
    tw_mem m;
    cc_world_def d;
    cc_world *w;
    cc_circle a = tw_circle(0, 0, 1, 0, 1, 1), b = tw_circle(5, 0, -1, 0, 1, 1), c = tw_circle(0, 20, 3, 0, 1, 2);
    cc_segment wall = tw_segment(10, 10, 10, 30);
    cc_world_stats s;
    cc_world_def_init(&d);
    d.max_segments = 1;
    w = tw_make(&m, &d, 0);
    (void)cc_world_add_circle(w, &a);
    (void)cc_world_add_circle(w, &b);
    (void)cc_world_add_circle(w, &c);
    (void)cc_world_add_segment(w, &wall);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 3.5));
    s = tw_stats(w);
    TEST_ASSERT_EQUAL_UINT64(2, s.collisions);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 4.0, s.virial);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 12.0, s.wall_impulse);
    tw_free(&m);
}

/* A channel: periodic along x (period 20), walls at y = 0 and y = 4 reaching past both ends. A
 * circle of radius 1 from (5, 2) at (3, 1): it bounces between the walls every 2 time units,
 * drifts 3 per unit along x; after 20 units it is at x = 65 mod 20 = 5 and y as at t = 0 (an
 * even number of bounces: 10), velocity (3, 1). */
static void test_channel(void)
{
    tw_mem m;
    cc_world *w = periodic(&m, CC_MODE_EXACT, 20.0, 0.0, 8, 2);
    cc_circle c = tw_circle(5, 2, 3, 1, 1, 1), got;
    cc_segment lo = tw_segment(-5, 0, 25, 0), hi = tw_segment(25, 4, -5, 4);
    (void)cc_world_add_segment(w, &lo);
    (void)cc_world_add_segment(w, &hi);
    (void)cc_world_add_circle(w, &c);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 20.0));
    (void)cc_world_get_circle(w, 0, &got);
    TEST_ASSERT_DOUBLE_WITHIN(1e-11, 5.0, got.pos.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-11, 2.0, got.pos.y);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1.0, got.vel.y);
    TEST_ASSERT_EQUAL_UINT64(10, tw_stats(w).collisions);
    tw_free(&m);
}

/* A gas of 200 disks in a torus, 2e5 collisions: every position stays in [0, period), energy to
 * 1e-12, no overlap beyond the documented tolerance (1e-10 of the radius sum). */
static void test_torus_gas(void)
{
    tw_mem m;
    cc_world *w = periodic(&m, CC_MODE_EXACT, 40.0, 40.0, 256, 0);
    cc_circle c[200];
    double e0 = 0.0, e1 = 0.0;
    uint64_t s = 99;
    int i, j, n = 0;
    for (i = 0; i < 14 && n < 200; i++)
        for (j = 0; j < 15 && n < 200; j++, n++) {
            double a = 6.283185307179586 * (double)((s = s * 6364136223846793005u + 1442695040888963407u) >> 11) * 0x1p-53;
            cc_circle d = tw_circle(1.4 + 2.7 * j, 1.4 + 2.8 * i, cos(a), sin(a), 1, 1);
            (void)cc_world_add_circle(w, &d);
            e0 += 0.5;
        }
    while (tw_stats(w).collisions < 200000)
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 1.0));
    TEST_ASSERT_EQUAL_INT(200, cc_world_get_circles(w, NULL, c, 200));
    for (i = 0; i < 200; i++) {
        TEST_ASSERT_TRUE(c[i].pos.x >= 0.0 && c[i].pos.x < 40.0 && c[i].pos.y >= 0.0 && c[i].pos.y < 40.0);
        e1 += 0.5 * (c[i].vel.x * c[i].vel.x + c[i].vel.y * c[i].vel.y);
        for (j = 0; j < i; j++) {
            double dx = fabs(c[i].pos.x - c[j].pos.x), dy = fabs(c[i].pos.y - c[j].pos.y);
            dx = dx > 20.0 ? 40.0 - dx : dx;
            dy = dy > 20.0 ? 40.0 - dy : dy;
            TEST_ASSERT_TRUE(sqrt(dx * dx + dy * dy) > 2.0 - 2e-10);
        }
    }
    TEST_ASSERT_DOUBLE_WITHIN(1e-12 * e0, e0, e1);
    printf("torus: %llu collisions, energy drift %.3g\n", (unsigned long long)tw_stats(w).collisions, (e1 - e0) / e0);
    tw_free(&m);
}

/* Queries and casts across the edge: a circle near x = 9.5 (period 10) is found by a disc query
 * at x = 0.2 and hit by a ray cast from x = 0.5 towards -x. */
static void test_queries_across_the_edge(void)
{
    tw_mem m;
    cc_world *w = periodic(&m, CC_MODE_EXACT, 10.0, 10.0, 8, 0);
    cc_circle c = tw_circle(9.5, 5, 0, 0, 0.5, 1);
    cc_vec2 p, d;
    cc_cast_hit h;
    int ids[4];
    (void)cc_world_add_circle(w, &c);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.0));
    p.x = 0.2, p.y = 5.0;
    TEST_ASSERT_EQUAL_INT(1, cc_world_query_circle(w, p, 0.5, 0xFFFFFFFFu, ids, 4)); /* 0.7 apart < 1 */
    p.x = 0.5;
    d.x = -2.0, d.y = 0.0;
    TEST_ASSERT_EQUAL_INT(CC_HIT, cc_world_cast_circle(w, p, 0.0, d, 0xFFFFFFFFu, &h));
    TEST_ASSERT_EQUAL_INT(0, h.circle);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.25, h.t); /* the surface at x = 10 = 0: 0.5 away of 2 */
    tw_free(&m);
}

/* A period must be at least twice the largest diameter plus a cell: in 10, a circle of radius
 * 1.6 fits (6.4 + 1.0625 * 3.2 = 9.8), one of 1.7 does not (6.8 + 3.6125 = 10.41). A period not
 * wider than def.cell_size, or negative, or not finite, is no def at all. */
static void test_validation(void)
{
    tw_mem m;
    cc_world_def d;
    cc_world *w = periodic(&m, CC_MODE_EXACT, 10.0, 0.0, 8, 0);
    cc_circle ok = tw_circle(5, 5, 0, 0, 1.6, 1), wide = tw_circle(5, 5, 0, 0, 1.7, 1);
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &ok));
    TEST_ASSERT_EQUAL_INT(tw_code(CC_ERR_RANGE), cc_world_add_circle(w, &wide));
    TEST_ASSERT_EQUAL_INT(tw_code(CC_ERR_RANGE), cc_world_set_circle(w, 0, &wide));
    tw_free(&m);
    cc_world_def_init(&d);
    d.period.x = 5.0;
    d.cell_size = 5.0;
    TEST_ASSERT_EQUAL_UINT64(0, cc_world_size(&d));
    d.cell_size = 0.0;
    d.period.y = -1.0;
    TEST_ASSERT_EQUAL_UINT64(0, cc_world_size(&d));
    d.period.y = INFINITY;
    TEST_ASSERT_EQUAL_UINT64(0, cc_world_size(&d));
    d.period.y = NAN;
    TEST_ASSERT_EQUAL_UINT64(0, cc_world_size(&d));
    d.period.y = 0.0;
    TEST_ASSERT_TRUE(cc_world_size(&d) > 0);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_through_the_edge);
    RUN_TEST(test_far_positions_wrap_exactly);
    RUN_TEST(test_tiny_cells_and_far_query_centres);
    RUN_TEST(test_impact_across_the_edge);
    RUN_TEST(test_virial_and_wall_impulse);
    RUN_TEST(test_channel);
    RUN_TEST(test_torus_gas);
    RUN_TEST(test_queries_across_the_edge);
    RUN_TEST(test_validation);
    return UNITY_END();
}
