/* Pair-level benchmark: time of impact of two moving circles, the same N random pairs for every
 * method (cc_sweep, cc_sweepf, cc_sweep_many, the textbook formula, Box2D's b2TimeOfImpact),
 * ns per pair as the median of several rounds, and accuracy against a high-precision reference.
 *
 * Usage: bench_pair [--pairs N] [--rounds R] [--csv FILE] [--only METHOD] [--no-reference]
 *
 * Honest loops: every method reads the same inputs from memory and writes its time and result
 * code to arrays that are read back afterwards (accuracy columns and a checksum), so nothing
 * can be optimised away; the methods live in other translation units (no inlining into the
 * loop). Rounds rotate the order of the methods so that a noisy neighbour hurts all alike. */
#include "bench_pair_methods.h"
#include "bench_util.h"

#include <float.h>

/* |t - t_ref| statistics and hit/miss disagreements of one method against the reference. */
typedef struct accuracy {
    long disagreements, both_hit;
    double err_median, err_max;
} accuracy;

static accuracy measure_accuracy(size_t n, const double *t, const int *code, const double *t_ref, const double *t_lo,
                                 const int *code_ref)
{
    accuracy acc;
    double *err = bench_alloc(n * sizeof *err);
    size_t i, m = 0;
    acc.disagreements = 0;
    for (i = 0; i < n; i++) {
        int hit = code[i] == CC_HIT, hit_ref = code_ref[i] == CC_HIT;
        if (hit != hit_ref)
            acc.disagreements++;
        else if (hit)
            err[m++] = fabs((t[i] - t_ref[i]) - t_lo[i]); /* t - t_ref exact when close (Sterbenz) */
    }
    acc.both_hit = (long)m;
    bench_range(err, m, &acc.err_median, &acc.err_max);
    acc.err_median = bench_median(err, m);
    free(err);
    return acc;
}

int main(int argc, char **argv)
{
    size_t n = 1000000, i;
    int rounds = 7, r, k, use_reference = 1;
    const char *csv_path = NULL, *only = NULL;
    bench_pair_data d;
    bench_method methods[BENCH_MAX_METHODS];
    int n_methods, n_all;
    double *times[BENCH_MAX_METHODS], *times_hot[BENCH_MAX_METHODS], *hot_raw[BENCH_MAX_METHODS];
    double *t_ref = NULL, *t_reff = NULL, *lo_ref = NULL, *lo_reff = NULL;
    int *code_ref = NULL, *code_reff = NULL;
    double ns_cc = NAN, ns_cc_hot = NAN;
    FILE *csv = NULL;

    for (k = 1; k < argc; k++) {
        if (!strcmp(argv[k], "--pairs") && k + 1 < argc)
            n = (size_t)strtod(argv[++k], NULL);
        else if (!strcmp(argv[k], "--rounds") && k + 1 < argc)
            rounds = atoi(argv[++k]);
        else if (!strcmp(argv[k], "--csv") && k + 1 < argc)
            csv_path = argv[++k];
        else if (!strcmp(argv[k], "--only") && k + 1 < argc)
            only = argv[++k]; /* one method, for profiling */
        else if (!strcmp(argv[k], "--no-reference"))
            use_reference = 0;
        else {
            fprintf(stderr, "usage: %s [--pairs N] [--rounds R] [--csv FILE] [--only METHOD] [--no-reference]\n", argv[0]);
            return 2;
        }
    }
    if (n < 1 || rounds < 1) {
        fprintf(stderr, "bench_pair: need --pairs >= 1 and --rounds >= 1\n");
        return 2;
    }

    bench_pair_data_init(&d, n);
    bench_make_pairs(n, 20261122u, d.a, d.b);
    bench_pair_data_derive(&d);
    n_all = n_methods = bench_methods(methods, n);
    if (only != NULL) {
        bench_method keep;
        for (k = 0; k < n_methods && strcmp(methods[k].name, only); k++)
            ;
        if (k == n_methods) {
            fprintf(stderr, "bench_pair: no method %s in this build\n", only);
            return 2;
        }
        keep = methods[k]; /* first, the others kept behind it for freeing */
        methods[k] = methods[0];
        methods[0] = keep;
        n_methods = 1;
    }

    for (k = 0; k < n_methods; k++) {
        times[k] = bench_alloc((size_t)rounds * sizeof(double));
        times_hot[k] = bench_alloc((size_t)rounds * sizeof(double));
    }
    /* one untimed pass of everything: page faults and lazy binding out of the way */
    for (k = 0; k < n_methods; k++)
        methods[k].run(&d, 0, n, methods[k].t, methods[k].code);

    for (r = 0; r < rounds; r++) {
        int j;
        for (j = 0; j < n_methods; j++) {
            bench_method *m = &methods[(j + r) % n_methods];
            double t0, hot = 0.0;
            size_t lo;
            /* streamed: every pair once, inputs from main memory as in a batch query */
            t0 = bench_now();
            m->run(&d, 0, n, m->t, m->code);
            times[(j + r) % n_methods][r] = (bench_now() - t0) / (double)n * 1e9;
            /* cache-resident: blocks of pairs swept twice, the second pass timed; the compute
             * cost alone, as when a world sweeps pairs whose circles it has just touched */
            for (lo = 0; lo < n; lo += BENCH_BLOCK) {
                size_t hi = lo + BENCH_BLOCK < n ? lo + BENCH_BLOCK : n;
                m->run(&d, lo, hi, m->t, m->code);
                t0 = bench_now();
                m->run(&d, lo, hi, m->t, m->code);
                hot += bench_now() - t0;
            }
            times_hot[(j + r) % n_methods][r] = hot / (double)n * 1e9;
        }
    }

    for (k = 0; k < n_methods; k++) {
        hot_raw[k] = bench_alloc((size_t)rounds * sizeof(double));
        memcpy(hot_raw[k], times_hot[k], (size_t)rounds * sizeof(double));
    }
    if (use_reference) {
        t_ref = bench_alloc(n * sizeof *t_ref);
        code_ref = bench_alloc(n * sizeof *code_ref);
        t_reff = bench_alloc(n * sizeof *t_reff);
        code_reff = bench_alloc(n * sizeof *code_reff);
        lo_ref = bench_alloc(n * sizeof *lo_ref);
        lo_reff = bench_alloc(n * sizeof *lo_reff);
        if (!bench_reference(&d, 0, t_ref, lo_ref, code_ref) || !bench_reference(&d, 1, t_reff, lo_reff, code_reff))
            use_reference = 0;
    }

    if (csv_path != NULL && (csv = fopen(csv_path, "w")) == NULL) {
        fprintf(stderr, "bench_pair: cannot write %s\n", csv_path);
        return 2;
    }
    if (csv != NULL)
        fprintf(csv, "method,precision,ns_hot_median,ns_hot_min,ns_hot_max,ns_stream_median,ns_stream_min,"
                     "ns_stream_max,hits,disagreements,both_hit,err_median,err_max,checksum,note\n");
    printf("bench_pair: %zu pairs, t_max = %g, %d rounds (median [min, max] ns per pair)\n", n, d.t_max, rounds);
    printf("%-22s %-26s %-26s %8s %8s %10s %10s\n", "method", "cache-resident", "streamed", "hits", "disagr",
           "err med", "err max");
    for (k = 0; k < n_methods; k++) {
        bench_method *m = &methods[k];
        double hot_lo, hot_hi, st_lo, st_hi, hot, st, checksum = 0.0;
        long hits = 0;
        accuracy acc;
        acc.disagreements = -1;
        acc.both_hit = 0;
        acc.err_median = acc.err_max = NAN;
        bench_range(times_hot[k], (size_t)rounds, &hot_lo, &hot_hi);
        bench_range(times[k], (size_t)rounds, &st_lo, &st_hi);
        hot = bench_median(times_hot[k], (size_t)rounds);
        st = bench_median(times[k], (size_t)rounds);
        for (i = 0; i < n; i++) {
            if (m->code[i] == CC_HIT) {
                hits++;
                checksum += m->t[i];
            }
        }
        if (use_reference && m->code != NULL && m->compare)
            acc = m->single ? measure_accuracy(n, m->t, m->code, t_reff, lo_reff, code_reff)
                            : measure_accuracy(n, m->t, m->code, t_ref, lo_ref, code_ref);
        printf("%-22s %7.2f [%6.2f, %6.2f]   %7.2f [%6.2f, %6.2f]   %8ld %8ld %10.3g %10.3g\n", m->name, hot, hot_lo,
               hot_hi, st, st_lo, st_hi, hits, acc.disagreements, acc.err_median, acc.err_max);
        if (csv != NULL)
            fprintf(csv, "%s,%s,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%ld,%ld,%ld,%.6g,%.6g,%.17g,\"%s\"\n", m->name,
                    m->single ? "float" : "double", hot, hot_lo, hot_hi, st, st_lo, st_hi, hits, acc.disagreements,
                    acc.both_hit, acc.err_median, acc.err_max, checksum, m->note);
        if (!strcmp(m->name, "cc_sweep")) {
            ns_cc = hot;
            ns_cc_hot = hot;
            ns_cc = st;
        }
    }
    /* Ratios to cc_sweep: the median over rounds of the per-round ratio, since methods measured
     * within one round are neighbours in time and share the machine's noise. */
    for (k = 0; k < n_methods && only == NULL; k++) {
        double *ratio = bench_alloc((size_t)rounds * sizeof *ratio), q;
        for (r = 0; r < rounds; r++)
            ratio[r] = hot_raw[k][r] / hot_raw[0][r];
        q = bench_median(ratio, (size_t)rounds);
        free(ratio);
        if (!strcmp(methods[k].name, "b2TimeOfImpact"))
            bench_figure("sweep_speedup_vs_box2d", q);
        else if (!strcmp(methods[k].name, "textbook"))
            bench_figure("sweep_cost_vs_textbook", 1.0 / q);
        else if (!strcmp(methods[k].name, "cc_sweep_many"))
            bench_figure("sweep_many_speedup", 1.0 / q);
        else if (!strcmp(methods[k].name, "cc_sweepf"))
            bench_figure("sweepf_speedup", 1.0 / q);
    }
    bench_figure("sweep_ns_per_pair", ns_cc_hot);
    bench_figure("sweep_ns_per_pair_streamed", ns_cc);
    if (!use_reference)
        printf("(no accuracy columns: built without the high-precision reference)\n");
    if (csv != NULL)
        fclose(csv);
    for (k = 0; k < n_methods; k++) {
        free(times[k]);
        free(times_hot[k]);
        free(hot_raw[k]);
    }
    for (k = 0; k < n_all; k++) {
        free(methods[k].t);
        free(methods[k].code);
    }
    free(t_ref);
    free(t_reff);
    free(lo_ref);
    free(lo_reff);
    free(code_ref);
    free(code_reff);
    bench_pair_data_free(&d);
    return 0;
}
