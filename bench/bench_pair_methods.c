/* The pair benchmark's methods from this library (cc_sweep, cc_sweepf, cc_sweep_many) and the
 * list of every method this build has; the peers live in bench_pair_<peer>.c. */
#include "bench_pair_methods.h"
#include "bench_util.h"

/* Inputs, chosen so that about half the pairs hit within t_max = 1 and none overlap at t = 0
 * (an overlap short-cuts every method and would hide the cost of the sweep). Units are metres
 * and seconds at everyday sizes so that Box2D (float, 5 mm linear slop) is on home ground. */
void bench_make_pairs(size_t n, uint64_t seed, cc_circle *a, cc_circle *b)
{
    bench_rng rng;
    size_t i;
    rng.s = seed;
    for (i = 0; i < n; i++) {
        double ra = bench_uniform(&rng, 0.05, 0.5), rb = bench_uniform(&rng, 0.05, 0.5);
        double ang = bench_uniform(&rng, 0.0, 6.283185307179586);
        double dist = (ra + rb) * 1.01 + bench_uniform(&rng, 0.0, 3.0);
        a[i].pos.x = bench_uniform(&rng, -50.0, 50.0);
        a[i].pos.y = bench_uniform(&rng, -50.0, 50.0);
        b[i].pos.x = a[i].pos.x + dist * cos(ang);
        b[i].pos.y = a[i].pos.y + dist * sin(ang);
        a[i].vel.x = bench_uniform(&rng, -4.0, 4.0);
        a[i].vel.y = bench_uniform(&rng, -4.0, 4.0);
        /* b heads roughly back towards a so that hits are common but not certain */
        b[i].vel.x = -2.0 * cos(ang) + bench_uniform(&rng, -4.0, 4.0);
        b[i].vel.y = -2.0 * sin(ang) + bench_uniform(&rng, -4.0, 4.0);
        a[i].radius = ra;
        b[i].radius = rb;
        a[i].mass = b[i].mass = 1.0;
    }
}

void bench_pair_data_init(bench_pair_data *d, size_t n)
{
    int k;
    d->n = n;
    d->t_max = 1.0;
    d->a = bench_alloc(n * sizeof *d->a);
    d->b = bench_alloc(n * sizeof *d->b);
    d->af = bench_alloc(n * sizeof *d->af);
    d->bf = bench_alloc(n * sizeof *d->bf);
    for (k = 0; k < 10; k++)
        d->col[k] = bench_alloc(n * sizeof(double));
}

void bench_pair_data_free(bench_pair_data *d)
{
    int k;
    free(d->a);
    free(d->b);
    free(d->af);
    free(d->bf);
    for (k = 0; k < 10; k++)
        free(d->col[k]);
}

static cc_circlef to_float(const cc_circle *c)
{
    cc_circlef f;
    f.pos.x = (float)c->pos.x;
    f.pos.y = (float)c->pos.y;
    f.vel.x = (float)c->vel.x;
    f.vel.y = (float)c->vel.y;
    f.radius = (float)c->radius;
    f.mass = (float)c->mass;
    return f;
}

void bench_pair_data_derive(const bench_pair_data *d)
{
    size_t i;
    bench_pair_data *w = (bench_pair_data *)d;
    for (i = 0; i < d->n; i++) {
        const cc_circle *c[2];
        int s;
        c[0] = &d->a[i];
        c[1] = &d->b[i];
        w->af[i] = to_float(c[0]);
        w->bf[i] = to_float(c[1]);
        for (s = 0; s < 2; s++) {
            d->col[5 * s + 0][i] = c[s]->pos.x;
            d->col[5 * s + 1][i] = c[s]->pos.y;
            d->col[5 * s + 2][i] = c[s]->vel.x;
            d->col[5 * s + 3][i] = c[s]->vel.y;
            d->col[5 * s + 4][i] = c[s]->radius;
        }
    }
    w->soa_a.px = d->col[0];
    w->soa_a.py = d->col[1];
    w->soa_a.vx = d->col[2];
    w->soa_a.vy = d->col[3];
    w->soa_a.radius = d->col[4];
    w->soa_b.px = d->col[5];
    w->soa_b.py = d->col[6];
    w->soa_b.vx = d->col[7];
    w->soa_b.vy = d->col[8];
    w->soa_b.radius = d->col[9];
}

static void run_cc_sweep(const bench_pair_data *d, size_t lo, size_t hi, double *t, int *code)
{
    size_t i;
    for (i = lo; i < hi; i++) {
        cc_contact c;
        int r = cc_sweep(&d->a[i], &d->b[i], d->t_max, &c);
        t[i] = r == CC_HIT ? c.t : INFINITY;
        code[i] = r;
    }
}

static void run_cc_sweepf(const bench_pair_data *d, size_t lo, size_t hi, double *t, int *code)
{
    size_t i;
    for (i = lo; i < hi; i++) {
        cc_contactf c;
        int r = cc_sweepf(&d->af[i], &d->bf[i], (float)d->t_max, &c);
        t[i] = r == CC_HIT ? (double)c.t : INFINITY;
        code[i] = r;
    }
}

static void run_cc_sweep_many(const bench_pair_data *d, size_t lo, size_t hi, double *t, int *code)
{
    cc_circle_soa a = d->soa_a, b = d->soa_b;
    a.px += lo, a.py += lo, a.vx += lo, a.vy += lo, a.radius += lo;
    b.px += lo, b.py += lo, b.vx += lo, b.vy += lo, b.radius += lo;
    if (cc_sweep_many(hi - lo, &a, &b, d->t_max, t + lo, code + lo) < 0) {
        fprintf(stderr, "bench_pair: cc_sweep_many rejected valid input\n");
        exit(1);
    }
}

#ifdef CC_BENCH_HAVE_TEXTBOOK
void bench_run_textbook(const bench_pair_data *d, size_t lo, size_t hi, double *t, int *code);
void bench_run_textbookf(const bench_pair_data *d, size_t lo, size_t hi, double *t, int *code);
#endif
#ifdef CC_BENCH_HAVE_BOX2D
void bench_run_box2d(const bench_pair_data *d, size_t lo, size_t hi, double *t, int *code);
#endif

static bench_method method(const char *name, bench_run_fn fn, int single, int compare, const char *note)
{
    bench_method m;
    m.name = name;
    m.run = fn;
    m.single = single;
    m.compare = compare;
    m.note = note;
    m.t = NULL;
    m.code = NULL;
    return m;
}

int bench_methods(bench_method *out, size_t pairs)
{
    int n = 0, k;
    out[n++] = method("cc_sweep", run_cc_sweep, 0, 1, "contact time, point and normal");
    out[n++] = method("cc_sweep_many", run_cc_sweep_many, 0, 1, "columns; time and code only");
    out[n++] = method("cc_sweepf", run_cc_sweepf, 1, 1, "float inputs and arithmetic");
#ifdef CC_BENCH_HAVE_TEXTBOOK
    out[n++] = method("textbook", bench_run_textbook, 0, 1, "absolute frame, (-B - sqrt(B^2 - 4AC)) / 2A");
    out[n++] = method("textbookf", bench_run_textbookf, 1, 1, "the same in float");
#endif
#ifdef CC_BENCH_HAVE_BOX2D
    out[n++] = method("b2TimeOfImpact", bench_run_box2d, 1, 1,
                      "Box2D 3.1, float; aims at distance R - linear slop (5 mm) by design");
#endif
    for (k = 0; k < n; k++) { /* each method writes its own outputs */
        out[k].t = bench_alloc(pairs * sizeof(double));
        out[k].code = bench_alloc(pairs * sizeof(int));
    }
    return n;
}
