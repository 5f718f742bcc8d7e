/* The event cap's default (the header's "Collapse"): a def from the 1.2 header leaves max_events
 * at 0, the automatic cap of 32 events per circle of max_circles and at least 10,000, so that a
 * step that jams returns within a frame's patience; a 1.0 or 1.1 def keeps 10,000,000, which its
 * programs rely on for long offline steps; an explicit value keeps its meaning. The cap in force
 * is read back through cc_world_hash (it mixes the cap) and, in a jam, through the events a
 * capped step processed. */
#include "unity.h"

#include "circlecollide.h"
#include "test_world_util.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define DEF_1_0 (offsetof(cc_world_def, user) + sizeof(void *))
#define DEF_1_1 (offsetof(cc_world_def, period) + sizeof(cc_vec2))

/* The automatic cap as the header states it. */
static uint64_t auto_cap(int max_circles)
{
    uint64_t n = 32u * (uint64_t)max_circles;
    return n > 10000u ? n : 10000u;
}

/* A jam: a kinematic circle (infinite mass, speed 1) driving into a row of rolling circles
 * (deceleration 0.5, restitution 0.5): its impacts come ever closer in time, and the step ends
 * at the cap. Returns the step's result; *events what it processed. */
static int jam(cc_world_def *d, uint64_t *events)
{
    tw_mem m;
    cc_world *w;
    int i, r;
    cc_circle k = tw_circle(-3, 0, 1, 0, 1, INFINITY);
    d->rolling_decel = 0.5;
    d->restitution = 0.5;
    w = tw_make(&m, d, 0);
    TEST_ASSERT_NOT_NULL(w);
    for (i = 0; i < 5; i++) {
        cc_circle c = tw_circle(i * 2.2, 0, 0, 0, 1, 1);
        TEST_ASSERT_EQUAL_INT(i, cc_world_add_circle(w, &c));
    }
    TEST_ASSERT_EQUAL_INT(5, cc_world_add_circle(w, &k));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.0));
    r = cc_world_step(w, 30.0);
    *events = tw_stats(w).events;
    if (r == CC_EVENT_LIMIT) { /* the next call continues, and stops at the cap again */
        TEST_ASSERT_EQUAL_INT(CC_EVENT_LIMIT, cc_world_step(w, 30.0));
        TEST_ASSERT_EQUAL_UINT64(2u * *events, tw_stats(w).events);
    }
    TEST_ASSERT_TRUE(tw_canary_ok(&m));
    tw_free(&m);
    return r;
}

/* The hash of an empty world made from d: equal hashes, equal settings (the cap among them). */
static uint64_t hash_of(const cc_world_def *d)
{
    tw_mem m;
    cc_world *w = tw_make(&m, d, 0);
    uint64_t h;
    TEST_ASSERT_NOT_NULL(w);
    h = cc_world_hash(w);
    tw_free(&m);
    return h;
}

static void test_a_1_2_def_caps_a_jam_at_32_events_per_circle_and_at_least_10000(void)
{
    static const int caps[2] = {6, 400}; /* below the floor (10,000) and above it (12,800) */
    int k;
    for (k = 0; k < 2; k++) {
        cc_world_def d;
        uint64_t ev = 0;
        cc_world_def_init(&d);
        TEST_ASSERT_EQUAL_UINT64(0u, d.max_events); /* the default: automatic */
        d.max_circles = caps[k];
        TEST_ASSERT_EQUAL_INT(CC_EVENT_LIMIT, jam(&d, &ev));
        TEST_ASSERT_EQUAL_UINT64(auto_cap(caps[k]), ev);
    }
}

static void test_the_automatic_cap_follows_max_circles(void)
{
    static const int caps[5] = {0, 1, 312, 313, 100000};
    int k;
    for (k = 0; k < 5; k++) {
        cc_world_def a, e;
        cc_world_def_init(&a);
        a.max_circles = caps[k];
        e = a;
        e.max_events = auto_cap(caps[k]);
        TEST_ASSERT_TRUE(hash_of(&a) == hash_of(&e));
        e.max_events++; /* the hash tells caps apart */
        TEST_ASSERT_FALSE(hash_of(&a) == hash_of(&e));
    }
}

static void test_an_explicit_cap_keeps_its_value(void)
{
    cc_world_def d, e;
    uint64_t ev = 0;
    cc_world_def_init(&d);
    d.max_circles = 6;
    d.max_events = 123;
    TEST_ASSERT_EQUAL_INT(CC_EVENT_LIMIT, jam(&d, &ev));
    TEST_ASSERT_EQUAL_UINT64(123u, ev);
    cc_world_def_init(&d);
    d.max_circles = 1000;
    e = d;
    d.max_events = 10000000u; /* what a long offline step sets */
    e.max_events = 0;
    TEST_ASSERT_FALSE(hash_of(&d) == hash_of(&e));
    e.max_events = 10000000u;
    TEST_ASSERT_TRUE(hash_of(&d) == hash_of(&e));
}

/* A def from the 1.0 or 1.1 header keeps 10,000,000: filled by the sized init of its size, cut
 * before max_events (the default fills it), or sent whole; and 0 stays invalid for it. */
static void test_a_1_0_or_1_1_def_keeps_ten_million(void)
{
    static const size_t sizes[3] = {DEF_1_0, DEF_1_1, offsetof(cc_world_def, max_events)};
    int k;
    for (k = 0; k < 3; k++) {
        cc_world_def d, full;
        int st = 0;
        memset(&d, 0, sizeof d);
        cc_world_def_init_sized(&d, k < 2 ? sizes[k] : DEF_1_1);
        if (k < 2)
            TEST_ASSERT_EQUAL_UINT64(10000000u, d.max_events);
        d.max_circles = 1000;
        d.struct_size = sizes[k];
        cc_world_def_init(&full);
        full.max_circles = 1000;
        full.max_events = 10000000u;
        TEST_ASSERT_TRUE(hash_of(&d) == hash_of(&full));
        if (k < 2) {
            tw_mem m;
            d.max_events = 0;
            TEST_ASSERT_EQUAL_UINT64(0u, cc_world_size(&d));
            m.raw = (unsigned char *)malloc(1u << 16);
            TEST_ASSERT_NULL(cc_world_init(m.raw, 1u << 16, &d, &st));
            TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, st);
            free(m.raw);
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_a_1_2_def_caps_a_jam_at_32_events_per_circle_and_at_least_10000);
    RUN_TEST(test_the_automatic_cap_follows_max_circles);
    RUN_TEST(test_an_explicit_cap_keeps_its_value);
    RUN_TEST(test_a_1_0_or_1_1_def_keeps_ten_million);
    return UNITY_END();
}
