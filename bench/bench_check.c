/* The step checker of bench_check.h: sweep and prune along x over each circle's swept box, then
 * the exact pair tests of this library (cc_sweep, cc_sweep_segment) on the survivors. */
#include "bench_check.h"
#include "bench_util.h"

void bench_check_init(bench_check *k, int n)
{
    memset(k, 0, sizeof *k);
    k->n = n;
    k->order = bench_alloc((size_t)n * sizeof *k->order);
    k->flag = bench_alloc((size_t)n * sizeof *k->flag);
    k->key = bench_alloc((size_t)n * sizeof *k->key);
}

void bench_check_free(bench_check *k)
{
    free(k->order);
    free(k->flag);
    free(k->key);
}

static const double *g_key; /* qsort has no context argument in C99 */
static int by_key(const void *a, const void *b)
{
    double x = g_key[*(const int *)a], y = g_key[*(const int *)b];
    return (x > y) - (x < y);
}

static int same_velocity(const cc_circle *a, const cc_circle *b)
{
    return a->vel.x == b->vel.x && a->vel.y == b->vel.y;
}

/* swept box of a circle over [0, dt] from its pre-step state */
static void swept_box(const cc_circle *c, double dt, double *x0, double *x1, double *y0, double *y1)
{
    double ex = c->pos.x + c->vel.x * dt, ey = c->pos.y + c->vel.y * dt;
    *x0 = (c->pos.x < ex ? c->pos.x : ex) - c->radius;
    *x1 = (c->pos.x < ex ? ex : c->pos.x) + c->radius;
    *y0 = (c->pos.y < ey ? c->pos.y : ey) - c->radius;
    *y1 = (c->pos.y < ey ? ey : c->pos.y) + c->radius;
}

void bench_check_step(bench_check *k, const bench_scene *s, const cc_circle *pre, const cc_circle *post, double dt)
{
    int n = k->n, i, w;
    /* a contact exactly at the step's end may be resolved at the start of the next step */
    double horizon = dt * (1.0 - 1e-9);

    /* tunnelling: pre-step motion, bodies the step did not touch */
    for (i = 0; i < n; i++) {
        double x0, x1, y0, y1;
        swept_box(&pre[i], dt, &x0, &x1, &y0, &y1);
        k->key[i] = x0;
        k->order[i] = i;
    }
    g_key = k->key;
    qsort(k->order, (size_t)n, sizeof *k->order, by_key);
    for (i = 0; i < n; i++) {
        int a = k->order[i], j;
        double ax0, ax1, ay0, ay1;
        if (!same_velocity(&pre[a], &post[a]))
            continue;
        swept_box(&pre[a], dt, &ax0, &ax1, &ay0, &ay1);
        for (j = i + 1; j < n && k->key[k->order[j]] <= ax1; j++) {
            int b = k->order[j];
            double bx0, bx1, by0, by1;
            cc_contact c;
            if (!same_velocity(&pre[b], &post[b]))
                continue;
            swept_box(&pre[b], dt, &bx0, &bx1, &by0, &by1);
            if (by0 > ay1 || ay0 > by1)
                continue;
            if (isinf(pre[a].mass) && isinf(pre[b].mass))
                continue;
            /* passed through: the pre-step motion meets within the step, yet they end apart */
            if (cc_sweep(&pre[a], &pre[b], horizon, &c) == CC_HIT && cc_detect_static(&post[a], &post[b], NULL) == CC_MISS)
                k->tunnel_circle++;
        }
        for (w = 0; w < s->n_walls; w++) {
            cc_contact c;
            if (isinf(pre[a].mass))
                continue;
            if (cc_sweep_segment(&pre[a], &s->walls[w], horizon, &c) == CC_HIT &&
                cc_sweep_segment(&post[a], &s->walls[w], 0.0, &c) != CC_OVERLAP)
                k->tunnel_wall++;
        }
    }

    /* escapes and overlaps after the step */
    for (i = 0; i < n; i++) {
        const cc_circle *c = &post[i];
        if (!k->flag[i] && (c->pos.x < s->x0 || c->pos.x > s->x1 || c->pos.y < s->y0 || c->pos.y > s->y1)) {
            k->flag[i] = 1;
            k->escaped++;
        }
        k->key[i] = c->pos.x - c->radius;
        k->order[i] = i;
        for (w = 0; w < s->n_walls; w++) {
            cc_vec2 q = cc_closest_point_on_segment(c->pos, &s->walls[w]);
            double d = hypot(q.x - c->pos.x, q.y - c->pos.y);
            if ((c->radius - d) / s->r_typ > k->max_overlap)
                k->max_overlap = (c->radius - d) / s->r_typ;
        }
    }
    qsort(k->order, (size_t)n, sizeof *k->order, by_key);
    for (i = 0; i < n; i++) {
        int a = k->order[i], j;
        double ax1 = post[a].pos.x + post[a].radius;
        for (j = i + 1; j < n && k->key[k->order[j]] <= ax1; j++) {
            int b = k->order[j];
            double R = post[a].radius + post[b].radius;
            double d = hypot(post[b].pos.x - post[a].pos.x, post[b].pos.y - post[a].pos.y);
            if ((R - d) / s->r_typ > k->max_overlap)
                k->max_overlap = (R - d) / s->r_typ;
        }
    }
}
