/* Every bad-input rule of the contract, for every pair function (float twins with
 * -DTEST_FLOAT): NaN/Inf coordinates or velocities, radius <= 0 or not finite, mass <= 0 or NaN
 * or -Inf, NULL pointers, t_max < 0 or NaN, restitution outside [0, 1], a normal that is not a
 * unit vector, two immovable bodies. Each returns CC_ERR_INVALID and leaves every argument
 * exactly as it was (compared byte for byte). Also: CC_MISS leaves outputs untouched, and the
 * edge values that ARE valid (mass +INFINITY, t_max 0 or +INFINITY, restitution 0 and 1) are
 * accepted. */
#include "core_precision.h"

void setUp(void) {}
void tearDown(void) {}

/* The i-th way to spoil a valid circle; returns 0 when there are no more. */
static int spoil_circle(int i, Circle *c)
{
    switch (i) {
    case 0: c->pos.x = (Real)NAN; return 1;
    case 1: c->pos.y = (Real)INFINITY; return 1;
    case 2: c->pos.x = (Real)-INFINITY; return 1;
    case 3: c->vel.x = (Real)NAN; return 1;
    case 4: c->vel.y = (Real)INFINITY; return 1;
    case 5: c->vel.x = (Real)-INFINITY; return 1;
    case 6: c->radius = 0; return 1;
    case 7: c->radius = (Real)-0.0; return 1;
    case 8: c->radius = -1; return 1;
    case 9: c->radius = (Real)NAN; return 1;
    case 10: c->radius = (Real)INFINITY; return 1;
    case 11: c->mass = 0; return 1;
    case 12: c->mass = (Real)-0.0; return 1;
    case 13: c->mass = -1; return 1;
    case 14: c->mass = (Real)NAN; return 1;
    case 15: c->mass = (Real)-INFINITY; return 1;
    default: return 0;
    }
}

static int spoil_segment(int i, Segment *s)
{
    switch (i) {
    case 0: s->a.x = (Real)NAN; return 1;
    case 1: s->a.y = (Real)INFINITY; return 1;
    case 2: s->b.x = (Real)-INFINITY; return 1;
    case 3: s->b.y = (Real)NAN; return 1;
    default: return 0;
    }
}

static const double bad_t_max[] = {-1.0, -1e-30, -INFINITY, NAN};
static const double bad_restitution[] = {-0.25, 1.0625, 2.0, -INFINITY, INFINITY, NAN};
/* |n| = 0, 1.01, 0.99, NaN, Inf: all outside 1 +- 1e-6 (float: 1e-4) */
static const double bad_normal[][2] = {{0, 0}, {1.01, 0}, {0, 0.99}, {NAN, 0}, {INFINITY, 0}, {0.6, NAN}};
#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* a and b overlap (a valid call writes out, moves them or changes velocities), approach each
 * other (so a sweep hits), and a's circle reaches the wall W. */
static Circle base_a(void) { return circle(0, 0, 1, 0, 1, 1); }
static Circle base_b(void) { return circle(1.5, 0, -1, 0, 1, 2); }
static Circle base_far_b(void) { return circle(10, 0, -1, 0, 1, 2); }
static Segment base_w(void) { return segment(5, -5, 5, 5); }
static Contact base_contact(void)
{
    Contact k;
    memset(&k, 0, sizeof k);
    k.normal = vec(1, 0);
    return k;
}

/* After a rejected call: both bodies (or body and wall) and the contact are as they were. */
#define CHECK_UNCHANGED(a0, a, b0, b, k0, k)                                                       \
    do {                                                                                           \
        TEST_ASSERT_EQUAL_MEMORY(&(a0), &(a), sizeof(a));                                          \
        TEST_ASSERT_EQUAL_MEMORY(&(b0), &(b), sizeof(b));                                          \
        TEST_ASSERT_EQUAL_MEMORY(&(k0), &(k), sizeof(k));                                          \
    } while (0)

static void test_detect_static(void)
{
    int i, which;
    for (which = 0; which < 2; which++)
        for (i = 0; ; i++) {
            Circle a = base_a(), b = base_b(), a0, b0;
            Contact k = sentinel_contact(), k0 = k;
            if (!spoil_circle(i, which ? &b : &a))
                break;
            a0 = a;
            b0 = b;
            TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_detect_static)(&a, &b, &k));
            TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_detect_static)(&a, &b, NULL));
            CHECK_UNCHANGED(a0, a, b0, b, k0, k);
        }
    {
        Circle a = base_a(), b = base_b();
        Contact k = sentinel_contact(), k0 = k;
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_detect_static)(NULL, &b, &k));
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_detect_static)(&a, NULL, &k));
        TEST_ASSERT_EQUAL_MEMORY(&k0, &k, sizeof k);
    }
}

static void test_separate(void)
{
    int i, which;
    for (which = 0; which < 2; which++)
        for (i = 0; ; i++) {
            Circle a = base_a(), b = base_b(), a0, b0;
            Contact k = sentinel_contact(), k0 = k;
            if (!spoil_circle(i, which ? &b : &a))
                break;
            a0 = a;
            b0 = b;
            TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_separate)(&a, &b));
            CHECK_UNCHANGED(a0, a, b0, b, k0, k);
        }
    {
        Circle a = base_a(), b = base_b(), a0, b0;
        a.mass = b.mass = (Real)INFINITY; /* two immovable circles */
        a0 = a;
        b0 = b;
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_separate)(&a, &b));
        TEST_ASSERT_EQUAL_MEMORY(&a0, &a, sizeof a);
        TEST_ASSERT_EQUAL_MEMORY(&b0, &b, sizeof b);
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_separate)(NULL, &b));
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_separate)(&a, NULL));
        TEST_ASSERT_EQUAL_MEMORY(&a0, &a, sizeof a);
        TEST_ASSERT_EQUAL_MEMORY(&b0, &b, sizeof b);
    }
}

static void test_sweep(void)
{
    int i, which;
    for (which = 0; which < 2; which++)
        for (i = 0; ; i++) {
            Circle a = base_a(), b = base_far_b(), a0, b0;
            Contact k = sentinel_contact(), k0 = k;
            if (!spoil_circle(i, which ? &b : &a))
                break;
            a0 = a;
            b0 = b;
            TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_sweep)(&a, &b, 10, &k));
            CHECK_UNCHANGED(a0, a, b0, b, k0, k);
        }
    for (i = 0; i < COUNT(bad_t_max); i++) {
        Circle a = base_a(), b = base_far_b(), a0 = a, b0 = b;
        Contact k = sentinel_contact(), k0 = k;
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_sweep)(&a, &b, (Real)bad_t_max[i], &k));
        CHECK_UNCHANGED(a0, a, b0, b, k0, k);
    }
    {
        Circle a = base_a(), b = base_far_b();
        Contact k = sentinel_contact(), k0 = k;
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_sweep)(NULL, &b, 10, &k));
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_sweep)(&a, NULL, 10, &k));
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_sweep)(&a, &b, 10, NULL));
        TEST_ASSERT_EQUAL_MEMORY(&k0, &k, sizeof k);
    }
}

static void test_sweep_segment(void)
{
    int i;
    for (i = 0; ; i++) {
        Circle c = base_a(), c0;
        Segment w = base_w(), w0 = w;
        Contact k = sentinel_contact(), k0 = k;
        if (!spoil_circle(i, &c))
            break;
        c0 = c;
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_sweep_segment)(&c, &w, 10, &k));
        CHECK_UNCHANGED(c0, c, w0, w, k0, k);
    }
    for (i = 0; ; i++) {
        Circle c = base_a(), c0 = c;
        Segment w = base_w(), w0;
        Contact k = sentinel_contact(), k0 = k;
        if (!spoil_segment(i, &w))
            break;
        w0 = w;
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_sweep_segment)(&c, &w, 10, &k));
        CHECK_UNCHANGED(c0, c, w0, w, k0, k);
    }
    for (i = 0; i < COUNT(bad_t_max); i++) {
        Circle c = base_a(), c0 = c;
        Segment w = base_w(), w0 = w;
        Contact k = sentinel_contact(), k0 = k;
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_sweep_segment)(&c, &w, (Real)bad_t_max[i], &k));
        CHECK_UNCHANGED(c0, c, w0, w, k0, k);
    }
    {
        Circle c = base_a();
        Segment w = base_w();
        Contact k = sentinel_contact(), k0 = k;
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_sweep_segment)(NULL, &w, 10, &k));
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_sweep_segment)(&c, NULL, 10, &k));
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_sweep_segment)(&c, &w, 10, NULL));
        TEST_ASSERT_EQUAL_MEMORY(&k0, &k, sizeof k);
    }
}

static void test_respond(void)
{
    int i, which;
    for (which = 0; which < 2; which++)
        for (i = 0; ; i++) {
            Circle a = base_a(), b = base_b(), a0, b0;
            Contact k = base_contact(), k0 = k;
            if (!spoil_circle(i, which ? &b : &a))
                break;
            a0 = a;
            b0 = b;
            TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_respond)(&a, &b, &k, 1));
            CHECK_UNCHANGED(a0, a, b0, b, k0, k);
        }
    for (i = 0; i < COUNT(bad_restitution); i++) {
        Circle a = base_a(), b = base_b(), a0 = a, b0 = b;
        Contact k = base_contact(), k0 = k;
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_respond)(&a, &b, &k, (Real)bad_restitution[i]));
        CHECK_UNCHANGED(a0, a, b0, b, k0, k);
    }
    for (i = 0; i < COUNT(bad_normal); i++) {
        Circle a = base_a(), b = base_b(), a0 = a, b0 = b;
        Contact k = base_contact(), k0;
        k.normal = vec(bad_normal[i][0], bad_normal[i][1]);
        k0 = k;
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_respond)(&a, &b, &k, 1));
        CHECK_UNCHANGED(a0, a, b0, b, k0, k);
    }
    {
        Circle a = base_a(), b = base_b(), a0, b0;
        Contact k = base_contact(), k0 = k;
        a.mass = b.mass = (Real)INFINITY;
        a0 = a;
        b0 = b;
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_respond)(&a, &b, &k, 1));
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_respond)(NULL, &b, &k, 1));
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_respond)(&a, NULL, &k, 1));
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_respond)(&a, &b, NULL, 1));
        CHECK_UNCHANGED(a0, a, b0, b, k0, k);
    }
}

static void test_respond_segment(void)
{
    int i;
    for (i = 0; ; i++) {
        Circle c = base_a(), c0, d = base_b(), d0 = d;
        Contact k = base_contact(), k0 = k;
        if (!spoil_circle(i, &c))
            break;
        c0 = c;
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_respond_segment)(&c, &k, 1));
        CHECK_UNCHANGED(c0, c, d0, d, k0, k);
    }
    for (i = 0; i < COUNT(bad_restitution); i++) {
        Circle c = base_a(), c0 = c, d = base_b(), d0 = d;
        Contact k = base_contact(), k0 = k;
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_respond_segment)(&c, &k, (Real)bad_restitution[i]));
        CHECK_UNCHANGED(c0, c, d0, d, k0, k);
    }
    for (i = 0; i < COUNT(bad_normal); i++) {
        Circle c = base_a(), c0 = c, d = base_b(), d0 = d;
        Contact k = base_contact(), k0;
        k.normal = vec(bad_normal[i][0], bad_normal[i][1]);
        k0 = k;
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_respond_segment)(&c, &k, 1));
        CHECK_UNCHANGED(c0, c, d0, d, k0, k);
    }
    {
        Circle c = base_a(), c0;
        Contact k = base_contact(), k0 = k;
        c.mass = (Real)INFINITY; /* an immovable circle against an immovable wall */
        c0 = c;
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_respond_segment)(&c, &k, 1));
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_respond_segment)(NULL, &k, 1));
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, F(cc_respond_segment)(&c, NULL, 1));
        TEST_ASSERT_EQUAL_MEMORY(&c0, &c, sizeof c);
        TEST_ASSERT_EQUAL_MEMORY(&k0, &k, sizeof k);
    }
}

/* The valid edges: mass +INFINITY for one body, t_max 0, -0.0 and +INFINITY, restitution 0
 * and 1 (and -0.0, which equals 0): none of them is an error. */
static void test_valid_edges_accepted(void)
{
    Circle a = base_a(), b = base_far_b();
    Contact k = sentinel_contact();
    Segment w = base_w();
    b.mass = (Real)INFINITY;
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_sweep)(&a, &b, (Real)INFINITY, &k));
    TEST_ASSERT_EQUAL_INT(CC_MISS, F(cc_sweep)(&a, &b, 0, &k));
    TEST_ASSERT_EQUAL_INT(CC_MISS, F(cc_sweep)(&a, &b, (Real)-0.0, &k));
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_sweep_segment)(&a, &w, (Real)INFINITY, &k));
    b = base_b();
    k = base_contact();
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_respond)(&a, &b, &k, 0));
    a = base_a();
    b = base_b();
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_respond)(&a, &b, &k, 1));
    a = base_a();
    b = base_b();
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_respond)(&a, &b, &k, (Real)-0.0));
    a = base_a();
    TEST_ASSERT_EQUAL_INT(CC_HIT, F(cc_respond_segment)(&a, &k, 1));
}

/* CC_MISS writes nothing: a sweep that misses, a static test without overlap, a response to
 * bodies already leaving, a push-apart of bodies apart. */
static void test_miss_leaves_outputs_untouched(void)
{
    Circle a = base_a(), b = circle(10, 5, 1, 0, 1, 1), a0, b0;
    Segment w = segment(-5, 5, 5, 5);
    Contact k = sentinel_contact(), k0 = k, kn = base_contact(), kn0 = kn;
    a0 = a;
    b0 = b;
    TEST_ASSERT_EQUAL_INT(CC_MISS, F(cc_sweep)(&a, &b, 100, &k));
    TEST_ASSERT_EQUAL_INT(CC_MISS, F(cc_sweep_segment)(&a, &w, 100, &k));
    TEST_ASSERT_EQUAL_INT(CC_MISS, F(cc_detect_static)(&a, &b, &k));
    TEST_ASSERT_EQUAL_INT(CC_MISS, F(cc_separate)(&a, &b));
    CHECK_UNCHANGED(a0, a, b0, b, k0, k);
    kn.normal = vec(-1, 0); /* a moves +x, b too: along -x, they separate */
    kn0 = kn;
    TEST_ASSERT_EQUAL_INT(CC_MISS, F(cc_respond)(&a, &b, &kn, 1));
    TEST_ASSERT_EQUAL_INT(CC_MISS, F(cc_respond_segment)(&a, &kn, 1));
    CHECK_UNCHANGED(a0, a, b0, b, kn0, kn);
}

#ifndef TEST_FLOAT
/* cc_sweep_many (double only) validates everything before writing anything. */
static void test_sweep_many(void)
{
    double px[2] = {0, 0}, py[2] = {0, 0}, vx[2] = {1, 1}, vy[2] = {0, 0}, r[2] = {1, 1};
    double qx[2] = {10, 10}, qy[2] = {0, 0}, wx[2] = {-1, -1}, wy[2] = {0, 0}, s[2] = {1, 1};
    cc_circle_soa A = {px, py, vx, vy, r}, B = {qx, qy, wx, wy, s}, holed = A;
    double t[2] = {-7, -7}, t0[2] = {-7, -7};
    int res[2] = {-9, -9}, res0[2] = {-9, -9}, k;
    holed.vy = NULL;
    TEST_ASSERT_EQUAL_INT(2, (int)cc_sweep_many(2, &A, &B, 10, t, res)); /* the valid call hits twice */
    memcpy(t, t0, sizeof t);
    memcpy(res, res0, sizeof res);
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, (int)cc_sweep_many(2, NULL, &B, 10, t, res));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, (int)cc_sweep_many(2, &A, NULL, 10, t, res));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, (int)cc_sweep_many(2, &holed, &B, 10, t, res));
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, (int)cc_sweep_many(2, &A, &B, 10, NULL, res));
    for (k = 0; k < COUNT(bad_t_max); k++)
        TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, (int)cc_sweep_many(2, &A, &B, bad_t_max[k], t, res));
    /* one bad value in the last pair spoils the call: nothing is written for the first pair */
    qx[1] = NAN;
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, (int)cc_sweep_many(2, &A, &B, 10, t, res));
    qx[1] = 10;
    s[1] = 0;
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, (int)cc_sweep_many(2, &A, &B, 10, t, res));
    s[1] = 1;
    vy[1] = INFINITY;
    TEST_ASSERT_EQUAL_INT(CC_ERR_INVALID, (int)cc_sweep_many(2, &A, &B, 10, t, res));
    TEST_ASSERT_EQUAL_MEMORY(t0, t, sizeof t);
    TEST_ASSERT_EQUAL_MEMORY(res0, res, sizeof res);
    /* n = 0 with NULL outputs is a valid empty call */
    TEST_ASSERT_EQUAL_INT(0, (int)cc_sweep_many(0, &A, &B, 10, NULL, NULL));
}
#endif

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_detect_static);
    RUN_TEST(test_separate);
    RUN_TEST(test_sweep);
    RUN_TEST(test_sweep_segment);
    RUN_TEST(test_respond);
    RUN_TEST(test_respond_segment);
    RUN_TEST(test_valid_edges_accepted);
    RUN_TEST(test_miss_leaves_outputs_untouched);
#ifndef TEST_FLOAT
    RUN_TEST(test_sweep_many);
#endif
    return UNITY_END();
}
