/* Prints the accuracy table of docs/NUMERICS.md: per corpus class and precision, the library's
 * sweeps and the textbook formula against the exact reference.
 *
 *   numerics_report [--seed S] [--count N] [--double | --float] [--no-textbook] [--check]
 *
 *   numerics_report --show CLASS INDEX [--seed S] [--float]   prints one case in full
 *
 * --check exits 1 when the library misses a target (a disagreement outside the rounding band,
 * or a t error above 4 condition-scaled ulps) in some class. */
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
    corpus_casef f;
    ref_problem p;
    ref_result r;
    int i, code[2];
    double t[2];
    corpus_make(seed, cls, (uint32_t)index, is_float, &c);
    corpus_to_float(&c, &f);
    if (is_float) {
        cc_contactf k[2];
        k[0].t = k[1].t = -1.0f;
        if (f.is_segment) {
            ref_segmentf(&p, &f.a, &f.s, f.t_max);
            code[0] = cc_sweep_segmentf(&f.a, &f.s, f.t_max, &k[0]);
            code[1] = tb_sweep_segmentf(&f.a, &f.s, f.t_max, &k[1]);
        } else {
            ref_circlesf(&p, &f.a, &f.b, f.t_max);
            code[0] = cc_sweepf(&f.a, &f.b, f.t_max, &k[0]);
            code[1] = tb_sweepf(&f.a, &f.b, f.t_max, &k[1]);
        }
        t[0] = k[0].t, t[1] = k[1].t;
    } else {
        cc_contact k[2];
        k[0].t = k[1].t = -1.0;
        if (c.is_segment) {
            ref_segment(&p, &c.a, &c.s, c.t_max);
            code[0] = cc_sweep_segment(&c.a, &c.s, c.t_max, &k[0]);
            code[1] = tb_sweep_segment(&c.a, &c.s, c.t_max, &k[1]);
        } else {
            ref_circles(&p, &c.a, &c.b, c.t_max);
            code[0] = cc_sweep(&c.a, &c.b, c.t_max, &k[0]);
            code[1] = tb_sweep(&c.a, &c.b, c.t_max, &k[1]);
        }
        t[0] = k[0].t, t[1] = k[1].t;
    }
    printf("%s case %lu (%s), %s\n", corpus_class_name(cls), index, is_float ? "float" : "double",
           p.kind == REF_CIRCLES ? "pa pa va va ra pb pb vb vb rb t_max" : "p p v v r a a b b t_max");
    for (i = 0; i < p.n; i++)
        printf("  x[%d] = %a  (%.17g)\n", i, p.x[i], p.x[i]);
    ref_solve(&p, &r);
    printf("exact: code %d t %.17g%+.3g feature %d cond %.3g normal (%.17g, %.17g)\n", r.code, r.t_hi, r.t_lo,
           r.feature, r.cond, r.normal_x, r.normal_y);
    for (i = 0; i < 2; i++)
        printf("%s: code %d t %.17g err %.3g ulps residual %.3g in band %d\n", i ? "textbook" : "ours", code[i], t[i],
               code[i] == CC_HIT && r.code == CC_HIT ? ref_t_error(&r, t[i]) / ((is_float ? 0x1p-23 : 0x1p-52) * r.cond) : 0.0,
               code[i] == CC_HIT ? ref_residual(&p, t[i]) : 0.0, ref_in_band(&p, code[i], ACC_BAND_ULPS));
}

static void cells(const acc_stats *s)
{
    printf(" %ld (%ld) | %.2f | %.2f | %.1e |", s->disagree, s->in_band, s->max_err, s->med_err, s->max_res);
}

int main(int argc, char **argv)
{
    unsigned long long seed = 20261122;
    unsigned long count = 2000;
    int precisions = 3, textbook = 1, check = 0, i, cls, prec, failed = 0, show_cls = -1;
    unsigned long show_index = 0;
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--seed") && i + 1 < argc)
            seed = strtoull(argv[++i], NULL, 0);
        else if (!strcmp(argv[i], "--count") && i + 1 < argc)
            count = strtoul(argv[++i], NULL, 0);
        else if (!strcmp(argv[i], "--double"))
            precisions = 1;
        else if (!strcmp(argv[i], "--float"))
            precisions = 2;
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
    if (show_cls >= 0) {
        show(seed, show_cls, show_index, precisions == 2);
        return 0;
    }
    printf("seed %llu, %lu cases per class; band = exact answer within %d ulps of every input\n\n", seed, count,
           ACC_BAND_ULPS);
    printf("| class | prec | hits timed | ours: wrong (in band) | max err | median err | max residual |"
           " textbook: wrong (in band) | max err | median err | max residual |\n");
    printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (prec = 0; prec < 2; prec++) {
        if (!(precisions & (1 << prec)))
            continue;
        for (cls = 0; cls < CORPUS_CLASSES; cls++) {
            acc_row row;
            acc_measure(seed, cls, (uint32_t)count, prec, textbook, &row);
            printf("| %s | %s | %ld |", corpus_class_name(cls), prec ? "float" : "double", row.ours.timed);
            cells(&row.ours);
            if (textbook)
                cells(&row.textbook);
            else
                printf(" | | | |");
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
    printf("\nwrong: answer differs from the exact one outside the band (in band: inside it); err: |t - t*| in units "
           "of eps * cond, cond = (|dp| + |dv| t + R) / closing speed; residual: relative to R.\n");
    return check && failed ? 1 : 0;
}
