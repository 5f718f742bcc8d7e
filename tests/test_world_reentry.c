/* The contact callback may read the world but never change it, whichever call fired it: a step,
 * or (EXACT) an add or set that pushes a circle apart from another and gives the pair its
 * impulse at once. Every mutator called from inside is refused with CC_ERR_BUSY (tw_code) and changes
 * nothing, so the world ends bit for bit where a world with a callback that does nothing ends.
 * Also the struct_size handshake of cc_world_get_stats and of the def: a size that ends inside
 * a field leaves that field alone (issue 19). */
#include "unity.h"

#include "test_world_util.h"

#include <stddef.h>
#include <stdio.h>

void setUp(void) {}
void tearDown(void) {}

enum { MUT_ADD, MUT_REMOVE_A, MUT_REMOVE_B, MUT_REMOVE_LAST, MUT_SET, MUT_STEP, MUT_SEGMENT, MUT_COUNT };
enum { FIRE_ADD, FIRE_SET, FIRE_STEP, FIRE_COUNT };

static const char *const mut_name[MUT_COUNT] = {"add", "remove a", "remove b", "remove newest", "set", "step",
                                                "add_segment"};
static const char *const fire_name[FIRE_COUNT] = {"add", "set", "step"};

/* What the callback does and what it saw. */
typedef struct probe {
    cc_world *w;
    int mutator; /* -1: nothing */
    int newest;  /* the id most recently added (a circle whose own add may be firing) */
    int calls;
    int refused; /* calls answered CC_ERR_BUSY (CC_ERR_INVALID for a 1.1 def: tw_code) */
    int tried;
} probe;

static void on_contact(const cc_contact_event *e, void *user)
{
    probe *p = (probe *)user;
    cc_circle c = tw_circle(e->point.x, e->point.y, 0.5, 0.25, 1, 1); /* on top of the contact */
    cc_segment s = tw_segment(-50, -50, 50, -50);
    int r = 0;
    p->calls++;
    if (p->mutator < 0)
        return;
    switch (p->mutator) {
    case MUT_ADD: r = cc_world_add_circle(p->w, &c); break;
    case MUT_REMOVE_A: r = cc_world_remove_circle(p->w, e->a); break;
    case MUT_REMOVE_B: r = cc_world_remove_circle(p->w, e->b >= 0 ? e->b : e->a); break;
    case MUT_REMOVE_LAST: r = cc_world_remove_circle(p->w, p->newest); break;
    case MUT_SET: r = cc_world_set_circle(p->w, e->a, &c); break;
    case MUT_STEP: r = cc_world_step(p->w, 1.0); break;
    case MUT_SEGMENT: r = cc_world_add_segment(p->w, &s); break;
    default: break;
    }
    p->tried++;
    p->refused += r == tw_code(CC_ERR_BUSY);
}

/* What the callback scenes start from: a (id 0) and b (1) at rest, c (2) bouncing between the
 * walls at x = -20 and x = 20. */
static void add_scene(cc_world *w)
{
    cc_circle a = tw_circle(0, 0, 0, 0, 1, 1), b = tw_circle(5, 0, 0, 0, 1, 1), c = tw_circle(0, 10, 3, 0, 1, 1);
    cc_segment l = tw_segment(-20, -30, -20, 30), r = tw_segment(20, -30, 20, 30);
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &a));
    TEST_ASSERT_EQUAL_INT(1, cc_world_add_circle(w, &b));
    TEST_ASSERT_EQUAL_INT(2, cc_world_add_circle(w, &c));
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_segment(w, &l));
    TEST_ASSERT_EQUAL_INT(1, cc_world_add_segment(w, &r));
}

/* A scene whose every entry point fires the callback: a and b at rest, c bouncing between walls,
 * then (FIRE_ADD) d added overlapping a and approaching it, (FIRE_SET) b set overlapping a and
 * approaching it, or (FIRE_STEP) a plain step with impacts. Returns the world. */
static cc_world *run(tw_mem *m, int mode, int fire, probe *p)
{
    cc_world_def d;
    cc_world *w;
    cc_circle onto = tw_circle(1.5, 0, -1, 0, 1, 1); /* overlaps a by 0.5, closing at speed 1 */
    int k;
    cc_world_def_init(&d);
    d.max_circles = 64;
    d.max_segments = 4;
    d.mode = mode;
    d.on_contact = on_contact;
    d.user = p;
    w = tw_make(m, &d, 0);
    TEST_ASSERT_NOT_NULL(w);
    p->w = w;
    add_scene(w);
    p->newest = 2;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.0)); /* everything filed: add and set act at once */
    if (fire == FIRE_ADD) {
        p->newest = 3;
        TEST_ASSERT_EQUAL_INT(3, cc_world_add_circle(w, &onto));
    } else if (fire == FIRE_SET) {
        p->newest = 1;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle(w, 1, &onto));
    }
    for (k = 0; k < 200; k++) /* steps of 0.1: c moves 0.3 per step, DISCRETE catches it too */
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.1));
    TEST_ASSERT_TRUE(tw_canary_ok(m));
    return w;
}

/* Every live circle's state, bit for bit, and the counters. */
static void assert_same_world(const cc_world *x, const cc_world *y, const char *what)
{
    cc_circle cx[8], cy[8];
    int ix[8], iy[8], nx = cc_world_get_circles(x, ix, cx, 8), ny = cc_world_get_circles(y, iy, cy, 8);
    cc_world_stats sx = tw_stats(x), sy = tw_stats(y);
    TEST_ASSERT_EQUAL_INT_MESSAGE(ny, nx, what);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(iy, ix, sizeof ix[0] * (size_t)nx, what);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(cy, cx, sizeof cx[0] * (size_t)nx, what);
    TEST_ASSERT_EQUAL_UINT64_MESSAGE(sy.collisions, sx.collisions, what);
    TEST_ASSERT_EQUAL_UINT64_MESSAGE(sy.events, sx.events, what);
    TEST_ASSERT_EQUAL_DOUBLE_MESSAGE(cc_world_time(y), cc_world_time(x), what);
}

/* Each mutator from a callback fired by add, set and step, in each mode: refused, every time,
 * and the world ends exactly as with a callback that does nothing. In SWEPT and DISCRETE add and
 * set act at the next step, so the callback is fired by steps only (and still refused). */
static void test_every_mutator_refused_from_every_callback(void)
{
    int mode, fire, mut;
    char what[128];
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++)
        for (fire = 0; fire < FIRE_COUNT; fire++) {
            tw_mem mq;
            probe quiet = {NULL, -1, 0, 0, 0, 0};
            cc_world *wq = run(&mq, mode, fire, &quiet);
            TEST_ASSERT_TRUE(quiet.calls > 0);
            for (mut = 0; mut < MUT_COUNT; mut++) {
                tw_mem m;
                probe p = {NULL, 0, 0, 0, 0, 0};
                cc_world *w;
                p.mutator = mut;
                w = run(&m, mode, fire, &p);
                snprintf(what, sizeof what, "mode %d, fired by %s, callback calls %s", mode, fire_name[fire], mut_name[mut]);
                TEST_ASSERT_EQUAL_INT_MESSAGE(quiet.calls, p.calls, what);
                TEST_ASSERT_EQUAL_INT_MESSAGE(p.tried, p.refused, what);
                assert_same_world(w, wq, what);
                tw_free(&m);
            }
            tw_free(&mq);
        }
}

/* The reproducer: a world stepped once with a at rest; b added overlapping a and
 * approaching it fires the callback from inside the add, and the callback's add is refused. */
static cc_world *g_world;
static int g_first_add;
static void add_on_first_call(const cc_contact_event *e, void *user)
{
    cc_circle c = tw_circle(10, 0, 0, 0, 1, 1);
    (void)e;
    (void)user;
    if (g_first_add == 1000)
        g_first_add = cc_world_add_circle(g_world, &c);
}

static void test_add_from_add_callback_is_refused(void)
{
    cc_world_def d;
    tw_mem m;
    cc_circle a = tw_circle(0, 0, 0, 0, 1, 1), b = tw_circle(1.5, 0, -1, 0, 1, 1);
    cc_world_def_init(&d);
    d.max_circles = 64;
    d.on_contact = add_on_first_call;
    g_world = tw_make(&m, &d, 0);
    g_first_add = 1000;
    TEST_ASSERT_NOT_NULL(g_world);
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(g_world, &a));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(g_world, 0.0));
    TEST_ASSERT_EQUAL_INT(1, cc_world_add_circle(g_world, &b)); /* fires the callback */
    TEST_ASSERT_EQUAL_INT(tw_code(CC_ERR_BUSY), g_first_add);
    TEST_ASSERT_EQUAL_INT(2, cc_world_get_circles(g_world, NULL, NULL, 0));
    tw_free(&m);
}

/* Nested adds on top of the contact point, had they been accepted, re-entered the grid's
 * bookkeeping while it was being updated. Now each is refused; the world stays consistent: it
 * steps on (a bounded number of events), keeps every circle, and no two overlap beyond rounding. */
static void test_pile_of_adds_from_callbacks_keeps_world_consistent(void)
{
    int mode;
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++) {
        tw_mem m;
        probe p = {NULL, MUT_ADD, 0, 0, 0, 0};
        cc_world *w = run(&m, mode, FIRE_ADD, &p);
        cc_circle c[8];
        int n = cc_world_get_circles(w, NULL, c, 8), i, j;
        cc_world_stats s;
        TEST_ASSERT_EQUAL_INT(4, n);
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 100.0));
        s = tw_stats(w);
        TEST_ASSERT_TRUE(s.events < 100000); /* finite work: no loop */
        n = cc_world_get_circles(w, NULL, c, 8);
        for (i = 0; i < n && mode == CC_MODE_EXACT; i++)
            for (j = i + 1; j < n; j++) {
                double dx = c[j].pos.x - c[i].pos.x, dy = c[j].pos.y - c[i].pos.y;
                TEST_ASSERT_TRUE(sqrt(dx * dx + dy * dy) > c[i].radius + c[j].radius - 1e-10);
            }
        tw_free(&m);
    }
}

/* Snapshots taken from inside a callback: the world's bytes copied (memcpy, as the header allows)
 * on the callback's first call, into memory of their own, while the call that fired it runs. */
typedef struct snap {
    tw_mem mem;      /* its memory (tw_make's alignment), as large as the world's */
    cc_world *live;  /* the world whose callback takes it */
    double t;        /* the callback's event time */
    int taken;
    int live_step;   /* what cc_world_step(live, 0) answered from inside the callback */
} snap;

static cc_world *snap_world(const snap *s) { return (cc_world *)(void *)s->mem.mem; }

/* 16-aligned memory of `bytes`, filled from `from`. */
static cc_world *mem_copy(tw_mem *m, const void *from, size_t bytes)
{
    m->raw = (unsigned char *)malloc(bytes + 16);
    TEST_ASSERT_NOT_NULL(m->raw);
    m->mem = m->raw + ((16u - ((size_t)m->raw & 15u)) & 15u);
    m->bytes = bytes;
    memcpy(m->mem, from, bytes);
    return (cc_world *)(void *)m->mem;
}

/* A second copy, in memory of its own, of the snapshot as it is now. */
static cc_world *snap_copy(tw_mem *m, const snap *s) { return mem_copy(m, s->mem.mem, s->mem.bytes); }

static snap *g_snap;

static void snap_on_contact(const cc_contact_event *e, void *user)
{
    snap *s = g_snap;
    (void)user;
    if (s == NULL || s->taken || s->live == NULL)
        return;
    s->taken = 1;
    s->t = e->t;
    memcpy(s->mem.mem, s->live, s->mem.bytes);
    s->live_step = cc_world_step(s->live, 0.0); /* the call that takes a snapshot over: refused here */
}

/* The scene of run() with the snapshot's callback (and, first, its memory). */
static cc_world *snap_run(tw_mem *m, int mode, int fire, snap *s)
{
    cc_world_def d;
    cc_world *w;
    cc_circle onto = tw_circle(1.5, 0, -1, 0, 1, 1);
    int k;
    cc_world_def_init(&d);
    d.max_circles = 64;
    d.max_segments = 4;
    d.mode = mode;
    d.on_contact = snap_on_contact;
    memset(s, 0, sizeof *s);
    w = tw_make(m, &d, 0);
    TEST_ASSERT_NOT_NULL(w);
    (void)mem_copy(&s->mem, m->mem, m->bytes);
    g_snap = s;
    add_scene(w);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.0));
    s->live = w; /* from here on: the first contact takes the snapshot */
    if (fire == FIRE_ADD)
        TEST_ASSERT_EQUAL_INT(3, cc_world_add_circle(w, &onto));
    else if (fire == FIRE_SET)
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle(w, 1, &onto));
    for (k = 0; k < 100; k++) /* c meets the wall at x = 20 near t = 6 */
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.1));
    TEST_ASSERT_TRUE(s->taken);
    g_snap = NULL;
    return w;
}

/* Every mutator on the copy, then steps: what a game does with the impact it kept. */
static void use_snapshot(cc_world *w, const char *what)
{
    cc_circle far = tw_circle(0, -20, 0, 1, 1, 1), got;
    cc_segment top = tw_segment(-20, 30, 20, 30);
    int k;
    TEST_ASSERT_EQUAL_INT_MESSAGE(CC_OK, cc_world_step(w, 0.1), what);
    int id = cc_world_add_circle(w, &far);
    TEST_ASSERT_TRUE_MESSAGE(id >= 3, what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(CC_OK, cc_world_remove_circle(w, id), what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(CC_OK, cc_world_get_circle(w, 2, &got), what);
    got.vel.y = 0.5;
    TEST_ASSERT_EQUAL_INT_MESSAGE(CC_OK, cc_world_set_circle(w, 2, &got), what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(2, cc_world_add_segment(w, &top), what);
    for (k = 0; k < 200; k++) /* steps of 0.1, as the world's own */
        TEST_ASSERT_EQUAL_INT_MESSAGE(CC_OK, cc_world_step(w, 0.1), what);
}

/* A copy taken inside the callback of each call that fires one (add, set, step), in each mode,
 * is a world of its own: not busy (its guard named the memory it was copied from), it steps,
 * takes every mutator, and two copies of it treated alike end bit for bit alike, their circles
 * apart (EXACT) and held by the walls. Meanwhile the world it was taken from still refuses, from
 * that callback, the very call that takes a copy over (a step of 0). */
static void test_snapshot_taken_in_a_callback_is_a_world_of_its_own(void)
{
    int mode, fire, i, j;
    char what[96];
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++)
        for (fire = 0; fire < FIRE_COUNT; fire++) {
            tw_mem m, m2;
            snap s;
            cc_world *w = snap_run(&m, mode, fire, &s), *c1 = snap_world(&s), *c2;
            cc_circle c[8];
            int n;
            snprintf(what, sizeof what, "mode %d, snapshot in a callback fired by %s", mode, fire_name[fire]);
            TEST_ASSERT_EQUAL_INT_MESSAGE(tw_code(CC_ERR_BUSY), s.live_step, what);
            TEST_ASSERT_EQUAL_DOUBLE_MESSAGE(s.t, cc_world_time(c1), what);
            c2 = snap_copy(&m2, &s);
            use_snapshot(c1, what);
            use_snapshot(c2, what);
            assert_same_world(c1, c2, what);
            TEST_ASSERT_EQUAL_UINT64_MESSAGE(cc_world_hash(c1), cc_world_hash(c2), what);
            n = cc_world_get_circles(c1, NULL, c, 8);
            TEST_ASSERT_EQUAL_INT_MESSAGE(fire == FIRE_ADD ? 4 : 3, n, what);
            for (i = 0; i < n; i++) {
                TEST_ASSERT_TRUE_MESSAGE(fabs(c[i].pos.x) < 20.0, what);
                for (j = i + 1; j < n && mode == CC_MODE_EXACT; j++) {
                    double dx = c[j].pos.x - c[i].pos.x, dy = c[j].pos.y - c[i].pos.y;
                    TEST_ASSERT_TRUE_MESSAGE(sqrt(dx * dx + dy * dy) > c[i].radius + c[j].radius - 1e-10, what);
                }
            }
            TEST_ASSERT_EQUAL_INT_MESSAGE(CC_OK, cc_world_step(w, 1.0), what); /* the world itself steps on */
            tw_free(&m2);
            tw_free(&s.mem);
            tw_free(&m);
        }
}

/* A snapshot kept for later and copied back over the world it came from (a replay): copied as
 * taken, its bytes are that world inside the call that took it, which no one can tell from the
 * call still running, so it stays busy (the header says so); taken over first where it was kept
 * (cc_world_step(copy, 0)), it is an ordinary world and goes anywhere, its own place included. */
static void test_snapshot_copied_back_over_its_world(void)
{
    int mode;
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++) {
        tw_mem m, m2, m3;
        snap s;
        cc_world *w = snap_run(&m, mode, FIRE_STEP, &s), *kept = snap_world(&s), *raw, *twin;
        raw = snap_copy(&m2, &s); /* as taken */
        memcpy(w, raw, s.mem.bytes);
        TEST_ASSERT_EQUAL_INT(tw_code(CC_ERR_BUSY), cc_world_step(w, 1.0));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(kept, 0.0)); /* taken over where it is kept */
        twin = snap_copy(&m3, &s);
        memcpy(w, kept, s.mem.bytes);
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 10.0));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(twin, 10.0));
        assert_same_world(w, twin, "a snapshot taken over, then copied back");
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(raw, 10.0)); /* the raw copy, where it is, steps */
        assert_same_world(raw, twin, "the raw copy stepped where it is");
        tw_free(&m3);
        tw_free(&m2);
        tw_free(&s.mem);
        tw_free(&m);
    }
}

/* cc_world_get_stats with every struct_size from the smallest accepted to the whole struct:
 * exactly the fields that end within it are written (a cut field is untouched), struct_size is
 * kept. Field ends are taken from offsetof, so the test holds on 32-bit targets too. */
static void test_stats_size_inside_every_field(void)
{
    static const size_t ends[] = {
        offsetof(cc_world_stats, collisions) + sizeof(uint64_t), offsetof(cc_world_stats, events) + sizeof(uint64_t),
        offsetof(cc_world_stats, stale_events) + sizeof(uint64_t),
        offsetof(cc_world_stats, pairs_tested) + sizeof(uint64_t),
        offsetof(cc_world_stats, cell_crossings) + sizeof(uint64_t),
        offsetof(cc_world_stats, max_overlap) + sizeof(double), offsetof(cc_world_stats, virial) + sizeof(double),
        offsetof(cc_world_stats, wall_impulse) + sizeof(double)};
    tw_mem m;
    probe p = {NULL, -1, 0, 0, 0, 0};
    cc_world *w = run(&m, CC_MODE_EXACT, FIRE_STEP, &p);
    cc_world_stats whole = tw_stats(w);
    size_t size, k;
    for (size = ends[0]; size <= sizeof(cc_world_stats); size++) {
        unsigned char buf[sizeof(cc_world_stats)];
        size_t written = 0;
        cc_world_stats s;
        for (k = 0; k < sizeof ends / sizeof ends[0]; k++)
            if (ends[k] <= size)
                written = ends[k];
        memset(buf, 0xEE, sizeof buf);
        memcpy(buf, &size, sizeof size); /* struct_size */
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_stats(w, (cc_world_stats *)(void *)buf));
        memcpy(&s, buf, sizeof s);
        TEST_ASSERT_EQUAL_UINT64(size, s.struct_size);
        /* the written part equals the whole struct's, the rest is untouched */
        TEST_ASSERT_EQUAL_MEMORY((const unsigned char *)&whole + sizeof(size_t), buf + sizeof(size_t),
                                 written - sizeof(size_t));
        for (k = written; k < sizeof buf; k++)
            TEST_ASSERT_EQUAL_INT(0xEE, buf[k]);
    }
    tw_free(&m);
}

/* A def whose struct_size ends inside max_events: max_events keeps its default (1e7), not a
 * mixture of the caller's bytes and the default's (on a little-endian machine the caller's low
 * half, 1, with the default's high half, 0, would cap every step at one event). */
static void test_def_size_inside_a_field(void)
{
    cc_world_def d;
    tw_mem m, whole;
    cc_world *w, *ref;
    /* a runs into b, b into c: at least two events in the step */
    cc_circle a = tw_circle(0, 0, 0.5, 0, 1, 1), b = tw_circle(3, 0, 0, 0, 1, 1), c = tw_circle(6, 0, 0, 0, 1, 1);
    cc_world_def_init(&d);
    d.max_circles = 4;
    d.restitution = 0.5;
    d.max_events = 1;
    d.struct_size = offsetof(cc_world_def, max_events) + 4;
    w = tw_make(&m, &d, 0);
    TEST_ASSERT_NOT_NULL(w);
    cc_world_def_init(&d);
    d.max_circles = 4;
    d.restitution = 0.5;
    ref = tw_make(&whole, &d, 0);
    TEST_ASSERT_NOT_NULL(ref);
    (void)cc_world_add_circle(w, &a);
    (void)cc_world_add_circle(w, &b);
    (void)cc_world_add_circle(w, &c);
    (void)cc_world_add_circle(ref, &a);
    (void)cc_world_add_circle(ref, &b);
    (void)cc_world_add_circle(ref, &c);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 100.0));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(ref, 100.0));
    TEST_ASSERT_TRUE(tw_stats(w).collisions >= 2);
    assert_same_world(w, ref, "def cut inside max_events");
    tw_free(&m);
    tw_free(&whole);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_every_mutator_refused_from_every_callback);
    RUN_TEST(test_add_from_add_callback_is_refused);
    RUN_TEST(test_pile_of_adds_from_callbacks_keeps_world_consistent);
    RUN_TEST(test_snapshot_taken_in_a_callback_is_a_world_of_its_own);
    RUN_TEST(test_snapshot_copied_back_over_its_world);
    RUN_TEST(test_stats_size_inside_every_field);
    RUN_TEST(test_def_size_inside_a_field);
    return UNITY_END();
}
