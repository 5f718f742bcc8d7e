/* Query filters (1.2): cc_world_cast_circle_filtered and the _filtered queries leave out the
 * circle the filter names (the cue ball's own aiming line), keep the mask, and the 1.1 calls
 * are the filtered ones with {mask, -1} bit for bit. */
#include "unity.h"

#include "test_world_util.h"

#include <stddef.h>

void setUp(void) {}
void tearDown(void) {}

/* The cue ball (id 0) at the origin, an object ball (id 1) at (10, 0), both of radius 1, a
 * third ball (id 2) of category 2 at (0, 5), a wall (id 0) at x = 30; grid or all pairs. */
static cc_world *table(tw_mem *m, int max_circles, int mode)
{
    cc_world_def d;
    cc_world *w;
    cc_circle cue = tw_circle(0, 0, 0, 0, 1, 1), ball = tw_circle(10, 0, 0, 0, 1, 1), other = tw_circle(0, 5, 0, 0, 1, 1);
    cc_segment wall = tw_segment(30, -10, 30, 10);
    cc_circle_props p;
    cc_world_def_init(&d);
    d.max_circles = max_circles;
    d.max_segments = 2;
    d.mode = mode;
    w = tw_make(m, &d, 0);
    TEST_ASSERT_NOT_NULL(w);
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &cue));
    TEST_ASSERT_EQUAL_INT(1, cc_world_add_circle(w, &ball));
    TEST_ASSERT_EQUAL_INT(2, cc_world_add_circle(w, &other));
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_segment(w, &wall));
    p.struct_size = sizeof p;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle_props(w, 2, &p));
    p.category = 2u;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, 2, &p));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.0));
    return w;
}

/* The cue ball's aiming line: a cast of its radius from its centre along +x by 20. Unfiltered
 * it overlaps the cue ball itself at t = 0; leaving the cue ball out, it touches the object
 * ball when its centre is 2 short of (10, 0): x = 8, t = 8 / 20 = 0.4, at (9, 0), normal +x. */
static void test_the_cue_balls_cast_leaves_it_out(void)
{
    int mode, cap;
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++)
        for (cap = 0; cap < 2; cap++) {
            tw_mem m;
            cc_world *w = table(&m, cap ? 64 : 8, mode);
            cc_query_filter f = CC_QUERY_FILTER_DEFAULT;
            cc_cast_hit h;
            TEST_ASSERT_EQUAL_INT(CC_OVERLAP, cc_world_cast_circle(w, tw_vec2(0, 0), 1.0, tw_vec2(20, 0), 0xFFFFFFFFu, &h));
            TEST_ASSERT_EQUAL_INT(0, h.circle);
            f.ignore = 0;
            TEST_ASSERT_EQUAL_INT(CC_HIT, cc_world_cast_circle_filtered(w, tw_vec2(0, 0), 1.0, tw_vec2(20, 0), &f, &h));
            TEST_ASSERT_EQUAL_INT(1, h.circle);
            TEST_ASSERT_EQUAL_INT(-1, h.segment);
            TEST_ASSERT_EQUAL_DOUBLE(0.4, h.t);
            TEST_ASSERT_EQUAL_DOUBLE(9.0, h.point.x);
            TEST_ASSERT_EQUAL_DOUBLE(1.0, h.normal.x);
            /* leaving out the object ball too would reach the wall: not a filter of walls */
            f.ignore = 1;
            TEST_ASSERT_EQUAL_INT(CC_OVERLAP, cc_world_cast_circle_filtered(w, tw_vec2(0, 0), 1.0, tw_vec2(20, 0), &f, &h));
            TEST_ASSERT_EQUAL_INT(0, h.circle);
            TEST_ASSERT_EQUAL_INT(CC_HIT, cc_world_cast_circle_filtered(w, tw_vec2(2, 0), 0.0, tw_vec2(40, 0), &f, &h));
            TEST_ASSERT_EQUAL_INT(0, h.segment); /* wall 0, though ignore is 1: ids of circles only */
            f.ignore = 0;
            TEST_ASSERT_EQUAL_INT(CC_HIT, cc_world_cast_circle_filtered(w, tw_vec2(20, 0), 0.0, tw_vec2(20, 0), &f, &h));
            TEST_ASSERT_EQUAL_INT(0, h.segment); /* ignore 0 leaves circle 0 out, never wall 0 */
            tw_free(&m);
        }
}

/* Queries: the disc of radius 0.5 at the origin holds the cue ball only; the box [-2, 12] x
 * [-2, 2] holds balls 0 and 1; each filtered, the ignored one drops out; mask 2 keeps ball 2. */
static void test_queries_leave_the_ignored_circle_out(void)
{
    tw_mem m;
    cc_world *w = table(&m, 64, CC_MODE_EXACT);
    cc_query_filter f = CC_QUERY_FILTER_DEFAULT;
    int ids[4] = {-7, -7, -7, -7};
    TEST_ASSERT_EQUAL_INT(1, cc_world_query_circle_filtered(w, tw_vec2(0, 0), 0.5, &f, ids, 4));
    TEST_ASSERT_EQUAL_INT(0, ids[0]);
    f.ignore = 0;
    TEST_ASSERT_EQUAL_INT(0, cc_world_query_circle_filtered(w, tw_vec2(0, 0), 0.5, &f, ids, 4));
    TEST_ASSERT_EQUAL_INT(1, cc_world_query_box_filtered(w, tw_vec2(-2, -2), tw_vec2(12, 2), &f, ids, 4));
    TEST_ASSERT_EQUAL_INT(1, ids[0]);
    f.ignore = 1;
    TEST_ASSERT_EQUAL_INT(1, cc_world_query_box_filtered(w, tw_vec2(-2, -2), tw_vec2(12, 2), &f, ids, 4));
    TEST_ASSERT_EQUAL_INT(0, ids[0]);
    f.ignore = -1;
    TEST_ASSERT_EQUAL_INT(2, cc_world_query_box_filtered(w, tw_vec2(-2, -2), tw_vec2(12, 2), &f, ids, 4));
    TEST_ASSERT_EQUAL_INT(0, ids[0]);
    TEST_ASSERT_EQUAL_INT(1, ids[1]);
    f.mask = 2u; /* only category 2: ball 2 at (0, 5) */
    TEST_ASSERT_EQUAL_INT(1, cc_world_query_box_filtered(w, tw_vec2(-20, -20), tw_vec2(20, 20), &f, ids, 4));
    TEST_ASSERT_EQUAL_INT(2, ids[0]);
    f.ignore = 2;
    TEST_ASSERT_EQUAL_INT(0, cc_world_query_box_filtered(w, tw_vec2(-20, -20), tw_vec2(20, 20), &f, ids, 4));
    tw_free(&m);
}

/* NULL is the default filter; an id not in use (never used, negative, removed) leaves nothing
 * out; a struct_size short of `ignore` is CC_ERR_VERSION with the outputs untouched; invalid
 * arguments stay CC_ERR_INVALID before the filter is read. */
static void test_defaults_unknown_ids_and_sizes(void)
{
    tw_mem m;
    cc_world *w = table(&m, 64, CC_MODE_EXACT);
    cc_query_filter f = CC_QUERY_FILTER_DEFAULT;
    cc_cast_hit h, untouched;
    int ids[4] = {-7, -7, -7, -7}, k;
    static const int unknown[] = {99, -5, 3};
    TEST_ASSERT_EQUAL_INT(3, cc_world_query_box_filtered(w, tw_vec2(-20, -20), tw_vec2(20, 20), NULL, ids, 4));
    TEST_ASSERT_EQUAL_INT(CC_OVERLAP, cc_world_cast_circle_filtered(w, tw_vec2(0, 0), 1.0, tw_vec2(20, 0), NULL, &h));
    TEST_ASSERT_EQUAL_INT(0, h.circle);
    {
        cc_circle c = tw_circle(-10, 0, 0, 0, 1, 1);
        TEST_ASSERT_EQUAL_INT(3, cc_world_add_circle(w, &c));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_remove_circle(w, 3));
    }
    for (k = 0; k < 3; k++) {
        f.ignore = unknown[k];
        TEST_ASSERT_EQUAL_INT(3, cc_world_query_box_filtered(w, tw_vec2(-20, -20), tw_vec2(20, 20), &f, ids, 4));
    }
    memset(&h, 0x3C, sizeof h);
    untouched = h;
    f.struct_size = offsetof(cc_query_filter, ignore);
    TEST_ASSERT_EQUAL_INT(CC_ERR_VERSION, cc_world_cast_circle_filtered(w, tw_vec2(0, 0), 1.0, tw_vec2(20, 0), &f, &h));
    TEST_ASSERT_EQUAL_MEMORY(&untouched, &h, sizeof h);
    ids[0] = -7;
    TEST_ASSERT_EQUAL_INT(CC_ERR_VERSION, cc_world_query_circle_filtered(w, tw_vec2(0, 0), 0.5, &f, ids, 4));
    TEST_ASSERT_EQUAL_INT(CC_ERR_VERSION, cc_world_query_box_filtered(w, tw_vec2(-2, -2), tw_vec2(2, 2), &f, ids, 4));
    TEST_ASSERT_EQUAL_INT(-7, ids[0]);
    f.struct_size = sizeof f + 16; /* a later header's filter: its unknown tail is not read */
    f.ignore = 0;
    TEST_ASSERT_EQUAL_INT(0, cc_world_query_circle_filtered(w, tw_vec2(0, 0), 0.5, &f, ids, 4));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_cast_circle_filtered(NULL, tw_vec2(0, 0), 1.0, tw_vec2(1, 0), &f, &h));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_query_box_filtered(w, tw_vec2(2, 2), tw_vec2(-2, -2), &f, ids, 4));
    tw_free(&m);
}

/* The 1.1 calls are the filtered ones with {mask, -1}: 200 casts and queries over a random
 * scene give the same results, bit for bit. */
static void test_the_1_1_calls_are_the_filtered_ones(void)
{
    tw_mem m;
    cc_world_def d;
    cc_world *w;
    uint64_t s = 12345;
    int k;
    cc_world_def_init(&d);
    d.max_circles = 200;
    w = tw_make(&m, &d, 0);
    for (k = 0; k < 150; k++) {
        double x, y;
        cc_circle c;
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        x = (double)(s >> 11) * 0x1p-53 * 100.0;
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        y = (double)(s >> 11) * 0x1p-53 * 100.0;
        c = tw_circle(x, y, 0, 0, 0.5, 1);
        (void)cc_world_add_circle(w, &c);
    }
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.0));
    for (k = 0; k < 200; k++) {
        cc_query_filter f = CC_QUERY_FILTER_DEFAULT;
        cc_cast_hit a, b;
        int ia[200], ib[200], na, nb;
        double x = (double)(k % 20) * 5.0, y = (double)(k / 20) * 10.0;
        uint32_t mask = k % 3 == 0 ? 0u : 0xFFFFFFFFu;
        f.mask = mask;
        memset(&a, 0, sizeof a);
        memset(&b, 0, sizeof b);
        TEST_ASSERT_EQUAL_INT(cc_world_cast_circle(w, tw_vec2(x, y), 0.25 * (k % 4), tw_vec2(30 - x, 17), mask, &a),
                              cc_world_cast_circle_filtered(w, tw_vec2(x, y), 0.25 * (k % 4), tw_vec2(30 - x, 17), &f, &b));
        TEST_ASSERT_EQUAL_MEMORY(&a, &b, sizeof a);
        na = cc_world_query_circle(w, tw_vec2(x, y), 3.0, mask, ia, 200);
        nb = cc_world_query_circle_filtered(w, tw_vec2(x, y), 3.0, &f, ib, 200);
        TEST_ASSERT_EQUAL_INT(na, nb);
        if (na > 0)
            TEST_ASSERT_EQUAL_MEMORY(ia, ib, sizeof ia[0] * (size_t)na);
        na = cc_world_query_box(w, tw_vec2(x, y), tw_vec2(x + 7, y + 3), mask, ia, 200);
        nb = cc_world_query_box_filtered(w, tw_vec2(x, y), tw_vec2(x + 7, y + 3), &f, ib, 200);
        TEST_ASSERT_EQUAL_INT(na, nb);
        if (na > 0)
            TEST_ASSERT_EQUAL_MEMORY(ia, ib, sizeof ia[0] * (size_t)na);
    }
    tw_free(&m);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_the_cue_balls_cast_leaves_it_out);
    RUN_TEST(test_queries_leave_the_ignored_circle_out);
    RUN_TEST(test_defaults_unknown_ids_and_sizes);
    RUN_TEST(test_the_1_1_calls_are_the_filtered_ones);
    return UNITY_END();
}
