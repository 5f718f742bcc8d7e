/* Soak: a million collisions of a hard-disc gas in a closed box (walls are segments), checked
 * after every step for escapes, overlaps beyond the tolerance and energy drift. A slow build
 * (e.g. sanitizers without optimisation) may define TW_SOAK_COLLISIONS lower. */
#include "unity.h"

#include "test_world_util.h"

#include <stdio.h>

#ifndef TW_SOAK_COLLISIONS
#define TW_SOAK_COLLISIONS 1000000
#endif

void setUp(void) {}
void tearDown(void) {}

static void test_soak_box(void)
{
    enum { N = 2000 };
    static cc_circle c[N];
    cc_world_def d;
    tw_mem m;
    cc_world *w;
    cc_world_stats s;
    double L, e0;
    int steps = 0;
    cc_world_def_init(&d);
    d.max_circles = N;
    d.max_segments = 4;
    w = tw_make(&m, &d, 0);
    TEST_ASSERT_NOT_NULL(w);
    L = tw_fill_box(w, N, 1.0, 0.4, 2024);
    TEST_ASSERT_EQUAL_INT(N, cc_world_get_circles(w, NULL, c, N));
    e0 = tw_sum(c, N).energy;
    s.struct_size = sizeof s;
    do {
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 10.0));
        TEST_ASSERT_EQUAL_INT(N, cc_world_get_circles(w, NULL, c, N));
        TEST_ASSERT_EQUAL_INT(0, tw_escapes(c, N, L, 1e-10));
        TEST_ASSERT_TRUE(tw_max_rel_overlap(c, N, 1.0) < 1e-10);
        TEST_ASSERT_DOUBLE_WITHIN(1e-11 * e0, e0, tw_sum(c, N).energy);
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_stats(w, &s));
        steps++;
    } while (s.collisions < TW_SOAK_COLLISIONS);
    TEST_ASSERT_TRUE(s.max_overlap < 1e-10 * 2.0);
    TEST_ASSERT_TRUE(tw_canary_ok(&m));
    printf("soak: %d steps, %llu collisions, %llu events (%llu stale, %llu cell crossings), %llu pair tests, "
           "max overlap %.3g, energy drift %.3g\n",
           steps, (unsigned long long)s.collisions, (unsigned long long)s.events, (unsigned long long)s.stale_events,
           (unsigned long long)s.cell_crossings, (unsigned long long)s.pairs_tested, s.max_overlap,
           (tw_sum(c, N).energy - e0) / e0);
    tw_free(&m);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_soak_box);
    return UNITY_END();
}
