/* The rolling pair benchmark (issue 12): the cost of a ball-ball time of impact with rolling
 * friction, cc_sweep_rolling against cc_sweep on the same pairs (the 3x target) and the
 * textbook quartic (Ferrari, tests/reference/textbook_quartic.c); bench/pooltool_rolling.py puts
 * pooltool's own collision time beside them, on the same pairs, in the same run.
 *
 *   bench_pair_rolling dump N FILE [--seed S]   pool-like pairs (14 doubles each, below)
 *   bench_pair_rolling time FILE [--rounds R]   ns per pair of each method (median, spread over
 *                                               the rounds), and FILE.ours: our t per pair
 *   bench_pair_rolling run N FILE               dump, then time one round (ctest's tiny run)
 *
 * A pair is 14 doubles: class (-1 for these), pa.x pa.y va.x va.y ra pb.x pb.y vb.x vb.y rb
 * decel_a decel_b t_max. The pool pairs: balls of radius 0.028575 m on a 2.54 x 1.27 m table,
 * speeds 0.05..3 m/s, rolling resistance mu g = 0.01 * 9.81 m/s^2, a third of the second balls at
 * rest, aimed at each other half of the time (within a ball radius), t_max unbounded. */
#include "bench_util.h"
#include "circlecollide.h"
#include "textbook.h"

#define POOL_R 0.028575
#define POOL_DECEL (0.01 * 9.81)

static void dump(long n, const char *path, uint64_t seed)
{
    FILE *f = fopen(path, "wb");
    bench_rng r;
    long i;
    if (f == NULL) {
        perror(path);
        exit(2);
    }
    r.s = seed;
    for (i = 0; i < n; i++) {
        double x[14], ang, sp;
        x[0] = -1.0;
        x[1] = bench_uniform(&r, 0.0, 2.54), x[2] = bench_uniform(&r, 0.0, 1.27);
        x[6] = bench_uniform(&r, 0.0, 2.54), x[7] = bench_uniform(&r, 0.0, 1.27);
        if (bench_uniform(&r, 0, 1) < 0.5) { /* aimed at b (within a radius of its centre) */
            double dx = x[6] - x[1] + bench_uniform(&r, -POOL_R, POOL_R), dy = x[7] - x[2] + bench_uniform(&r, -POOL_R, POOL_R);
            ang = atan2(dy, dx);
        } else {
            ang = bench_uniform(&r, -3.14159265358979, 3.14159265358979);
        }
        sp = bench_uniform(&r, 0.05, 3.0);
        x[3] = sp * cos(ang), x[4] = sp * sin(ang), x[5] = POOL_R;
        if (bench_uniform(&r, 0, 1) < 1.0 / 3.0)
            x[8] = x[9] = 0.0;
        else {
            ang = bench_uniform(&r, -3.14159265358979, 3.14159265358979);
            sp = bench_uniform(&r, 0.05, 3.0);
            x[8] = sp * cos(ang), x[9] = sp * sin(ang);
        }
        x[10] = POOL_R, x[11] = POOL_DECEL, x[12] = POOL_DECEL, x[13] = HUGE_VAL;
        if (hypot(x[6] - x[1], x[7] - x[2]) < 2 * POOL_R) { /* no overlapping starts */
            i--;
            continue;
        }
        fwrite(x, sizeof x, 1, f);
    }
    fclose(f);
    printf("%ld pairs written to %s\n", n, path);
}

typedef struct pair {
    cc_circle a, b;
    double da, db, t_max;
} pair;

static volatile double sink;

enum { M_ROLL, M_SWEEP, M_TEXTBOOK, M_COUNT };

static double run(int m, const pair *p, long n, double *t_out)
{
    double t0 = bench_now(), acc = 0.0;
    long i;
    for (i = 0; i < n; i++) {
        cc_contact k;
        int r;
        if (m == M_ROLL)
            r = cc_sweep_rolling(&p[i].a, p[i].da, &p[i].b, p[i].db, p[i].t_max, &k);
        else if (m == M_SWEEP)
            r = cc_sweep(&p[i].a, &p[i].b, p[i].t_max, &k);
        else
            r = tb_sweep_rolling(&p[i].a, p[i].da, &p[i].b, p[i].db, p[i].t_max, &k);
        acc += r == CC_HIT ? k.t : 0.0;
        if (t_out)
            t_out[i] = r == CC_HIT ? k.t : r == CC_OVERLAP ? 0.0 : HUGE_VAL;
    }
    sink = acc;
    return (bench_now() - t0) / (double)n * 1e9;
}

static void timing(const char *path, int rounds)
{
    static const char *const names[M_COUNT] = {"cc_sweep_rolling", "cc_sweep (same pairs, no friction)",
                                               "textbook quartic (Ferrari)"};
    FILE *f = fopen(path, "rb");
    pair *p;
    double *ns[M_COUNT], *t_ours, ratio_sweep[64], ratio_tb[64];
    long n = 0, cap = 1024, i, hits = 0;
    int m, k;
    char out[1024];
    if (f == NULL) {
        perror(path);
        exit(2);
    }
    p = bench_alloc(sizeof *p * (size_t)cap);
    for (;;) {
        double x[14];
        if (fread(x, sizeof x, 1, f) != 1)
            break;
        if (n == cap) {
            pair *q = bench_alloc(sizeof *p * (size_t)cap * 2);
            memcpy(q, p, sizeof *p * (size_t)n);
            free(p);
            p = q, cap *= 2;
        }
        p[n].a.pos.x = x[1], p[n].a.pos.y = x[2], p[n].a.vel.x = x[3], p[n].a.vel.y = x[4], p[n].a.radius = x[5];
        p[n].b.pos.x = x[6], p[n].b.pos.y = x[7], p[n].b.vel.x = x[8], p[n].b.vel.y = x[9], p[n].b.radius = x[10];
        p[n].a.mass = p[n].b.mass = 1.0;
        p[n].da = x[11], p[n].db = x[12], p[n].t_max = x[13];
        n++;
    }
    fclose(f);
    if (rounds > 64)
        rounds = 64;
    t_ours = bench_alloc(sizeof(double) * (size_t)n);
    for (m = 0; m < M_COUNT; m++)
        ns[m] = bench_alloc(sizeof(double) * (size_t)rounds);
    (void)run(M_ROLL, p, n, t_ours); /* warm-up, and our answers */
    for (i = 0; i < n; i++)
        hits += t_ours[i] < HUGE_VAL;
    for (k = 0; k < rounds; k++) {
        for (m = 0; m < M_COUNT; m++) { /* rotating order within the round */
            int mm = (m + k) % M_COUNT;
            ns[mm][k] = run(mm, p, n, NULL);
        }
        ratio_sweep[k] = ns[M_ROLL][k] / ns[M_SWEEP][k];
        ratio_tb[k] = ns[M_ROLL][k] / ns[M_TEXTBOOK][k];
    }
    printf("%ld pairs (%ld hits), %d rounds; ns per pair: median (min - max)\n", n, hits, rounds);
    for (m = 0; m < M_COUNT; m++) {
        double lo, hi;
        bench_range(ns[m], (size_t)rounds, &lo, &hi);
        printf("  %-36s %8.1f  (%.1f - %.1f)\n", names[m], bench_median(ns[m], (size_t)rounds), lo, hi);
    }
    printf("  cc_sweep_rolling / cc_sweep: %.2f (median of per-round ratios)\n", bench_median(ratio_sweep, (size_t)rounds));
    printf("  cc_sweep_rolling / textbook quartic: %.2f\n", bench_median(ratio_tb, (size_t)rounds));
    printf("csv ns_per_pair cc_sweep_rolling %.6g\n", bench_median(ns[M_ROLL], (size_t)rounds));
    bench_figure("rolling_pair_over_sweep", bench_median(ratio_sweep, (size_t)rounds));
    snprintf(out, sizeof out, "%s.ours", path);
    f = fopen(out, "wb");
    if (f) {
        fwrite(t_ours, sizeof(double), (size_t)n, f);
        fclose(f);
    }
    for (m = 0; m < M_COUNT; m++)
        free(ns[m]);
    free(t_ours);
    free(p); /* (the ASan run's leak check) */
}

int main(int argc, char **argv)
{
    if (argc >= 4 && !strcmp(argv[1], "dump")) {
        uint64_t seed = 12;
        if (argc >= 6 && !strcmp(argv[4], "--seed"))
            seed = strtoull(argv[5], NULL, 0);
        dump(strtol(argv[2], NULL, 0), argv[3], seed);
        return 0;
    }
    if (argc >= 4 && !strcmp(argv[1], "run")) { /* dump, then time one round (the ctest's tiny run) */
        dump(strtol(argv[2], NULL, 0), argv[3], 12);
        timing(argv[3], 1);
        return 0;
    }
    if (argc >= 3 && !strcmp(argv[1], "time")) {
        int rounds = argc >= 5 && !strcmp(argv[3], "--rounds") ? atoi(argv[4]) : 9;
        timing(argv[2], rounds > 0 ? rounds : 9);
        return 0;
    }
    fprintf(stderr, "usage: %s dump N FILE [--seed S] | time FILE [--rounds R] | run N FILE\n", argv[0]);
    return 2;
}
