/* EXACT's event calendar (src/world/calendar.c): a world large enough to have one runs exactly
 * the events of the same world whose queue is the heap alone (cal_nb forced to 0 after init),
 * state hash and counters equal after every step, through re-tunings, the overflow list, the
 * rebuilds that adding and removing circles cause, and a memcpy of the world in mid-run; and the
 * calendar's own bookkeeping holds after every step. */
#include "unity.h"

#include "test_world_util.h"
#include "world/world_internal.h"

void setUp(void) {}
void tearDown(void) {}

#define NC 5000 /* above CC__CAL_MIN_CIRCLES (4096): the world has a calendar */

static uint64_t g_rng;

static double uniform(void) /* xorshift64, [0, 1) */
{
    g_rng ^= g_rng << 13, g_rng ^= g_rng >> 7, g_rng ^= g_rng << 17;
    return (double)(g_rng >> 11) * 0x1p-53;
}

/* n disks of radius 0.5 on a square lattice at area fraction phi in a box of side L (walls, or
 * periodic), speeds spread over four decades (slow ones wait in the overflow list). */
static cc_world *make(tw_mem *m, int n, double phi, int periodic, int heap_only, uint64_t seed)
{
    cc_world_def d;
    cc_world *w;
    double L = sqrt(n * 3.141592653589793 * 0.25 / phi);
    int side = (int)ceil(sqrt((double)n)), i;
    cc_world_def_init(&d);
    d.max_circles = n + 16;
    d.max_segments = 4;
    d.restitution = 1.0;
    if (periodic)
        d.period.x = d.period.y = L;
    w = tw_make(m, &d, 0);
    TEST_ASSERT_NOT_NULL(w);
    TEST_ASSERT_TRUE(w->cal_nb > 0);
    if (heap_only)
        w->cal_nb = 0; /* the same layout, the heap alone */
    if (!periodic) {
        cc_world_add_segment(w, &(cc_segment){{0.0, 0.0}, {L, 0.0}});
        cc_world_add_segment(w, &(cc_segment){{L, 0.0}, {L, L}});
        cc_world_add_segment(w, &(cc_segment){{L, L}, {0.0, L}});
        cc_world_add_segment(w, &(cc_segment){{0.0, L}, {0.0, 0.0}});
    }
    g_rng = seed;
    for (i = 0; i < n; i++) {
        double sp = pow(10.0, -3.0 + 4.0 * uniform()), a = 6.283185307179586 * uniform();
        double x = (i % side + 0.5) * L / side, y = (i / side + 0.5) * L / side;
        TEST_ASSERT_EQUAL_INT(i, cc_world_add_circle(w, &(cc_circle){{x, y}, {sp * cos(a), sp * sin(a)}, 0.5, 1.0}));
    }
    return w;
}

/* The calendar's bookkeeping: every body filed where hpos says, the counts right, the heap's
 * events of blocks up to cal_cur and the buckets' of later blocks within the window. */
static void check_books(cc_world *w)
{
    const int32_t *hpos = CC__CARR(w, int32_t, off_hpos), *head = CC__CARR(w, int32_t, off_calhead);
    const int32_t *link = CC__CARR(w, int32_t, off_callink);
    const cc__heap_entry *heap = CC__CARR(w, cc__heap_entry, off_heap);
    const cc__event *ev = CC__CARR(w, cc__event, off_ev);
    int b, k, n = 0, over = 0;
    if (!w->cal_tuned)
        return;
    for (b = 0; b <= w->cal_nb; b++) {
        int32_t j, prev = -1;
        for (j = head[b]; j >= 0; prev = j, j = link[3 * j]) {
            double key = ev[j].t < ev[j].t_cross ? ev[j].t : ev[j].t_cross;
            double blk = (key - w->cal_base) * w->cal_inv_w;
            TEST_ASSERT_EQUAL_INT(-2 - b, hpos[3 * j]); /* (body j's hpos, next, prev: one node) */
            TEST_ASSERT_EQUAL_INT(prev, link[3 * j + 1]);
            TEST_ASSERT_TRUE(blk >= (double)(w->cal_cur + 1));
            if (b < w->cal_nb) {
                TEST_ASSERT_TRUE(blk < (double)(w->cal_cur + w->cal_nb));
                TEST_ASSERT_EQUAL_INT(b, (int)((int64_t)blk & (int64_t)(w->cal_nb - 1)));
            } else
                over++;
            n++;
        }
    }
    TEST_ASSERT_EQUAL_INT(w->cal_n, n);
    TEST_ASSERT_EQUAL_INT(w->cal_over, over);
    for (k = 0; k < w->heap_n; k++) {
        TEST_ASSERT_EQUAL_INT(k, hpos[3 * heap[k].id]);
        TEST_ASSERT_TRUE((heap[k].key - w->cal_base) * w->cal_inv_w < (double)(w->cal_cur + 1));
    }
}

/* World a (calendar) and b (heap alone) step alike; returns how many steps a's calendar was in
 * use. */
static int run_pair(cc_world *a, cc_world *b, int steps, double dt)
{
    int s, used = 0;
    for (s = 0; s < steps; s++) {
        cc_world_stats sa, sb;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(a, dt));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(b, dt));
        sa = tw_stats(a);
        sb = tw_stats(b);
        TEST_ASSERT_EQUAL_UINT64(sb.events, sa.events);
        TEST_ASSERT_EQUAL_UINT64(sb.collisions, sa.collisions);
        TEST_ASSERT_EQUAL_UINT64(cc_world_hash(b), cc_world_hash(a));
        if (s % 4 == 3)
            check_books(a);
        used += a->cal_tuned && a->cal_n > 0;
    }
    return used;
}

static void same_as_heap(double phi, int periodic, uint64_t seed)
{
    tw_mem ma, mb;
    cc_world *a = make(&ma, NC, phi, periodic, 0, seed), *b = make(&mb, NC, phi, periodic, 1, seed);
    int used = run_pair(a, b, 24, 1.0);
    TEST_ASSERT_TRUE(used > 12);        /* the calendar was tuned and held events */
    TEST_ASSERT_TRUE(tw_stats(a).collisions > 10000u);
    TEST_ASSERT_TRUE(tw_canary_ok(&ma));
    tw_free(&ma);
    tw_free(&mb);
}

void test_walled_gas_same_events_as_the_heap(void) { same_as_heap(0.3, 0, 11); }
void test_periodic_dense_same_events_as_the_heap(void) { same_as_heap(0.7, 1, 12); }

/* Circles added, removed and stopped mid-run (rebuilds and queue removals), and a memcpy of the
 * world with its calendar in use: still the heap's events. */
void test_rebuilds_and_memcpy_keep_the_events(void)
{
    tw_mem ma, mb, mc;
    cc_world *a = make(&ma, NC, 0.3, 0, 0, 21), *b = make(&mb, NC, 0.3, 0, 1, 21), *c;
    int k;
    TEST_ASSERT_TRUE(run_pair(a, b, 12, 0.25) > 0);
    for (k = 0; k < 4; k++) {
        cc_circle q;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_remove_circle(a, 100 * k + 3));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_remove_circle(b, 100 * k + 3));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(a, 100 * k + 50, &q));
        q.vel.x = q.vel.y = 0.0;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle(a, 100 * k + 50, &q));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle(b, 100 * k + 50, &q));
        TEST_ASSERT_TRUE(run_pair(a, b, 2, 0.25) >= 0);
    }
    /* the copy goes on where a stops; b keeps pace with it */
    mc = ma;
    mc.raw = (unsigned char *)malloc(ma.bytes + 32);
    TEST_ASSERT_NOT_NULL(mc.raw);
    mc.mem = mc.raw + ((16u - ((size_t)mc.raw & 15u)) & 15u);
    memcpy(mc.mem, ma.mem, ma.bytes);
    c = (cc_world *)(void *)mc.mem;
    memset(ma.mem, 0, ma.bytes); /* the original is gone */
    TEST_ASSERT_TRUE(run_pair(c, b, 12, 0.25) > 0);
    free(mc.raw);
    tw_free(&ma);
    tw_free(&mb);
}

/* Every circle slowed a thousandfold mid-run: the calendar's window holds nothing, the overflow
 * all (the window jumps to it), and the width is tuned again for the new pace. */
void test_slowdown_jumps_and_tunes_again(void)
{
    tw_mem ma, mb;
    cc_world *a = make(&ma, NC, 0.3, 1, 0, 31), *b = make(&mb, NC, 0.3, 1, 1, 31);
    double w0;
    int i;
    TEST_ASSERT_TRUE(run_pair(a, b, 12, 1.0) > 0);
    w0 = a->cal_w;
    for (i = 0; i < NC; i++) {
        cc_circle q;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(a, i, &q));
        q.vel.x *= 1e-3;
        q.vel.y *= 1e-3;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle(a, i, &q));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle(b, i, &q));
    }
    TEST_ASSERT_TRUE(run_pair(a, b, 16, 1000.0) > 0);
    TEST_ASSERT_TRUE(a->cal_w > 100.0 * w0); /* tuned again to the slower pace */
    tw_free(&ma);
    tw_free(&mb);
}

/* The queue itself against a plain search for the least (key, id): random keys over six decades
 * of lead time (many beyond the window: the overflow list), removals, and phases in which every
 * key lies far ahead (the window jumps); the calendar forced on at a narrow width from the start
 * and left to tune itself as the pace changes. */
void test_queue_pops_the_least_key(void)
{
    enum { ACTIVE = 600, OPS = 150000 };
    cc_world_def d;
    tw_mem m;
    cc_world *w;
    cc__event *ev;
    double key[ACTIVE], now = 0.0;
    int k, i, pops = 0, tunes_seen = 0;
    double w_first;
    cc_world_def_init(&d);
    d.max_circles = NC;
    w = tw_make(&m, &d, 0);
    TEST_ASSERT_NOT_NULL(w);
    ev = CC__ARR(w, cc__event, off_ev);
    w->cal_tuned = 1;
    w->cal_w = 1.0 / 64;
    w->cal_inv_w = 64.0;
    w_first = w->cal_w;
    g_rng = 77;
    for (i = 0; i < ACTIVE; i++)
        key[i] = HUGE_VAL;
    for (k = 0; k < OPS; k++) {
        double u = uniform(), far = (k / 20000) % 3 == 2 ? 1e4 : 1.0; /* a far phase now and then */
        int id = (int)(uniform() * ACTIVE);
        if (u < 0.45) { /* (re)key a body */
            key[id] = now + far * pow(10.0, -3.0 + 6.0 * uniform());
            ev[id].t = key[id];
            ev[id].t_cross = HUGE_VAL;
            cc__queue_update(w, id, key[id]);
        } else if (u < 0.5) {
            key[id] = HUGE_VAL;
            cc__queue_remove(w, id);
        } else { /* pop: the least (key, id), then that body looks ahead again */
            double t, best = HUGE_VAL;
            int top, want = -1;
            for (i = 0; i < ACTIVE; i++)
                if (key[i] < best)
                    best = key[i], want = i;
            w->now = now;
            top = cc__queue_top(w, &t);
            TEST_ASSERT_EQUAL_INT(want, top);
            if (top < 0)
                continue;
            TEST_ASSERT_EQUAL_DOUBLE(best, t);
            now = t;
            w->stats.events++;
            pops++;
            key[top] = now + far * pow(10.0, -3.0 + 6.0 * uniform());
            ev[top].t = key[top];
            ev[top].t_cross = HUGE_VAL;
            cc__queue_update(w, top, key[top]);
        }
        tunes_seen |= w->cal_w != w_first;
    }
    TEST_ASSERT_TRUE(pops > 50000);
    TEST_ASSERT_TRUE(tunes_seen);
    tw_free(&m);
}

/* A world below the calendar's size has none, and costs no memory for it. */
void test_small_world_has_no_calendar(void)
{
    cc_world_def d;
    tw_mem m;
    cc_world *w;
    cc_world_def_init(&d);
    d.max_circles = 1000;
    w = tw_make(&m, &d, 0);
    TEST_ASSERT_NOT_NULL(w);
    TEST_ASSERT_EQUAL_INT(0, w->cal_nb);
    tw_free(&m);
    d.mode = CC_MODE_SWEPT;
    d.max_circles = NC;
    w = tw_make(&m, &d, 0);
    TEST_ASSERT_NOT_NULL(w);
    TEST_ASSERT_EQUAL_INT(0, w->cal_nb);
    tw_free(&m);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_walled_gas_same_events_as_the_heap);
    RUN_TEST(test_periodic_dense_same_events_as_the_heap);
    RUN_TEST(test_rebuilds_and_memcpy_keep_the_events);
    RUN_TEST(test_slowdown_jumps_and_tunes_again);
    RUN_TEST(test_queue_pops_the_least_key);
    RUN_TEST(test_small_world_has_no_calendar);
    return UNITY_END();
}
