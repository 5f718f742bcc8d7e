/* Queries and walls at scale (issue 14): what a cast and an overlap query cost as the world grows
 * at the same local density (the cost should follow the region, not the world), and what many
 * walls cost a gas that touches few of them (the walls' tree). Ratios against the smallest world
 * or the 4-wall gas measured in the same run; medians and spreads over rounds.
 *
 *   bench_queries casts [--quick]   cast and query cost, N = 1e3 .. 1e6 (1e5 with --quick)
 *   bench_queries walls [--quick]   the gas with 4 walls and with 10,000 short walls outside it
 *   bench_queries periodic [--quick]  periodic casts in each mode against the walled cast
 *   bench_queries filter [--quick]  casts and queries unfiltered, _filtered passing all, and
 *                                   _filtered with ignore= (gas of 10,000; 5,000 with --quick) */
#include "bench_scenes.h"
#include "bench_util.h"

#include "circlecollide.h"

typedef struct qworld {
    cc_world *w;
    void *mem;
    double L;
} qworld;

static void make_gas(qworld *q, const bench_scene *s, int extra_walls, int rounds_of_walls)
{
    cc_world_def d;
    int i;
    cc_world_def_init(&d);
    d.max_circles = s->n;
    d.max_segments = 4 + extra_walls;
    q->mem = bench_alloc(cc_world_size(&d));
    q->w = cc_world_init(q->mem, cc_world_size(&d), &d, NULL);
    q->L = s->x1;
    for (i = 0; i < s->n; i++)
        cc_world_add_circle(q->w, &s->c[i]);
    for (i = 0; i < 4; i++)
        cc_world_add_segment(q->w, &s->walls[i]);
    /* extra walls: short segments on rings around the box, from L/20 to L/4 outside it */
    for (i = 0; i < extra_walls; i++) {
        int ring = i % rounds_of_walls, k = i / rounds_of_walls, per = (extra_walls + rounds_of_walls - 1) / rounds_of_walls;
        double c = 0.5 * q->L, rad = q->L * (0.75 + 0.25 * (double)ring / (double)rounds_of_walls);
        double a0 = 6.283185307179586 * (double)k / (double)per, a1 = a0 + 0.5 * 6.283185307179586 / (double)per;
        cc_segment g;
        g.a.x = c + rad * cos(a0), g.a.y = c + rad * sin(a0);
        g.b.x = c + rad * cos(a1), g.b.y = c + rad * sin(a1);
        cc_world_add_segment(q->w, &g);
    }
    cc_world_step(q->w, 0.5); /* filed and moving */
}

static void free_gas(qworld *q) { free(q->mem); }

static uint64_t collisions(const cc_world *w) { return bench_stats(w).collisions; }

/* ns per cast of a ray and of a circle of radius 1 over 20 circle radii, and per disc query of
 * radius 3, from random points of the gas; each a median over rounds. */
static void cast_costs(const qworld *q, int rounds, double *ns_ray, double *ns_cast, double *ns_query, int *hits)
{
    enum { PER = 20000 };
    double *a = bench_alloc((size_t)rounds * sizeof *a), *b = bench_alloc((size_t)rounds * sizeof *b),
           *c = bench_alloc((size_t)rounds * sizeof *c);
    int r, k, ids[64];
    *hits = 0;
    for (r = 0; r < rounds; r++) {
        bench_rng rng;
        double t0;
        cc_cast_hit h;
        rng.s = 99u + (uint64_t)r;
        t0 = bench_now();
        for (k = 0; k < PER; k++) {
            cc_vec2 p, d;
            double ang = bench_uniform(&rng, 0.0, 6.283185307179586);
            p.x = bench_uniform(&rng, 0.1, 0.9) * q->L, p.y = bench_uniform(&rng, 0.1, 0.9) * q->L;
            d.x = 10.0 * cos(ang), d.y = 10.0 * sin(ang);
            *hits += cc_world_cast_circle(q->w, p, 0.0, d, 0xFFFFFFFFu, &h) != CC_MISS;
        }
        a[r] = (bench_now() - t0) * 1e9 / PER;
        t0 = bench_now();
        for (k = 0; k < PER; k++) {
            cc_vec2 p, d;
            double ang = bench_uniform(&rng, 0.0, 6.283185307179586);
            p.x = bench_uniform(&rng, 0.1, 0.9) * q->L, p.y = bench_uniform(&rng, 0.1, 0.9) * q->L;
            d.x = 10.0 * cos(ang), d.y = 10.0 * sin(ang);
            (void)cc_world_cast_circle(q->w, p, 0.5, d, 0xFFFFFFFFu, &h);
        }
        b[r] = (bench_now() - t0) * 1e9 / PER;
        t0 = bench_now();
        for (k = 0; k < PER; k++) {
            cc_vec2 p;
            p.x = bench_uniform(&rng, 0.1, 0.9) * q->L, p.y = bench_uniform(&rng, 0.1, 0.9) * q->L;
            (void)cc_world_query_circle(q->w, p, 1.5, 0xFFFFFFFFu, ids, 64);
        }
        c[r] = (bench_now() - t0) * 1e9 / PER;
    }
    *ns_ray = bench_median(a, (size_t)rounds);
    *ns_cast = bench_median(b, (size_t)rounds);
    *ns_query = bench_median(c, (size_t)rounds);
    free(a);
    free(b);
    free(c);
}

static int cmd_casts(int quick)
{
    static const int sizes[4] = {1000, 10000, 100000, 1000000};
    int n_sizes = quick ? 3 : 4, v, rounds = quick ? 3 : 7;
    double base[3] = {0, 0, 0};
    printf("%10s %12s %12s %12s %10s %10s %10s\n", "N", "ray ns", "cast ns", "query ns", "ray x", "cast x",
           "query x");
    for (v = 0; v < n_sizes; v++) {
        bench_scene s;
        qworld q;
        double ray, cast, query;
        int hits;
        bench_scene_gas(&s, sizes[v], 0.3, 7);
        make_gas(&q, &s, 0, 1);
        cast_costs(&q, rounds, &ray, &cast, &query, &hits);
        if (v == 0)
            base[0] = ray, base[1] = cast, base[2] = query;
        printf("%10d %12.1f %12.1f %12.1f %10.2f %10.2f %10.2f\n", sizes[v], ray, cast, query, ray / base[0],
               cast / base[1], query / base[2]);
        if (v == n_sizes - 1) {
            char name[64];
            snprintf(name, sizeof name, "cast_cost_n%d_vs_n1000", sizes[v]);
            bench_figure(name, cast / base[1]);
            snprintf(name, sizeof name, "query_cost_n%d_vs_n1000", sizes[v]);
            bench_figure(name, query / base[2]);
        }
        fflush(stdout);
        free_gas(&q);
        bench_scene_free(&s);
    }
    return 0;
}

/* The gas of 10,000 circles at 0.3 in its box, 5 simulated seconds, with its 4 walls only and
 * with 10,000 short walls on rings outside the box that no circle reaches: the same collisions;
 * the ratio of costs per collision in rounds that alternate the two. */
static int cmd_walls(int quick)
{
    int n = quick ? 2000 : 10000, rounds = quick ? 3 : 7, r, v, walls = 10000;
    double cost[2][16], lo[2], hi[2], ratio[16];
    uint64_t coll[2] = {0, 0};
    bench_scene s;
    bench_scene_gas(&s, n, 0.3, 11);
    for (r = 0; r < rounds; r++)
        for (v = 0; v < 2; v++) {
            int var = (v + r) & 1, k;
            qworld q;
            double t0;
            uint64_t c0;
            make_gas(&q, &s, var ? walls : 0, 20);
            c0 = collisions(q.w);
            t0 = bench_now();
            for (k = 0; k < 300; k++)
                cc_world_step(q.w, 1.0 / 60);
            coll[var] = collisions(q.w) - c0;
            cost[var][r] = (bench_now() - t0) * 1e9 / (double)coll[var];
            free_gas(&q);
        }
    for (r = 0; r < rounds; r++)
        ratio[r] = cost[1][r] / cost[0][r];
    for (v = 0; v < 2; v++)
        bench_range(cost[v], (size_t)rounds, &lo[v], &hi[v]);
    printf("%-34s %14s %22s %12s\n", "walls", "ns/collision", "spread", "collisions");
    printf("%-34s %14.1f %10.1f - %-9.1f %12llu\n", "4 (the box)", bench_median(cost[0], (size_t)rounds), lo[0],
           hi[0], (unsigned long long)coll[0]);
    printf("%-34s %14.1f %10.1f - %-9.1f %12llu%s\n", "4 + 10,000 short walls outside", bench_median(cost[1], (size_t)rounds),
           lo[1], hi[1], (unsigned long long)coll[1], coll[0] == coll[1] ? "" : "  (different collisions!)");
    bench_figure("walls_10000_cost_ratio", bench_median(ratio, (size_t)rounds));
    bench_figure("walls_10000_cost_ratio_of_minima", lo[1] / lo[0]);
    bench_scene_free(&s);
    return 0;
}

/* A gas of n circles in its walled box (EXACT) and in a periodic box of the same side, in each
 * mode, after one step: ns per ray cast 10 radii long (a few cells, now and then across the
 * edge) and per ray three periods long, from random points; medians over rounds, the spread of
 * each, and the ratio to the walled EXACT cast of the same length measured in the same run. A
 * periodic cast walks every image along its path (in SWEPT and DISCRETE, or in EXACT past a
 * cell per circle, every circle each half period of the path). */
static double cast_ns(const cc_world *w, double L, double len, int per, uint64_t seed)
{
    bench_rng rng;
    cc_cast_hit h;
    double t0;
    int k, hits = 0;
    rng.s = seed;
    t0 = bench_now();
    for (k = 0; k < per; k++) {
        cc_vec2 p, d;
        double ang = bench_uniform(&rng, 0.0, 6.283185307179586);
        p.x = bench_uniform(&rng, 0.1, 0.9) * L, p.y = bench_uniform(&rng, 0.1, 0.9) * L;
        d.x = len * cos(ang), d.y = len * sin(ang);
        hits += cc_world_cast_circle(w, p, 0.0, d, 0xFFFFFFFFu, &h) != CC_MISS;
    }
    (void)hits;
    return (bench_now() - t0) * 1e9 / per;
}

static int cmd_periodic(int quick)
{
    enum { ROUNDS_MAX = 16 };
    static const char *names[4] = {"walled, EXACT", "periodic, EXACT", "periodic, SWEPT", "periodic, DISCRETE"};
    int n = quick ? 1000 : 10000, rounds = quick ? 3 : 7, v, r, l;
    double ns[2][4][ROUNDS_MAX], lo, hi, base[2];
    bench_scene s;
    cc_world *w[4];
    void *mem[4];
    bench_scene_gas(&s, n, 0.3, 13);
    for (v = 0; v < 4; v++) {
        cc_world_def d;
        int i;
        cc_world_def_init(&d);
        d.max_circles = n;
        d.max_segments = 4;
        d.mode = v == 0 ? CC_MODE_EXACT : v - 1;
        if (v > 0)
            d.period.x = d.period.y = s.x1;
        mem[v] = bench_alloc(cc_world_size(&d));
        w[v] = cc_world_init(mem[v], cc_world_size(&d), &d, NULL);
        for (i = 0; i < n; i++)
            cc_world_add_circle(w[v], &s.c[i]);
        for (i = 0; v == 0 && i < 4; i++)
            cc_world_add_segment(w[v], &s.walls[i]);
        cc_world_step(w[v], 0.05);
    }
    for (r = 0; r < rounds; r++)
        for (l = 0; l < 2; l++)
            for (v = 0; v < 4; v++) /* every variant in each round, so that drifts hit them alike */
                /* (SWEPT and DISCRETE look at every circle: fewer casts, the same time a round) */
                ns[l][v][r] = cast_ns(w[v], s.x1, l == 0 ? 10.0 * s.r_typ : 3.0 * s.x1, v < 2 ? 20000 : 20000 * 100 / n + 100,
                                      99u + (uint64_t)r);
    printf("%-22s %-18s %12s %22s %10s\n", "world", "ray", "ns/cast", "spread", "x walled");
    for (l = 0; l < 2; l++) {
        base[l] = bench_median(ns[l][0], (size_t)rounds);
        for (v = 0; v < 4; v++) {
            double med = bench_median(ns[l][v], (size_t)rounds);
            bench_range(ns[l][v], (size_t)rounds, &lo, &hi);
            printf("%-22s %-18s %12.1f %10.1f - %-9.1f %10.2f\n", names[v], l == 0 ? "10 radii" : "3 periods", med, lo, hi,
                   med / base[l]);
            if (v > 0) {
                char name[64];
                snprintf(name, sizeof name, "periodic_cast_%s_%s_vs_walled", l == 0 ? "short" : "long",
                         v == 1 ? "exact" : v == 2 ? "swept" : "discrete");
                bench_figure(name, med / base[l]);
            }
        }
    }
    for (v = 0; v < 4; v++)
        free(mem[v]);
    bench_scene_free(&s);
    return 0;
}

/* The query filter (1.2): each cast and query as the 1.1 call (a mask), as its _filtered twin
 * with a filter that passes everything (CC_QUERY_FILTER_DEFAULT), with ignore= a circle far from
 * every path (the one farthest from the box's centre: the same answers, the filter's own cost), and
 * with ignore= the circle nearest the start (a cue ball's own cast: the cast goes on past it to
 * the next, a longer search); the same points in every variant, the variants' order rotated each
 * round, ratios to the unfiltered call per round. */
enum { F_PLAIN, F_PASS, F_IGNORE_FAR, F_IGNORE, F_COUNT };

/* ns per call of one kind (0 ray, 1 cast of radius 0.5, 2 disc query of radius 1.5) in the
 * variant var, from the same random points (seeded by the round); the ignored circle is the one
 * nearest each start (what a cue ball's own cast leaves out), found before the clock starts. */
static double one_kind(cc_world *w, double L, const int *near, int far, int kind, int var, int round, int per,
                       long *found)
{
    bench_rng rng;
    int k, ids[64];
    double t0;
    cc_query_filter f = CC_QUERY_FILTER_DEFAULT;
    cc_cast_hit h;
    rng.s = 1234u + (uint64_t)round;
    t0 = bench_now();
    for (k = 0; k < per; k++) {
        cc_vec2 p, d;
        double ang = bench_uniform(&rng, 0.0, 6.283185307179586), rad = kind == 1 ? 0.5 : 0.0;
        int rc;
        p.x = bench_uniform(&rng, 0.1, 0.9) * L, p.y = bench_uniform(&rng, 0.1, 0.9) * L;
        d.x = 10.0 * cos(ang), d.y = 10.0 * sin(ang);
        f.ignore = var == F_IGNORE ? near[k] : var == F_IGNORE_FAR ? far : -1;
        if (kind == 2)
            rc = var == F_PLAIN ? cc_world_query_circle(w, p, 1.5, 0xFFFFFFFFu, ids, 64)
                                : cc_world_query_circle_filtered(w, p, 1.5, &f, ids, 64);
        else
            rc = var == F_PLAIN ? cc_world_cast_circle(w, p, rad, d, 0xFFFFFFFFu, &h)
                                : cc_world_cast_circle_filtered(w, p, rad, d, &f, &h);
        *found += kind == 2 ? rc : rc != CC_MISS ? h.circle : -1;
    }
    return (bench_now() - t0) * 1e9 / per;
}

static int cmd_filter(int quick)
{
    static const char *const kinds[3] = {"ray cast", "circle cast r 0.5", "disc query r 1.5"};
    static const char *const vars[F_COUNT] = {"unfiltered (mask)", "_filtered, passes all", "_filtered, ignore= far",
                                              "_filtered, ignore= near"};
    enum { PER = 20000 };
    int n = quick ? 5000 : 10000, rounds = quick ? 3 : 11, r, kind, var, k, far = -1;
    bench_scene s;
    qworld q;
    cc_world *w;
    int *near = bench_alloc(PER * sizeof *near);
    double t[3][F_COUNT][16], ratio[3][F_COUNT][16];
    long found[3][F_COUNT];
    memset(found, 0, sizeof found);
    bench_scene_gas(&s, n, 0.3, 7);
    make_gas(&q, &s, 0, 1);
    w = q.w;
    { /* the circle farthest from the box's centre: in a corner, at least 0.14 L from every start
         (16 radii at N = 5000), beyond every path */
        cc_circle *all = bench_alloc((size_t)n * sizeof *all);
        int *ids = bench_alloc((size_t)n * sizeof *ids), i, m = cc_world_get_circles(w, ids, all, n);
        double best = -1.0;
        for (i = 0; i < m; i++) {
            double dx = all[i].pos.x - 0.5 * q.L, dy = all[i].pos.y - 0.5 * q.L;
            if (dx * dx + dy * dy > best)
                best = dx * dx + dy * dy, far = ids[i];
        }
        free(all);
        free(ids);
    }
    for (r = 0; r < rounds; r++) {
        for (kind = 0; kind < 3; kind++) {
            bench_rng rng;
            rng.s = 1234u + (uint64_t)r;
            for (k = 0; k < PER; k++) { /* the circle nearest each start point: what ignore= leaves out */
                cc_vec2 p;
                int ids[8], m;
                double rq = 0.25;
                (void)bench_uniform(&rng, 0.0, 1.0);
                p.x = bench_uniform(&rng, 0.1, 0.9) * q.L, p.y = bench_uniform(&rng, 0.1, 0.9) * q.L;
                while ((m = cc_world_query_circle(w, p, rq, 0xFFFFFFFFu, ids, 8)) == 0)
                    rq *= 2.0;
                near[k] = ids[0];
            }
            for (var = 0; var < F_COUNT; var++) {
                int which = (var + r) % F_COUNT; /* rotate which runs first */
                t[kind][which][r] = one_kind(w, q.L, near, far, kind, which, r, PER, &found[kind][which]);
            }
            for (var = 0; var < F_COUNT; var++)
                ratio[kind][var][r] = t[kind][var][r] / t[kind][F_PLAIN][r];
        }
    }
    printf("%-18s %-22s %9s %20s %26s\n", "call", "variant", "ns/call", "spread", "ratio to unfiltered [min-max]");
    for (kind = 0; kind < 3; kind++)
        for (var = 0; var < F_COUNT; var++) {
            double lo, hi, rlo, rhi;
            bench_range(t[kind][var], (size_t)rounds, &lo, &hi);
            bench_range(ratio[kind][var], (size_t)rounds, &rlo, &rhi);
            printf("%-18s %-22s %9.1f %9.1f - %-9.1f %12.3f [%.3f-%.3f]%s\n", kinds[kind], vars[var],
                   bench_median(t[kind][var], (size_t)rounds), lo, hi, bench_median(ratio[kind][var], (size_t)rounds),
                   rlo, rhi,
                   (var == F_PASS || var == F_IGNORE_FAR) && found[kind][var] != found[kind][F_PLAIN]
                       ? "  (different answers!)"
                       : "");
            if (var != F_PLAIN) {
                char name[64];
                snprintf(name, sizeof name, "filter_%s_%s_over_plain", kind == 2 ? "query" : kind ? "cast" : "ray",
                         var == F_PASS ? "pass" : var == F_IGNORE_FAR ? "ignore_far" : "ignore_near");
                bench_figure(name, bench_median(ratio[kind][var], (size_t)rounds));
            }
        }
    printf("(gas of %d circles at 0.3, %d calls per variant a round, %d rounds; the same points in every variant)\n",
           n, PER, rounds);
    free(near);
    free_gas(&q);
    bench_scene_free(&s);
    return 0;
}

int main(int argc, char **argv)
{
    int quick = argc > 2 && !strcmp(argv[2], "--quick");
    if (argc >= 2 && !strcmp(argv[1], "casts"))
        return cmd_casts(quick);
    if (argc >= 2 && !strcmp(argv[1], "walls"))
        return cmd_walls(quick);
    if (argc >= 2 && !strcmp(argv[1], "periodic"))
        return cmd_periodic(quick);
    if (argc >= 2 && !strcmp(argv[1], "filter"))
        return cmd_filter(quick);
    fprintf(stderr, "usage: %s casts|walls|periodic|filter [--quick]\n", argv[0]);
    return 2;
}
