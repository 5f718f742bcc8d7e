/* The world's batch calls (1.2): cc_world_add_circles does what one cc_world_add_circle per
 * circle in order does, or, when one circle is refused, changes nothing at all (the world's
 * memory compared byte for byte) and names that circle; cc_world_get_unwrapped_all gives
 * cc_world_get_unwrapped's answer for every live circle, in id order. */
#include "unity.h"

#include "test_world_util.h"

#include <stdio.h>

void setUp(void) {}
void tearDown(void) {}

static int g_contacts;
static cc_world *g_world;
static int g_inner_result, g_inner_failed;

static void count_contact(const cc_contact_event *e, void *user)
{
    (void)e;
    (void)user;
    g_contacts++;
}

/* From inside a callback the world may be read, not changed: the batch too is refused. */
static void add_from_callback(const cc_contact_event *e, void *user)
{
    cc_circle c = tw_circle(100.0, 100.0, 0.0, 0.0, 1.0, 1.0);
    (void)e;
    (void)user;
    g_contacts++;
    g_inner_failed = 77;
    g_inner_result = cc_world_add_circles(g_world, &c, 1, NULL, &g_inner_failed);
}

static cc_world_def def_of(int max_circles, cc_contact_fn fn)
{
    cc_world_def d;
    cc_world_def_init(&d);
    d.max_circles = max_circles;
    d.on_contact = fn;
    return d;
}

/* n circles of radius 1 on a row 1.5 apart, so that neighbours overlap by 0.5 and are pushed
 * apart (and, approaching, struck) when they are added to a settled EXACT world. */
static void overlapping_row(cc_circle *c, int n, double y)
{
    int i;
    for (i = 0; i < n; i++)
        c[i] = tw_circle(1.5 * i, y, i % 2 ? -1.0 : 1.0, 0.25 * i, 1.0, 1.0 + i % 3);
}

/* Two worlds fed the same calls, except that one gets the batch and the other one add per
 * circle: the same ids, the same callbacks, the same state (hash and every circle). Run on a
 * world before its first step (nothing is filed yet) and after one (each circle added is
 * pushed apart from its neighbours at once, which fires on_contact), with removed ids on the
 * free stack (reused last-in first-out, then fresh ones). */
static void batch_against_singles(int settle_first)
{
    enum { N = 40, B = 12 };
    cc_world_def d = def_of(N + B, count_contact);
    tw_mem ma, mb;
    cc_world *a = tw_make(&ma, &d, 0), *b = tw_make(&mb, &d, 0);
    cc_circle base[N], batch[B];
    int ids_batch[B], ids_single[B], i, failed = 1234, contacts_single;
    TEST_ASSERT_NOT_NULL(a);
    TEST_ASSERT_NOT_NULL(b);
    for (i = 0; i < N; i++)
        base[i] = tw_circle(3.0 * (i % 8), 3.0 * (i / 8), 0.1 * (i % 5), -0.1 * (i % 3), 1.0, 1.0);
    for (i = 0; i < N; i++) {
        TEST_ASSERT_EQUAL_INT(i, cc_world_add_circle(a, &base[i]));
        TEST_ASSERT_EQUAL_INT(i, cc_world_add_circle(b, &base[i]));
    }
    /* ids 5, 17, 30 removed in that order: the free stack hands back 30, 17, 5, then 40, 41, ... */
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_remove_circle(a, 5));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_remove_circle(a, 17));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_remove_circle(a, 30));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_remove_circle(b, 5));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_remove_circle(b, 17));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_remove_circle(b, 30));
    if (settle_first) {
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(a, 0.5));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(b, 0.5));
    }
    overlapping_row(batch, B, -10.0);
    g_contacts = 0;
    for (i = 0; i < B; i++)
        ids_single[i] = cc_world_add_circle(b, &batch[i]);
    contacts_single = g_contacts;
    g_contacts = 0;
    TEST_ASSERT_EQUAL_INT(B, cc_world_add_circles(a, batch, B, ids_batch, &failed));
    TEST_ASSERT_EQUAL_INT(1234, failed); /* written on an error only */
    TEST_ASSERT_EQUAL_INT(30, ids_batch[0]);
    TEST_ASSERT_EQUAL_INT(17, ids_batch[1]);
    TEST_ASSERT_EQUAL_INT(5, ids_batch[2]);
    TEST_ASSERT_EQUAL_INT(40, ids_batch[3]);
    for (i = 0; i < B; i++)
        TEST_ASSERT_EQUAL_INT(ids_single[i], ids_batch[i]);
    TEST_ASSERT_EQUAL_INT(contacts_single, g_contacts);
    if (settle_first) /* 11 neighbouring pairs overlap and approach or not: some are struck */
        TEST_ASSERT_TRUE(g_contacts > 0);
    else /* nothing is filed before the first step: the overlaps wait for it */
        TEST_ASSERT_EQUAL_INT(0, g_contacts);
    TEST_ASSERT_EQUAL_UINT64(cc_world_hash(b), cc_world_hash(a));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(a, 3.0));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(b, 3.0));
    TEST_ASSERT_EQUAL_UINT64(cc_world_hash(b), cc_world_hash(a));
    TEST_ASSERT_TRUE(tw_canary_ok(&ma));
    tw_free(&ma);
    tw_free(&mb);
}

static void test_batch_is_the_singles_before_the_first_step(void) { batch_against_singles(0); }
static void test_batch_is_the_singles_in_a_settled_world(void) { batch_against_singles(1); }

/* A world with 7 circles in a settled state, and a copy of its memory to compare with. */
typedef struct fixture {
    tw_mem m;
    cc_world *w;
    unsigned char *before;
} fixture;

static void fixture_make(fixture *f, int capacity, double period)
{
    cc_world_def d = def_of(capacity, NULL);
    int i;
    d.period.x = period;
    d.period.y = period;
    f->w = tw_make(&f->m, &d, 0);
    TEST_ASSERT_NOT_NULL(f->w);
    for (i = 0; i < 7; i++) {
        cc_circle c = tw_circle(3.0 * i + 1.5, 2.0, 0.5, 0.25, 1.0, 1.0);
        TEST_ASSERT_EQUAL_INT(i, cc_world_add_circle(f->w, &c));
    }
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(f->w, 0.25));
    f->before = (unsigned char *)malloc(f->m.bytes);
    TEST_ASSERT_NOT_NULL(f->before);
    memcpy(f->before, f->m.mem, f->m.bytes);
}

static void fixture_unchanged(fixture *f)
{
    TEST_ASSERT_EQUAL_INT(0, memcmp(f->before, f->m.mem, f->m.bytes));
    TEST_ASSERT_TRUE(tw_canary_ok(&f->m));
}

static void fixture_free(fixture *f)
{
    free(f->before);
    tw_free(&f->m);
}

/* ids_out is left as it was by every refusal: 8 sentinels compared after each. */
static void assert_ids_untouched(const int *ids)
{
    int i;
    for (i = 0; i < 8; i++)
        TEST_ASSERT_EQUAL_INT(-99, ids[i]);
}

static void test_an_invalid_circle_changes_nothing_and_is_named(void)
{
    fixture f;
    cc_circle batch[8];
    int ids[8], failed = 55, i, k;
    fixture_make(&f, 64, 0.0);
    for (k = 0; k < 5; k++) { /* each kind of invalid circle, at index 3 of 8 */
        for (i = 0; i < 8; i++)
            batch[i] = tw_circle(50.0 + 3.0 * i, 50.0, 0.0, 0.0, 1.0, 1.0);
        if (k == 0)
            batch[3].radius = NAN;
        else if (k == 1)
            batch[3].radius = 0.0;
        else if (k == 2)
            batch[3].mass = -1.0;
        else if (k == 3)
            batch[3].pos.y = INFINITY;
        else
            batch[3].vel.x = NAN;
        for (i = 0; i < 8; i++)
            ids[i] = -99;
        failed = 55;
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_add_circles(f.w, batch, 8, ids, &failed));
        TEST_ASSERT_EQUAL_INT(3, failed); /* not 0..2, which were fine: none of them was added */
        assert_ids_untouched(ids);
        fixture_unchanged(&f);
        TEST_ASSERT_EQUAL_INT(7, cc_world_get_circles(f.w, NULL, NULL, 0));
    }
    /* the first bad one is named when there are several */
    batch[1].radius = -2.0;
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_add_circles(f.w, batch, 8, ids, &failed));
    TEST_ASSERT_EQUAL_INT(1, failed);
    /* failed may be NULL */
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_add_circles(f.w, batch, 8, ids, NULL));
    fixture_unchanged(&f);
    fixture_free(&f);
}

static void test_a_full_world_changes_nothing_and_names_the_first_that_does_not_fit(void)
{
    fixture f;
    cc_circle batch[8];
    int ids[8], failed, i;
    fixture_make(&f, 10, 0.0); /* 7 of 10 used: 3 fit, the 4th (index 3) finds it full */
    for (i = 0; i < 8; i++) {
        batch[i] = tw_circle(50.0 + 3.0 * i, 50.0, 0.0, 0.0, 1.0, 1.0);
        ids[i] = -99;
    }
    failed = 55;
    TEST_ASSERT_EQUAL_INT(CC_ERR_FULL, cc_world_add_circles(f.w, batch, 5, ids, &failed));
    TEST_ASSERT_EQUAL_INT(3, failed);
    assert_ids_untouched(ids);
    fixture_unchanged(&f);
    /* an invalid circle after the first that does not fit: full decides (index 3), as the
     * single adds would meet it first; one before it: invalid decides */
    batch[4].radius = NAN;
    TEST_ASSERT_EQUAL_INT(CC_ERR_FULL, cc_world_add_circles(f.w, batch, 5, ids, &failed));
    TEST_ASSERT_EQUAL_INT(3, failed);
    batch[1].mass = 0.0;
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_add_circles(f.w, batch, 5, ids, &failed));
    TEST_ASSERT_EQUAL_INT(1, failed);
    assert_ids_untouched(ids);
    fixture_unchanged(&f);
    /* exactly the room there is: all three added, ids 7, 8, 9 */
    batch[1].mass = 1.0;
    TEST_ASSERT_EQUAL_INT(3, cc_world_add_circles(f.w, batch, 3, ids, &failed));
    TEST_ASSERT_EQUAL_INT(7, ids[0]);
    TEST_ASSERT_EQUAL_INT(9, ids[2]);
    TEST_ASSERT_EQUAL_INT(10, cc_world_get_circles(f.w, NULL, NULL, 0));
    fixture_free(&f);
}

static void test_a_circle_too_wide_for_the_period_changes_nothing(void)
{
    fixture f;
    cc_circle batch[4];
    int ids[8], failed = 55, i;
    /* period 21.5: a circle of radius r needs 2 (2r) + 1.0625 (2r) = 6.125 r <= 21.5, r <= 3.51 */
    fixture_make(&f, 64, 21.5);
    for (i = 0; i < 4; i++)
        batch[i] = tw_circle(2.0 + 4.0 * i, 12.0, 0.0, 0.0, 1.0, 1.0);
    for (i = 0; i < 8; i++)
        ids[i] = -99;
    batch[2].radius = 3.6;
    TEST_ASSERT_EQUAL_INT(tw_code(CC_ERR_RANGE), cc_world_add_circles(f.w, batch, 4, ids, &failed));
    TEST_ASSERT_EQUAL_INT(2, failed);
    assert_ids_untouched(ids);
    fixture_unchanged(&f);
    batch[2].radius = 3.5;
    TEST_ASSERT_EQUAL_INT(4, cc_world_add_circles(f.w, batch, 4, ids, &failed));
    fixture_free(&f);
}

static void test_bad_arguments(void)
{
    fixture f;
    cc_circle c = tw_circle(60.0, 60.0, 0.0, 0.0, 1.0, 1.0);
    int ids[8], failed, i;
    fixture_make(&f, 64, 0.0);
    for (i = 0; i < 8; i++)
        ids[i] = -99;
    failed = 55;
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_add_circles(NULL, &c, 1, ids, &failed));
    TEST_ASSERT_EQUAL_INT(-1, failed);
    failed = 55;
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_add_circles(f.w, &c, -1, ids, &failed));
    TEST_ASSERT_EQUAL_INT(-1, failed);
    failed = 55;
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_add_circles(f.w, NULL, 1, ids, &failed));
    TEST_ASSERT_EQUAL_INT(-1, failed);
    assert_ids_untouched(ids);
    fixture_unchanged(&f);
    /* nothing to add: 0, with or without an array, nothing written */
    failed = 55;
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circles(f.w, NULL, 0, ids, &failed));
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circles(f.w, &c, 0, NULL, NULL));
    TEST_ASSERT_EQUAL_INT(55, failed);
    assert_ids_untouched(ids);
    fixture_unchanged(&f);
    /* ids_out may be NULL: the circle is added all the same, with the next id (7) */
    TEST_ASSERT_EQUAL_INT(1, cc_world_add_circles(f.w, &c, 1, NULL, NULL));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(f.w, 7, &c));
    TEST_ASSERT_EQUAL_DOUBLE(60.0, c.pos.x);
    fixture_free(&f);
}

static void test_refused_from_a_callback(void)
{
    cc_world_def d = def_of(8, add_from_callback);
    tw_mem m;
    cc_world *w = tw_make(&m, &d, 0);
    cc_circle a = tw_circle(0.0, 0.0, 1.0, 0.0, 1.0, 1.0), b = tw_circle(4.0, 0.0, -1.0, 0.0, 1.0, 1.0);
    TEST_ASSERT_NOT_NULL(w);
    g_world = w;
    g_contacts = 0;
    g_inner_result = 0;
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &a));
    TEST_ASSERT_EQUAL_INT(1, cc_world_add_circle(w, &b));
    /* the gap of 2 closes at speed 2: one impact at t = 1, whose callback tries the batch */
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 2.0));
    TEST_ASSERT_EQUAL_INT(1, g_contacts);
    TEST_ASSERT_EQUAL_INT(tw_code(CC_ERR_BUSY), g_inner_result);
    TEST_ASSERT_EQUAL_INT(-1, g_inner_failed);
    TEST_ASSERT_EQUAL_INT(2, cc_world_get_circles(w, NULL, NULL, 0));
    tw_free(&m);
}

static void test_unwrapped_all_is_get_unwrapped_for_each(void)
{
    cc_world_def d = def_of(16, NULL);
    tw_mem m;
    cc_world *w;
    cc_vec2 all[16], one;
    int ids[16], i, n;
    d.period.x = 10.0;
    d.period.y = 10.0;
    w = tw_make(&m, &d, 0);
    TEST_ASSERT_NOT_NULL(w);
    /* six circles of radius 0.5 on a row 1.5 apart moving at (1, -0.5) each: no contacts */
    for (i = 0; i < 6; i++) {
        cc_circle c = tw_circle(1.5 * i + 1.0, 5.0, 1.0, -0.5, 0.5, 1.0);
        TEST_ASSERT_EQUAL_INT(i, cc_world_add_circle(w, &c));
    }
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_remove_circle(w, 2));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 25.0));
    for (i = 0; i < 16; i++) {
        ids[i] = -99;
        all[i].x = all[i].y = -99.0;
    }
    n = cc_world_get_unwrapped_all(w, ids, all, 16);
    TEST_ASSERT_EQUAL_INT(5, n);
    for (i = 0; i < n; i++) {
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_unwrapped(w, ids[i], &one));
        TEST_ASSERT_EQUAL_DOUBLE(one.x, all[i].x);
        TEST_ASSERT_EQUAL_DOUBLE(one.y, all[i].y);
    }
    TEST_ASSERT_EQUAL_INT(-99, ids[5]); /* nothing past the live circles */
    /* circle 5 started at x = 8.5, y = 5 and moved 25 along (1, -0.5): unwrapped at (33.5,
     * -7.5), 3 periods right of its image 3.5 and 2 below 2.5 (the order: 0, 1, 3, 4, 5) */
    TEST_ASSERT_EQUAL_INT(5, ids[4]);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 33.5, all[4].x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, -7.5, all[4].y);
    TEST_ASSERT_EQUAL_INT(3, ids[2]);
    /* a smaller capacity: the first ones only, the count all the same; NULL skips either */
    for (i = 0; i < 16; i++)
        ids[i] = -99;
    TEST_ASSERT_EQUAL_INT(5, cc_world_get_unwrapped_all(w, ids, NULL, 2));
    TEST_ASSERT_EQUAL_INT(0, ids[0]);
    TEST_ASSERT_EQUAL_INT(1, ids[1]);
    TEST_ASSERT_EQUAL_INT(-99, ids[2]);
    TEST_ASSERT_EQUAL_INT(5, cc_world_get_unwrapped_all(w, NULL, NULL, 0));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_get_unwrapped_all(w, ids, all, -1));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_get_unwrapped_all(NULL, ids, all, 16));
    tw_free(&m);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_batch_is_the_singles_before_the_first_step);
    RUN_TEST(test_batch_is_the_singles_in_a_settled_world);
    RUN_TEST(test_an_invalid_circle_changes_nothing_and_is_named);
    RUN_TEST(test_a_full_world_changes_nothing_and_names_the_first_that_does_not_fit);
    RUN_TEST(test_a_circle_too_wide_for_the_period_changes_nothing);
    RUN_TEST(test_bad_arguments);
    RUN_TEST(test_refused_from_a_callback);
    RUN_TEST(test_unwrapped_all_is_get_unwrapped_for_each);
    return UNITY_END();
}
