/* Issue 16's targets in one run: EXACT's cost per collision as a ratio to cc_sweep's
 * cache-resident time per pair, measured in the same process and round (so that the ratios hold
 * on any machine): periodic hard disks at N = 1e4, area fractions 0.3 and 0.7; the walled gas of
 * the headline (N = 1e4, 0.3); the growth of the cost per collision from N = 1e4 to a large N;
 * the pool break and the air-hockey rally; the world's bytes per circle.
 *
 * Usage: bench_exact [--quick] [--max-n N] [--rounds R] [--only disks|scaling|scenes|d3|d7|gas|big]
 *                    [--cell S] [--phi F] (F: the area fraction of the one world of --only d3, d7, big)
 *
 * Each figure is the median over rounds of the per-round ratio (a round measures cc_sweep, then
 * each world, so that a noisy neighbour hurts numerator and denominator alike); min and max of
 * the ratios are printed beside it. Times are the process's CPU time (cpu_now below), so that
 * the waits of a shared machine stay out of them. */
#include "bench_pair_methods.h"
#include "bench_scenes.h"
#include "bench_util.h"

#define MAX_ROUNDS 32

static volatile double g_sink;
static double g_cell = 0.0; /* --cell: def.cell_size of the disks' worlds (0: the world's choice) */
static double g_phi = 0.0; /* --phi: the area fraction of --only d3, d7, big (0: theirs) */

/* This process's CPU seconds: on a machine shared with other jobs, the time this process ran
 * (its memory stalls included), not the time it waited for a core. Both sides of each ratio are
 * timed alike. */
static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
#define bench_now cpu_now

/* cc_sweep's cache-resident ns per pair: blocks of BENCH_BLOCK pairs swept twice, the second
 * pass timed (as bench_pair's "cache-resident" column). */
static double sweep_hot_ns(const cc_circle *a, const cc_circle *b, size_t n)
{
    double spent = 0.0, acc = 0.0;
    size_t lo, i;
    for (lo = 0; lo < n; lo += BENCH_BLOCK) {
        size_t hi = lo + BENCH_BLOCK < n ? lo + BENCH_BLOCK : n;
        double t0;
        int pass;
        for (pass = 0; pass < 2; pass++) {
            t0 = bench_now();
            for (i = lo; i < hi; i++) {
                cc_contact c;
                if (cc_sweep(&a[i], &b[i], 1.0, &c) == CC_HIT)
                    acc += c.t;
            }
            if (pass == 1)
                spent += bench_now() - t0;
        }
    }
    g_sink = acc;
    return spent / (double)n * 1e9;
}

typedef struct world_box {
    cc_world *w;
    void *mem;
    size_t bytes;
} world_box;

static void step(cc_world *w, double dt) { bench_step(w, dt, "bench_exact"); }

static cc_world_stats stats_of(const cc_world *w) { return bench_stats(w); }

/* n disks of diameter 1 in a periodic square box at area fraction phi, on a square lattice with
 * velocities uniform in [-0.5, 0.5) per component (bench_world's disks scene, any n). */
static void disks_make(world_box *b, int n, double phi, uint64_t seed)
{
    bench_scene sc;
    double side;
    int i;
    cc_world_def def;
    bench_scene_disks(&sc, n, phi, seed, &side);
    cc_world_def_init(&def);
    def.max_circles = n;
    def.period.x = def.period.y = side;
    def.cell_size = g_cell;
    b->bytes = cc_world_size(&def);
    b->mem = bench_alloc(b->bytes);
    b->w = cc_world_init(b->mem, b->bytes, &def, NULL);
    if (b->w == NULL) {
        fprintf(stderr, "bench_exact: init failed\n");
        exit(1);
    }
    for (i = 0; i < n; i++)
        if (cc_world_add_circle(b->w, &sc.c[i]) != i) {
            fprintf(stderr, "bench_exact: add_circle failed\n");
            exit(1);
        }
    bench_scene_free(&sc);
}

/* The walled gas of bench_world's headline (bench_scene_gas, restitution 1). */
static void gas_make(world_box *b, int n, double phi)
{
    bench_scene s;
    cc_world_def def;
    int i;
    bench_scene_gas(&s, n, phi, 7);
    cc_world_def_init(&def);
    def.max_circles = n;
    def.max_segments = 4;
    def.restitution = 1.0;
    b->bytes = cc_world_size(&def);
    b->mem = bench_alloc(b->bytes);
    b->w = cc_world_init(b->mem, b->bytes, &def, NULL);
    if (b->w == NULL) {
        fprintf(stderr, "bench_exact: init failed\n");
        exit(1);
    }
    for (i = 0; i < n; i++)
        cc_world_add_circle(b->w, &s.c[i]);
    for (i = 0; i < s.n_walls; i++)
        cc_world_add_segment(b->w, &s.walls[i]);
    bench_scene_free(&s);
}

typedef struct per_coll {
    double ns;                        /* wall ns per collision */
    double events, crossings, stale, tests; /* per collision */
    size_t bytes;
    int n;
    uint64_t hash; /* the world's state hash at the end (cc_world_hash): the same events or not */
} per_coll;

/* Steps of dt until warm collisions (leaving the lattice), then timed steps until `coll` more. */
static per_coll run_world(world_box *b, int n, double dt, double warm, double coll)
{
    per_coll r;
    cc_world_stats s0, s1;
    double t0, c0;
    do
        step(b->w, dt);
    while ((double)stats_of(b->w).collisions < warm);
    s0 = stats_of(b->w);
    c0 = (double)s0.collisions;
    t0 = bench_now();
    do
        step(b->w, dt);
    while ((double)stats_of(b->w).collisions - c0 < coll);
    r.ns = (bench_now() - t0) * 1e9;
    s1 = stats_of(b->w);
    c0 = (double)(s1.collisions - s0.collisions);
    r.ns /= c0;
    r.events = (double)(s1.events - s0.events) / c0;
    r.crossings = (double)(s1.cell_crossings - s0.cell_crossings) / c0;
    r.stale = (double)(s1.stale_events - s0.stale_events) / c0;
    r.tests = (double)(s1.pairs_tested - s0.pairs_tested) / c0;
    r.bytes = b->bytes;
    r.n = n;
    r.hash = cc_world_hash(b->w);
    free(b->mem);
    return r;
}

static per_coll disks_run(int n, double phi, double per_disk, uint64_t seed)
{
    world_box b;
    disks_make(&b, n, phi, seed);
    return run_world(&b, n, 0.5, (double)n, per_disk * n);
}

static per_coll gas_run(int n, double phi, double per_disk)
{
    world_box b;
    gas_make(&b, n, phi);
    return run_world(&b, n, 1.0 / 60, 0.5 * n, per_disk * n);
}

/* A small scene (pool, hockey) run to its end again and again for at least min_time: ns per
 * collision. */
static double scene_ns(const bench_scene *s, double min_time)
{
    double spent = 0.0;
    uint64_t coll = 0;
    int steps = (int)ceil(s->t_end * 60.0 - 1e-9);
    do {
        cc_world_def def;
        world_box b;
        double t0;
        int i;
        cc_world_def_init(&def);
        def.max_circles = s->n;
        def.max_segments = s->n_walls;
        def.restitution = 1.0;
        b.bytes = cc_world_size(&def);
        b.mem = bench_alloc(b.bytes);
        b.w = cc_world_init(b.mem, b.bytes, &def, NULL);
        for (i = 0; i < s->n; i++)
            cc_world_add_circle(b.w, &s->c[i]);
        for (i = 0; i < s->n_walls; i++)
            cc_world_add_segment(b.w, &s->walls[i]);
        t0 = bench_now();
        for (i = 0; i < steps; i++)
            step(b.w, 1.0 / 60);
        spent += bench_now() - t0;
        coll += stats_of(b.w).collisions;
        free(b.mem);
    } while (spent < min_time);
    return spent * 1e9 / (double)coll;
}

/* median and range of v[0..n) (v is sorted) */
static void summary(const char *label, const char *figure, double *v, int n)
{
    double lo, hi, med;
    bench_range(v, (size_t)n, &lo, &hi);
    med = bench_median(v, (size_t)n);
    printf("  %-52s %10.3g  [%.3g - %.3g]\n", label, med, lo, hi);
    if (figure != NULL)
        bench_figure(figure, med);
}

static void print_counts(const char *name, const per_coll *r)
{
    printf("  %-28s %8.1f ns/coll, per collision: %.2f events, %.2f crossings, %.2f stale, %.1f pair tests; "
           "%.1f bytes/circle\n",
           name, r->ns, r->events, r->crossings, r->stale, r->tests, (double)r->bytes / r->n);
}

int main(int argc, char **argv)
{
    int quick = 0, rounds = 0, k, max_n = 1000000, n_pairs = 65536;
    const char *only = NULL;
    cc_circle *pa, *pb;
    double sweep[MAX_ROUNDS], d3[MAX_ROUNDS], d7[MAX_ROUNDS], g3[MAX_ROUNDS], big[MAX_ROUNDS], scale[MAX_ROUNDS];
    double pool[MAX_ROUNDS], hockey[MAX_ROUNDS], pool_r[MAX_ROUNDS], hockey_r[MAX_ROUNDS], v[MAX_ROUNDS];
    double ns_d3[MAX_ROUNDS], ns_d7[MAX_ROUNDS], ns_g3[MAX_ROUNDS];
    int rounds_big;
    bench_scene s_pool, s_hockey;
    for (k = 1; k < argc; k++) {
        if (!strcmp(argv[k], "--quick"))
            quick = 1;
        else if (!strcmp(argv[k], "--max-n") && k + 1 < argc)
            max_n = atoi(argv[++k]);
        else if (!strcmp(argv[k], "--rounds") && k + 1 < argc)
            rounds = atoi(argv[++k]);
        else if (!strcmp(argv[k], "--cell") && k + 1 < argc)
            g_cell = atof(argv[++k]);
        else if (!strcmp(argv[k], "--phi") && k + 1 < argc)
            g_phi = atof(argv[++k]);
        else if (!strcmp(argv[k], "--only") && k + 1 < argc)
            only = argv[++k];
        else {
            fprintf(stderr, "usage: bench_exact [--quick] [--max-n N] [--rounds R] [--only disks|scaling|scenes|d3|d7|gas|big] [--cell S] [--phi F]\n");
            return 2;
        }
    }
    if (rounds <= 0)
        rounds = quick ? 3 : 7;
    if (rounds > MAX_ROUNDS)
        rounds = MAX_ROUNDS;
    if (quick && max_n > 100000)
        max_n = 100000;
    rounds_big = rounds < 3 ? rounds : 3;
    pa = bench_alloc((size_t)n_pairs * sizeof *pa);
    pb = bench_alloc((size_t)n_pairs * sizeof *pb);
    bench_make_pairs((size_t)n_pairs, 20261122u, pa, pb);
    (void)sweep_hot_ns(pa, pb, (size_t)n_pairs); /* page faults and lazy binding out of the way */
    bench_scene_pool(&s_pool);
    bench_scene_hockey(&s_hockey);

    if (only != NULL && (!strcmp(only, "d3") || !strcmp(only, "d7") || !strcmp(only, "gas") || !strcmp(only, "big"))) {
        /* one world, once, for a profiler: perf stat / perf record bench_exact --only d3 */
        per_coll r = !strcmp(only, "gas")  ? gas_run(10000, 0.3, 20.0)
                     : !strcmp(only, "big") ? disks_run(max_n, g_phi > 0.0 ? g_phi : 0.3, 2.0, 199)
                                            : disks_run(10000, g_phi > 0.0 ? g_phi : !strcmp(only, "d3") ? 0.3 : 0.7, 20.0, 99);
        print_counts(only, &r);
        printf("  state hash at the end: %016llx\n", (unsigned long long)r.hash);
        return 0;
    }
    printf("EXACT at research speed (issue 16): cost per collision / cc_sweep's cache-resident ns per pair\n");
    if (only == NULL || !strcmp(only, "disks")) {
        double per_disk = quick ? 5.0 : 20.0;
        for (k = 0; k < rounds; k++) {
            per_coll a, b, c;
            sweep[k] = sweep_hot_ns(pa, pb, (size_t)n_pairs);
            a = disks_run(10000, 0.3, per_disk, 99 + (uint64_t)k);
            b = disks_run(10000, 0.7, per_disk, 99 + (uint64_t)k);
            c = gas_run(10000, 0.3, per_disk);
            ns_d3[k] = a.ns, ns_d7[k] = b.ns, ns_g3[k] = c.ns;
            d3[k] = a.ns / sweep[k];
            d7[k] = b.ns / sweep[k];
            g3[k] = c.ns / sweep[k];
            if (k == 0) {
                print_counts("disks N=1e4 phi=0.3", &a);
                print_counts("disks N=1e4 phi=0.7", &b);
                print_counts("walled gas N=1e4 phi=0.3", &c);
                bench_figure("exact_bytes_per_circle_disks", (double)a.bytes / a.n);
            }
            fflush(stdout);
        }
        memcpy(v, sweep, sizeof v);
        summary("cc_sweep ns per pair (cache-resident)", "exact_sweep_ns_per_pair", v, rounds);
        summary("disks N=1e4 phi=0.3 ns per collision", NULL, ns_d3, rounds);
        summary("disks N=1e4 phi=0.7 ns per collision", NULL, ns_d7, rounds);
        summary("walled gas N=1e4 phi=0.3 ns per collision", NULL, ns_g3, rounds);
        summary("disks N=1e4 phi=0.3 / cc_sweep (target <= 25)", "exact_disks_n1e4_phi03_per_sweep", d3, rounds);
        summary("disks N=1e4 phi=0.7 / cc_sweep (target <= 12)", "exact_disks_n1e4_phi07_per_sweep", d7, rounds);
        summary("walled gas N=1e4 phi=0.3 / cc_sweep (target <= 25)", "exact_gas_n1e4_phi03_per_sweep", g3, rounds);
    }
    if (only == NULL || !strcmp(only, "scaling")) {
        char label[96], fig[64];
        for (k = 0; k < rounds_big; k++) {
            per_coll a, b;
            a = disks_run(10000, 0.3, quick ? 5.0 : 20.0, 199 + (uint64_t)k);
            b = disks_run(max_n, 0.3, quick ? 1.0 : 2.0, 199 + (uint64_t)k);
            big[k] = b.ns;
            scale[k] = b.ns / a.ns;
            if (k == 0) {
                print_counts("disks phi=0.3 (N=1e4)", &a);
                print_counts("disks phi=0.3 (large N)", &b);
            }
            fflush(stdout);
        }
        snprintf(label, sizeof label, "disks phi=0.3 N=%d ns per collision", max_n);
        summary(label, NULL, big, rounds_big);
        snprintf(label, sizeof label, "N=%d vs N=1e4 per collision (target <= 1.5)", max_n);
        snprintf(fig, sizeof fig, "exact_disks_n%d_vs_n1e4", max_n);
        summary(label, fig, scale, rounds_big);
    }
    if (only == NULL || !strcmp(only, "scenes")) {
        for (k = 0; k < rounds; k++) {
            double sw = sweep_hot_ns(pa, pb, (size_t)n_pairs);
            pool[k] = scene_ns(&s_pool, quick ? 0.05 : 0.2);
            hockey[k] = scene_ns(&s_hockey, quick ? 0.05 : 0.2);
            pool_r[k] = pool[k] / sw;
            hockey_r[k] = hockey[k] / sw;
        }
        summary("pool break ns per collision", "exact_pool_ns_per_collision", pool, rounds);
        summary("air-hockey rally ns per collision", "exact_hockey_ns_per_collision", hockey, rounds);
        summary("pool break / cc_sweep", "exact_pool_per_sweep", pool_r, rounds);
        summary("air-hockey rally / cc_sweep", "exact_hockey_per_sweep", hockey_r, rounds);
    }
    bench_scene_free(&s_pool);
    bench_scene_free(&s_hockey);
    free(pa);
    free(pb);
    return 0;
}
