/* Prints the accuracy table of docs/NUMERICS.md: per corpus class and precision, the library's
 * sweeps and the textbook formula against the exact reference.
 *
 *   numerics_report [--seed S] [--count N] [--double | --float] [--straight | --rolling] [--no-textbook] [--check]
 *
 * Two tables: the straight sweeps' classes, then rolling to rest's (cc_sweep_rolling and
 * cc_sweep_segment_rolling against the MPFR reference, the textbook quartic beside them).
 *
 *   numerics_report --show CLASS INDEX [--seed S] [--float]   prints one case in full
 *   numerics_report --dump-rolling FILE [--count N]   the rolling pair cases, for bench/pooltool_rolling.py
 *   numerics_report --judge PAIRS TIMES   another method's answers on such pairs against the reference
 *
 * --check exits 1 when the library misses a target (a disagreement outside the rounding band,
 * or a t error above 4 condition-scaled ulps) in some class. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accuracy.h"
#include "corpus.h"
#include "reference.h"
#include "textbook.h"


/* one case: inputs (hex floats, exact), the exact answer, ours and the textbook's */
static void show(unsigned long long seed, int cls, unsigned long index, int is_float)
{
    corpus_case c;
    ref_problem p;
    ref_result r;
    int i, code[2];
    double t[2];
    corpus_make(seed, cls, (uint32_t)index, is_float, &c);
    acc_problem(&c, is_float, &p);
    for (i = 0; i < 2; i++) {
        code[i] = -99, t[i] = -1.0;
        if (!acc_solve(&c, is_float, i, &code[i], &t[i]))
            code[i] = -99;
    }
    printf("%s case %lu (%s), %s\n", corpus_class_name(cls), index, is_float ? "float" : "double",
           p.kind == REF_CIRCLES        ? "pa pa va va ra pb pb vb vb rb t_max"
           : p.kind == REF_SEGMENT      ? "p p v v r a a b b t_max"
           : p.kind == REF_ROLL_CIRCLES ? "pa pa va va ra pb pb vb vb rb decel_a decel_b t_max"
                                        : "p p v v r a a b b decel t_max");
    for (i = 0; i < p.n; i++)
        printf("  x[%d] = %a  (%.17g)\n", i, p.x[i], p.x[i]);
    ref_solve(&p, &r);
    printf("exact: code %d t %.17g%+.3g feature %d cond %.3g normal (%.17g, %.17g) degenerate %d\n", r.code, r.t_hi,
           r.t_lo, r.feature, r.cond, r.normal_x, r.normal_y, r.degenerate);
    for (i = 0; i < 2; i++)
        if (code[i] != -99)
            printf("%s: code %d t %.17g err %.3g ulps residual %.3g in band %d\n", i ? "textbook" : "ours", code[i], t[i],
               code[i] == CC_HIT && r.code == CC_HIT ? ref_t_error(&r, t[i]) / ((is_float ? 0x1p-23 : 0x1p-52) * r.cond) : 0.0,
               code[i] == CC_HIT ? ref_residual(&p, t[i]) : 0.0, ref_in_band(&p, code[i], ACC_BAND_ULPS));
}

/* --dump-rolling FILE: the double rolling pair classes' cases (not the walls), 14 doubles each
 * (class, pa, va, ra, pb, vb, rb, decel_a, decel_b, t_max: bench/bench_pair_rolling.c's format),
 * for bench/pooltool_rolling.py */
static int dump_rolling(const char *path, unsigned long long seed, unsigned long count)
{
    FILE *f = fopen(path, "wb");
    int cls;
    unsigned long i;
    if (f == NULL)
        return 2;
    for (cls = CORPUS_ROLL_FIRST; cls < CORPUS_CLASSES; cls++)
        for (i = 0; i < count; i++) {
            corpus_case c;
            double x[14];
            corpus_make(seed, cls, (uint32_t)i, 0, &c);
            if (c.is_segment)
                continue;
            x[0] = cls, x[1] = c.a.pos.x, x[2] = c.a.pos.y, x[3] = c.a.vel.x, x[4] = c.a.vel.y, x[5] = c.a.radius;
            x[6] = c.b.pos.x, x[7] = c.b.pos.y, x[8] = c.b.vel.x, x[9] = c.b.vel.y, x[10] = c.b.radius;
            x[11] = c.decel_a, x[12] = c.decel_b, x[13] = c.t_max;
            fwrite(x, sizeof x, 1, f);
        }
    fclose(f);
    return 0;
}

/* --judge PAIRS TIMES: another method's answers (8 bytes per pair: t, +inf for a miss, 0 for an
 * overlap, NaN when it failed: counted wrong) against the reference, per class: wrong (outside the band), in band, t errors */
static int judge(const char *pairs, const char *times)
{
    FILE *fp = fopen(pairs, "rb"), *ft = fopen(times, "rb");
    enum { NC = CORPUS_CLASSES + 1 };
    long cases[NC] = {0}, wrong[NC] = {0}, band[NC] = {0}, timed[NC] = {0}, ties[NC] = {0};
    double max_err[NC] = {0}, max_rel[NC] = {0};
    int k;
    if (fp == NULL || ft == NULL)
        return 2;
    for (;;) {
        double x[14], t;
        ref_problem p;
        ref_result r;
        cc_circle a, b;
        int code, cls;
        if (fread(x, sizeof x, 1, fp) != 1 || fread(&t, sizeof t, 1, ft) != 1)
            break;
        cls = x[0] < 0 ? CORPUS_CLASSES : (int)x[0];
        a.pos.x = x[1], a.pos.y = x[2], a.vel.x = x[3], a.vel.y = x[4], a.radius = x[5], a.mass = 1;
        b.pos.x = x[6], b.pos.y = x[7], b.vel.x = x[8], b.vel.y = x[9], b.radius = x[10], b.mass = 1;
        ref_roll_circles(&p, &a, x[11], &b, x[12], x[13]);
        ref_solve(&p, &r);
        code = t == 0.0 ? (r.code == CC_OVERLAP ? CC_OVERLAP : CC_HIT) : t < HUGE_VAL ? CC_HIT : CC_MISS;
        cases[cls]++;
        if (isnan(t)) { /* the method failed (raised) */
            wrong[cls]++;
            continue;
        }
        if (r.degenerate) {
            ties[cls]++;
            continue;
        }
        if (code != r.code || (code == CC_HIT && !(t >= 0.0 && t <= x[13]))) {
            if (code == CC_HIT && !(t >= 0.0 && t <= x[13]))
                wrong[cls]++;
            else if (ref_in_band(&p, code, ACC_BAND_ULPS))
                band[cls]++;
            else
                wrong[cls]++;
            continue;
        }
        if (code == CC_HIT) {
            double e = isinf(r.cond) ? 0.0 : ref_t_error(&r, t) / (0x1p-52 * r.cond);
            timed[cls]++;
            if (e > max_err[cls])
                max_err[cls] = e;
            if (r.t_hi > 0 && ref_t_error(&r, t) / r.t_hi > max_rel[cls])
                max_rel[cls] = ref_t_error(&r, t) / r.t_hi;
        }
    }
    fclose(fp);
    fclose(ft);
    printf("| class | cases | ties | hits timed | wrong (in band) | max err | max rel. err |\n|---|---|---|---|---|---|---|\n");
    for (k = 0; k < NC; k++)
        if (cases[k] > 0)
            printf("| %s | %ld | %ld | %ld | %ld (%ld) | %.3g | %.1e |\n", k == CORPUS_CLASSES ? "pool pairs" : corpus_class_name(k),
                   cases[k], ties[k], timed[k], wrong[k], band[k], max_err[k], max_rel[k]);
    return 0;
}

static void roll_cells(const acc_stats *s)
{
    printf(" %ld (%ld) | %.2f | %.2f | %.1e | %.1e |", s->disagree, s->in_band, s->max_err, s->med_err, s->max_rel,
           s->max_res);
}

static void cells(const acc_stats *s)
{
    printf(" %ld (%ld) | %.2f | %.2f | %.1e |", s->disagree, s->in_band, s->max_err, s->med_err, s->max_res);
}

int main(int argc, char **argv)
{
    unsigned long long seed = 20261122;
    unsigned long count = 2000;
    int precisions = 3, textbook = 1, check = 0, i, cls, prec, failed = 0, show_cls = -1, tables = 3, table;
    unsigned long show_index = 0;
    const char *dump_path = NULL, *judge_pairs = NULL, *judge_times = NULL;
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--seed") && i + 1 < argc)
            seed = strtoull(argv[++i], NULL, 0);
        else if (!strcmp(argv[i], "--count") && i + 1 < argc)
            count = strtoul(argv[++i], NULL, 0);
        else if (!strcmp(argv[i], "--double"))
            precisions = 1;
        else if (!strcmp(argv[i], "--float"))
            precisions = 2;
        else if (!strcmp(argv[i], "--dump-rolling") && i + 1 < argc)
            dump_path = argv[++i];
        else if (!strcmp(argv[i], "--judge") && i + 2 < argc) {
            judge_pairs = argv[++i];
            judge_times = argv[++i];
        } else if (!strcmp(argv[i], "--straight"))
            tables = 1;
        else if (!strcmp(argv[i], "--rolling"))
            tables = 2;
        else if (!strcmp(argv[i], "--no-textbook"))
            textbook = 0;
        else if (!strcmp(argv[i], "--show") && i + 2 < argc) {
            show_cls = atoi(argv[++i]);
            show_index = strtoul(argv[++i], NULL, 0);
        } else if (!strcmp(argv[i], "--check"))
            check = 1;
        else {
            fprintf(stderr, "usage: %s [--seed S] [--count N] [--double|--float] [--no-textbook] [--check]\n", argv[0]);
            return 2;
        }
    }
    if (dump_path)
        return dump_rolling(dump_path, seed, count);
    if (judge_pairs)
        return judge(judge_pairs, judge_times);
    if (show_cls >= 0) {
        show(seed, show_cls, show_index, precisions == 2);
        return 0;
    }
    printf("seed %llu, %lu cases per class; band = exact answer within %d ulps of every input\n\n", seed, count,
           ACC_BAND_ULPS);
    for (table = 0; table < 2; table++) {
    if (!(tables & (1 << table)))
        continue;
    if (table == 0) {
        printf("| class | prec | hits timed | ours: wrong (in band) | max err | median err | max residual |"
               " textbook: wrong (in band) | max err | median err | max residual |\n");
        printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
    } else {
        printf("\n| class | prec | hits timed | ties | ours: wrong (in band) | max err | median err | max rel. err |"
               " max residual | textbook quartic: wrong (in band) | max err | median err | max rel. err | max residual |\n");
        printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    }
    for (prec = 0; prec < 2; prec++) {
        if (!(precisions & (1 << prec)))
            continue;
        for (cls = table ? CORPUS_ROLL_FIRST : 0; cls < (table ? CORPUS_CLASSES : CORPUS_ROLL_FIRST); cls++) {
            acc_row row;
            acc_measure(seed, cls, (uint32_t)count, prec, textbook, &row);
            if (table == 0) {
                printf("| %s | %s | %ld |", corpus_class_name(cls), prec ? "float" : "double", row.ours.timed);
                cells(&row.ours);
                if (textbook)
                    cells(&row.textbook);
                else
                    printf(" | | | |");
            } else {
                printf("| %s | %s | %ld | %ld |", corpus_class_name(cls), prec ? "float" : "double", row.ours.timed,
                       row.ours.degenerate);
                roll_cells(&row.ours);
                if (textbook && row.textbook.cases > 0)
                    roll_cells(&row.textbook);
                else
                    printf(" - | - | - | - | - |");
            }
            printf("\n");
            fflush(stdout);
            if (row.ours.disagree > 0 || row.ours.max_err > ACC_TARGET_ULPS) {
                failed = 1;
                fprintf(stderr, "target missed: %s %s (class %d), first wrong case %ld, worst t case %ld (seed %llu)\n",
                        corpus_class_name(cls), prec ? "float" : "double", cls, row.ours.first_wrong, row.ours.worst,
                        seed);
            }
        }
    }
    }
    printf("\nwrong: answer differs from the exact one outside the band (in band: inside it); err: |t - t*| in units "
           "of eps * cond, cond = (|dp| + |dv| t + R) / closing speed; residual: relative to R.\n");
    return check && failed ? 1 : 0;
}
