/* A program built against the 1.0 header keeps working against this library (API.md, "Version
 * 1.1"): its def is smaller, and the exported cc_world_def_init, which it calls, must write that
 * def and nothing past it (the first 1.1 cut wrote the whole 1.1 def: 40 bytes past a 1.0
 * program's). The 1.1 header's macro passes the size of its own def. */
#include "unity.h"

#include "circlecollide.h"

#include <stddef.h>
#include <stdlib.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

/* The def as the 1.0 header declared it. */
typedef struct def_1_0 {
    size_t struct_size;
    int max_circles, max_segments, mode;
    double restitution, rest_speed, cell_size;
    uint64_t max_events;
    cc_contact_fn on_contact;
    void *user;
} def_1_0;

static void test_the_exported_function_writes_a_1_0_def_only(void)
{
    union {
        def_1_0 d;
        unsigned char bytes[sizeof(cc_world_def) + 64];
    } u;
    size_t i, bytes;
    void *mem;
    cc_world *w;
    cc_circle c = {{0.0, 0.0}, {1.0, 0.0}, 0.5, 1.0}, got;
    memset(&u, 0xA5, sizeof u);
    (cc_world_def_init)((cc_world_def *)(void *)&u.d); /* the symbol, as a 1.0 program calls it */
    for (i = sizeof(def_1_0); i < sizeof u.bytes; i++)
        TEST_ASSERT_EQUAL_INT(0xA5, (int)u.bytes[i]);
    TEST_ASSERT_TRUE(sizeof(def_1_0) == u.d.struct_size);
    TEST_ASSERT_EQUAL_INT(64, u.d.max_circles);
    TEST_ASSERT_EQUAL_DOUBLE(1.0, u.d.restitution);
    /* and a world made from it runs, the 1.1 fields at their defaults */
    u.d.max_circles = 4;
    bytes = cc_world_size((const cc_world_def *)(const void *)&u.d);
    TEST_ASSERT_TRUE(bytes > 0);
    mem = malloc(bytes);
    w = cc_world_init(mem, bytes, (const cc_world_def *)(const void *)&u.d, NULL);
    TEST_ASSERT_NOT_NULL(w);
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &c));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 2.0));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
    TEST_ASSERT_EQUAL_DOUBLE(2.0, got.pos.x); /* no rolling friction: the default */
    free(mem);
}

static void test_the_header_macro_fills_the_whole_1_1_def(void)
{
    cc_world_def d;
    memset(&d, 0xA5, sizeof d);
    cc_world_def_init(&d);
    TEST_ASSERT_TRUE(sizeof d == d.struct_size);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, d.rolling_decel);
    TEST_ASSERT_EQUAL_INT(CC_MIX_MIN, d.restitution_mix);
    TEST_ASSERT_NULL(d.on_sensor);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, d.period.x);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, d.period.y);
    TEST_ASSERT_TRUE(CC_USES_ALL == d.uses);
}

/* A def of 1.0's or 1.1's size (as a program built against those headers sends it, garbage
 * after it) gets every use: its world reserves the properties and takes a sensor and per-circle
 * properties as before, and costs what a 1.2 def of CC_USES_ALL costs. */
static void test_a_1_0_or_1_1_def_uses_everything(void)
{
    size_t sizes[2];
    int k;
    sizes[0] = sizeof(def_1_0);
    sizes[1] = offsetof(cc_world_def, period) + sizeof(cc_vec2);
    for (k = 0; k < 2; k++) {
        cc_world_def full, d;
        cc_world *w;
        void *mem;
        size_t bytes;
        cc_circle c = {{0.0, 0.0}, {0.0, 0.0}, 0.5, 1.0};
        cc_circle_props p;
        cc_world_def_init(&full);
        full.max_circles = 8;
        memset(&d, 0xA5, sizeof d);
        memcpy(&d, &full, sizes[k]);
        d.struct_size = sizes[k];
        d.max_events = 10000000u; /* a 1.0 or 1.1 header's default (full's 0 is 1.2's automatic cap) */
        if (k == 1)
            d.rolling_decel = 0.0;
        else
            d.uses = 0; /* beyond a 1.0 def's size: never read */
        bytes = cc_world_size(&d);
        TEST_ASSERT_TRUE(bytes == cc_world_size(&full));
        mem = malloc(bytes);
        w = cc_world_init(mem, bytes, &d, NULL);
        TEST_ASSERT_NOT_NULL(w);
        TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &c));
        p.struct_size = sizeof p;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle_props(w, 0, &p));
        p.sensor = 1;
        p.restitution = 0.5;
        p.rolling_decel = 0.25;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, 0, &p));
        free(mem);
    }
}

static void test_sized_init_zeroes_a_newer_tail_and_refuses_too_small(void)
{
    union {
        cc_world_def d;
        unsigned char bytes[sizeof(cc_world_def) + 32];
    } u;
    size_t i;
    memset(&u, 0xA5, sizeof u);
    cc_world_def_init_sized(&u.d, sizeof u.d + 16); /* a def of a future header */
    TEST_ASSERT_TRUE(sizeof u.d + 16 == u.d.struct_size);
    for (i = sizeof u.d; i < sizeof u.d + 16; i++)
        TEST_ASSERT_EQUAL_INT(0, (int)u.bytes[i]);
    for (; i < sizeof u.bytes; i++)
        TEST_ASSERT_EQUAL_INT(0xA5, (int)u.bytes[i]);
    memset(&u, 0xA5, sizeof u);
    cc_world_def_init_sized(&u.d, 8); /* below 1.0's def: nothing written */
    for (i = 0; i < sizeof u.bytes; i++)
        TEST_ASSERT_EQUAL_INT(0xA5, (int)u.bytes[i]);
    cc_world_def_init_sized(NULL, sizeof u.d);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_the_exported_function_writes_a_1_0_def_only);
    RUN_TEST(test_the_header_macro_fills_the_whole_1_1_def);
    RUN_TEST(test_sized_init_zeroes_a_newer_tail_and_refuses_too_small);
    RUN_TEST(test_a_1_0_or_1_1_def_uses_everything);
    return UNITY_END();
}
