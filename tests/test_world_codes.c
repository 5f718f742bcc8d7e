/* The 1.2 codes (the header's Results): a refusal that 1.0 and 1.1 reported as CC_ERR_INVALID
 * names its cause, CC_ERR_RANGE (a value beyond a documented limit) or CC_ERR_BUSY (a change from
 * inside a callback), for a world made from a def past 1.1's last field; a world made from a 1.0
 * or 1.1 def keeps CC_ERR_INVALID. Either way nothing changes (the state hash is the same).
 *
 * "A later def" below is this header's def with room after it and struct_size saying so: what a
 * program compiled against the 1.2 header (or a later one) hands the library. */
#include "unity.h"

#include "test_world_util.h"

#include <stddef.h>
#include <stdio.h>

void setUp(void) {}
void tearDown(void) {}

typedef struct later_def {
    cc_world_def def;
    unsigned char later[64]; /* fields of a later header: zeroed by the library's init */
} later_def;

/* 1.0's def ends at user, 1.1's at period. */
#define DEF_1_0 (offsetof(cc_world_def, user) + sizeof(void *))
#define DEF_1_1 (offsetof(cc_world_def, period) + sizeof(cc_vec2))

enum { AS_1_0, AS_1_1, AS_LATER, AS_COUNT };
static const char *const as_name[AS_COUNT] = {"1.0 def", "1.1 def", "later def"};

/* A def as each header makes it, with this mode and period (1.0's def has no period). */
static void make_def(later_def *x, int as, int mode, double period)
{
    size_t size = as == AS_1_0 ? DEF_1_0 : as == AS_1_1 ? DEF_1_1 : sizeof *x;
    memset(x, 0, sizeof *x);
    cc_world_def_init_sized(&x->def, size);
    TEST_ASSERT_EQUAL_UINT64(size, x->def.struct_size);
    x->def.max_circles = 64;
    x->def.max_segments = 4;
    x->def.mode = mode;
    if (as != AS_1_0)
        x->def.period.x = x->def.period.y = period;
}

/* What each caller is told for a 1.2 code: the code itself only after 1.1. */
static int expect(int as, int code) { return as == AS_LATER ? code : CC_ERR_INVALID; }

static int init_status(const cc_world_def *d)
{
    static double memory[64];
    int st = 12345;
    TEST_ASSERT_NULL(cc_world_init(memory, sizeof memory, d, &st));
    return st;
}

/* Capacities above 2^26 (the def's comment) are a range: RANGE; a negative one stays INVALID.
 * cc_world_size says 0 for each, having no code to give. */
static void test_capacity_beyond_the_limit(void)
{
    int as;
    for (as = AS_1_0; as < AS_COUNT; as++) {
        later_def x;
        make_def(&x, as, CC_MODE_EXACT, 0.0);
        x.def.max_circles = (1 << 26) + 1;
        TEST_ASSERT_EQUAL_UINT64(0, cc_world_size(&x.def));
        TEST_ASSERT_EQUAL_INT_MESSAGE(expect(as, CC_ERR_RANGE), init_status(&x.def), as_name[as]);
        x.def.max_circles = 1;
        x.def.max_segments = (1 << 26) + 1;
        TEST_ASSERT_EQUAL_INT_MESSAGE(expect(as, CC_ERR_RANGE), init_status(&x.def), as_name[as]);
        x.def.max_segments = -1;
        TEST_ASSERT_EQUAL_INT_MESSAGE(CC_ERR_INVALID, init_status(&x.def), as_name[as]);
    }
}

/* A period must be wider than def.cell_size (it holds at least one cell): 4 against a cell of
 * 4 is a range; a negative period stays INVALID. */
static void test_period_not_wider_than_its_cell(void)
{
    int as;
    for (as = AS_1_1; as < AS_COUNT; as++) {
        later_def x;
        make_def(&x, as, CC_MODE_EXACT, 4.0);
        x.def.cell_size = 4.0;
        TEST_ASSERT_EQUAL_INT_MESSAGE(expect(as, CC_ERR_RANGE), init_status(&x.def), as_name[as]);
        x.def.period.x = -1.0;
        TEST_ASSERT_EQUAL_INT_MESSAGE(CC_ERR_INVALID, init_status(&x.def), as_name[as]);
    }
}

/* Period 10: a circle needs 2 d + 1.0625 d <= 10, d <= 3.27. Radius 2 (12.25) is too wide:
 * add and set refuse it as a range; radius 1 (6.125) fits. A NaN radius stays INVALID. */
static void test_circle_too_wide_for_its_period(void)
{
    int as;
    for (as = AS_1_1; as < AS_COUNT; as++) {
        later_def x;
        tw_mem m;
        cc_world *w;
        cc_circle fits = tw_circle(5, 5, 0, 0, 1, 1), wide = tw_circle(5, 5, 0, 0, 2, 1), bad = fits;
        uint64_t h;
        make_def(&x, as, CC_MODE_EXACT, 10.0);
        w = tw_make(&m, &x.def, 0);
        TEST_ASSERT_NOT_NULL(w);
        TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &fits));
        h = cc_world_hash(w);
        TEST_ASSERT_EQUAL_INT_MESSAGE(expect(as, CC_ERR_RANGE), cc_world_add_circle(w, &wide), as_name[as]);
        TEST_ASSERT_EQUAL_INT_MESSAGE(expect(as, CC_ERR_RANGE), cc_world_set_circle(w, 0, &wide), as_name[as]);
        bad.radius = NAN;
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_add_circle(w, &bad));
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_set_circle(w, 0, &bad));
        TEST_ASSERT_TRUE(h == cc_world_hash(w));
        TEST_ASSERT_TRUE(tw_canary_ok(&m));
        tw_free(&m);
    }
}

/* SWEPT, period 10: a circle moving at 10 may be carried less than half a period (5) per step:
 * 0.5 s is refused as a range, 0.4 s made. A step past 2^1017 (x = 1e306 moving at 1e306 for
 * 1 s: 2e306 > 1.4e306) is a range in every mode, and so is a world time that would overflow
 * (1.5e308 twice). dt < 0 stays INVALID. */
static void test_steps_beyond_what_the_world_allows(void)
{
    int as;
    for (as = AS_1_1; as < AS_COUNT; as++) {
        later_def x;
        tw_mem m;
        cc_world *w;
        cc_circle c = tw_circle(5, 5, 10, 0, 0.5, 1), far = tw_circle(1e306, 0, 1e306, 0, 1, 1);
        uint64_t h;
        make_def(&x, as, CC_MODE_SWEPT, 10.0);
        w = tw_make(&m, &x.def, 0);
        TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &c));
        h = cc_world_hash(w);
        TEST_ASSERT_EQUAL_INT_MESSAGE(expect(as, CC_ERR_RANGE), cc_world_step(w, 0.5), as_name[as]);
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, cc_world_step(w, -1.0));
        TEST_ASSERT_TRUE(h == cc_world_hash(w));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.4));
        tw_free(&m);

        make_def(&x, as, CC_MODE_EXACT, 0.0);
        w = tw_make(&m, &x.def, 0);
        TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &far));
        h = cc_world_hash(w);
        TEST_ASSERT_EQUAL_INT_MESSAGE(expect(as, CC_ERR_RANGE), cc_world_step(w, 1.0), as_name[as]);
        TEST_ASSERT_TRUE(h == cc_world_hash(w));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_remove_circle(w, 0));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 1.5e308));
        h = cc_world_hash(w);
        TEST_ASSERT_EQUAL_INT_MESSAGE(expect(as, CC_ERR_RANGE), cc_world_step(w, 1.5e308), as_name[as]);
        TEST_ASSERT_TRUE(h == cc_world_hash(w));
        tw_free(&m);
    }
}

/* From inside the contact callback, every mutator: BUSY, nothing done. */
typedef struct probe {
    cc_world *w;
    int as;
    int calls;
    int answers[7];
} probe;

static void on_contact(const cc_contact_event *e, void *user)
{
    probe *p = (probe *)user;
    cc_circle c = tw_circle(-30, 0, 0, 0, 1, 1);
    cc_segment s = tw_segment(-50, -50, 50, -50);
    cc_circle_props cp;
    cc_segment_props sp;
    if (p->calls++ > 0)
        return;
    cp.struct_size = sizeof cp;
    sp.struct_size = sizeof sp;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle_props(p->w, e->a, &cp));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_segment_props(p->w, 0, &sp));
    p->answers[0] = cc_world_add_circle(p->w, &c);
    p->answers[1] = cc_world_set_circle(p->w, e->a, &c);
    p->answers[2] = cc_world_remove_circle(p->w, e->a);
    p->answers[3] = cc_world_add_segment(p->w, &s);
    p->answers[4] = cc_world_step(p->w, 1.0);
    p->answers[5] = cc_world_set_circle_props(p->w, e->a, &cp);
    p->answers[6] = cc_world_set_segment_props(p->w, 0, &sp);
}

static void test_changes_from_a_callback(void)
{
    int as, k, mode;
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++)
        for (as = AS_1_0; as < AS_COUNT; as++) {
            later_def x;
            tw_mem m;
            probe p;
            cc_circle c = tw_circle(0, 0, 1, 0, 1, 1), at;
            cc_segment wall = tw_segment(5, -10, 5, 10);
            memset(&p, 0, sizeof p);
            make_def(&x, as, mode, 0.0);
            x.def.on_contact = on_contact;
            x.def.user = &p;
            p.w = tw_make(&m, &x.def, 0);
            p.as = as;
            TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(p.w, &c));
            TEST_ASSERT_EQUAL_INT(0, cc_world_add_segment(p.w, &wall));
            for (k = 0; k < 100; k++) /* the wall at x = 5 is touched at t = 4 */
                TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(p.w, 0.1));
            TEST_ASSERT_TRUE(p.calls >= 1);
            for (k = 0; k < 7; k++)
                TEST_ASSERT_EQUAL_INT_MESSAGE(expect(as, CC_ERR_BUSY), p.answers[k], as_name[as]);
            /* nothing was done: one circle, one wall, bounced back */
            TEST_ASSERT_EQUAL_INT(1, cc_world_get_circles(p.w, NULL, NULL, 0));
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(p.w, 0, &at));
            TEST_ASSERT_TRUE(at.vel.x < 0.0);
            TEST_ASSERT_EQUAL_INT(CC_ERR_NOT_FOUND, cc_world_get_segment(p.w, 1, &wall));
            tw_free(&m);
        }
}

/* A world keeps what its caller knows across a memcpy (it holds no address, and what it knows
 * is in its memory): a copy of a later def's world still names the range. */
static void test_a_copy_keeps_the_codes(void)
{
    later_def x;
    tw_mem m, n;
    cc_world *w, *copy;
    cc_circle wide = tw_circle(5, 5, 0, 0, 2, 1);
    make_def(&x, AS_LATER, CC_MODE_EXACT, 10.0);
    w = tw_make(&m, &x.def, 0);
    copy = tw_make(&n, &x.def, 0);
    memcpy(n.mem, m.mem, m.bytes);
    TEST_ASSERT_EQUAL_INT(CC_ERR_RANGE, cc_world_add_circle(copy, &wide));
    TEST_ASSERT_EQUAL_INT(CC_ERR_RANGE, cc_world_add_circle(w, &wide));
    tw_free(&m);
    tw_free(&n);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_capacity_beyond_the_limit);
    RUN_TEST(test_period_not_wider_than_its_cell);
    RUN_TEST(test_circle_too_wide_for_its_period);
    RUN_TEST(test_steps_beyond_what_the_world_allows);
    RUN_TEST(test_changes_from_a_callback);
    RUN_TEST(test_a_copy_keeps_the_codes);
    return UNITY_END();
}
