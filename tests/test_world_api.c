/* The world's API contract: the def handshake, caller memory (never written beyond the bytes
 * given), ids, accessors, and every error path, each of which changes nothing. */
#include "unity.h"

#include "test_world_util.h"

#include <stddef.h>
#include <stdio.h>

void setUp(void) {}
void tearDown(void) {}

static void test_def_defaults(void)
{
    cc_world_def d;
    cc_world_def_init(&d);
    TEST_ASSERT_EQUAL_UINT64(sizeof d, d.struct_size);
    TEST_ASSERT_EQUAL_INT(64, d.max_circles);
    TEST_ASSERT_EQUAL_INT(0, d.max_segments);
    TEST_ASSERT_EQUAL_INT(CC_MODE_EXACT, d.mode);
    TEST_ASSERT_EQUAL_DOUBLE(1.0, d.restitution);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, d.rest_speed);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, d.cell_size);
    TEST_ASSERT_EQUAL_UINT64(0u, d.max_events); /* automatic (test_world_event_cap.c) */
    TEST_ASSERT_NULL(d.on_contact);
    TEST_ASSERT_TRUE(cc_world_size(&d) > 0);
}

static void test_size_follows_capacity(void)
{
    cc_world_def d;
    size_t s64, s1000, s1000w;
    cc_world_def_init(&d);
    s64 = cc_world_size(&d);
    d.max_circles = 1000;
    s1000 = cc_world_size(&d);
    d.max_segments = 10;
    s1000w = cc_world_size(&d);
    TEST_ASSERT_TRUE(s1000 > s64);
    /* ten walls of 4 doubles each (320 bytes), their properties (restitution, category and
     * mask: 16 bytes each, 160), and the walls' tree: a box of 8 doubles each (640), up to 20
     * nodes of 4 doubles and 2 ints (800) and the walls' order (40 bytes, 48 once rounded up) */
    TEST_ASSERT_EQUAL_UINT64(s1000 + 320 + 160 + 640 + 800 + 48, s1000w);
    /* per circle: below 256 bytes (the body is one 64-byte line, plus event, cell, heap, hash) */
    TEST_ASSERT_TRUE(s1000 / 1000 < 256);
}

static void test_invalid_defs(void)
{
    cc_world_def d;
    cc_world_def_init(&d);
    d.max_circles = -1;
    TEST_ASSERT_EQUAL_UINT64(0, cc_world_size(&d));
    cc_world_def_init(&d);
    d.mode = 3;
    TEST_ASSERT_EQUAL_UINT64(0, cc_world_size(&d));
    cc_world_def_init(&d);
    d.restitution = 1.5;
    TEST_ASSERT_EQUAL_UINT64(0, cc_world_size(&d));
    d.restitution = NAN;
    TEST_ASSERT_EQUAL_UINT64(0, cc_world_size(&d));
    cc_world_def_init(&d);
    d.rest_speed = -1.0;
    TEST_ASSERT_EQUAL_UINT64(0, cc_world_size(&d));
    cc_world_def_init(&d);
    d.cell_size = INFINITY;
    TEST_ASSERT_EQUAL_UINT64(0, cc_world_size(&d));
    cc_world_def_init_sized(&d, offsetof(cc_world_def, period) + sizeof(cc_vec2));
    d.max_events = 0; /* invalid for a 1.0 or 1.1 def; a 1.2 def's automatic cap */
    TEST_ASSERT_EQUAL_UINT64(0, cc_world_size(&d));
    TEST_ASSERT_EQUAL_UINT64(0, cc_world_size(NULL));
}

static void test_init_memory_errors(void)
{
    cc_world_def d;
    int st = 99;
    size_t n;
    unsigned char *raw, *mem;
    cc_world_def_init(&d);
    n = cc_world_size(&d);
    raw = (unsigned char *)malloc(n + 64);
    mem = raw + ((16u - ((size_t)raw & 15u)) & 15u);
    memset(mem, 0x33, n + 32);
    TEST_ASSERT_NULL(cc_world_init(NULL, n, &d, &st));
    TEST_ASSERT_EQUAL_INT(CC_ERR_MEMORY, st);
    st = 99;
    TEST_ASSERT_NULL(cc_world_init(mem, n - 1, &d, &st));
    TEST_ASSERT_EQUAL_INT(CC_ERR_MEMORY, st);
    st = 99;
    TEST_ASSERT_NULL(cc_world_init(mem + 4, n, &d, &st)); /* misaligned: 8 bytes are required */
    TEST_ASSERT_EQUAL_INT(CC_ERR_MEMORY, st);
    /* nothing was written by the failed calls */
    TEST_ASSERT_EQUAL_INT(0x33, mem[0]);
    TEST_ASSERT_EQUAL_INT(0x33, mem[4]);
    st = 99;
    TEST_ASSERT_NULL(cc_world_init(mem, n, NULL, &st));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, st);
    d.restitution = -0.5;
    TEST_ASSERT_NULL(cc_world_init(mem, n, &d, &st));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, st);
    TEST_ASSERT_NULL(cc_world_init(mem, n, &d, NULL)); /* status may be NULL */
    cc_world_def_init(&d);
    TEST_ASSERT_NOT_NULL(cc_world_init(mem, n, &d, NULL));
    free(raw);
}

/* An older caller's def ends after restitution: the rest must come from the defaults, even
 * when the bytes after it (not the caller's) hold garbage. */
static int g_called;
static void count_contact(const cc_contact_event *e, void *user)
{
    (void)e;
    (void)user;
    g_called++;
}

static void test_def_cut_short(void)
{
    cc_world_def d;
    tw_mem m;
    cc_world *w;
    cc_circle a = tw_circle(0, 0, 1, 0, 1, 1), b = tw_circle(4, 0, -1, 0, 1, 1), got;
    int st = 99;
    size_t old = offsetof(cc_world_def, restitution) + sizeof(double);
    memset(&d, 0xFF, sizeof d); /* garbage in rest_speed, cell_size, max_events, on_contact... */
    d.struct_size = old;
    d.max_circles = 4;
    d.max_segments = 0;
    d.mode = CC_MODE_EXACT;
    d.restitution = 1.0;
    TEST_ASSERT_TRUE(cc_world_size(&d) > 0);
    {
        cc_world_def full;
        cc_world_def_init(&full);
        full.max_circles = 4;
        TEST_ASSERT_EQUAL_UINT64(cc_world_size(&full), cc_world_size(&d));
    }
    w = tw_make(&m, &d, 0);
    TEST_ASSERT_NOT_NULL(w);
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &a));
    TEST_ASSERT_EQUAL_INT(1, cc_world_add_circle(w, &b));
    g_called = 0;
    /* gap 2 closes at speed 2: contact at t = 1, velocities exchanged (equal masses, e = 1) */
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 2.0));
    TEST_ASSERT_EQUAL_INT(0, g_called); /* no callback: the default NULL, not the garbage */
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
    TEST_ASSERT_EQUAL_DOUBLE(-1.0, got.vel.x);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, got.pos.x); /* 1 right to x = 1, then 1 back */
    TEST_ASSERT_TRUE(tw_canary_ok(&m));
    tw_free(&m);
    /* shorter than the fields every def must have */
    d.struct_size = old - 1;
    TEST_ASSERT_EQUAL_UINT64(0, cc_world_size(&d));
    {
        unsigned char buf[64];
        TEST_ASSERT_NULL(cc_world_init(buf, sizeof buf, &d, &st));
        TEST_ASSERT_EQUAL_INT(CC_ERR_VERSION, st);
    }
}

/* A busy world's memory is never written past the bytes given. */
static void test_canary_after_use(void)
{
    cc_world_def d;
    tw_mem m;
    cc_world *w;
    int i;
    cc_world_def_init(&d);
    d.max_circles = 100;
    d.max_segments = 4;
    w = tw_make(&m, &d, 0);
    TEST_ASSERT_NOT_NULL(w);
    (void)tw_fill_box(w, 100, 1.0, 0.3, 7);
    for (i = 0; i < 10; i++)
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 5.0));
    for (i = 0; i < 100; i += 3)
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_remove_circle(w, i));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 5.0));
    TEST_ASSERT_TRUE(tw_canary_ok(&m));
    tw_free(&m);
}

static cc_world *small_world(tw_mem *m, int cap, int segs)
{
    cc_world_def d;
    cc_world_def_init(&d);
    d.max_circles = cap;
    d.max_segments = segs;
    return tw_make(m, &d, 0);
}

static void test_ids_stable_and_reused(void)
{
    tw_mem m;
    cc_world *w = small_world(&m, 3, 0);
    cc_circle c = tw_circle(0, 0, 0, 0, 1, 1), got;
    int ids[3];
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &c));
    c.pos.x = 10;
    TEST_ASSERT_EQUAL_INT(1, cc_world_add_circle(w, &c));
    c.pos.x = 20;
    TEST_ASSERT_EQUAL_INT(2, cc_world_add_circle(w, &c));
    c.pos.x = 30;
    TEST_ASSERT_EQUAL_INT(CC_ERR_FULL, cc_world_add_circle(w, &c));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_remove_circle(w, 1));
    TEST_ASSERT_EQUAL_INT(CC_ERR_NOT_FOUND, cc_world_remove_circle(w, 1));
    TEST_ASSERT_EQUAL_INT(CC_ERR_NOT_FOUND, cc_world_get_circle(w, 1, &got));
    TEST_ASSERT_EQUAL_INT(CC_ERR_NOT_FOUND, cc_world_set_circle(w, 1, &c));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 2, &got)); /* others keep their ids */
    TEST_ASSERT_EQUAL_DOUBLE(20.0, got.pos.x);
    TEST_ASSERT_EQUAL_INT(2, cc_world_get_circles(w, ids, NULL, 3));
    TEST_ASSERT_EQUAL_INT(0, ids[0]);
    TEST_ASSERT_EQUAL_INT(2, ids[1]);
    TEST_ASSERT_EQUAL_INT(1, cc_world_add_circle(w, &c)); /* the freed id comes back */
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 1, &got));
    TEST_ASSERT_EQUAL_DOUBLE(30.0, got.pos.x);
    TEST_ASSERT_EQUAL_INT(3, cc_world_get_circles(w, NULL, NULL, 0));
    TEST_ASSERT_EQUAL_INT(CC_ERR_NOT_FOUND, cc_world_get_circle(w, 3, &got));
    TEST_ASSERT_EQUAL_INT(CC_ERR_NOT_FOUND, cc_world_get_circle(w, -1, &got));
    tw_free(&m);
}

static void test_segments(void)
{
    tw_mem m;
    cc_world *w = small_world(&m, 2, 1);
    cc_segment s, got;
    s.a.x = 0;
    s.a.y = 0;
    s.b.x = 1;
    s.b.y = 2;
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_segment(w, &s));
    TEST_ASSERT_EQUAL_INT(CC_ERR_FULL, cc_world_add_segment(w, &s));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_segment(w, 0, &got));
    TEST_ASSERT_EQUAL_MEMORY(&s, &got, sizeof s);
    TEST_ASSERT_EQUAL_INT(CC_ERR_NOT_FOUND, cc_world_get_segment(w, 1, &got));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_get_segment(w, 0, NULL));
    tw_free(&m);
    w = small_world(&m, 2, 2);
    s.a.x = NAN;
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_add_segment(w, &s));
    s.a.x = INFINITY;
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_add_segment(w, &s));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_add_segment(w, NULL));
    TEST_ASSERT_EQUAL_INT(CC_ERR_NOT_FOUND, cc_world_get_segment(w, 0, &got));
    tw_free(&m);
}

/* Every invalid call returns its error and leaves the world bit for bit as it was. */
static void test_errors_change_nothing(void)
{
    tw_mem m;
    cc_world *w = small_world(&m, 4, 0);
    cc_circle a = tw_circle(0, 0, 1, 0.5, 1, 2), b = tw_circle(5, 1, -1, 0, 0.5, 1), bad;
    cc_circle before[2], after[2];
    cc_world_stats s0, s1;
    double t0;
    int i;
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &a));
    TEST_ASSERT_EQUAL_INT(1, cc_world_add_circle(w, &b));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.5));
    TEST_ASSERT_EQUAL_INT(2, cc_world_get_circles(w, NULL, before, 2));
    s0.struct_size = sizeof s0;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_stats(w, &s0));
    t0 = cc_world_time(w);
    for (i = 0; i < 12; i++) {
        bad = a;
        switch (i) {
        case 0: bad.pos.x = NAN; break;
        case 1: bad.vel.y = INFINITY; break;
        case 2: bad.radius = 0; break;
        case 3: bad.radius = -1; break;
        case 4: bad.radius = NAN; break;
        case 5: bad.radius = INFINITY; break;
        case 6: bad.mass = 0; break;
        case 7: bad.mass = -1; break;
        case 8: bad.mass = NAN; break;
        case 9: bad.mass = -INFINITY; break;
        case 10: bad.pos.y = -INFINITY; break;
        default: bad.vel.x = NAN; break;
        }
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_add_circle(w, &bad));
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_set_circle(w, 0, &bad));
    }
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_add_circle(w, NULL));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_add_circle(NULL, &a));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_set_circle(w, 0, NULL));
    TEST_ASSERT_EQUAL_INT(CC_ERR_NOT_FOUND, cc_world_set_circle(w, 7, &a));
    TEST_ASSERT_EQUAL_INT(CC_ERR_NOT_FOUND, cc_world_remove_circle(w, 7));
    TEST_ASSERT_EQUAL_INT(CC_ERR_NOT_FOUND, cc_world_remove_circle(w, -3));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_remove_circle(NULL, 0));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_step(w, -1.0));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_step(w, -0.0 - 1e-300));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_step(w, NAN));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_step(w, INFINITY));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_step(w, 1e308 * 10));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_step(NULL, 1.0));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_get_circle(w, 0, NULL));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_get_circle(NULL, 0, &bad));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_get_circles(w, NULL, NULL, -1));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_get_stats(w, NULL));
    TEST_ASSERT_TRUE(isnan(cc_world_time(NULL)));
    s1.struct_size = sizeof(size_t); /* not even collisions */
    TEST_ASSERT_EQUAL_INT(CC_ERR_VERSION, cc_world_get_stats(w, &s1));
    /* nothing changed */
    TEST_ASSERT_EQUAL_DOUBLE(t0, cc_world_time(w));
    TEST_ASSERT_EQUAL_INT(2, cc_world_get_circles(w, NULL, after, 2));
    TEST_ASSERT_EQUAL_MEMORY(before, after, sizeof before);
    s1.struct_size = sizeof s1;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_stats(w, &s1));
    TEST_ASSERT_EQUAL_MEMORY(&s0, &s1, sizeof s0);
    /* and stepping from here is as if the errors had never been made */
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.0));
    TEST_ASSERT_EQUAL_DOUBLE(t0, cc_world_time(w));
    tw_free(&m);
}

/* An older caller's stats struct: only the fields it has are written. */
static void test_stats_cut_short(void)
{
    tw_mem m;
    cc_world *w = small_world(&m, 2, 0);
    cc_circle a = tw_circle(0, 0, 1, 0, 1, 1), b = tw_circle(4, 0, -1, 0, 1, 1);
    cc_world_stats s;
    (void)cc_world_add_circle(w, &a);
    (void)cc_world_add_circle(w, &b);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 10.0));
    memset(&s, 0xEE, sizeof s);
    s.struct_size = offsetof(cc_world_stats, collisions) + sizeof(uint64_t);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_stats(w, &s));
    TEST_ASSERT_EQUAL_UINT64(1, s.collisions);
    TEST_ASSERT_EQUAL_UINT64(UINT64_C(0xEEEEEEEEEEEEEEEE), s.events); /* beyond its size: untouched */
    TEST_ASSERT_EQUAL_UINT64(offsetof(cc_world_stats, collisions) + sizeof(uint64_t), s.struct_size);
    tw_free(&m);
}

/* The callback may not change the world it is called from: those calls are refused. */
static cc_world *g_world;
static int g_refused;
static void meddle(const cc_contact_event *e, void *user)
{
    cc_circle c = tw_circle(100, 100, 0, 0, 1, 1);
    (void)user;
    g_refused += cc_world_remove_circle(g_world, e->a) == tw_code(CC_ERR_BUSY);
    g_refused += cc_world_add_circle(g_world, &c) == tw_code(CC_ERR_BUSY);
    g_refused += cc_world_step(g_world, 1.0) == tw_code(CC_ERR_BUSY);
}

static void test_callback_cannot_meddle(void)
{
    cc_world_def d;
    tw_mem m;
    cc_circle a = tw_circle(0, 0, 1, 0, 1, 1), b = tw_circle(4, 0, -1, 0, 1, 1);
    cc_world_def_init(&d);
    d.max_circles = 3;
    d.on_contact = meddle;
    g_world = tw_make(&m, &d, 0);
    g_refused = 0;
    (void)cc_world_add_circle(g_world, &a);
    (void)cc_world_add_circle(g_world, &b);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(g_world, 10.0));
    TEST_ASSERT_EQUAL_INT(3, g_refused);
    TEST_ASSERT_EQUAL_INT(2, cc_world_get_circles(g_world, NULL, NULL, 0));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_remove_circle(g_world, 0)); /* after the step: fine */
    tw_free(&m);
}

/* A world with no capacity at all is valid and does nothing. */
static void test_empty_world(void)
{
    tw_mem m;
    cc_world *w = small_world(&m, 0, 0);
    cc_circle c = tw_circle(0, 0, 0, 0, 1, 1);
    TEST_ASSERT_NOT_NULL(w);
    TEST_ASSERT_EQUAL_INT(CC_ERR_FULL, cc_world_add_circle(w, &c));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 1.0));
    TEST_ASSERT_EQUAL_DOUBLE(1.0, cc_world_time(w));
    TEST_ASSERT_TRUE(tw_canary_ok(&m));
    tw_free(&m);
}

int main(void)
{
    (void)count_contact;
    UNITY_BEGIN();
    RUN_TEST(test_def_defaults);
    RUN_TEST(test_size_follows_capacity);
    RUN_TEST(test_invalid_defs);
    RUN_TEST(test_init_memory_errors);
    RUN_TEST(test_def_cut_short);
    RUN_TEST(test_canary_after_use);
    RUN_TEST(test_ids_stable_and_reused);
    RUN_TEST(test_segments);
    RUN_TEST(test_errors_change_nothing);
    RUN_TEST(test_stats_cut_short);
    RUN_TEST(test_callback_cannot_meddle);
    RUN_TEST(test_empty_world);
    return UNITY_END();
}
