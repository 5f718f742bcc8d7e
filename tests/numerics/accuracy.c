/* The accuracy columns (see accuracy.h): every case of a class solved exactly (reference.h),
 * by the library and by the textbook formula, and compared. */
#include "accuracy.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "circlecollide.h"
#include "corpus.h"
#include "reference.h"
#include "textbook.h"

typedef struct acc_work {
    acc_stats *st;
    double *err, *res; /* per timed case, for the medians */
} acc_work;

/* one measured answer: code and t (when CC_HIT) */
static void tally(acc_work *w, const ref_problem *p, const ref_result *exact, int code, double t, double eps,
                  long index)
{
    acc_stats *s = w->st;
    s->cases++;
    if (code == CC_HIT && !(t >= 0.0 && t <= p->x[p->n - 1])) {
        if (s->disagree++ == 0)
            s->first_wrong = index; /* a hit at a time outside [0, t_max] (or NaN) is wrong whatever the answer */
        return;
    }
    if (exact->degenerate) {
        s->degenerate++;
        return;
    }
    if (code != exact->code) {
        if (ref_in_band(p, code, ACC_BAND_ULPS))
            s->in_band++;
        else {
            if (s->disagree++ == 0)
                s->first_wrong = index;
        }
        return;
    }
    if (code == CC_HIT) {
        double e = isinf(exact->cond) ? 0.0 : ref_t_error(exact, t) / (eps * exact->cond);
        if (e > ACC_TARGET_ULPS && ref_t_in_band(p, t, ACC_TARGET_ULPS, ACC_BAND_ULPS)) {
            s->in_band++;
            return;
        }
        w->err[s->timed] = e;
        w->res[s->timed] = ref_residual(p, t);
        if (e > s->max_err) {
            s->max_err = e;
            s->worst = index;
        }
        if (w->res[s->timed] > s->max_res)
            s->max_res = w->res[s->timed];
        if (exact->t_hi > 0.0 && ref_t_error(exact, t) / exact->t_hi > s->max_rel)
            s->max_rel = ref_t_error(exact, t) / exact->t_hi;
        s->timed++;
    }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double median(double *v, long n)
{
    if (n == 0)
        return 0.0;
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

void acc_problem(const corpus_case *c, int is_float, ref_problem *p)
{
    if (is_float) {
        corpus_casef f;
        corpus_to_float(c, &f);
        if (f.rolling && f.is_segment)
            ref_roll_segmentf(p, &f.a, f.decel_a, &f.s, f.t_max);
        else if (f.rolling)
            ref_roll_circlesf(p, &f.a, f.decel_a, &f.b, f.decel_b, f.t_max);
        else if (f.is_segment)
            ref_segmentf(p, &f.a, &f.s, f.t_max);
        else
            ref_circlesf(p, &f.a, &f.b, f.t_max);
    } else {
        if (c->rolling && c->is_segment)
            ref_roll_segment(p, &c->a, c->decel_a, &c->s, c->t_max);
        else if (c->rolling)
            ref_roll_circles(p, &c->a, c->decel_a, &c->b, c->decel_b, c->t_max);
        else if (c->is_segment)
            ref_segment(p, &c->a, &c->s, c->t_max);
        else
            ref_circles(p, &c->a, &c->b, c->t_max);
    }
}

int acc_solve(const corpus_case *c, int is_float, int textbook, int *code, double *t)
{
    if (is_float) {
        corpus_casef f;
        cc_contactf k;
        corpus_to_float(c, &f);
        k.t = -1.0f;
        if (f.rolling && textbook)
            return 0;
        if (f.rolling && f.is_segment)
            *code = cc_sweep_segment_rollingf(&f.a, f.decel_a, &f.s, f.t_max, &k);
        else if (f.rolling)
            *code = cc_sweep_rollingf(&f.a, f.decel_a, &f.b, f.decel_b, f.t_max, &k);
        else if (f.is_segment)
            *code = textbook ? tb_sweep_segmentf(&f.a, &f.s, f.t_max, &k) : cc_sweep_segmentf(&f.a, &f.s, f.t_max, &k);
        else
            *code = textbook ? tb_sweepf(&f.a, &f.b, f.t_max, &k) : cc_sweepf(&f.a, &f.b, f.t_max, &k);
        *t = k.t;
    } else {
        cc_contact k;
        k.t = -1.0;
        if (c->rolling && c->is_segment && textbook)
            return 0;
        if (c->rolling && c->is_segment)
            *code = cc_sweep_segment_rolling(&c->a, c->decel_a, &c->s, c->t_max, &k);
        else if (c->rolling)
            *code = textbook ? tb_sweep_rolling(&c->a, c->decel_a, &c->b, c->decel_b, c->t_max, &k)
                             : cc_sweep_rolling(&c->a, c->decel_a, &c->b, c->decel_b, c->t_max, &k);
        else if (c->is_segment)
            *code = textbook ? tb_sweep_segment(&c->a, &c->s, c->t_max, &k) : cc_sweep_segment(&c->a, &c->s, c->t_max, &k);
        else
            *code = textbook ? tb_sweep(&c->a, &c->b, c->t_max, &k) : cc_sweep(&c->a, &c->b, c->t_max, &k);
        *t = k.t;
    }
    return 1;
}

void acc_measure(uint64_t seed, int cls, uint32_t n, int is_float, int with_textbook, acc_row *row)
{
    acc_work w[2];
    uint32_t i;
    int m;
    double eps = is_float ? FLT_EPSILON : DBL_EPSILON;
    memset(row, 0, sizeof *row);
    row->ours.worst = row->textbook.worst = row->ours.first_wrong = row->textbook.first_wrong = -1;
    w[0].st = &row->ours, w[1].st = &row->textbook;
    for (m = 0; m < 2; m++) {
        w[m].err = malloc(sizeof(double) * (n + 1));
        w[m].res = malloc(sizeof(double) * (n + 1));
    }
    for (i = 0; i < n; i++) {
        corpus_case c;
        ref_problem p;
        ref_result exact;
        corpus_make(seed, cls, i, is_float, &c);
        for (m = 0; m < (with_textbook ? 2 : 1); m++) {
            int code;
            double t;
            if (m == 0)
                acc_problem(&c, is_float, &p);
            if (!acc_solve(&c, is_float, m, &code, &t))
                continue; /* no textbook method for this case */
            if (m == 0)
                (void)ref_solve(&p, &exact);
            tally(&w[m], &p, &exact, code, t, eps, (long)i);
        }
    }
    for (m = 0; m < 2; m++) {
        w[m].st->med_err = median(w[m].err, w[m].st->timed);
        w[m].st->med_res = median(w[m].res, w[m].st->timed);
        free(w[m].err);
        free(w[m].res);
    }
}
