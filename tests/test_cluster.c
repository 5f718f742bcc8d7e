/* Specification of the simultaneous-impact model (src/world/cluster.c): generalized
 * reflections with generalized restitution, tested on clusters given directly as bodies and
 * contacts. Expected values are derived beside each check; docs/SIMULTANEOUS.md explains the
 * model. */
#include "unity.h"

#include "world/cluster.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define MAX_B 64
#define MAX_C 256

static double scratch_mem[(2 * MAX_C * MAX_C + 6 * MAX_C + 2 * MAX_B) + 4 * MAX_C + 64];

typedef struct scene {
    int nb, nc;
    cc__cluster_body body[MAX_B];
    cc__cluster_contact contact[MAX_C];
    cc_vec2 pos[MAX_B]; /* only for building contacts and checking symmetry */
    cc__cluster_report report;
} scene;

static int solve(scene *s, double e, double rest_speed)
{
    size_t need = cc__cluster_scratch_size(s->nb, s->nc);
    TEST_ASSERT_TRUE(need > 0 && need <= sizeof scratch_mem);
    return cc__cluster_resolve(s->body, s->nb, s->contact, s->nc, e, rest_speed, scratch_mem,
                               sizeof scratch_mem, &s->report);
}

static int add_body(scene *s, double x, double y, double vx, double vy, double inv_mass)
{
    int i = s->nb++;
    s->pos[i].x = x;
    s->pos[i].y = y;
    s->body[i].vel.x = vx;
    s->body[i].vel.y = vy;
    s->body[i].inv_mass = inv_mass;
    return i;
}

static void add_contact(scene *s, int a, int b, double nx, double ny)
{
    cc__cluster_contact *k = &s->contact[s->nc++];
    k->a = a;
    k->b = b;
    k->normal.x = nx;
    k->normal.y = ny;
    k->impulse = -1.0; /* must be overwritten */
}

/* Every pair of circles of radius r whose centres are 2r apart up to rounding becomes a contact
 * with the normal along the centre line: the scenes below are built with sqrt(3). */
static void touching_contacts(scene *s, double r)
{
    int i, j;
    for (i = 0; i < s->nb; ++i)
        for (j = i + 1; j < s->nb; ++j) {
            double dx = s->pos[j].x - s->pos[i].x, dy = s->pos[j].y - s->pos[i].y;
            double d = sqrt(dx * dx + dy * dy);
            if (fabs(d - 2.0 * r) <= 1e-12 * r)
                add_contact(s, i, j, dx / d, dy / d);
        }
}

static double mass_of(const scene *s, int i) { return 1.0 / s->body[i].inv_mass; }

static cc_vec2 momentum(const scene *s)
{
    cc_vec2 p = {0.0, 0.0};
    int i;
    for (i = 0; i < s->nb; ++i)
        if (s->body[i].inv_mass > 0.0) {
            p.x += mass_of(s, i) * s->body[i].vel.x;
            p.y += mass_of(s, i) * s->body[i].vel.y;
        }
    return p;
}

static double energy(const scene *s)
{
    double k = 0.0;
    int i;
    for (i = 0; i < s->nb; ++i)
        if (s->body[i].inv_mass > 0.0)
            k += 0.5 * mass_of(s, i) *
                 (s->body[i].vel.x * s->body[i].vel.x + s->body[i].vel.y * s->body[i].vel.y);
    return k;
}

/* the most negative relative normal velocity left (0 when nothing approaches) */
static double worst_approach(const scene *s)
{
    double worst = 0.0;
    int k;
    for (k = 0; k < s->nc; ++k) {
        const cc__cluster_contact *c = &s->contact[k];
        cc_vec2 rel = {-s->body[c->a].vel.x, -s->body[c->a].vel.y};
        double vn;
        if (c->b >= 0) {
            rel.x += s->body[c->b].vel.x;
            rel.y += s->body[c->b].vel.y;
        }
        vn = rel.x * c->normal.x + rel.y * c->normal.y;
        if (vn < worst)
            worst = vn;
    }
    return worst;
}

/* ---- Newton's cradle -------------------------------------------------------------------- */

/* n equal balls in a row along the unit direction d (0.6, 0.8), touching; ball 0 arrives at
 * speed 2.5. GR resolves the contacts one round at a time as each becomes approaching: round k
 * exchanges the velocities of balls k and k+1 (equal masses, elastic), so exactly the last ball
 * leaves at 2.5 and every other ball is at rest, after n - 1 rounds, each contact taking the
 * impulse m * 2.5 = 2.5. */
static void build_cradle(scene *s, int n, double speed)
{
    const double dx = 0.6, dy = 0.8;
    int i;
    memset(s, 0, sizeof *s);
    for (i = 0; i < n; ++i)
        add_body(s, 2.0 * i * dx, 2.0 * i * dy, i == 0 ? speed * dx : 0.0, i == 0 ? speed * dy : 0.0,
                 1.0);
    for (i = 0; i + 1 < n; ++i)
        add_contact(s, i, i + 1, dx, dy);
}

static void test_cradle_sends_out_exactly_one_ball(void)
{
    int n, i;
    for (n = 2; n <= 10; ++n) {
        scene s;
        build_cradle(&s, n, 2.5);
        TEST_ASSERT_EQUAL_INT(CC_OK, solve(&s, 1.0, 0.0));
        for (i = 0; i + 1 < n; ++i) {
            TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.0, s.body[i].vel.x);
            TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.0, s.body[i].vel.y);
            TEST_ASSERT_DOUBLE_WITHIN(1e-14, 2.5, s.contact[i].impulse);
        }
        TEST_ASSERT_DOUBLE_WITHIN(1e-15, 2.5 * 0.6, s.body[n - 1].vel.x);
        TEST_ASSERT_DOUBLE_WITHIN(1e-15, 2.5 * 0.8, s.body[n - 1].vel.y);
        TEST_ASSERT_EQUAL_INT(n - 1, s.report.rounds);
        TEST_ASSERT_EQUAL_INT(n - 1, s.report.impulses);
        TEST_ASSERT_EQUAL_INT(0, s.report.capped);
        TEST_ASSERT_EQUAL_INT(0, s.report.jammed);
    }
}

/* Restitution 0.9: GRR takes 0.1 of the plastic answer (the touching row moves as one at
 * 2.5 / n) plus 0.9 of the elastic one (last ball at 2.5): balls 0..n-2 at 0.25 / n, the last at
 * 0.25 / n + 2.25; momentum 2.5 stays, energy drops. At restitution 0 all move at 2.5 / n. */
static void test_cradle_with_restitution(void)
{
    int n, i;
    for (n = 2; n <= 10; ++n) {
        scene s;
        double along;
        build_cradle(&s, n, 2.5);
        TEST_ASSERT_EQUAL_INT(CC_OK, solve(&s, 0.9, 0.0));
        for (i = 0; i < n; ++i) {
            along = s.body[i].vel.x * 0.6 + s.body[i].vel.y * 0.8;
            TEST_ASSERT_DOUBLE_WITHIN(1e-14, 0.25 / n + (i == n - 1 ? 2.25 : 0.0), along);
        }
        TEST_ASSERT_DOUBLE_WITHIN(1e-14, 2.5 * 0.6, momentum(&s).x);
        TEST_ASSERT_TRUE(energy(&s) < 0.5 * 2.5 * 2.5);
        TEST_ASSERT_TRUE(worst_approach(&s) >= -1e-14);

        build_cradle(&s, n, 2.5);
        TEST_ASSERT_EQUAL_INT(CC_OK, solve(&s, 0.0, 0.0));
        for (i = 0; i < n; ++i)
            TEST_ASSERT_DOUBLE_WITHIN(1e-14, 2.5 / n, s.body[i].vel.x * 0.6 + s.body[i].vel.y * 0.8);
        TEST_ASSERT_EQUAL_INT(0, s.report.rounds);
    }
}

/* ---- the 15-ball rack ------------------------------------------------------------------- */

/* Radius 1, unit masses. Row k (0..4) of the triangle stands at x = k sqrt(3) (rows of touching
 * balls are 2 sin 60 = sqrt(3) apart) with balls at y = 2j - k, j = 0..k; the apex is at the
 * origin and the cue ball at (-2, 0) arrives along +x at speed 1. Contacts: the triangle of
 * side 5 has 3 * (4 * 5 / 2) = 30 touching pairs, plus cue-apex: 31. */
static int rack_row[16];

static void build_rack(scene *s)
{
    const double r3 = sqrt(3.0);
    int k, j;
    memset(s, 0, sizeof *s);
    add_body(s, -2.0, 0.0, 1.0, 0.0, 1.0);
    rack_row[0] = -1;
    for (k = 0; k < 5; ++k)
        for (j = 0; j <= k; ++j) {
            rack_row[s->nb] = k;
            add_body(s, k * r3, 2.0 * j - k, 0.0, 0.0, 1.0);
        }
    touching_contacts(s, 1.0);
}

static int mirror_of(const scene *s, int i)
{
    int j;
    for (j = 0; j < s->nb; ++j)
        if (s->pos[j].x == s->pos[i].x && s->pos[j].y == -s->pos[i].y)
            return j;
    return -1;
}

static void check_rack(double e)
{
    scene s;
    cc_vec2 p;
    double back = 0.0;
    int i, moving_back = 0;
    char msg[96];
    build_rack(&s);
    TEST_ASSERT_EQUAL_INT(16, s.nb);
    TEST_ASSERT_EQUAL_INT(31, s.nc);
    TEST_ASSERT_EQUAL_INT(CC_OK, solve(&s, e, 0.0));
    printf("rack e=%.1f: %d rounds, %d impulses, capped %d, jammed %d\n", e, s.report.rounds,
           s.report.impulses, s.report.capped, s.report.jammed);
    TEST_ASSERT_EQUAL_INT(0, s.report.capped);
    TEST_ASSERT_EQUAL_INT(0, s.report.jammed);
    /* momentum: (1, 0) before, internal impulses only */
    p = momentum(&s);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1.0, p.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.0, p.y);
    /* energy: 1/2 before; kept at e = 1, lost (but never gained) below */
    if (e == 1.0)
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.5, energy(&s));
    else
        TEST_ASSERT_TRUE(energy(&s) < 0.5);
    /* mirror symmetry about the axis y = 0, ball by ball */
    for (i = 0; i < s.nb; ++i) {
        int m = mirror_of(&s, i);
        TEST_ASSERT_TRUE(m >= 0);
        sprintf(msg, "ball %d at (%g, %g) vs its mirror %d", i, s.pos[i].x, s.pos[i].y, m);
        TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-9, s.body[i].vel.x, s.body[m].vel.x, msg);
        TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-9, -s.body[i].vel.y, s.body[m].vel.y, msg);
    }
    /* nothing approaches afterwards */
    TEST_ASSERT_TRUE(worst_approach(&s) >= -1e-12);
    /* the break reaches the back row (row 4): each of its 5 balls is driven away from the pack */
    for (i = 0; i < s.nb; ++i) {
        if (rack_row[i] == 4) {
            printf("  back ball y=%+.0f: v = (%.6f, %+.6f)\n", s.pos[i].y, s.body[i].vel.x,
                   s.body[i].vel.y);
            back += s.body[i].vel.x;
            if (s.body[i].vel.x > 1e-3)
                moving_back++;
        }
    }
    TEST_ASSERT_EQUAL_INT(5, moving_back);
    TEST_ASSERT_TRUE(back > 0.1);
}

static void test_rack_break_elastic(void) { check_rack(1.0); }
static void test_rack_break_restitution_0_9(void) { check_rack(0.9); }

/* ---- walls and immovable bodies --------------------------------------------------------- */

/* A ball in the corner of walls x = 0 and y = 0, touching both, arrives at 45 degrees with
 * velocity s (-1, -1)/sqrt(2). Both contacts approach, their normals are orthogonal, so the
 * round's plastic projection stops the ball and the reflection sends it back along its incoming
 * line: v' = -e v. Each wall takes m (1 + e) s / sqrt(2). Below rest_speed, e acts as 0. */
static void test_corner_at_45_degrees(void)
{
    const double es[3] = {1.0, 0.9, 0.0};
    const double sp = 3.0, c = sp / sqrt(2.0);
    int t;
    for (t = 0; t < 4; ++t) {
        scene s;
        double e = t < 3 ? es[t] : 0.0;
        memset(&s, 0, sizeof s);
        add_body(&s, 1.0, 1.0, -c, -c, 0.5); /* mass 2 */
        add_contact(&s, 0, -1, -1.0, 0.0);
        add_contact(&s, 0, -1, 0.0, -1.0);
        TEST_ASSERT_EQUAL_INT(CC_OK, solve(&s, t < 3 ? e : 1.0, t < 3 ? 0.0 : 2.0 * sp));
        TEST_ASSERT_DOUBLE_WITHIN(1e-14, e * c, s.body[0].vel.x);
        TEST_ASSERT_DOUBLE_WITHIN(1e-14, e * c, s.body[0].vel.y);
        TEST_ASSERT_DOUBLE_WITHIN(1e-13, 2.0 * (1.0 + e) * c, s.contact[0].impulse);
        TEST_ASSERT_DOUBLE_WITHIN(1e-13, 2.0 * (1.0 + e) * c, s.contact[1].impulse);
        TEST_ASSERT_EQUAL_INT(2, s.report.impulses);
        TEST_ASSERT_EQUAL_DOUBLE(e, s.report.restitution);
    }
}

/* A heavy ball A (m = 2, speed 1) hits B (m = 1) touching C (m = 1), e = 1. Rounds:
 *   1. A-B:  vA = (2-1)/3 = 1/3, vB = 2*2/3 = 4/3;
 *   2. B-C (equal masses swap): vB = 0, vC = 4/3;
 *   3. A-B again (1/3 > 0): vA = 1/3 * 1/3 = 1/9, vB = 4/3 * 1/3 = 4/9;
 * then B (4/9) trails C (4/3): done. Momentum 2/9 + 4/9 + 12/9 = 2 and energy
 * (2/81 + 16/81 + 144/81)/2 = 1 = 2 * 1^2 / 2: both kept. */
static void test_unequal_masses(void)
{
    scene s;
    memset(&s, 0, sizeof s);
    add_body(&s, 0.0, 0.0, 1.0, 0.0, 0.5);
    add_body(&s, 2.0, 0.0, 0.0, 0.0, 1.0);
    add_body(&s, 4.0, 0.0, 0.0, 0.0, 1.0);
    add_contact(&s, 0, 1, 1.0, 0.0);
    add_contact(&s, 1, 2, 1.0, 0.0);
    TEST_ASSERT_EQUAL_INT(CC_OK, solve(&s, 1.0, 0.0));
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 1.0 / 9.0, s.body[0].vel.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 4.0 / 9.0, s.body[1].vel.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 4.0 / 3.0, s.body[2].vel.x);
    TEST_ASSERT_EQUAL_INT(3, s.report.rounds);
    /* impulses: A lost 2 * (1 - 1/9) = 16/9 at contact A-B; C gained 4/3 at B-C */
    TEST_ASSERT_DOUBLE_WITHIN(1e-14, 16.0 / 9.0, s.contact[0].impulse);
    TEST_ASSERT_DOUBLE_WITHIN(1e-14, 4.0 / 3.0, s.contact[1].impulse);
    TEST_ASSERT_DOUBLE_WITHIN(1e-14, 1.0, energy(&s));
}

/* B (unit mass) touches a wall on its left (normal (-1, 0)) and an immovable circle O above it
 * (normal (0, 1)); A (unit mass) touches B from the lower right (normal B->A (1, -1)/sqrt(2))
 * and arrives along -normal at speed s. Rounds:
 *   1. A-B swap: A stops, B moves s(-1, 1)/sqrt(2);
 *   2. B approaches wall and O at once, orthogonal normals: B reflects to s(1, -1)/sqrt(2);
 *   3. B-A swap: B stops, A leaves at s(1, -1)/sqrt(2): back along its incoming line.
 * Impulses: A-B twice m s = 2 s; wall and O each m (s/sqrt(2)) * 2 = sqrt(2) s. O keeps its
 * velocity bit for bit. */
static void build_obstacle_cluster(scene *s, double sp)
{
    const double h = 1.0 / sqrt(2.0);
    memset(s, 0, sizeof *s);
    add_body(s, 0.0, 0.0, 0.0, 0.0, 1.0);                   /* B */
    add_body(s, 2.0 * h, -2.0 * h, -sp * h, sp * h, 1.0);    /* A */
    add_body(s, 0.0, 2.0, 0.0, 0.0, 0.0);                   /* O, immovable */
    add_contact(s, 0, 1, h, -h);
    add_contact(s, 0, -1, -1.0, 0.0);
    add_contact(s, 0, 2, 0.0, 1.0);
}

static void test_immovable_circle_and_wall(void)
{
    scene s;
    const double sp = 2.0, h = 1.0 / sqrt(2.0);
    build_obstacle_cluster(&s, sp);
    TEST_ASSERT_EQUAL_INT(CC_OK, solve(&s, 1.0, 0.0));
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.0, s.body[0].vel.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.0, s.body[0].vel.y);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, sp * h, s.body[1].vel.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, -sp * h, s.body[1].vel.y);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, s.body[2].vel.x);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, s.body[2].vel.y);
    TEST_ASSERT_EQUAL_INT(3, s.report.rounds);
    TEST_ASSERT_DOUBLE_WITHIN(1e-14, 2.0 * sp, s.contact[0].impulse);
    TEST_ASSERT_DOUBLE_WITHIN(1e-14, sqrt(2.0) * sp, s.contact[1].impulse);
    TEST_ASSERT_DOUBLE_WITHIN(1e-14, sqrt(2.0) * sp, s.contact[2].impulse);
    TEST_ASSERT_DOUBLE_WITHIN(1e-14, 0.5 * sp * sp, energy(&s));
}

/* ---- independence of input order -------------------------------------------------------- */

/* The same physical cluster listed in another order (bodies permuted, contacts permuted, and
 * every other contact written from the other side with the normal negated) must give the same
 * velocities body by body, to rounding. */
static void permuted(const scene *in, scene *out, const int *perm)
{
    int i;
    memset(out, 0, sizeof *out);
    out->nb = in->nb;
    out->nc = in->nc;
    for (i = 0; i < in->nb; ++i) {
        out->body[perm[i]] = in->body[i];
        out->pos[perm[i]] = in->pos[i];
    }
    for (i = 0; i < in->nc; ++i) {
        const cc__cluster_contact *k = &in->contact[i];
        cc__cluster_contact *o = &out->contact[in->nc - 1 - i];
        if (i % 2 == 1 && k->b >= 0) {
            o->a = perm[k->b];
            o->b = perm[k->a];
            o->normal.x = -k->normal.x;
            o->normal.y = -k->normal.y;
        } else {
            o->a = perm[k->a];
            o->b = k->b >= 0 ? perm[k->b] : -1;
            o->normal = k->normal;
        }
    }
}

static void check_order_independence(const scene *base, double e)
{
    static const int mult[3] = {7, 11, 13};
    scene ref, other;
    int t, i;
    ref = *base;
    TEST_ASSERT_EQUAL_INT(CC_OK, solve(&ref, e, 0.0));
    for (t = 0; t < 3; ++t) {
        int perm[MAX_B];
        for (i = 0; i < base->nb; ++i)
            perm[i] = (mult[t] * i + t + 1) % base->nb; /* a bijection: gcd(mult, nb) = 1 here */
        permuted(base, &other, perm);
        TEST_ASSERT_EQUAL_INT(CC_OK, solve(&other, e, 0.0));
        for (i = 0; i < base->nb; ++i) {
            TEST_ASSERT_DOUBLE_WITHIN(1e-12, ref.body[i].vel.x, other.body[perm[i]].vel.x);
            TEST_ASSERT_DOUBLE_WITHIN(1e-12, ref.body[i].vel.y, other.body[perm[i]].vel.y);
        }
    }
}

static void test_order_independence(void)
{
    scene s;
    build_rack(&s); /* 16 bodies: coprime with 7, 11, 13 */
    check_order_independence(&s, 1.0);
    check_order_independence(&s, 0.9);
    check_order_independence(&s, 0.0);
    build_obstacle_cluster(&s, 2.0); /* 3 bodies: coprime with 7, 11, 13 */
    check_order_independence(&s, 1.0);
    check_order_independence(&s, 0.5);
    build_cradle(&s, 5, 1.0);
    check_order_independence(&s, 1.0);
}

static void test_deterministic(void)
{
    scene a, b;
    build_rack(&a);
    b = a;
    TEST_ASSERT_EQUAL_INT(CC_OK, solve(&a, 0.9, 0.0));
    TEST_ASSERT_EQUAL_INT(CC_OK, solve(&b, 0.9, 0.0));
    TEST_ASSERT_EQUAL_MEMORY(a.body, b.body, sizeof a.body);
    TEST_ASSERT_EQUAL_MEMORY(a.contact, b.contact, sizeof a.contact);
}

/* ---- random packed clusters: the conservation laws hold everywhere ------------------------ */

static unsigned long long rng_state = 88172645463325252ULL;
static double uniform(void) /* xorshift64: reproducible on every platform */
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return (double)(rng_state >> 11) * (1.0 / 9007199254740992.0);
}

/* Patches of a hex lattice (every neighbour touching, so W is singular), random velocities and
 * masses: at e = 1 energy and momentum are kept to rounding, and at any e nothing approaches
 * afterwards and energy never grows. */
static void test_random_hex_patches(void)
{
    int trial;
    for (trial = 0; trial < 200; ++trial) {
        scene s;
        const double r3 = sqrt(3.0);
        double e = (trial % 4) / 3.0, k0, k1, scale = 0.0;
        cc_vec2 p0, p1;
        int n = 3 + (int)(uniform() * 5.0), i, j;
        memset(&s, 0, sizeof s);
        for (i = 0; i < n; ++i)
            for (j = 0; j < n; ++j)
                if (uniform() < 0.8)
                    add_body(&s, 2.0 * j + (i % 2), i * r3, uniform() * 2.0 - 1.0,
                             uniform() * 2.0 - 1.0, 0.25 + uniform() * 2.0);
        touching_contacts(&s, 1.0);
        if (trial % 5 == 0 && s.nb > 0) { /* a wall under the first row */
            for (i = 0; i < s.nb; ++i)
                if (s.pos[i].y == 0.0)
                    add_contact(&s, i, -1, 0.0, -1.0);
        }
        for (i = 0; i < s.nb; ++i)
            if (fabs(s.body[i].vel.x) + fabs(s.body[i].vel.y) > scale)
                scale = fabs(s.body[i].vel.x) + fabs(s.body[i].vel.y);
        p0 = momentum(&s);
        k0 = energy(&s);
        TEST_ASSERT_EQUAL_INT(CC_OK, solve(&s, e, 0.0));
        p1 = momentum(&s);
        k1 = energy(&s);
        TEST_ASSERT_EQUAL_INT(0, s.report.jammed);
        TEST_ASSERT_EQUAL_INT(0, s.report.capped);
        TEST_ASSERT_TRUE(worst_approach(&s) >= -1e-12 * scale);
        TEST_ASSERT_TRUE(k1 <= k0 * (1.0 + 1e-12));
        if (e == 1.0)
            TEST_ASSERT_DOUBLE_WITHIN(1e-12 * k0, k0, k1);
        if (trial % 5 != 0) {
            TEST_ASSERT_DOUBLE_WITHIN(1e-12 * s.nb, p0.x, p1.x);
            TEST_ASSERT_DOUBLE_WITHIN(1e-12 * s.nb, p0.y, p1.y);
        }
        for (i = 0; i < s.nc; ++i)
            TEST_ASSERT_TRUE(s.contact[i].impulse >= 0.0);
    }
}

/* A ball B at rest squeezed between two immovable circles that close in on it from both sides
 * (velocities (+1, 0) and (-1, 0)): no impulse on B can stop both approaching, so the solve
 * reports a jam instead of looping or inventing motion of the immovable bodies, which keep their
 * velocities bit for bit. */
static void test_jam_between_immovable_bodies(void)
{
    scene s;
    memset(&s, 0, sizeof s);
    add_body(&s, 0.0, 0.0, 0.0, 0.0, 1.0);
    add_body(&s, -2.0, 0.0, 1.0, 0.0, 0.0);
    add_body(&s, 2.0, 0.0, -1.0, 0.0, 0.0);
    add_contact(&s, 0, 1, -1.0, 0.0);
    add_contact(&s, 0, 2, 1.0, 0.0);
    TEST_ASSERT_EQUAL_INT(CC_OK, solve(&s, 1.0, 0.0));
    TEST_ASSERT_EQUAL_INT(1, s.report.jammed);
    TEST_ASSERT_EQUAL_DOUBLE(1.0, s.body[1].vel.x);
    TEST_ASSERT_EQUAL_DOUBLE(-1.0, s.body[2].vel.x);
    TEST_ASSERT_TRUE(fabs(s.body[0].vel.x) <= 3.0 && s.body[0].vel.y == 0.0);
}

/* A cluster of one contact is the ordinary pair impulse: the same velocities as cc_respond
 * (with its mass shares) and cc_respond_segment, to rounding, for random pairs and e. */
static void test_single_contact_is_the_pair_response(void)
{
    int trial;
    for (trial = 0; trial < 1000; ++trial) {
        scene s;
        cc_circle a, b;
        cc_contact k;
        double e = uniform(), ang = 6.283185307179586 * uniform();
        int wall = trial % 3 == 0;
        memset(&s, 0, sizeof s);
        memset(&k, 0, sizeof k);
        a.pos.x = a.pos.y = 0.0;
        a.radius = b.radius = 1.0;
        a.vel.x = uniform() * 4.0 - 2.0;
        a.vel.y = uniform() * 4.0 - 2.0;
        b.vel.x = uniform() * 4.0 - 2.0;
        b.vel.y = uniform() * 4.0 - 2.0;
        a.mass = 0.1 + uniform() * 10.0;
        b.mass = trial % 7 == 0 ? (double)INFINITY : 0.1 + uniform() * 10.0;
        k.normal.x = cos(ang);
        k.normal.y = sin(ang);
        b.pos.x = 2.0 * k.normal.x;
        b.pos.y = 2.0 * k.normal.y;
        add_body(&s, 0.0, 0.0, a.vel.x, a.vel.y, 1.0 / a.mass);
        if (wall) {
            add_contact(&s, 0, -1, k.normal.x, k.normal.y);
            TEST_ASSERT_EQUAL_INT(CC_OK, solve(&s, e, 0.0));
            (void)cc_respond_segment(&a, &k, e);
        } else {
            add_body(&s, b.pos.x, b.pos.y, b.vel.x, b.vel.y, 1.0 / b.mass);
            add_contact(&s, 0, 1, k.normal.x, k.normal.y);
            TEST_ASSERT_EQUAL_INT(CC_OK, solve(&s, e, 0.0));
            (void)cc_respond(&a, &b, &k, e);
            TEST_ASSERT_DOUBLE_WITHIN(1e-14, b.vel.x, s.body[1].vel.x);
            TEST_ASSERT_DOUBLE_WITHIN(1e-14, b.vel.y, s.body[1].vel.y);
        }
        TEST_ASSERT_DOUBLE_WITHIN(1e-14, a.vel.x, s.body[0].vel.x);
        TEST_ASSERT_DOUBLE_WITHIN(1e-14, a.vel.y, s.body[0].vel.y);
    }
}

/* ---- bad input changes nothing ---------------------------------------------------------- */

static void expect_rejected(const scene *bad, double e, double rest, int code)
{
    scene s = *bad;
    TEST_ASSERT_EQUAL_INT(code, solve(&s, e, rest));
    TEST_ASSERT_EQUAL_MEMORY(bad, &s, sizeof s);
}

static void test_bad_input(void)
{
    scene s, bad;
    char small[64];
    build_cradle(&s, 3, 1.0);
    expect_rejected(&s, -0.1, 0.0, CC_ERR_INVALID);
    expect_rejected(&s, 1.5, 0.0, CC_ERR_INVALID);
    expect_rejected(&s, NAN, 0.0, CC_ERR_INVALID);
    expect_rejected(&s, 1.0, -1.0, CC_ERR_INVALID);
    expect_rejected(&s, 1.0, NAN, CC_ERR_INVALID);
    bad = s;
    bad.contact[1].b = 3; /* out of range */
    expect_rejected(&bad, 1.0, 0.0, CC_ERR_INVALID);
    bad = s;
    bad.contact[1].b = 1; /* a == b */
    expect_rejected(&bad, 1.0, 0.0, CC_ERR_INVALID);
    bad = s;
    bad.contact[0].normal.x = 2.0; /* not unit */
    expect_rejected(&bad, 1.0, 0.0, CC_ERR_INVALID);
    bad = s;
    bad.body[2].vel.y = INFINITY;
    expect_rejected(&bad, 1.0, 0.0, CC_ERR_INVALID);
    bad = s;
    bad.body[1].inv_mass = -1.0;
    expect_rejected(&bad, 1.0, 0.0, CC_ERR_INVALID);
    bad = s;
    bad.body[1].inv_mass = 0.0;
    bad.body[2].inv_mass = 0.0; /* two immovable bodies in contact */
    expect_rejected(&bad, 1.0, 0.0, CC_ERR_INVALID);
    bad = s;
    bad.body[0].inv_mass = 0.0;
    bad.contact[0].b = -1; /* an immovable body against a wall */
    expect_rejected(&bad, 1.0, 0.0, CC_ERR_INVALID);
    /* too little scratch */
    bad = s;
    TEST_ASSERT_EQUAL_INT(CC_ERR_MEMORY,
                          cc__cluster_resolve(bad.body, bad.nb, bad.contact, bad.nc, 1.0, 0.0, small,
                                              sizeof small, NULL));
    TEST_ASSERT_EQUAL_INT(CC_ERR_MEMORY, cc__cluster_resolve(bad.body, bad.nb, bad.contact, bad.nc,
                                                             1.0, 0.0, NULL, 0, NULL));
    TEST_ASSERT_EQUAL_MEMORY(&s, &bad, sizeof s);
    TEST_ASSERT_EQUAL_INT(0, (int)cc__cluster_scratch_size(-1, 2));
    TEST_ASSERT_EQUAL_INT(0, (int)cc__cluster_scratch_size(2, 1 << 30));
    /* an empty cluster is fine and does nothing */
    TEST_ASSERT_EQUAL_INT(CC_OK, cc__cluster_resolve(NULL, 0, NULL, 0, 1.0, 0.0, small, sizeof small,
                                                     NULL));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_cradle_sends_out_exactly_one_ball);
    RUN_TEST(test_cradle_with_restitution);
    RUN_TEST(test_rack_break_elastic);
    RUN_TEST(test_rack_break_restitution_0_9);
    RUN_TEST(test_corner_at_45_degrees);
    RUN_TEST(test_unequal_masses);
    RUN_TEST(test_immovable_circle_and_wall);
    RUN_TEST(test_order_independence);
    RUN_TEST(test_deterministic);
    RUN_TEST(test_random_hex_patches);
    RUN_TEST(test_jam_between_immovable_bodies);
    RUN_TEST(test_single_contact_is_the_pair_response);
    RUN_TEST(test_bad_input);
    return UNITY_END();
}
