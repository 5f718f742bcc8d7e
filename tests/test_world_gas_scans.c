/* EXACT's neighbour scans on dense and dilute gases, periodic and walled: no circle ever passes
 * into another (a neighbour the scans miss, or a list not made again in time, lets two disks
 * overlap by about their speed times the step), energy and momentum are kept, and a memcpy'd
 * world runs on bit for bit. Written for issue 16's neighbour lists with a shell (tag
 * experiment/nlist, where -DCC_NLIST=ON runs these scenes on the lists and the crossings count the
 * relists); on main it checks the grid's cell crossings and 3x3 scans the same way. */
#include "unity.h"
#include "test_world_util.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define N 900

/* Deepest overlap of two of the n circles relative to their radius sum, through the nearest
 * image along each periodic axis (period 0: open). All pairs: n is small. */
static double max_overlap(const cc_circle *c, int n, double P)
{
    double worst = 0.0;
    int i, j;
    for (i = 0; i < n; i++)
        for (j = i + 1; j < n; j++) {
            double dx = c[j].pos.x - c[i].pos.x, dy = c[j].pos.y - c[i].pos.y, R = c[i].radius + c[j].radius, o;
            if (P > 0.0) {
                dx -= P * floor(dx / P + 0.5);
                dy -= P * floor(dy / P + 0.5);
            }
            if (fabs(dx) > R || fabs(dy) > R)
                continue;
            o = (R - sqrt(dx * dx + dy * dy)) / R;
            worst = o > worst ? o : worst;
        }
    return worst;
}

/* n disks of radius 0.5 (mass 1, velocities in [-1, 1]^2) on a lattice at area fraction phi, in a
 * periodic square box (periodic) or one of four walls. Returns the box's side. */
static double gas(cc_world *w, double phi, int periodic, uint64_t seed)
{
    double L;
    int side = (int)ceil(sqrt((double)N)), i;
    if (!periodic)
        return tw_fill_box(w, N, 0.5, phi, seed);
    L = sqrt(N * 3.14159265358979323846 * 0.25 / phi);
    for (i = 0; i < N; i++) {
        cc_circle c = tw_circle(L / side * (i % side + 0.5), L / side * (i / side + 0.5), 2.0 * tw_rand(&seed) - 1.0,
                                2.0 * tw_rand(&seed) - 1.0, 0.5, 1.0);
        (void)cc_world_add_circle(w, &c);
    }
    return L;
}

static void run(double phi, int periodic)
{
    static cc_circle c[N];
    cc_world_def d;
    cc_world_stats s;
    tw_mem m, m2;
    cc_world *w, *w2;
    tw_totals t0, t1;
    double L, worst = 0.0;
    int k;
    cc_world_def_init(&d);
    d.max_circles = N;
    d.max_segments = 4;
    if (periodic) {
        d.period.x = d.period.y = sqrt(N * 3.14159265358979323846 * 0.25 / phi);
    }
    w = tw_make(&m, &d, 0);
    w2 = tw_make(&m2, &d, 0);
    L = gas(w, phi, periodic, 7);
    TEST_ASSERT_EQUAL_INT(N, cc_world_get_circles(w, NULL, c, N));
    t0 = tw_sum(c, N);
    for (k = 0; k < 40; k++) {
        double o;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.25));
        TEST_ASSERT_EQUAL_INT(N, cc_world_get_circles(w, NULL, c, N));
        o = max_overlap(c, N, periodic ? L : 0.0);
        worst = o > worst ? o : worst;
        if (k == 20) /* a copy of the world goes on as the world does, bit for bit */
            memcpy(w2, w, cc_world_size(&d));
    }
    for (k = 21; k < 40; k++)
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w2, 0.25));
    TEST_ASSERT_EQUAL_UINT64(cc_world_hash(w), cc_world_hash(w2));
    t1 = tw_sum(c, N);
    s = tw_stats(w);
    printf("phi %.1f %s: %llu collisions, %.2f crossings and %.1f pair tests per collision; deepest "
           "overlap %.3g of the radius sum\n",
           phi, periodic ? "periodic" : "walled", (unsigned long long)s.collisions,
           (double)s.cell_crossings / (double)s.collisions, (double)s.pairs_tested / (double)s.collisions, worst);
    TEST_ASSERT_TRUE(s.collisions > (uint64_t)N * (phi > 0.5 ? 10u : 1u)); /* the scans had work to do */
    /* impacts leave pairs at contact to rounding (~1e-15); a missed neighbour, at 0.25 s and
     * speeds ~1, passes ~0.1 of a diameter into another */
    TEST_ASSERT_TRUE_MESSAGE(worst < 1e-9, "two disks overlap: a neighbour was missed");
    TEST_ASSERT_DOUBLE_WITHIN(1e-9 * t0.energy, t0.energy, t1.energy);
    if (periodic) { /* (the walls take momentum) */
        TEST_ASSERT_DOUBLE_WITHIN(1e-9 * N, t0.px, t1.px);
        TEST_ASSERT_DOUBLE_WITHIN(1e-9 * N, t0.py, t1.py);
    }
    tw_free(&m);
    tw_free(&m2);
}

static void test_dense_periodic(void) { run(0.7, 1); }
static void test_dilute_periodic(void) { run(0.3, 1); }
static void test_dense_walled(void) { run(0.7, 0); }
static void test_sparse_walled(void) { run(0.1, 0); }

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_dense_periodic);
    RUN_TEST(test_dilute_periodic);
    RUN_TEST(test_dense_walled);
    RUN_TEST(test_sparse_walled);
    return UNITY_END();
}
