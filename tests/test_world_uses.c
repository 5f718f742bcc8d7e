/* Worlds that reserve only what they use (cc_world_def.uses, 1.2): the memory cc_world_size
 * asks for shrinks with what uses leaves out, a call that needs what the world did not reserve
 * is refused with CC_ERR_INVALID and changes nothing (neither the hash nor a byte of the world's
 * memory), and a scene that uses nothing of it runs bit for bit alike in a world of uses = 0 and
 * one of CC_USES_ALL, in every mode. */
#include "unity.h"

#include "test_world_util.h"

#include <stdio.h>

void setUp(void) {}
void tearDown(void) {}

static cc_world_def def_of(int n, int segs, int mode, unsigned uses)
{
    cc_world_def d;
    cc_world_def_init(&d);
    d.max_circles = n;
    d.max_segments = segs;
    d.mode = mode;
    d.uses = uses;
    return d;
}

static void test_the_size_shrinks_with_uses(void)
{
    int n = 10000;
    cc_world_def d = def_of(n, 4, CC_MODE_EXACT, 0);
    size_t none = cc_world_size(&d), props, sensors, rolling, all, cloth;
    d.uses = CC_USES_PROPS;
    props = cc_world_size(&d);
    d.uses = CC_USES_SENSORS;
    sensors = cc_world_size(&d);
    d.uses = CC_USES_ROLLING;
    rolling = cc_world_size(&d);
    d.uses = CC_USES_CLOTH;
    cloth = cc_world_size(&d);
    d.uses = CC_USES_ALL;
    all = cc_world_size(&d);
    TEST_ASSERT_TRUE(none > 0);
    /* the properties' block (at least 48 bytes a circle) is what PROPS, SENSORS or ROLLING add */
    TEST_ASSERT_TRUE(props >= none + 48u * (size_t)n);
    TEST_ASSERT_TRUE(props == sensors && props == rolling && props == all);
    TEST_ASSERT_TRUE(cloth == none); /* (spin has no block of its own yet) */
    /* the header's figures: a world of uses = 0 costs under 165 bytes a circle at N = 1e4, at
     * most 160 at N = 1e6 */
    TEST_ASSERT_TRUE(none < 165u * (size_t)n);
    d.uses = 0;
    d.max_circles = 1000000;
    TEST_ASSERT_TRUE(cc_world_size(&d) <= 160u * 1000000u);
    d.max_circles = n;
    /* the turns of a periodic world are reserved only there */
    d.period.x = 1000.0;
    TEST_ASSERT_TRUE(cc_world_size(&d) == none + 8u * (size_t)n);
}

static void test_a_def_beyond_its_uses_is_refused(void)
{
    cc_world_def d = def_of(8, 0, CC_MODE_EXACT, CC_USES_PROPS | CC_USES_SENSORS);
    unsigned char mem[1];
    int st = 1;
    d.rolling_decel = 0.5; /* rolling_decel needs ROLLING */
    TEST_ASSERT_TRUE(cc_world_size(&d) == 0);
    TEST_ASSERT_NULL(cc_world_init(mem, sizeof mem, &d, &st));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, st);
    d.uses |= CC_USES_ROLLING;
    TEST_ASSERT_TRUE(cc_world_size(&d) > 0);
    d.rolling_decel = 0.0;
    d.uses = 0x10000u; /* a bit beyond CC_USES_ALL */
    TEST_ASSERT_TRUE(cc_world_size(&d) == 0);
}

/* A world lacking some uses, with circles and a wall and a few steps behind it. */
static cc_world *busy_world(tw_mem *m, unsigned uses)
{
    cc_world_def d = def_of(16, 2, CC_MODE_EXACT, uses);
    cc_world *w = tw_make(m, &d, 0);
    cc_circle a = tw_circle(0.0, 0.0, 1.0, 0.25, 0.5, 1.0), b = tw_circle(3.0, 0.0, -1.0, 0.0, 0.5, 2.0);
    cc_segment s = tw_segment(-5.0, -2.0, 5.0, -2.0);
    TEST_ASSERT_NOT_NULL(w);
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &a));
    TEST_ASSERT_EQUAL_INT(1, cc_world_add_circle(w, &b));
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_segment(w, &s));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 1.5));
    return w;
}

static cc_circle_props circle_props_of(const cc_world *w, int id)
{
    cc_circle_props p;
    p.struct_size = sizeof p;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle_props(w, id, &p));
    return p;
}

/* call must return CC_ERR_INVALID, the hash and every byte of the world's memory as before. */
#define REFUSED(m, w, call)                                                                       \
    do {                                                                                          \
        uint64_t h_ = cc_world_hash(w);                                                           \
        unsigned char *copy_ = (unsigned char *)malloc((m)->bytes);                               \
        TEST_ASSERT_NOT_NULL(copy_);                                                              \
        memcpy(copy_, (m)->mem, (m)->bytes);                                                      \
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, (call));                                            \
        TEST_ASSERT_TRUE(h_ == cc_world_hash(w));                                                 \
        TEST_ASSERT_TRUE(memcmp(copy_, (m)->mem, (m)->bytes) == 0);                               \
        free(copy_);                                                                              \
    } while (0)

static void test_calls_that_need_an_unreserved_use_are_refused(void)
{
    tw_mem m;
    cc_world *w = busy_world(&m, 0);
    cc_circle_props p = circle_props_of(w, 0), q;
    cc_segment_props sp;
    /* the defaults, which a world without props reports and accepts (nothing changes) */
    TEST_ASSERT_EQUAL_DOUBLE(1.0, p.restitution);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, p.rolling_decel);
    TEST_ASSERT_TRUE(p.category == 1u && p.mask == 0xFFFFFFFFu && p.sensor == 0);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, 0, &p));
    q = p;
    q.restitution = 0.5;
    REFUSED(&m, w, cc_world_set_circle_props(w, 0, &q));
    q = p;
    q.category = 2u;
    REFUSED(&m, w, cc_world_set_circle_props(w, 0, &q));
    q = p;
    q.mask = 2u;
    REFUSED(&m, w, cc_world_set_circle_props(w, 1, &q));
    q = p;
    q.rolling_decel = 0.25;
    REFUSED(&m, w, cc_world_set_circle_props(w, 0, &q));
    q = p;
    q.sensor = 1;
    REFUSED(&m, w, cc_world_set_circle_props(w, 1, &q));
    sp.struct_size = sizeof sp;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_segment_props(w, 0, &sp));
    TEST_ASSERT_EQUAL_DOUBLE(1.0, sp.restitution);
    TEST_ASSERT_TRUE(sp.category == 1u && sp.mask == 0xFFFFFFFFu);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_segment_props(w, 0, &sp));
    sp.restitution = 0.25;
    REFUSED(&m, w, cc_world_set_segment_props(w, 0, &sp));
    sp.restitution = 1.0;
    sp.mask = 4u;
    REFUSED(&m, w, cc_world_set_segment_props(w, 0, &sp));
    TEST_ASSERT_TRUE(tw_canary_ok(&m));
    tw_free(&m);
}

/* The readers that look at properties (casts and queries filter by category) find the defaults
 * in a world without them, as a world of ALL has them. */
static void test_casts_and_queries_see_the_default_categories(void)
{
    unsigned k;
    for (k = 0; k < 2; k++) {
        tw_mem m;
        cc_world *w = busy_world(&m, k ? CC_USES_ALL : 0u);
        cc_query_filter f1 = {sizeof(cc_query_filter), 1u, -1}, f2 = {sizeof(cc_query_filter), 2u, -1};
        cc_cast_hit hit;
        int ids[4];
        /* down onto the wall at y = -2, between the circles */
        TEST_ASSERT_EQUAL_INT(CC_HIT, cc_world_cast_circle_filtered(w, tw_vec2(-4.0, 0.0), 0.25, tw_vec2(0.0, -10.0),
                                                                    &f1, &hit));
        TEST_ASSERT_EQUAL_INT(0, hit.segment);
        TEST_ASSERT_EQUAL_INT(CC_MISS, cc_world_cast_circle_filtered(w, tw_vec2(-4.0, 0.0), 0.25, tw_vec2(0.0, -10.0),
                                                                     &f2, &hit));
        TEST_ASSERT_EQUAL_INT(2, cc_world_query_circle_filtered(w, tw_vec2(1.5, 0.0), 10.0, &f1, ids, 4));
        TEST_ASSERT_EQUAL_INT(0, cc_world_query_circle_filtered(w, tw_vec2(1.5, 0.0), 10.0, &f2, ids, 4));
        tw_free(&m);
    }
}

/* Each use allows its own calls and still refuses the others'. */
static void test_each_use_allows_its_own_calls(void)
{
    tw_mem m;
    cc_world *w = busy_world(&m, CC_USES_SENSORS);
    cc_circle_props p = circle_props_of(w, 0), q = p;
    q.restitution = 0.5;
    REFUSED(&m, w, cc_world_set_circle_props(w, 0, &q));
    q = p;
    q.rolling_decel = 0.5;
    REFUSED(&m, w, cc_world_set_circle_props(w, 0, &q));
    q = p;
    q.sensor = 1;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, 1, &q));
    TEST_ASSERT_EQUAL_INT(1, circle_props_of(w, 1).sensor);
    tw_free(&m);

    w = busy_world(&m, CC_USES_ROLLING);
    q = p;
    q.sensor = 1;
    REFUSED(&m, w, cc_world_set_circle_props(w, 1, &q));
    q = p;
    q.rolling_decel = 0.5;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, 0, &q));
    TEST_ASSERT_EQUAL_DOUBLE(0.5, circle_props_of(w, 0).rolling_decel);
    tw_free(&m);

    w = busy_world(&m, CC_USES_PROPS);
    q = p;
    q.sensor = 1;
    REFUSED(&m, w, cc_world_set_circle_props(w, 1, &q));
    q = p;
    q.restitution = 0.5;
    q.rolling_decel = 0.5; /* per-circle deceleration is a property too */
    q.category = 2u;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, 0, &q));
    TEST_ASSERT_EQUAL_DOUBLE(0.5, circle_props_of(w, 0).restitution);
    {
        cc_segment_props sp;
        sp.struct_size = sizeof sp;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_segment_props(w, 0, &sp));
        sp.restitution = 0.25;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_segment_props(w, 0, &sp));
    }
    tw_free(&m);
}

/* A plain scene: a box of walls (or a periodic box without them), circles removed and added
 * again (the free stack), run in a world of uses `uses`; its hash and the circles at the end. */
static uint64_t run_plain(int mode, int periodic, unsigned uses, cc_circle *out, int n)
{
    tw_mem m;
    cc_world_def d = def_of(n + 8, periodic ? 0 : 4, mode, uses);
    cc_world *w;
    uint64_t h, seed = 99;
    double L = 40.0;
    int i;
    if (periodic)
        d.period.x = d.period.y = L;
    w = tw_make(&m, &d, 0);
    TEST_ASSERT_NOT_NULL(w);
    if (periodic) {
        for (i = 0; i < n; i++) {
            cc_circle c = tw_circle(L * ((i % 16) + 0.5) / 16.0, L * ((i / 16) + 0.5) / 16.0,
                                    2.0 * tw_rand(&seed) - 1.0, 2.0 * tw_rand(&seed) - 1.0, 0.6, 1.0);
            TEST_ASSERT_EQUAL_INT(i, cc_world_add_circle(w, &c));
        }
    } else {
        (void)tw_fill_box(w, n, 0.5, 0.3, 7);
    }
    for (i = 0; i < 20; i++)
        TEST_ASSERT_TRUE(cc_world_step(w, 0.25) >= 0);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_remove_circle(w, 3));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_remove_circle(w, 7));
    {
        cc_circle c;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 5, &c));
        c.pos.x += 0.01;
        TEST_ASSERT_EQUAL_INT(7, cc_world_add_circle(w, &c)); /* the last removed id first */
    }
    for (i = 0; i < 20; i++)
        TEST_ASSERT_TRUE(cc_world_step(w, 0.25) >= 0);
    TEST_ASSERT_EQUAL_INT(n - 1, cc_world_get_circles(w, NULL, out, n));
    if (periodic) { /* the turns counted, as a world of ALL counts them */
        cc_vec2 u[256];
        TEST_ASSERT_EQUAL_INT(n - 1, cc_world_get_unwrapped_all(w, NULL, u, 256));
        for (i = 0; i < n - 1; i++) {
            out[i].pos.x += 1e-3 * u[i].x; /* folded into what the caller compares */
            out[i].pos.y += 1e-3 * u[i].y;
        }
    }
    h = cc_world_hash(w);
    TEST_ASSERT_TRUE(tw_canary_ok(&m));
    tw_free(&m);
    return h;
}

static void test_a_plain_scene_runs_alike_with_and_without_reserves(void)
{
    enum { N = 200 };
    static cc_circle a[N], b[N];
    int mode, periodic;
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++)
        for (periodic = 0; periodic < 2; periodic++) {
            uint64_t h0 = run_plain(mode, periodic, 0, a, N), h1 = run_plain(mode, periodic, CC_USES_ALL, b, N);
            TEST_ASSERT_TRUE(h0 == h1);
            TEST_ASSERT_TRUE(memcmp(a, b, sizeof a) == 0);
        }
}

/* The turns of a periodic world live in their own block, outside the bodies: they must follow
 * each circle as storage is sorted. An unwrapped position moves continuously, so between two
 * short steps it moves by far less than half a period; a count left with another circle's
 * storage moves it by a whole period. */
static void test_turns_follow_their_circles_through_sorting(void)
{
    enum { N = 300 };
    static cc_vec2 u0[N], u1[N];
    tw_mem m;
    cc_world_def d = def_of(N, 0, CC_MODE_EXACT, 0);
    cc_world *w;
    uint64_t seed = 5;
    double L = 30.0;
    int i, k;
    d.period.x = d.period.y = L;
    w = tw_make(&m, &d, 0);
    TEST_ASSERT_NOT_NULL(w);
    for (i = 0; i < N; i++) {
        cc_circle c = tw_circle(L * ((i % 20) + 0.5) / 20.0, L * ((i / 20) + 0.5) / 20.0, 4.0 * tw_rand(&seed) - 2.0,
                                4.0 * tw_rand(&seed) - 2.0, 0.5, 1.0);
        TEST_ASSERT_EQUAL_INT(i, cc_world_add_circle(w, &c));
    }
    TEST_ASSERT_EQUAL_INT(N, cc_world_get_unwrapped_all(w, NULL, u0, N));
    for (k = 0; k < 1600; k++) {
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.05));
        TEST_ASSERT_EQUAL_INT(N, cc_world_get_unwrapped_all(w, NULL, u1, N));
        for (i = 0; i < N; i++)
            TEST_ASSERT_TRUE(fabs(u1[i].x - u0[i].x) < 0.5 * L && fabs(u1[i].y - u0[i].y) < 0.5 * L);
        memcpy(u0, u1, sizeof u0);
    }
    /* enough events for storage to have been sorted more than once (sort.c: 64 per circle) */
    TEST_ASSERT_TRUE(tw_stats(w).events > 2u * (64u * N + 1024u));
    tw_free(&m);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_the_size_shrinks_with_uses);
    RUN_TEST(test_a_def_beyond_its_uses_is_refused);
    RUN_TEST(test_calls_that_need_an_unreserved_use_are_refused);
    RUN_TEST(test_casts_and_queries_see_the_default_categories);
    RUN_TEST(test_each_use_allows_its_own_calls);
    RUN_TEST(test_a_plain_scene_runs_alike_with_and_without_reserves);
    RUN_TEST(test_turns_follow_their_circles_through_sorting);
    return UNITY_END();
}
