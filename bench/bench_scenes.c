/* The world benchmark's scenes: construction of the gas, pool and air-hockey initial states. */
#include "bench_scenes.h"
#include "bench_util.h"

static void box_walls(bench_scene *s, double x0, double y0, double x1, double y1)
{
    cc_segment w[4];
    int k;
    w[0].a.x = x0, w[0].a.y = y0, w[0].b.x = x1, w[0].b.y = y0;
    w[1].a.x = x1, w[1].a.y = y0, w[1].b.x = x1, w[1].b.y = y1;
    w[2].a.x = x1, w[2].a.y = y1, w[2].b.x = x0, w[2].b.y = y1;
    w[3].a.x = x0, w[3].a.y = y1, w[3].b.x = x0, w[3].b.y = y0;
    for (k = 0; k < 4; k++)
        s->walls[k] = w[k];
    s->n_walls = 4;
    s->x0 = x0, s->y0 = y0, s->x1 = x1, s->y1 = y1;
}

static double gauss(bench_rng *rng)
{
    /* Box-Muller; the 1 - u keeps the logarithm finite */
    double u = bench_uniform(rng, 0.0, 1.0), v = bench_uniform(rng, 0.0, 1.0);
    return sqrt(-2.0 * log(1.0 - u)) * cos(6.283185307179586 * v);
}

void bench_scene_gas(bench_scene *s, int n, double phi, unsigned long long seed)
{
    const double r = 0.5;
    double L = sqrt((double)n * 3.141592653589793 * r * r / phi), a, jitter, mx = 0.0, my = 0.0;
    int rows, cols, sites, i, *order;
    double *sx, *sy;
    bench_rng rng;
    rng.s = seed;
    memset(s, 0, sizeof *s);
    snprintf(s->name, sizeof s->name, "gas phi=%.2f n=%d", phi, n);
    s->n = n;
    s->c = bench_alloc((size_t)n * sizeof *s->c);
    s->r_typ = r;
    box_walls(s, 0.0, 0.0, L, L);

    /* the widest triangular lattice with n sites in [r, L - r]^2 (a hair inside the walls) */
    for (a = L;; a *= 0.999) {
        double span = L - 2.0 * r - 1e-9 * L;
        cols = (int)floor(span / a) + 1;
        rows = (int)floor(span / (a * 0.8660254037844386)) + 1;
        if (cols > 1 && (double)rows * (double)(cols - 1) >= (double)n) /* odd rows lose a site */
            break;
    }
    sx = bench_alloc((size_t)rows * (size_t)cols * sizeof *sx);
    sy = bench_alloc((size_t)rows * (size_t)cols * sizeof *sy);
    order = bench_alloc((size_t)rows * (size_t)cols * sizeof *order);
    sites = 0;
    for (i = 0; i < rows; i++) {
        int j, shift = i % 2;
        for (j = 0; j < cols - shift; j++) {
            sx[sites] = r + a * ((double)j + 0.5 * shift);
            sy[sites] = r + a * 0.8660254037844386 * (double)i;
            order[sites] = sites;
            sites++;
        }
    }
    for (i = sites - 1; i > 0; i--) { /* Fisher-Yates: which sites are used is random */
        int j = (int)(bench_next(&rng) % (unsigned long long)(i + 1)), t = order[i];
        order[i] = order[j];
        order[j] = t;
    }
    /* each centre moves by at most 0.45 (a - 2r): no two come closer than 2r + 0.1 (a - 2r),
     * and none closer to a wall than r */
    jitter = 0.45 * (a - 2.0 * r);
    for (i = 0; i < n; i++) {
        double ang = bench_uniform(&rng, 0.0, 6.283185307179586), rad = jitter * bench_uniform(&rng, 0.0, 1.0);
        cc_circle *c = &s->c[i];
        c->pos.x = sx[order[i]] + rad * cos(ang);
        c->pos.y = sy[order[i]] + rad * sin(ang);
        if (c->pos.x < r)
            c->pos.x = r + 1e-9;
        if (c->pos.y < r)
            c->pos.y = r + 1e-9;
        if (c->pos.x > L - r)
            c->pos.x = L - r - 1e-9;
        if (c->pos.y > L - r)
            c->pos.y = L - r - 1e-9;
        c->vel.x = gauss(&rng);
        c->vel.y = gauss(&rng);
        c->radius = r;
        c->mass = 1.0;
        mx += c->vel.x;
        my += c->vel.y;
    }
    for (i = 0; i < n; i++) {
        s->c[i].vel.x -= mx / n;
        s->c[i].vel.y -= my / n;
    }
    free(sx);
    free(sy);
    free(order);
    s->t_end = 10.0;
}

void bench_scene_pool(bench_scene *s)
{
    const double r = 0.028575, gap = 1e-6, W = 2.54, H = 1.27;
    int row, k = 0;
    memset(s, 0, sizeof *s);
    snprintf(s->name, sizeof s->name, "pool break");
    s->n = 16;
    s->c = bench_alloc(16 * sizeof *s->c);
    s->r_typ = r;
    box_walls(s, 0.0, 0.0, W, H);
    for (row = 0; row < 5; row++) {
        int j;
        for (j = 0; j <= row; j++, k++) {
            double d = 2.0 * r + gap;
            s->c[k].pos.x = 0.75 * W + row * d * 0.8660254037844386;
            s->c[k].pos.y = 0.5 * H + (j - 0.5 * row) * d;
            s->c[k].radius = r;
            s->c[k].mass = 0.17;
        }
    }
    s->c[15].pos.x = 0.25 * W; /* the cue ball, a hair off the axis */
    s->c[15].pos.y = 0.5 * H + 0.002;
    s->c[15].vel.x = 10.0;
    s->c[15].radius = r;
    s->c[15].mass = 0.17;
    s->t_end = 2.0;
}

void bench_scene_hockey(bench_scene *s)
{
    memset(s, 0, sizeof *s);
    snprintf(s->name, sizeof s->name, "air hockey");
    s->n = 3;
    s->c = bench_alloc(3 * sizeof *s->c);
    s->r_typ = 0.0315;
    box_walls(s, 0.0, 0.0, 2.0, 1.0);
    s->c[0].pos.x = 1.0, s->c[0].pos.y = 0.5; /* the puck */
    s->c[0].vel.x = 30.0 * 0.8, s->c[0].vel.y = 30.0 * 0.6;
    s->c[0].radius = 0.0315, s->c[0].mass = 0.02;
    s->c[1].pos.x = 0.35, s->c[1].pos.y = 0.55; /* mallets held still: immovable */
    s->c[2].pos.x = 1.65, s->c[2].pos.y = 0.45;
    s->c[1].radius = s->c[2].radius = 0.05;
    s->c[1].mass = s->c[2].mass = INFINITY;
    s->t_end = 2.0;
}

void bench_scene_free(bench_scene *s)
{
    free(s->c);
    s->c = NULL;
}

double bench_energy(const cc_circle *c, int n)
{
    double e = 0.0;
    int i;
    for (i = 0; i < n; i++)
        if (isfinite(c[i].mass))
            e += 0.5 * c[i].mass * (c[i].vel.x * c[i].vel.x + c[i].vel.y * c[i].vel.y);
    return e;
}

void bench_scene_disks(bench_scene *s, int n, double phi, uint64_t seed, double *side)
{
    int side_n = (int)ceil(sqrt((double)n)), i;
    double l = sqrt(n * 3.141592653589793 * 0.25 / phi);
    uint64_t x = seed;
    memset(s, 0, sizeof *s);
    snprintf(s->name, sizeof s->name, "disks %d phi %.2f", n, phi);
    s->n = n;
    s->c = (cc_circle *)bench_alloc(sizeof *s->c * (size_t)n);
    for (i = 0; i < n; i++) {
        double u[2];
        int q;
        for (q = 0; q < 2; q++) {
            x ^= x << 13, x ^= x >> 7, x ^= x << 17;
            u[q] = (double)(x >> 11) / 9007199254740992.0 - 0.5;
        }
        s->c[i].pos.x = (i % side_n + 0.5) * l / side_n;
        s->c[i].pos.y = (i / side_n + 0.5) * l / side_n;
        s->c[i].vel.x = u[0];
        s->c[i].vel.y = u[1];
        s->c[i].radius = 0.5;
        s->c[i].mass = 1.0;
    }
    s->x0 = s->y0 = 0.0;
    s->x1 = s->y1 = l;
    s->r_typ = 0.5;
    *side = l;
}

cc_world_stats bench_stats(const cc_world *w)
{
    cc_world_stats st;
    memset(&st, 0, sizeof st);
    st.struct_size = sizeof st;
    cc_world_get_stats(w, &st);
    return st;
}

void bench_step(cc_world *w, double dt, const char *who)
{
    const double end = cc_world_time(w) + dt;
    int r = cc_world_step(w, dt);
    /* a capped step stopped at its last event: on to the same end time (a step of 0 would stop
     * there, short of it); the automatic cap of a 1.2 def is sized for a frame, not a run */
    while (r == CC_EVENT_LIMIT)
        r = cc_world_step(w, end > cc_world_time(w) ? end - cc_world_time(w) : 0.0);
    if (r != CC_OK) {
        fprintf(stderr, "%s: cc_world_step: %s\n", who, cc_result_string(r));
        exit(1);
    }
}
