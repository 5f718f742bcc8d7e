/* physics_eos: the slow hard-disk figures of docs/PHYSICS.md (issue 15); not a ctest test (it
 * takes minutes), run by scripts/physics-report.sh. Public API only: an EXACT world of N equal
 * disks (radius 1/2, mass 1, restitution 1) in a periodic square box.
 *
 *   physics_eos eos  [--n N] [--eta e1,e2,...] [--equil C] [--blocks B] [--per-block C] [--seed S]
 *       The equation of state: Z = P A / (N kT) from the collision virial, block averages, against
 *       Kolafa and Rottner's fit and Henderson's formula, with the global bond-orientational
 *       order |Psi6| (is the box liquid, hexatic or solid?). One tab-separated line per eta.
 *   physics_eos long [--n N] [--eta E] [--collisions C] [--every C] [--seed S]
 *       Conservation over a long run: relative kinetic-energy change, momentum and the centre of
 *       mass of the unwrapped positions every C collisions; and the rounding model of the energy
 *       drift (the mean and spread of |n|^2 - 1 for a normal made as the library makes it).
 *   physics_eos vacf [--n N] [--eta E] [--lags K] [--origins M] [--seed S]
 *       The velocity autocorrelation against Enskog's exponential, and the running diffusion
 *       coefficient over Enskog's.
 *
 * C counts collisions per disk for eos (each impact involves two disks) and impacts for long.
 * docs/PHYSICS.md gives the formulas, the literature values and the figures. */
#include "hard_disks.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>


#define KT HD_KT
#define MAXBLOCKS 256
#define MAXETA 64

static uint64_t g_seed = 0; /* --seed */

static void die(const char *what)
{
    fprintf(stderr, "physics_eos: %s\n", what);
    exit(1);
}

/* ---- the literature ---- */

/* Engel et al., PRE 87, 042134 (2013): liquid-hexatic coexistence at beta P sigma^2 = 9.185 for
 * 0.700 <= eta <= 0.716; in the thermodynamic limit Z is that pressure over rho sigma^2 there. */
static double z_engel_coexistence(double eta)
{
    if (eta < 0.700 - 1e-12 || eta > 0.716 + 1e-12)
        return NAN;
    return 9.185 * M_PI / (4.0 * eta);
}

/* ---- the world ---- */
typedef struct sim {
    hd_box b;     /* the world (hard_disks.h) */
    cc_world *w;  /* b.w */
    cc_circle *c; /* its circles, as last read */
    int n;
    double eta, box;
} sim;

static cc_world_stats stats_of(const cc_world *w)
{
    cc_world_stats st;
    if (hd_stats(w, &st) != CC_OK)
        die("cc_world_get_stats");
    return st;
}

static void step(sim *s, double dt)
{
    if (cc_world_step(s->w, dt) != CC_OK)
        die("cc_world_step failed");
}

/* hard_disks.h's box of n disks, its circles kept in s->c. */
static void sim_make(sim *s, int n, double eta)
{
    const char *failed;
    memset(s, 0, sizeof *s);
    s->c = (cc_circle *)malloc((size_t)n * sizeof *s->c);
    if (s->c == NULL)
        die("out of memory");
    if ((failed = hd_box_make(&s->b, n, eta, s->c)) != NULL)
        die(failed);
    s->w = s->b.w, s->n = n, s->eta = eta, s->box = s->b.box;
    step(s, 0.0);
}

static void sim_free(sim *s)
{
    hd_box_free(&s->b);
    free(s->c);
    memset(s, 0, sizeof *s);
}

static void read_circles(sim *s)
{
    if (cc_world_get_circles(s->w, NULL, s->c, s->n) != s->n)
        die("cc_world_get_circles");
}

/* |Psi6|: the modulus of the mean over disks of psi6_j = mean over neighbours k (centre
 * distance below 1.4 sigma, minimum image) of exp(6 i theta_jk). Near 1 in a triangular
 * crystal or a hexatic box, O(1/sqrt N) in a liquid. O(N^2): fine at the sizes used here. */
static double psi6_global(sim *s)
{
    double re = 0.0, im = 0.0, rc2 = (1.4 * 2.0 * HD_RADIUS) * (1.4 * 2.0 * HD_RADIUS), L = s->box;
    int j, k;
    read_circles(s);
    for (j = 0; j < s->n; j++) {
        double pr = 0.0, pi = 0.0;
        int m = 0;
        for (k = 0; k < s->n; k++) {
            double dx, dy;
            if (k == j)
                continue;
            dx = s->c[k].pos.x - s->c[j].pos.x;
            dy = s->c[k].pos.y - s->c[j].pos.y;
            dx -= L * floor(dx / L + 0.5);
            dy -= L * floor(dy / L + 0.5);
            if (dx * dx + dy * dy < rc2) {
                double th = 6.0 * atan2(dy, dx);
                pr += cos(th);
                pi += sin(th);
                m++;
            }
        }
        if (m > 0) {
            re += pr / m;
            im += pi / m;
        }
    }
    return hypot(re, im) / s->n;
}

static void totals(sim *s, double *ke, double *px, double *py, double *pabs, double *cx, double *cy)
{
    int i;
    read_circles(s);
    *ke = *px = *py = *pabs = *cx = *cy = 0.0;
    for (i = 0; i < s->n; i++) {
        cc_vec2 u;
        const cc_circle *c = &s->c[i];
        *ke += 0.5 * c->mass * (c->vel.x * c->vel.x + c->vel.y * c->vel.y);
        *px += c->mass * c->vel.x;
        *py += c->mass * c->vel.y;
        *pabs += c->mass * hypot(c->vel.x, c->vel.y);
        if (cc_world_get_unwrapped(s->w, i, &u) != CC_OK)
            die("cc_world_get_unwrapped");
        *cx += u.x;
        *cy += u.y;
    }
    *cx /= s->n;
    *cy /= s->n;
}

/* Steps until `impacts` more collisions have happened, in steps of about `chunk` impacts. */
static void run_impacts(sim *s, double impacts, double rate_per_disk)
{
    uint64_t c0 = stats_of(s->w).collisions;
    double dt = fmax(1.0, fmin(impacts, 0.05 * s->n)) / (0.5 * s->n * rate_per_disk);
    while ((double)(stats_of(s->w).collisions - c0) < impacts)
        step(s, dt);
}

static double sd_of(const double *x, int n)
{
    double m = 0.0, v = 0.0;
    int i;
    for (i = 0; i < n; i++)
        m += x[i];
    m /= n;
    for (i = 0; i < n; i++)
        v += (x[i] - m) * (x[i] - m);
    return sqrt(v / (n - 1));
}

/* ---- eos ---- */
static void run_eos(int n, const double *etas, int neta, double equil, int nb, double per_block)
{
    int e, b;
    printf("# N\teta\tZ\tZ_err\tZ_err_B/2\tZ_KR\tZ_H\tZ_Engel_coex\tdev_KR_%%\tdev_sigma\tpsi6\tpsi6_sd\t"
           "impacts\tcpu_s\tZ_1st_half\tZ_2nd_half\n");
    fflush(stdout);
    for (e = 0; e < neta; e++) {
        double eta = etas[e], zb[MAXBLOCKS], wb[MAXBLOCKS], tb[MAXBLOCKS], z2[MAXBLOCKS / 2], ps[MAXBLOCKS];
        double rate, t0, tblock, zh1, zh2, wsum = 0.0, tsum = 0.0, z, err, err2, zkr, psi = 0.0, cpu0 = (double)clock();
        cc_world_stats a, c;
        sim s;
        hd_rng_state = g_seed * 0x9E3779B97F4A7C15ull + 1000003u * (uint64_t)(1 + e) + (uint64_t)(eta * 1e4) + 77u * (uint64_t)n;
        sim_make(&s, n, eta);
        /* equilibration; the second half also measures the collision rate that sizes the blocks */
        rate = hd_enskog_rate(hd_z_henderson(eta), 2.0 * HD_RADIUS); /* Enskog with Henderson: a guess */
        run_impacts(&s, 0.5 * equil * n / 2.0, rate);
        a = stats_of(s.w);
        t0 = cc_world_time(s.w);
        run_impacts(&s, 0.5 * equil * n / 2.0, rate);
        c = stats_of(s.w);
        rate = 2.0 * (double)(c.collisions - a.collisions) / (n * (cc_world_time(s.w) - t0));
        tblock = per_block / rate;
        for (b = 0; b < nb; b++) {
            double tb0 = cc_world_time(s.w);
            a = stats_of(s.w);
            step(&s, tblock);
            c = stats_of(s.w);
            tb[b] = cc_world_time(s.w) - tb0;
            wb[b] = c.virial - a.virial;
            zb[b] = 1.0 + wb[b] / (2.0 * tb[b] * n * KT);
            wsum += wb[b];
            tsum += tb[b];
            ps[b] = psi6_global(&s);
            psi += ps[b];
        }
        for (b = 0; b + 1 < nb; b += 2) /* blocks twice as long: the error must not grow */
            z2[b / 2] = 1.0 + (wb[b] + wb[b + 1]) / (2.0 * (tb[b] + tb[b + 1]) * n * KT);
        z = 1.0 + wsum / (2.0 * tsum * n * KT);
        err = sd_of(zb, nb) / sqrt((double)nb);
        err2 = nb >= 4 ? sd_of(z2, nb / 2) / sqrt((double)(nb / 2)) : NAN;
        zkr = hd_z_kolafa_rottner(eta);
        {   /* Z over the first and the second half of the blocks: a drift shows unfinished equilibration */
            double w1 = 0.0, t1 = 0.0, w2 = 0.0, t2 = 0.0;
            for (b = 0; b < nb; b++) {
                if (2 * b < nb) {
                    w1 += wb[b];
                    t1 += tb[b];
                } else {
                    w2 += wb[b];
                    t2 += tb[b];
                }
            }
            zh1 = 1.0 + w1 / (2.0 * t1 * n * KT);
            zh2 = 1.0 + w2 / (2.0 * t2 * n * KT);
        }
        c = stats_of(s.w);
        printf("%d\t%.4f\t%.5f\t%.5f\t%.5f\t%.5f\t%.5f\t%.5f\t%+.3f\t%+.1f\t%.3f\t%.3f\t%llu\t%.1f\t%.5f\t%.5f\n", n, eta, z, err,
               err2, zkr, hd_z_henderson(eta), z_engel_coexistence(eta), 100.0 * (z / zkr - 1.0),
               (z - zkr) / fmax(err, err2 == err2 ? err2 : 0.0), psi / nb, sd_of(ps, nb),
               (unsigned long long)c.collisions, ((double)clock() - cpu0) / CLOCKS_PER_SEC, zh1, zh2);
        fflush(stdout);
        sim_free(&s);
    }
}

/* ---- long ---- */

/* The library's unit normal (src/helpers.inc, cc__unit, for ordinary magnitudes): d / |d| with
 * |d| = sqrt(dx^2 + dy^2). For equal masses at restitution 1 the impulse changes the kinetic
 * energy by m vn^2 (|n|^2 - 1) exactly, so the mean of |n|^2 - 1 over the contact directions is
 * the systematic part of the drift; its spread, with the rounding of the velocity updates, the
 * random part. */
static void normal_rounding(double *mean, double *sd)
{
    double s1 = 0.0, s2 = 0.0;
    int i, m = 4000000;
    for (i = 0; i < m; i++) {
        double th = 2.0 * M_PI * hd_uniform(), r = 1.0 + 1e-9 * (hd_uniform() - 0.5);
        double x = 1000.0 * hd_uniform(), y = 1000.0 * hd_uniform();
        double dx = (x + r * cos(th)) - x, dy = (y + r * sin(th)) - y; /* differences of positions */
        double len = sqrt(dx * dx + dy * dy), nx = dx / len, ny = dy / len;
        double del = nx * nx + ny * ny - 1.0;
        s1 += del;
        s2 += del * del;
    }
    *mean = s1 / m;
    *sd = sqrt(s2 / m - (*mean) * (*mean));
}

static void run_long(int n, double eta, double total, double every)
{
    sim s;
    double ke0, px0, py0, pa0, cx0, cy0, rate, cpu0 = (double)clock(), dmean, dsd;
    uint64_t c0;
    hd_rng_state = g_seed * 0x9E3779B97F4A7C15ull + 4242u + (uint64_t)n;
    sim_make(&s, n, eta);
    totals(&s, &ke0, &px0, &py0, &pa0, &cx0, &cy0);
    c0 = stats_of(s.w).collisions;
    rate = hd_enskog_rate(hd_z_henderson(eta), 2.0 * HD_RADIUS);
    printf("# N %d, eta %.3f, L %.4f; from the lattice, no separate equilibration\n", n, eta, s.box);
    printf("# impacts\tworld_time\tdE/E\t|dP|/sum|p|\tdCM/L\tmax_overlap\tcpu_s\n");
    fflush(stdout);
    while ((double)(stats_of(s.w).collisions - c0) < total) {
        double ke, px, py, pa, cx, cy;
        cc_world_stats st;
        run_impacts(&s, every, rate);
        st = stats_of(s.w);
        totals(&s, &ke, &px, &py, &pa, &cx, &cy);
        printf("%llu\t%.1f\t%+.3e\t%.2e\t%.2e\t%.2e\t%.1f\n", (unsigned long long)(st.collisions - c0),
               cc_world_time(s.w), (ke - ke0) / ke0, hypot(px - px0, py - py0) / pa0, hypot(cx - cx0, cy - cy0) / s.box,
               st.max_overlap, ((double)clock() - cpu0) / CLOCKS_PER_SEC);
        fflush(stdout);
    }
    normal_rounding(&dmean, &dsd);
    printf("# rounding model: |n|^2 - 1 of the library's normal has mean %+.3e and sd %.3e (in units of "
           "DBL_EPSILON: %+.4f, %.4f);\n# the mean contact impact changes K by m vn^2 (|n|^2 - 1) with "
           "<m vn^2> = 4 kT, so the systematic drift of K / (N kT) per impact is 4 <|n|^2 - 1> / N = %+.2e\n",
           dmean, dsd, dmean / 2.220446049250313e-16, dsd / 2.220446049250313e-16, 4.0 * dmean / n);
    sim_free(&s);
}

/* ---- vacf ---- */

/* The velocity autocorrelation C(t) = <v(0).v(t)> / <v.v> after 200 collisions per disk of
 * equilibration: snapshots every dt = (1/8) mean free time, correlated with the `lags` before
 * them, `origins` time origins. Printed beside the Enskog exponential exp(-Gamma t) (in 2D the
 * first Enskog approximation relaxes a disk's velocity at the collision rate: D_E = (kT/m) /
 * Gamma_E), with the running diffusion coefficient D(t) = (kT/m) integral_0^t C over D_E. */
static void run_vacf(int n, double eta, int lags, int origins)
{
    sim s;
    double *ring, *acc, rate, dt, t0, c0 = 0.0, integral = 0.0;
    int k, j, i, filled = 0;
    cc_world_stats a, c;
    hd_rng_state = g_seed * 0x9E3779B97F4A7C15ull + 999u + (uint64_t)n;
    sim_make(&s, n, eta);
    rate = hd_enskog_rate(hd_z_henderson(eta), 2.0 * HD_RADIUS);
    run_impacts(&s, 100.0 * n, rate);
    a = stats_of(s.w);
    t0 = cc_world_time(s.w);
    run_impacts(&s, 100.0 * n, rate);
    c = stats_of(s.w);
    rate = 2.0 * (double)(c.collisions - a.collisions) / (n * (cc_world_time(s.w) - t0)); /* measured */
    dt = 0.125 / rate;
    ring = (double *)malloc((size_t)(lags + 1) * 2 * (size_t)n * sizeof *ring);
    acc = (double *)calloc((size_t)(lags + 1), sizeof *acc);
    if (ring == NULL || acc == NULL)
        die("out of memory");
    for (k = 0; k < origins + lags; k++) {
        double *cur = ring + (size_t)(k % (lags + 1)) * 2 * (size_t)n;
        read_circles(&s);
        for (i = 0; i < n; i++) {
            cur[2 * i] = s.c[i].vel.x;
            cur[2 * i + 1] = s.c[i].vel.y;
        }
        filled = k + 1 < lags + 1 ? k + 1 : lags + 1;
        if (k >= lags) /* a full window: correlate the oldest with every later one */
            for (j = 0; j <= lags; j++) {
                const double *o = ring + (size_t)((k - lags) % (lags + 1)) * 2 * (size_t)n;
                const double *v = ring + (size_t)((k - lags + j) % (lags + 1)) * 2 * (size_t)n;
                double sum = 0.0;
                for (i = 0; i < 2 * n; i++)
                    sum += o[i] * v[i];
                acc[j] += sum;
            }
        step(&s, dt);
    }
    (void)filled;
    c0 = acc[0];
    printf("# N %d, eta %.3f: collision rate per disk %.5f (Enskog with Kolafa-Rottner's Z: %.5f), dt = %.5f = "
           "1/8 mean free time, %d origins\n",
           n, eta, rate, hd_enskog_rate(hd_z_kolafa_rottner(eta), 2.0 * HD_RADIUS), dt, origins);
    printf("# t_Gamma\tC(t)/C(0)\texp(-Gamma t)\tD(t)/D_E\n");
    for (j = 0; j <= lags; j++) {
        if (j > 0)
            integral += 0.5 * (acc[j - 1] + acc[j]) / c0 * dt; /* trapezoid, in units of C(0) */
        if (j % 4 == 0)
            printf("%.3f\t%.5f\t%.5f\t%.4f\n", j * dt * rate, acc[j] / c0, exp(-j * dt * rate), integral * rate);
    }
    free(ring);
    free(acc);
    sim_free(&s);
}

static int parse_list(const char *arg, double *out, int cap)
{
    int k = 0;
    char *end;
    while (*arg && k < cap) {
        out[k++] = strtod(arg, &end);
        if (end == arg)
            return -1;
        arg = *end == ',' ? end + 1 : end;
        if (*end && *end != ',')
            return -1;
    }
    return k;
}

int main(int argc, char **argv)
{
    int n = 400, nb = 20, neta = 0, i, mode;
    double etas[MAXETA], equil = 200.0, per_block = 500.0, total = 1e7, every = 1e6;
    int lags = 160, origins = 4000;
    if (argc < 2 || (strcmp(argv[1], "eos") && strcmp(argv[1], "long") && strcmp(argv[1], "vacf")))
        goto usage;
    mode = !strcmp(argv[1], "long") ? 1 : !strcmp(argv[1], "vacf") ? 2 : 0;
    for (i = 2; i < argc; i++) {
        if (!strcmp(argv[i], "--n") && i + 1 < argc)
            n = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--eta") && i + 1 < argc)
            neta = parse_list(argv[++i], etas, MAXETA);
        else if (!strcmp(argv[i], "--equil") && i + 1 < argc)
            equil = atof(argv[++i]);
        else if (!strcmp(argv[i], "--blocks") && i + 1 < argc)
            nb = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--per-block") && i + 1 < argc)
            per_block = atof(argv[++i]);
        else if (!strcmp(argv[i], "--collisions") && i + 1 < argc)
            total = atof(argv[++i]);
        else if (!strcmp(argv[i], "--every") && i + 1 < argc)
            every = atof(argv[++i]);
        else if (!strcmp(argv[i], "--lags") && i + 1 < argc)
            lags = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--origins") && i + 1 < argc)
            origins = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--seed") && i + 1 < argc)
            g_seed = (uint64_t)strtoull(argv[++i], NULL, 10);
        else
            goto usage;
    }
    if (neta < 0 || n < 2 || nb < 2 || nb > MAXBLOCKS || !(per_block > 0.0) || !(equil >= 0.0) || !(total > 0.0) ||
        !(every > 0.0))
        goto usage;
    if (neta == 0) {
        etas[0] = 0.5;
        neta = 1;
    }
    for (i = 0; i < neta; i++)
        if (!(etas[i] > 0.0 && etas[i] < 0.78))
            goto usage;
    if (lags < 1 || origins < 1)
        goto usage;
    if (mode == 2)
        run_vacf(n, etas[0], lags, origins);
    else if (mode == 1)
        run_long(n, etas[0], total, every);
    else
        run_eos(n, etas, neta, equil, nb, per_block);
    return 0;
usage:
    fprintf(stderr,
            "usage: %s eos [--n N] [--eta e1,e2,...] [--equil C] [--blocks B (2..%d)] [--per-block C]\n"
            "       %s long [--n N] [--eta E] [--collisions C] [--every C]\n"
            "       %s vacf [--n N] [--eta E] [--lags K] [--origins M]\n",
            argv[0], MAXBLOCKS, argv[0], argv[0]);
    return 2;
}
