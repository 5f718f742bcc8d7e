/* Physics validation (issue 15): the world, in EXACT mode on a periodic square box, simulates a
 * hard-disk fluid correctly. N = 400 equal disks (radius 0.5, mass 1) at area fractions 0.1, 0.3,
 * 0.5 and 0.65, started on a square lattice with all speeds equal (random directions, zero total
 * momentum, total kinetic energy N kT with kT = 1), equilibrated, then measured over blocks:
 *   1. equation of state: Z = P A / (N kT) from the virial (cc_world_stats.virial) against
 *      Kolafa and Rottner's fit to the simulated hard-disk EOS, within max(4 sigma, 0.3 %)
 *      (Henderson's Z = (1 + eta^2 / 8) / (1 - eta)^2 is printed beside it); a fourth run at
 *      0.65, the dense fluid, where Henderson is 2.2 % high;
 *   2. collision rate (cc_world_stats.collisions) against Enskog's rate with the contact value
 *      g(sigma) taken from the measured Z (an identity for hard disks), within 2 %;
 *   3. Maxwell-Boltzmann: velocity components pooled over disks and snapshots pass a
 *      Kolmogorov-Smirnov test against the Gaussian of variance kT/m at 1 %, the mean speed is
 *      sqrt(pi kT / (2 m)), and the (equal-speed) start fails both;
 *   4. kinetic energy and momentum conserved to 1e-10 relative, and the centre of mass of the
 *      unwrapped positions (cc_world_get_unwrapped) stays put.
 * docs/PHYSICS.md derives the formulas and lists the figures. Options (for scripts/physics-report.sh
 * and to show that the test can fail): --blocks B, --per-block C (collisions per disk per block),
 * --seed S, --virial-scale F (multiplies the measured virial: 0.5 must fail), --ideal (compares
 * with the ideal gas Z = 1: must fail). */
#include "unity.h"

#include "hard_disks.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NDISK 400
#define SIDE 20 /* SIDE * SIDE = NDISK lattice sites */
#define MAXBLOCKS 64
#define KT HD_KT

static int g_blocks = 10;
static double g_per_block = 300.0; /* collisions per disk in each block */
static double g_equil = 100.0;     /* collisions per disk to equilibrate */
static uint64_t g_seed = 15;
static double g_virial_scale = 1.0;
static int g_ideal = 0;

void setUp(void) {}
void tearDown(void) {}

/* ---- the world: hard_disks.h's box of NDISK disks ---- */
typedef hd_box sim;
#define SIGMA (2.0 * HD_RADIUS)

static cc_world_stats stats_of(const cc_world *w)
{
    cc_world_stats st;
    TEST_ASSERT_EQUAL_INT(CC_OK, hd_stats(w, &st));
    return st;
}

/* Kinetic energy, momentum and the sum of |p| (the scale the momentum is compared with). */
static void totals(const cc_world *w, double *ke, double *px, double *py, double *pabs)
{
    static cc_circle c[NDISK];
    int i;
    TEST_ASSERT_EQUAL_INT(NDISK, cc_world_get_circles(w, NULL, c, NDISK));
    *ke = *px = *py = *pabs = 0.0;
    for (i = 0; i < NDISK; i++) {
        *ke += 0.5 * c[i].mass * (c[i].vel.x * c[i].vel.x + c[i].vel.y * c[i].vel.y);
        *px += c[i].mass * c[i].vel.x;
        *py += c[i].mass * c[i].vel.y;
        *pabs += c[i].mass * hypot(c[i].vel.x, c[i].vel.y);
    }
}

static void centre_of_mass(const cc_world *w, double *x, double *y)
{
    int i;
    *x = *y = 0.0;
    for (i = 0; i < NDISK; i++) {
        cc_vec2 u;
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_unwrapped(w, i, &u));
        *x += u.x;
        *y += u.y;
    }
    *x /= NDISK;
    *y /= NDISK;
}

/* NDISK disks on the SIDE x SIDE lattice of hard_disks.h (equal speeds, zero momentum, K = N kT). */
static void sim_make(sim *s, double eta)
{
    static cc_circle c[NDISK];
    TEST_ASSERT_EQUAL_INT(NDISK, SIDE * SIDE);
    TEST_ASSERT_NULL(hd_box_make(s, NDISK, eta, c));
}

/* ---- Maxwell-Boltzmann checks ---- */
static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Kolmogorov-Smirnov statistic of the samples x[0..n) (sorted here) against N(0, var). */
static double ks_gauss(double *x, int n, double var)
{
    double d = 0.0, sd = sqrt(var);
    int i;
    qsort(x, (size_t)n, sizeof *x, cmp_double);
    for (i = 0; i < n; i++) {
        double cdf = 0.5 * erfc(-x[i] / (sd * sqrt(2.0)));
        double lo = cdf - (double)i / n, hi = (double)(i + 1) / n - cdf;
        if (lo > d)
            d = lo;
        if (hi > d)
            d = hi;
    }
    return d;
}

/* Appends both velocity components of every disk to comp and its speed to speed. */
static void snapshot(const cc_world *w, double *comp, int *ncomp, double *speed, int *nspeed)
{
    static cc_circle c[NDISK];
    int i;
    TEST_ASSERT_EQUAL_INT(NDISK, cc_world_get_circles(w, NULL, c, NDISK));
    for (i = 0; i < NDISK; i++) {
        comp[(*ncomp)++] = c[i].vel.x;
        comp[(*ncomp)++] = c[i].vel.y;
        speed[(*nspeed)++] = hypot(c[i].vel.x, c[i].vel.y);
    }
}

static double mean_sd(const double *x, int n, double *sd)
{
    double m = 0.0, v = 0.0;
    int i;
    for (i = 0; i < n; i++)
        m += x[i];
    m /= n;
    for (i = 0; i < n; i++)
        v += (x[i] - m) * (x[i] - m);
    *sd = sqrt(v / (n - 1));
    return m;
}

/* The asymptotic 1 % critical value of the one-sample KS statistic: sqrt(-ln(0.005) / 2). */
static double ks_crit_1pc(int n) { return sqrt(-0.5 * log(0.005)) / sqrt((double)n); }

/* ---- the run at one area fraction ---- */
typedef struct result {
    double z, z_err, z_ref, z_h, ratio, ratio_err, ks, ks_crit, ks0, vmean, vmean_err, vmean0;
    double de, dp, dcm;
} result;

static void run_eta(double eta, result *r)
{
    static double comp[2 * NDISK * (MAXBLOCKS + 1)], speed[NDISK * (MAXBLOCKS + 1)];
    double zb[MAXBLOCKS], rb[MAXBLOCKS], wb[MAXBLOCKS], tb[MAXBLOCKS], z2[MAXBLOCKS / 2];
    /* the dense fluid relaxes more slowly: three times the equilibration and the block length */
    double dense = eta >= 0.6 ? 3.0 : 1.0;
    int ncomp = 0, nspeed = 0, b, nb = g_blocks;
    sim s;
    cc_world_stats s0, s1, sa, sb;
    double ke0, px0, py0, pa0, ke1, px1, py1, pa1, cx0, cy0, cx1, cy1, sd, gamma_h, t_block, t0;
    double wsum = 0.0, tsum = 0.0, csum = 0.0;

    hd_rng_state = g_seed * 1000003u + (uint64_t)(eta * 1000.0);
    sim_make(&s, eta);
    gamma_h = hd_enskog_rate(hd_z_henderson(eta), SIGMA); /* the expected rate, to size the blocks */

    /* the start: all speeds equal; must fail the Maxwell-Boltzmann checks */
    snapshot(s.w, comp, &ncomp, speed, &nspeed);
    r->ks0 = ks_gauss(comp, ncomp, KT);
    r->vmean0 = mean_sd(speed, nspeed, &sd);
    ncomp = nspeed = 0;

    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(s.w, 0.0)); /* settle the start (no overlaps) */
    totals(s.w, &ke0, &px0, &py0, &pa0);
    centre_of_mass(s.w, &cx0, &cy0);

    /* equilibrate: about g_equil collisions per disk (each collision involves two disks) */
    s0 = stats_of(s.w);
    while ((double)(stats_of(s.w).collisions - s0.collisions) < dense * g_equil * NDISK / 2.0)
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(s.w, 1.0 / gamma_h));

    /* measure over nb blocks of fixed duration */
    t_block = dense * g_per_block / gamma_h;
    for (b = 0; b < nb; b++) {
        double dw, dt, dc, zz;
        sa = stats_of(s.w);
        t0 = cc_world_time(s.w);
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(s.w, t_block));
        sb = stats_of(s.w);
        dt = cc_world_time(s.w) - t0;
        dw = (sb.virial - sa.virial) * g_virial_scale;
        dc = (double)(sb.collisions - sa.collisions);
        zz = 1.0 + dw / (2.0 * dt * NDISK * KT); /* P A = N kT + virial / (2 t) */
        zb[b] = zz;
        rb[b] = (2.0 * dc / (NDISK * dt)) / hd_enskog_rate(zz, SIGMA);
        wb[b] = dw;
        tb[b] = dt;
        wsum += dw;
        tsum += dt;
        csum += dc;
        snapshot(s.w, comp, &ncomp, speed, &nspeed);
    }
    s1 = stats_of(s.w);
    totals(s.w, &ke1, &px1, &py1, &pa1);
    centre_of_mass(s.w, &cx1, &cy1);

    r->z = 1.0 + wsum / (2.0 * tsum * NDISK * KT);
    r->z_err = 0.0;
    (void)mean_sd(zb, nb, &sd);
    r->z_err = sd / sqrt((double)nb);
    if (nb >= 4) { /* blocks twice as long: if their error is larger, the blocks were correlated */
        for (b = 0; b + 1 < nb; b += 2)
            z2[b / 2] = 1.0 + (wb[b] + wb[b + 1]) / (2.0 * (tb[b] + tb[b + 1]) * NDISK * KT);
        (void)mean_sd(z2, nb / 2, &sd);
        r->z_err = fmax(r->z_err, sd / sqrt((double)(nb / 2)));
    }
    r->z_ref = g_ideal ? 1.0 : hd_z_kolafa_rottner(eta);
    r->z_h = hd_z_henderson(eta);
    r->ratio = (2.0 * csum / (NDISK * tsum)) / hd_enskog_rate(r->z, SIGMA);
    (void)mean_sd(rb, nb, &sd);
    r->ratio_err = sd / sqrt((double)nb);
    r->ks = ks_gauss(comp, ncomp, KT);
    r->ks_crit = ks_crit_1pc(ncomp);
    r->vmean = mean_sd(speed, nspeed, &sd);
    r->vmean_err = sd / sqrt((double)nspeed);
    r->de = fabs(ke1 - ke0) / ke0;
    r->dp = hypot(px1 - px0, py1 - py0) / pa0;
    r->dcm = hypot(cx1 - cx0, cy1 - cy0) / s.box;

    printf("eta %.2f: L %.4f, %llu collisions, t %.3f; Z %.5f +- %.5f, Kolafa-Rottner %.5f (%+.2f %%, "
           "%.1f sigma), Henderson %.5f; rate / Enskog(Z) %.5f +- %.5f; KS %.5f (1 %% crit %.5f, start %.4f); "
           "mean speed %.5f +- %.5f (MB %.5f, start %.4f); dE/E %.1e, dP/sum|p| %.1e, dCM/L %.1e; "
           "max overlap %.1e\n",
           eta, s.box, (unsigned long long)s1.collisions, cc_world_time(s.w), r->z, r->z_err, r->z_ref,
           100.0 * (r->z - r->z_ref) / r->z_ref, fabs(r->z - r->z_ref) / r->z_err, r->z_h, r->ratio, r->ratio_err,
           r->ks, r->ks_crit, r->ks0, r->vmean, r->vmean_err, sqrt(M_PI * KT / 2.0), r->vmean0, r->de,
           r->dp, r->dcm, s1.max_overlap);
    fflush(stdout);
    hd_box_free(&s);
}

static void check(const result *r)
{
    double vmb = sqrt(M_PI * KT / 2.0);
    double tol = fmax(4.0 * r->z_err, 0.003 * r->z_ref);
    /* 1. equation of state */
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(tol, r->z_ref, r->z, "Z from the virial vs Kolafa-Rottner");
    /* 2. collision rate vs Enskog with g(sigma) from the measured Z */
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(fmax(0.02, 4.0 * r->ratio_err), 1.0, r->ratio,
                                      "collision rate / Enskog(Z)");
    /* 3. Maxwell-Boltzmann, and the start is not */
    TEST_ASSERT_TRUE_MESSAGE(r->ks < r->ks_crit, "KS statistic above the 1 % critical value");
    TEST_ASSERT_TRUE_MESSAGE(r->ks0 > r->ks_crit, "the start should not pass the KS test");
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(4.0 * r->vmean_err, vmb, r->vmean, "mean speed vs sqrt(pi kT/2m)");
    TEST_ASSERT_TRUE_MESSAGE(fabs(r->vmean0 - vmb) > 4.0 * r->vmean_err, "the start's mean speed");
    /* 4. conservation */
    TEST_ASSERT_TRUE_MESSAGE(r->de < 1e-10, "kinetic energy not conserved");
    TEST_ASSERT_TRUE_MESSAGE(r->dp < 1e-10, "momentum not conserved");
    TEST_ASSERT_TRUE_MESSAGE(r->dcm < 1e-10, "centre of mass (unwrapped) moved");
}

static void test_eta_010(void)
{
    result r;
    run_eta(0.1, &r);
    check(&r);
}

static void test_eta_030(void)
{
    result r;
    run_eta(0.3, &r);
    check(&r);
}

static void test_eta_050(void)
{
    result r;
    run_eta(0.5, &r);
    check(&r);
}

static void test_eta_065(void)
{
    result r;
    run_eta(0.65, &r);
    check(&r);
}

int main(int argc, char **argv)
{
    int i;
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--blocks") && i + 1 < argc)
            g_blocks = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--per-block") && i + 1 < argc)
            g_per_block = atof(argv[++i]);
        else if (!strcmp(argv[i], "--equil") && i + 1 < argc)
            g_equil = atof(argv[++i]);
        else if (!strcmp(argv[i], "--seed") && i + 1 < argc)
            g_seed = (uint64_t)strtoull(argv[++i], NULL, 10);
        else if (!strcmp(argv[i], "--virial-scale") && i + 1 < argc)
            g_virial_scale = atof(argv[++i]);
        else if (!strcmp(argv[i], "--ideal"))
            g_ideal = 1;
        else {
            fprintf(stderr, "usage: %s [--blocks B (2..%d)] [--per-block C] [--equil C] [--seed S] "
                            "[--virial-scale F] [--ideal]\n",
                    argv[0], MAXBLOCKS);
            return 2;
        }
    }
    if (g_blocks < 2 || g_blocks > MAXBLOCKS || !(g_per_block > 0.0) || !(g_equil >= 0.0)) {
        fprintf(stderr, "bad options\n");
        return 2;
    }
    UNITY_BEGIN();
    RUN_TEST(test_eta_010);
    RUN_TEST(test_eta_030);
    RUN_TEST(test_eta_050);
    RUN_TEST(test_eta_065);
    return UNITY_END();
}
