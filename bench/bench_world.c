/* World-level benchmark: scenes x modes x step sizes (cost, collisions per second, tunnelling,
 * worst overlap, energy drift, trajectory error against EXACT at a tiny step), the EXACT
 * headline at N = 1e4, the scaling of EXACT's cost per collision with N, and the cost of
 * features a scene does not use. Results as CSV rows and `figure NAME VALUE` lines.
 *
 * Usage: bench_world matrix   [--quick] [--csv FILE]
 *        bench_world headline [--quick]
 *        bench_world scaling  [--quick] [--max-n N] [--csv FILE]
 *        bench_world features [--quick] [--csv FILE]
 *        bench_world disks [--quick]       periodic hard disks at area fractions 0.3, 0.5, 0.7
 *        bench_world uses [--quick] [--max-n N] [--csv FILE]  bytes per circle for uses = 0, PROPS,
 *                                          ALL, and the periodic gas with uses = 0 against ALL
 *        bench_world table [--quick]       walls hold: escapes against |v| dt / r, every mode
 *        bench_world jam [--quick]         how long a step that jams takes at its event cap
 *        bench_world dump-gas N PHI    (the gas's initial state, one circle a line, for peers)
 *        bench_world check-trace N PHI FILE (judges a peer's recorded steps, see peers.py)
 *        bench_world peer N PHI T_END DT  (our EXACT world on the peers' terms)
 *
 * Timed runs call nothing but cc_world_step; the checks (bench_check.h) run in a separate,
 * untimed run of the same steps. */
#include "bench_check.h"
#include "bench_util.h"

static const char *mode_name[] = {"EXACT", "SWEPT", "DISCRETE"};
static int g_verbose = 1; /* the world's own counters next to the timings */

typedef struct world_box {
    cc_world *w;
    void *mem;
    size_t bytes;
} world_box;

/* A world holding the scene, with room for extra circles and walls as asked. */
static void world_make(world_box *b, const bench_scene *s, int mode, int extra_circles, int max_segments)
{
    cc_world_def def;
    int i, st;
    cc_world_def_init(&def);
    def.max_circles = s->n + extra_circles;
    def.max_segments = max_segments;
    def.mode = mode;
    def.restitution = 1.0;
    b->bytes = cc_world_size(&def);
    b->mem = bench_alloc(b->bytes);
    b->w = cc_world_init(b->mem, b->bytes, &def, &st);
    if (b->w == NULL) {
        fprintf(stderr, "bench_world: cc_world_init: %s\n", cc_result_string(st));
        exit(1);
    }
    for (i = 0; i < s->n; i++)
        if (cc_world_add_circle(b->w, &s->c[i]) != i) {
            fprintf(stderr, "bench_world: cc_world_add_circle failed for circle %d\n", i);
            exit(1);
        }
    for (i = 0; i < s->n_walls && i < max_segments; i++)
        if (cc_world_add_segment(b->w, &s->walls[i]) < 0) {
            fprintf(stderr, "bench_world: cc_world_add_segment failed\n");
            exit(1);
        }
}

static void world_free(world_box *b) { free(b->mem); }

static void step(cc_world *w, double dt) { bench_step(w, dt, "bench_world"); }

static uint64_t collisions(const cc_world *w) { return bench_stats(w).collisions; }

/* ---- one configuration of the matrix ------------------------------------------------------ */

typedef struct run_result {
    double sec_per_sim_s, sec_lo, sec_hi; /* wall time per simulated second: median, min, max */
    double coll_per_s;                    /* collisions per wall second */
    uint64_t coll;                        /* collisions in one run */
    long tunnel, escaped;
    double max_overlap, energy_drift, traj_err;
} run_result;

/* Wall time of one run of the scene, repeated until min_time has passed; per-run median of
 * `reps` such measurements. */
static void time_runs(const bench_scene *s, int mode, double dt, int reps, double min_time, run_result *out)
{
    double *per = bench_alloc((size_t)reps * sizeof *per);
    int k, steps = (int)ceil(s->t_end / dt - 1e-9);
    for (k = 0; k < reps; k++) {
        double spent = 0.0;
        int runs = 0;
        do {
            world_box b;
            double t0;
            int i;
            world_make(&b, s, mode, 0, s->n_walls);
            t0 = bench_now();
            for (i = 0; i < steps; i++)
                step(b.w, dt);
            spent += bench_now() - t0;
            out->coll = collisions(b.w);
            world_free(&b);
            runs++;
        } while (spent < min_time);
        per[k] = spent / runs;
    }
    bench_range(per, (size_t)reps, &out->sec_lo, &out->sec_hi);
    out->sec_per_sim_s = bench_median(per, (size_t)reps) / (steps * dt);
    out->sec_lo /= steps * dt;
    out->sec_hi /= steps * dt;
    out->coll_per_s = (double)out->coll / (out->sec_per_sim_s * steps * dt);
    free(per);
}

/* The checked run: tunnelling, escapes, overlap, energy, and the final state. */
static void checked_run(const bench_scene *s, int mode, double dt, cc_circle *final, run_result *out)
{
    world_box b;
    bench_check k;
    cc_circle *pre = bench_alloc((size_t)s->n * sizeof *pre), *post = bench_alloc((size_t)s->n * sizeof *post);
    int i, steps = (int)ceil(s->t_end / dt - 1e-9);
    double e0 = bench_energy(s->c, s->n);
    world_make(&b, s, mode, 0, s->n_walls);
    bench_check_init(&k, s->n);
    cc_world_get_circles(b.w, NULL, pre, s->n);
    for (i = 0; i < steps; i++) {
        step(b.w, dt);
        cc_world_get_circles(b.w, NULL, post, s->n);
        bench_check_step(&k, s, pre, post, dt);
        memcpy(pre, post, (size_t)s->n * sizeof *pre);
    }
    out->tunnel = k.tunnel_circle + k.tunnel_wall;
    out->escaped = k.escaped;
    out->max_overlap = k.max_overlap;
    out->energy_drift = e0 > 0.0 ? fabs(bench_energy(post, s->n) - e0) / e0 : 0.0;
    if (final != NULL)
        memcpy(final, post, (size_t)s->n * sizeof *post);
    bench_check_free(&k);
    world_free(&b);
    free(pre);
    free(post);
}

static double traj_error(const bench_scene *s, const cc_circle *a, const cc_circle *ref)
{
    double sum = 0.0;
    int i;
    for (i = 0; i < s->n; i++) {
        double dx = a[i].pos.x - ref[i].pos.x, dy = a[i].pos.y - ref[i].pos.y;
        sum += dx * dx + dy * dy;
    }
    return sqrt(sum / s->n) / s->r_typ;
}

typedef struct opts {
    int quick;
    const char *csv;
    long max_n;
} opts;

static FILE *open_csv(const char *path, const char *header)
{
    FILE *f;
    if (path == NULL)
        return NULL;
    f = fopen(path, "w");
    if (f == NULL) {
        fprintf(stderr, "bench_world: cannot write %s\n", path);
        exit(2);
    }
    fprintf(f, "%s\n", header);
    return f;
}

static int cmd_matrix(const opts *o)
{
    static const double steps_full[] = {1.0 / 30, 1.0 / 60, 1.0 / 120, 1.0 / 240, 1.0 / 480};
    const double dt_ref = 1.0 / 7680; /* "a tiny step" for the EXACT reference */
    bench_scene scenes[5];
    int n_scenes = 0, si, gas_n = o->quick ? 300 : 1000, reps = o->quick ? 3 : 5;
    double min_time = o->quick ? 0.01 : 0.1;
    FILE *csv = open_csv(o->csv, "scene,mode,dt,sec_per_sim_s,sec_min,sec_max,collisions,collisions_per_s,"
                                 "tunnelling,escaped,max_overlap_r,energy_drift,traj_err_r");
    bench_scene_gas(&scenes[n_scenes++], gas_n, 0.05, 1);
    bench_scene_gas(&scenes[n_scenes++], gas_n, 0.3, 2);
    bench_scene_gas(&scenes[n_scenes++], gas_n, 0.6, 3);
    bench_scene_pool(&scenes[n_scenes++]);
    bench_scene_hockey(&scenes[n_scenes++]);
    for (si = 0; si < n_scenes; si++) {
        bench_scene *s = &scenes[si];
        cc_circle *ref = bench_alloc((size_t)s->n * sizeof *ref), *fin = bench_alloc((size_t)s->n * sizeof *fin);
        run_result rr;
        int mode, d;
        if (s->n > 100)
            s->t_end = 1.0; /* a few collisions per molecule: before chaos erases any comparison */
        memset(&rr, 0, sizeof rr);
        checked_run(s, CC_MODE_EXACT, dt_ref, ref, &rr);
        printf("%-22s %-8s %-9s %12s %10s %12s %6s %6s %10s %10s %10s\n", s->name, "mode", "dt", "s/sim s",
               "spread", "coll/s", "tunnel", "escape", "overlap/r", "dE/E", "err/r");
        for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++) {
            int n_dt = mode == CC_MODE_EXACT ? 2 : (int)(sizeof steps_full / sizeof steps_full[0]);
            for (d = 0; d < n_dt; d++) {
                double dt = mode == CC_MODE_EXACT ? (d == 0 ? 1.0 / 60 : dt_ref) : steps_full[d];
                memset(&rr, 0, sizeof rr);
                time_runs(s, mode, dt, reps, min_time, &rr);
                checked_run(s, mode, dt, fin, &rr);
                rr.traj_err = traj_error(s, fin, ref);
                printf("%-22s %-8s 1/%-7.0f %12.4g %4.0f%%-%3.0f%% %12.4g %6ld %6ld %10.3g %10.3g %10.3g\n", s->name,
                       mode_name[mode], 1.0 / dt, rr.sec_per_sim_s, 100.0 * (rr.sec_lo / rr.sec_per_sim_s - 1.0),
                       100.0 * (rr.sec_hi / rr.sec_per_sim_s - 1.0), rr.coll_per_s, rr.tunnel, rr.escaped,
                       rr.max_overlap, rr.energy_drift, rr.traj_err);
                if (csv != NULL)
                    fprintf(csv, "%s,%s,%.9g,%.6g,%.6g,%.6g,%llu,%.6g,%ld,%ld,%.6g,%.6g,%.6g\n", s->name,
                            mode_name[mode], dt, rr.sec_per_sim_s, rr.sec_lo, rr.sec_hi, (unsigned long long)rr.coll,
                            rr.coll_per_s, rr.tunnel, rr.escaped, rr.max_overlap, rr.energy_drift, rr.traj_err);
                if (mode == CC_MODE_EXACT && rr.tunnel + rr.escaped > 0)
                    printf("EXACT tunnelled in %s at dt 1/%.0f\n", s->name, 1.0 / dt);
            }
        }
        free(ref);
        free(fin);
        bench_scene_free(s);
    }
    if (csv != NULL)
        fclose(csv);
    return 0;
}

/* EXACT on the gas: collisions per wall second over steps of 1/60 after a warm-up of about half
 * a collision per circle, median of reps runs. Returns the median; *cost_ns = ns per collision. */
static double exact_rate(int n, double phi, int reps, uint64_t min_coll, double *cost_ns, double *lo, double *hi,
                         size_t *bytes)
{
    bench_scene s;
    double *rate = bench_alloc((size_t)reps * sizeof *rate), med;
    int k;
    bench_scene_gas(&s, n, phi, 7);
    for (k = 0; k < reps; k++) {
        world_box b;
        uint64_t c0;
        double t0, spent;
        world_make(&b, &s, CC_MODE_EXACT, 0, 4);
        /* warm-up: the first step makes every initial prediction, and the lattice start needs
         * about a collision per circle to become a gas; neither is steady state */
        t0 = bench_now();
        do
            step(b.w, 1.0 / 60);
        while (collisions(b.w) < (uint64_t)n / 2 && bench_now() - t0 < 60.0);
        c0 = collisions(b.w);
        t0 = bench_now();
        do /* enough collisions, or a minute: a stuck world must not hang the benchmark */
            step(b.w, 1.0 / 60);
        while (collisions(b.w) - c0 < min_coll && bench_now() - t0 < 60.0);
        spent = bench_now() - t0;
        rate[k] = (double)(collisions(b.w) - c0) / spent;
        *bytes = b.bytes;
        if (k == 0 && g_verbose) {
            cc_world_stats st = bench_stats(b.w);
            printf("  n=%d: per collision %.2f events, %.2f stale, %.2f pair tests, %.2f cell crossings\n", n,
                   (double)st.events / st.collisions, (double)st.stale_events / st.collisions,
                   (double)st.pairs_tested / st.collisions, (double)st.cell_crossings / st.collisions);
        }
        world_free(&b);
    }
    bench_range(rate, (size_t)reps, lo, hi);
    med = bench_median(rate, (size_t)reps);
    *cost_ns = 1e9 / med;
    free(rate);
    bench_scene_free(&s);
    return med;
}

static int cmd_headline(const opts *o)
{
    double cost, lo, hi;
    size_t bytes;
    double rate = exact_rate(10000, 0.3, o->quick ? 3 : 7, o->quick ? 300000 : 2000000, &cost, &lo, &hi, &bytes);
    printf("EXACT gas n=10000 phi=0.3: %.4g collisions/s [%.4g, %.4g], %.1f ns per collision\n", rate, lo, hi, cost);
    bench_figure("world_collisions_per_s_n10000", rate);
    return 0;
}

static int cmd_scaling(const opts *o)
{
    long n;
    FILE *csv = open_csv(o->csv, "n,collisions_per_s,cost_ns,rate_min,rate_max,bytes_per_circle");
    printf("%10s %14s %12s %24s %14s\n", "N", "collisions/s", "ns/collision", "spread", "bytes/circle");
    for (n = 100; n <= o->max_n; n *= 10) {
        double cost, lo, hi;
        size_t bytes;
        uint64_t min_coll = (uint64_t)(n < 100000 ? 200000 : 2 * n);
        double rate = exact_rate((int)n, 0.3, o->quick ? 1 : 3, o->quick ? min_coll / 4 : min_coll, &cost, &lo, &hi,
                                 &bytes);
        printf("%10ld %14.4g %12.1f %11.4g - %-11.4g %14.1f\n", n, rate, cost, lo, hi, (double)bytes / (double)n);
        if (csv != NULL)
            fprintf(csv, "%ld,%.6g,%.6g,%.6g,%.6g,%.6g\n", n, rate, cost, lo, hi, (double)bytes / (double)n);
        fflush(stdout);
    }
    if (csv != NULL)
        fclose(csv);
    return 0;
}

/* "Model only what a scene requires": the same free gas (no walls touched within the run)
 * with features absent, present but idle, and far away. */
static int cmd_features(const opts *o)
{
    enum { BASE, SEG_CAP, FAR_WALLS, FAR_IMMOVABLE, FAR_BIG, PROPS_ALL, SENSORS, HALF_FILTERED, ROLL_FAR, ROLL_ALL,
           N_VARIANTS };
    static const char *names[N_VARIANTS] = {"no walls, max_segments = 0", "max_segments = 4, no walls",
                                            "4 walls 1000 boxes away", "16 immovable circles far away",
                                            "1 immovable circle r = 2 far away",
                                            "every circle with props (filters)", "16 sensors in the gas",
                                            "half the pairs filtered", "1 rolling circle far away",
                                            "every circle rolls (slows 1% in the run)"};
    bench_scene s;
    int n = o->quick ? 2000 : 10000, reps = o->quick ? 3 : 9, v, k;
    double t_run = 5.0, base = 0.0;
    double *cost[N_VARIANTS], rat[N_VARIANTS], rat_min[N_VARIANTS], lo_v, hi_v, lo_b, hi_b;
    uint64_t coll[N_VARIANTS];
    FILE *csv = open_csv(o->csv, "variant,ns_per_collision,ns_min,ns_max,collisions,ratio_to_base,ratio_of_minima");
    bench_scene_gas(&s, n, 0.3, 11);
    for (v = 0; v < N_VARIANTS; v++)
        cost[v] = bench_alloc((size_t)reps * sizeof(double));
    /* rounds rotate the variants so that noise falls on all alike */
    for (k = 0; k < reps; k++) {
        for (v = 0; v < N_VARIANTS; v++) {
            int var = (v + k) % N_VARIANTS, i;
            world_box b;
            double t0, L = s.x1;
            bench_scene far = s;
            far.n_walls = 0;
            if (var == FAR_WALLS) {
                far.n_walls = 4;
                for (i = 0; i < 4; i++) {
                    far.walls[i].a.x = (s.walls[i].a.x - 0.5 * L) * 1000.0;
                    far.walls[i].a.y = (s.walls[i].a.y - 0.5 * L) * 1000.0;
                    far.walls[i].b.x = (s.walls[i].b.x - 0.5 * L) * 1000.0;
                    far.walls[i].b.y = (s.walls[i].b.y - 0.5 * L) * 1000.0;
                }
            }
            world_make(&b, &far, CC_MODE_EXACT, 16, var == BASE ? 0 : 4);
            if (var == FAR_IMMOVABLE || var == FAR_BIG) {
                for (i = 0; i < (var == FAR_BIG ? 1 : 16); i++) {
                    cc_circle c;
                    memset(&c, 0, sizeof c);
                    c.pos.x = -1000.0 * L + 3.0 * i;
                    c.pos.y = -1000.0 * L;
                    c.radius = var == FAR_BIG ? 4.0 * s.r_typ : s.r_typ;
                    c.mass = INFINITY;
                    cc_world_add_circle(b.w, &c);
                }
            }
            if (var == PROPS_ALL || var == HALF_FILTERED) {
                /* PROPS_ALL: filters that admit every pair (the featured prediction path, the
                 * same collisions); HALF_FILTERED: two families that pass through each other */
                for (i = 0; i < s.n; i++) {
                    cc_circle_props p;
                    p.struct_size = sizeof p;
                    cc_world_get_circle_props(b.w, i, &p);
                    p.category = var == PROPS_ALL ? 3u : 1u << (i & 1);
                    p.mask = var == PROPS_ALL ? 0xFFFFFFFFu : 1u << (i & 1);
                    cc_world_set_circle_props(b.w, i, &p);
                }
            }
            if (var == ROLL_FAR) { /* one circle with friction, far away: the world predicts
                                    * along rolling paths from then on (w->features) */
                cc_circle c;
                cc_circle_props p;
                int id;
                memset(&c, 0, sizeof c);
                c.pos.x = c.pos.y = -1000.0 * L;
                c.vel.x = 1.0;
                c.radius = s.r_typ;
                c.mass = 1.0;
                id = cc_world_add_circle(b.w, &c);
                p.struct_size = sizeof p;
                cc_world_get_circle_props(b.w, id, &p);
                p.rolling_decel = 1e-9;
                cc_world_set_circle_props(b.w, id, &p);
            }
            if (var == ROLL_ALL) { /* decel = 1% of the mean speed over the run's time */
                double vsum = 0.0;
                for (i = 0; i < s.n; i++)
                    vsum += sqrt(s.c[i].vel.x * s.c[i].vel.x + s.c[i].vel.y * s.c[i].vel.y);
                for (i = 0; i < s.n; i++) {
                    cc_circle_props p;
                    p.struct_size = sizeof p;
                    cc_world_get_circle_props(b.w, i, &p);
                    p.rolling_decel = 0.01 * vsum / s.n / (t_run + 1.0 / 60);
                    cc_world_set_circle_props(b.w, i, &p);
                }
            }
            if (var == SENSORS) /* 16 pockets of radius r_typ spread over the gas: same collisions */
                for (i = 0; i < 16; i++) {
                    cc_circle c;
                    cc_circle_props p;
                    int id;
                    memset(&c, 0, sizeof c);
                    c.pos.x = L * (0.125 + 0.25 * (i % 4));
                    c.pos.y = L * (0.125 + 0.25 * (i / 4));
                    c.radius = s.r_typ;
                    c.mass = INFINITY;
                    id = cc_world_add_circle(b.w, &c);
                    p.struct_size = sizeof p;
                    cc_world_get_circle_props(b.w, id, &p);
                    p.sensor = 1;
                    cc_world_set_circle_props(b.w, id, &p);
                }
            step(b.w, 1.0 / 60);
            t0 = bench_now();
            for (i = 0; i < (int)(t_run * 60); i++)
                step(b.w, 1.0 / 60);
            coll[var] = collisions(b.w);
            cost[var][k] = (bench_now() - t0) * 1e9 / (double)coll[var];
            world_free(&b);
        }
    }
    printf("%-34s %14s %22s %12s %8s %10s\n", "variant", "ns/collision", "spread", "collisions", "ratio",
           "min ratio");
    for (v = N_VARIANTS - 1; v >= 0; v--) {
        /* ratio: median over rounds of the per-round ratio (neighbours in time share the noise) */
        double *ratio = bench_alloc((size_t)reps * sizeof *ratio);
        for (k = 0; k < reps; k++)
            ratio[k] = cost[v][k] / cost[BASE][k];
        rat[v] = bench_median(ratio, (size_t)reps);
        free(ratio);
        /* noise only ever adds time: the ratio of the fastest runs is the steadier estimate */
        bench_range(cost[v], (size_t)reps, &lo_v, &hi_v);
        bench_range(cost[BASE], (size_t)reps, &lo_b, &hi_b);
        rat_min[v] = lo_v / lo_b;
    }
    for (v = 0; v < N_VARIANTS; v++) {
        double lo, hi, med;
        bench_range(cost[v], (size_t)reps, &lo, &hi);
        med = bench_median(cost[v], (size_t)reps);
        (void)base;
        printf("%-34s %14.2f %10.2f - %-9.2f %12llu %8.3f %10.3f%s\n", names[v], med, lo, hi,
               (unsigned long long)coll[v], rat[v], rat_min[v],
               coll[v] == coll[BASE] ? "" : v == HALF_FILTERED || v == ROLL_ALL ? "  (other collisions: by design)" : "  (different collisions!)");
        if (csv != NULL)
            fprintf(csv, "\"%s\",%.6g,%.6g,%.6g,%llu,%.6g,%.6g\n", names[v], med, lo, hi, (unsigned long long)coll[v],
                    rat[v], rat_min[v]);
        if (v == FAR_WALLS)
            bench_figure("feature_cost_far_walls", rat_min[v]);
        if (v == FAR_IMMOVABLE)
            bench_figure("feature_cost_far_immovable", rat_min[v]);
        if (v == SEG_CAP)
            bench_figure("feature_cost_segment_capacity", rat_min[v]);
        if (v == PROPS_ALL)
            bench_figure("feature_cost_props_all", rat_min[v]);
        if (v == SENSORS)
            bench_figure("feature_cost_16_sensors", rat_min[v]);
        if (v == HALF_FILTERED)
            bench_figure("feature_cost_half_filtered", rat_min[v]);
        if (v == ROLL_FAR)
            bench_figure("feature_cost_one_rolling_far", rat_min[v]);
        if (v == ROLL_ALL)
            bench_figure("feature_cost_all_rolling", rat_min[v]);
        free(cost[v]);
    }
    bench_scene_free(&s);
    if (csv != NULL)
        fclose(csv);
    return 0;
}

/* The periodic hard-disk gas of N disks of diameter 1 at area fraction eta (the lattice start of
 * seed), in a world of the given uses: stepped away from the lattice, then timed over per_disk
 * collisions per disk. Writes the cost per collision and the world's collisions at the end;
 * returns 0, or 1 when the world cannot be made. */
static int gas_cost(int n, double eta, uint64_t seed, unsigned uses, double per_disk, double *ns_per_collision,
                    uint64_t *total)
{
    double side, t0, c0;
    bench_scene sc;
    cc_world_def def;
    world_box b;
    int i;
    bench_scene_disks(&sc, n, eta, seed, &side);
    cc_world_def_init(&def);
    def.max_circles = n;
    def.period.x = def.period.y = side;
    def.uses = uses;
    b.bytes = cc_world_size(&def);
    b.mem = bench_alloc(b.bytes);
    b.w = cc_world_init(b.mem, b.bytes, &def, NULL);
    if (b.w == NULL) {
        bench_scene_free(&sc);
        free(b.mem);
        return 1;
    }
    for (i = 0; i < n; i++)
        cc_world_add_circle(b.w, &sc.c[i]);
    bench_scene_free(&sc);
    step(b.w, 5.0); /* away from the lattice */
    c0 = (double)collisions(b.w);
    t0 = bench_now();
    while ((double)collisions(b.w) - c0 < per_disk * n)
        step(b.w, 0.5);
    *ns_per_collision = (bench_now() - t0) * 1e9 / ((double)collisions(b.w) - c0);
    *total = collisions(b.w);
    world_free(&b);
    return 0;
}

/* Hard disks in a periodic box (issue 15): the cost per collision of N = 4000 disks of diameter
 * 1 at area fractions 0.3, 0.5 and 0.7 (20 collisions per disk each, after leaving the lattice),
 * as ratios to 0.3 within each round: a denser fluid collides more often, and each collision
 * should cost about the same. */
static int cmd_disks(const opts *o)
{
    static const double etas[3] = {0.3, 0.5, 0.7};
    int n = 4000, reps = o->quick ? 3 : 7, k, e;
    double cost[3][16], med[3], lo[3], hi[3];
    for (k = 0; k < reps; k++)
        for (e = 0; e < 3; e++) {
            int v = (e + k) % 3;
            uint64_t total;
            if (gas_cost(n, etas[v], 99 + (uint64_t)k, CC_USES_ALL, 20.0, &cost[v][k], &total) != 0) {
                fprintf(stderr, "bench_world disks: init failed\n");
                return 1;
            }
        }
    printf("%-28s %14s %22s %10s\n", "periodic hard disks N=4000", "ns/collision", "spread", "ratio");
    for (e = 0; e < 3; e++) {
        double ratio[16];
        for (k = 0; k < reps; k++)
            ratio[k] = cost[e][k] / cost[0][k];
        med[e] = bench_median(cost[e], (size_t)reps);
        bench_range(cost[e], (size_t)reps, &lo[e], &hi[e]);
        printf("area fraction %-14.1f %14.1f %10.1f - %-9.1f %10.3f\n", etas[e], med[e], lo[e], hi[e],
               bench_median(ratio, (size_t)reps));
    }
    return 0;
}

/* Worlds that reserve only what they use (def.uses): the bytes per circle cc_world_size asks for
 * with uses = 0, PROPS and ALL (EXACT, open and periodic), then the plain periodic gas (hard
 * disks at area fraction 0.3, nothing of 1.1 used) run with uses = 0 and with ALL in the same
 * rounds, the order alternating: the medians of the cost per collision, and the median over
 * rounds of the per-round ratio uses = 0 / ALL. The two worlds must run the same collisions. */
static int cmd_uses(const opts *o)
{
    static const unsigned uses[3] = {0u, CC_USES_PROPS, CC_USES_ALL};
    static const char *uses_name[3] = {"0", "PROPS", "ALL"};
    int ns[2] = {10000, 1000000}, nn = o->quick || o->max_n < 1000000 ? 1 : 2, a, u, p, k;
    FILE *csv = open_csv(o->csv, "row,n,value,lo,hi");
    if (o->quick)
        ns[0] = 2000;
    printf("%-12s %10s %12s %12s %12s\n", "memory", "N", "uses=0", "uses=PROPS", "uses=ALL");
    for (a = 0; a < 2; a++)
        for (p = 0; p < 2; p++) {
            double per[3];
            for (u = 0; u < 3; u++) {
                cc_world_def def;
                cc_world_def_init(&def);
                def.max_circles = ns[a];
                def.uses = uses[u];
                if (p)
                    def.period.x = def.period.y = 1000.0;
                per[u] = (double)cc_world_size(&def) / ns[a];
                if (csv != NULL)
                    fprintf(csv, "\"bytes per circle, EXACT%s, uses=%s\",%d,%.6g,,\n", p ? " periodic" : "",
                            uses_name[u], ns[a], per[u]);
            }
            printf("%-12s %10d %12.1f %12.1f %12.1f\n", p ? "periodic" : "open", ns[a], per[0], per[1], per[2]);
            if (!p)
                bench_figure(a ? "uses_none_bytes_per_circle_1e6" : "uses_none_bytes_per_circle_1e4", per[0]);
        }
    printf("%-34s %14s %22s %12s %8s\n", "periodic gas, EXACT", "ns/collision", "spread", "collisions", "ratio");
    for (a = 0; a < nn; a++) {
        int n = ns[a], reps = o->quick ? 3 : a ? 3 : 7;
        double cost[2][16], ratio[16], lo, hi, per_disk = a ? 5.0 : 20.0;
        uint64_t coll[2] = {0, 0};
        for (k = 0; k < reps; k++)
            for (u = 0; u < 2; u++) {
                int v = (u + k) % 2;
                uint64_t total;
                if (gas_cost(n, 0.3, 99 + (uint64_t)k, v ? CC_USES_ALL : 0u, per_disk, &cost[v][k], &total) != 0) {
                    fprintf(stderr, "bench_world uses: init failed\n");
                    return 1;
                }
                if (k == 0)
                    coll[v] = total;
            }
        for (u = 0; u < 2; u++) {
            bench_range(cost[u], (size_t)reps, &lo, &hi);
            printf("N=%-7d uses=%-22s %14.2f %10.2f - %-9.2f %12llu\n", n, u ? "ALL" : "0",
                   bench_median(cost[u], (size_t)reps), lo, hi, (unsigned long long)coll[u]);
            if (csv != NULL)
                fprintf(csv, "\"periodic gas ns/collision, uses=%s\",%d,%.6g,%.6g,%.6g\n", u ? "ALL" : "0", n,
                        bench_median(cost[u], (size_t)reps), lo, hi);
        }
        for (k = 0; k < reps; k++)
            ratio[k] = cost[0][k] / cost[1][k];
        bench_range(ratio, (size_t)reps, &lo, &hi);
        printf("N=%-7d %-27s %14.3f %10.3f - %-9.3f%s\n", n, "ratio uses=0 / ALL", bench_median(ratio, (size_t)reps),
               lo, hi, coll[0] == coll[1] ? "" : "  (different collisions!)");
        if (csv != NULL)
            fprintf(csv, "\"periodic gas ratio uses=0 / ALL\",%d,%.6g,%.6g,%.6g\n", n, bench_median(ratio, (size_t)reps),
                    lo, hi);
        bench_figure(a ? "uses_none_speed_ratio_1e6" : "uses_none_speed_ratio_1e4", bench_median(ratio, (size_t)reps));
    }
    if (csv != NULL)
        fclose(csv);
    return 0;
}

/* The table (issue 36): a walled 20 x 10 box, 80 circles of radius 0.4 on a lattice, moving at
 * one speed in random directions, 3,000 steps of 0.05 (300 with --quick) in each mode, at speeds
 * of 0.25 to 16 radii a step (|v| dt / r). escapes: circle-steps with a centre outside the box
 * after a step; lost: circles outside at the end. Walls keep their side in every mode, so both
 * must be 0 at every speed (circles may still pass through each other in DISCRETE and SWEPT). */
static long table_run(int mode, double per_r, int steps, long *lost, double *sec)
{
    static const cc_segment box[4] = {{{0, 0}, {20, 0}}, {{20, 0}, {20, 10}}, {{20, 10}, {0, 10}}, {{0, 10}, {0, 0}}};
    const double r = 0.4, dt = 0.05, speed = per_r * r / dt;
    cc_world_def def;
    cc_world *w;
    cc_circle c[80];
    bench_rng rng = {36};
    void *mem;
    size_t bytes;
    long out = 0;
    int i, k, st;
    double t0;
    cc_world_def_init(&def);
    def.mode = mode;
    def.max_circles = 80;
    def.max_segments = 4;
    bytes = cc_world_size(&def);
    mem = bench_alloc(bytes);
    w = cc_world_init(mem, bytes, &def, &st);
    for (i = 0; i < 4; i++)
        (void)cc_world_add_segment(w, &box[i]);
    for (i = 0; i < 80; i++) {
        double a = bench_uniform(&rng, 0.0, 6.283185307179586);
        cc_circle q = {{1.0 + 2.0 * (i % 10), 0.625 + 1.25 * (i / 10)}, {speed * cos(a), speed * sin(a)}, r, 1.0};
        (void)cc_world_add_circle(w, &q);
    }
    *sec = 0.0;
    for (k = 0; k < steps; k++) {
        t0 = bench_now();
        step(w, dt);
        *sec += bench_now() - t0;
        (void)cc_world_get_circles(w, NULL, c, 80);
        for (i = 0; i < 80; i++)
            out += !(c[i].pos.x > 0.0 && c[i].pos.x < 20.0 && c[i].pos.y > 0.0 && c[i].pos.y < 10.0);
    }
    *lost = 0;
    for (i = 0; i < 80; i++)
        *lost += !(c[i].pos.x > 0.0 && c[i].pos.x < 20.0 && c[i].pos.y > 0.0 && c[i].pos.y < 10.0);
    *sec /= steps;
    free(mem);
    return out;
}

static int cmd_table(const opts *o)
{
    static const double per_r[] = {0.25, 0.5, 1.0, 1.05, 2.0, 4.0, 8.0, 16.0};
    int mode, k, steps = o->quick ? 300 : 3000;
    long bad = 0;
    printf("%-8s %8s %10s %6s %12s\n", "mode", "|v|dt/r", "escapes", "lost", "us/step");
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++)
        for (k = 0; k < (int)(sizeof per_r / sizeof per_r[0]); k++) {
            long lost;
            double sec;
            long esc = table_run(mode, per_r[k], steps, &lost, &sec);
            printf("%-8s %8.2f %10ld %6ld %12.2f\n", mode_name[mode], per_r[k], esc, lost, 1e6 * sec);
            printf("figure table_%s_escapes_at_%g_r %ld\n", mode_name[mode], per_r[k], esc);
            bad += esc + lost;
        }
    printf("figure table_escapes_total %ld\n", bad);
    return 0;
}

/* A step that jams (issue 36): a kinematic circle (mass +INFINITY, speed 1) driving into a row of
 * rolling circles (deceleration 0.5, restitution 0.5): its impacts come ever closer in time and
 * EXACT stops at max_events. The time of a capped step at caps of 1e4, 1e5 (and 1e6 without
 * --quick), per event and in all, next to the time per event of the same world's circles as a
 * plain gas (no kinematic circle, no friction) measured in the same run: what the header's
 * "Collapse" quotes. Medians of 3 runs with their spread. */
static double jam_run(int n, uint64_t cap, int jam, uint64_t *events)
{
    cc_world_def def;
    cc_world *w;
    cc_world_stats s;
    void *mem;
    size_t bytes;
    int i, st;
    double t0, t1;
    cc_world_def_init(&def);
    def.max_circles = n + 1;
    def.max_events = cap;
    if (jam) {
        def.rolling_decel = 0.5;
        def.restitution = 0.5;
    }
    bytes = cc_world_size(&def);
    mem = bench_alloc(bytes);
    w = cc_world_init(mem, bytes, &def, &st);
    for (i = 0; i < n; i++) {
        cc_circle c = {{(i % 10) * 2.2, (i / 10) * 2.2}, {0, 0}, 1, 1};
        if (!jam)
            c.vel.x = (i * 7) % 5 - 2.0, c.vel.y = (i * 3) % 5 - 2.0;
        (void)cc_world_add_circle(w, &c);
    }
    if (jam) {
        cc_circle k = {{-3, 0}, {1, 0}, 1, INFINITY};
        (void)cc_world_add_circle(w, &k);
    }
    (void)cc_world_step(w, 0.0);
    t0 = bench_now();
    (void)cc_world_step(w, jam ? 30.0 : 200.0);
    t1 = bench_now();
    s.struct_size = sizeof s;
    (void)cc_world_get_stats(w, &s);
    *events = s.events;
    free(mem);
    return t1 - t0;
}

/* The automatic cap of a 1.2 def (max_events = 0): a jammed step's time at N = 100 and 1,000
 * circles, and what ordinary steps spend of it: a pool break taken in one call and in 1/60 s
 * steps, and a periodic gas (area fraction 0.5) stepped a few collisions per disk per call, its
 * largest step in events per circle (the cap is 32 per circle: the margin is their ratio). */
static void jam_auto(const opts *o)
{
    static const int ns[2] = {100, 1000};
    int a, k, rep;
    for (a = 0; a < 2; a++) {
        double t[3], lo, hi, tmed;
        uint64_t ev = 0;
        for (rep = 0; rep < 3; rep++)
            t[rep] = jam_run(ns[a], 0u, 1, &ev);
        bench_range(t, 3, &lo, &hi);
        tmed = bench_median(t, 3);
        printf("jam of %d circles, automatic cap: %llu events, %.3g s (%.3g-%.3g), %.3g us/event\n", ns[a],
               (unsigned long long)ev, tmed, lo, hi, 1e6 * tmed / (double)ev);
        printf("figure jam_auto_seconds_n%d %.4g\n", ns[a], tmed);
    }
    for (k = 0; k < 2; k++) { /* the pool break: in one call of its whole 2 s, then at 1/60 s */
        bench_scene sc;
        cc_world_def def;
        world_box b;
        cc_world_stats s0, s1;
        uint64_t most = 0;
        int i, st, capped = 0, steps = k ? 120 : 1;
        bench_scene_pool(&sc);
        cc_world_def_init(&def);
        def.max_circles = sc.n;
        def.max_segments = sc.n_walls;
        b.bytes = cc_world_size(&def);
        b.mem = bench_alloc(b.bytes);
        b.w = cc_world_init(b.mem, b.bytes, &def, &st);
        for (i = 0; i < sc.n_walls; i++)
            (void)cc_world_add_segment(b.w, &sc.walls[i]);
        for (i = 0; i < sc.n; i++)
            (void)cc_world_add_circle(b.w, &sc.c[i]);
        for (i = 0; i < steps; i++) {
            s0 = bench_stats(b.w);
            capped += cc_world_step(b.w, sc.t_end / steps) == CC_EVENT_LIMIT;
            s1 = bench_stats(b.w);
            if (s1.events - s0.events > most)
                most = s1.events - s0.events;
        }
        printf("pool break in %d step%s (automatic cap 10000): at most %llu events a step, %d capped\n", steps,
               steps > 1 ? "s" : "", (unsigned long long)most, capped);
        printf("figure jam_auto_pool_events_%d_steps %llu\n", steps, (unsigned long long)most);
        bench_scene_free(&sc);
        world_free(&b);
    }
    for (k = 0; k < 2; k++) { /* a periodic gas of 1,000 disks, calls of dt 0.5 and 2 */
        const int n = 1000, steps = o->quick ? 10 : 40;
        const double dt = k ? 2.0 : 0.5;
        bench_scene sc;
        cc_world_def def;
        world_box b;
        cc_world_stats s0, s1;
        double side, most = 0.0, coll = 0.0;
        int i, st, capped = 0;
        bench_scene_disks(&sc, n, 0.5, 36, &side);
        cc_world_def_init(&def);
        def.max_circles = n;
        def.period.x = def.period.y = side;
        b.bytes = cc_world_size(&def);
        b.mem = bench_alloc(b.bytes);
        b.w = cc_world_init(b.mem, b.bytes, &def, &st);
        for (i = 0; i < n; i++)
            (void)cc_world_add_circle(b.w, &sc.c[i]);
        bench_scene_free(&sc);
        step(b.w, 5.0); /* away from the lattice */
        for (i = 0; i < steps; i++) {
            s0 = bench_stats(b.w);
            capped += cc_world_step(b.w, dt) == CC_EVENT_LIMIT;
            s1 = bench_stats(b.w);
            if ((double)(s1.events - s0.events) / n > most)
                most = (double)(s1.events - s0.events) / n;
            coll += 2.0 * (double)(s1.collisions - s0.collisions) / n;
        }
        printf("periodic gas of %d disks, phi 0.5, steps of %g: %.2f collisions per disk a step, at most %.2f "
               "events per circle a step (cap 32), %d capped\n", n, dt, coll / steps, most, capped);
        printf("figure jam_auto_gas_events_per_circle_dt%g %.4g\n", dt, most);
        world_free(&b);
    }
}

static int cmd_jam(const opts *o)
{
    static const uint64_t caps[] = {10000, 100000, 1000000};
    int n = 100, k, rep, ncaps = o->quick ? 2 : 3;
    double gas[3], lo, hi, gas_us;
    uint64_t ev;
    for (rep = 0; rep < 3; rep++)
        gas[rep] = 1e6 * jam_run(n, 10000000u, 0, &ev) / (double)(ev ? ev : 1);
    bench_range(gas, 3, &lo, &hi);
    gas_us = bench_median(gas, 3);
    printf("gas of %d circles: %.3g us/event (%.3g-%.3g)\n", n, gas_us, lo, hi);
    for (k = 0; k < ncaps; k++) {
        double t[3], tmed;
        for (rep = 0; rep < 3; rep++)
            t[rep] = jam_run(n, caps[k], 1, &ev);
        bench_range(t, 3, &lo, &hi);
        tmed = bench_median(t, 3);
        printf("jam of %d circles, cap %llu: %llu events, %.3g s (%.3g-%.3g), %.3g us/event, %.3g x the gas's\n", n,
               (unsigned long long)caps[k], (unsigned long long)ev, tmed, lo, hi, 1e6 * tmed / (double)ev,
               1e6 * tmed / (double)ev / gas_us);
        printf("figure jam_us_per_event_cap_%llu %.4g\n", (unsigned long long)caps[k], 1e6 * tmed / (double)ev);
        printf("figure jam_over_gas_per_event_cap_%llu %.4g\n", (unsigned long long)caps[k],
               1e6 * tmed / (double)ev / gas_us);
    }
    jam_auto(o);
    return 0;
}

static int cmd_dump_gas(int n, double phi)
{
    bench_scene s;
    int i;
    bench_scene_gas(&s, n, phi, 2);
    printf("# box %.17g %.17g %.17g %.17g\n", s.x0, s.y0, s.x1, s.y1);
    for (i = 0; i < s.n; i++)
        printf("%.17g %.17g %.17g %.17g %.17g %.17g\n", s.c[i].pos.x, s.c[i].pos.y, s.c[i].vel.x, s.c[i].vel.y,
               s.c[i].radius, s.c[i].mass);
    bench_scene_free(&s);
    return 0;
}

/* A peer's trajectory: int32 n, int32 steps, float64 dt, then (steps + 1) x n x (px py vx vy). */
static int cmd_check_trace(int n, double phi, const char *path)
{
    bench_scene s;
    bench_check k;
    FILE *f = fopen(path, "rb");
    int32_t hn, steps, i, j;
    double dt, *raw, e0 = 0.0;
    cc_circle *pre, *post;
    if (f == NULL || fread(&hn, 4, 1, f) != 1 || fread(&steps, 4, 1, f) != 1 || fread(&dt, 8, 1, f) != 1 || hn != n) {
        fprintf(stderr, "bench_world: bad trace %s\n", path);
        return 1;
    }
    bench_scene_gas(&s, n, phi, 2);
    bench_check_init(&k, n);
    raw = bench_alloc((size_t)n * 4 * sizeof *raw);
    pre = bench_alloc((size_t)n * sizeof *pre);
    post = bench_alloc((size_t)n * sizeof *post);
    for (i = 0; i <= steps; i++) {
        if (fread(raw, sizeof *raw, (size_t)n * 4, f) != (size_t)n * 4) {
            fprintf(stderr, "bench_world: trace %s ends early\n", path);
            return 1;
        }
        for (j = 0; j < n; j++) {
            post[j] = s.c[j];
            post[j].pos.x = raw[4 * j], post[j].pos.y = raw[4 * j + 1];
            post[j].vel.x = raw[4 * j + 2], post[j].vel.y = raw[4 * j + 3];
        }
        if (i == 0)
            e0 = bench_energy(post, n);
        else
            bench_check_step(&k, &s, pre, post, dt);
        memcpy(pre, post, (size_t)n * sizeof *pre);
    }
    fclose(f);
    printf("tunnelling=%ld escaped=%ld max_overlap_r=%.6g energy_drift=%.6g\n", k.tunnel_circle + k.tunnel_wall,
           k.escaped, k.max_overlap, fabs(bench_energy(post, n) - e0) / e0);
    bench_check_free(&k);
    bench_scene_free(&s);
    free(raw);
    free(pre);
    free(post);
    return 0;
}

/* Our world on the peers' terms: the same gas, n, phi, t_end and step, one line like theirs. */
static int cmd_peer_line(int n, double phi, double t_end, double dt)
{
    bench_scene s;
    run_result rr;
    bench_scene_gas(&s, n, phi, 2);
    s.t_end = t_end;
    memset(&rr, 0, sizeof rr);
    time_runs(&s, CC_MODE_EXACT, dt, 5, 0.2, &rr);
    checked_run(&s, CC_MODE_EXACT, dt, NULL, &rr);
    printf("peer circlecollide n=%d phi=%g dt=%g sec_per_sim_s=%.6g collisions=%llu collisions_per_s=%.6g "
           "tunnelling=%ld escaped=%ld max_overlap_r=%.6g energy_drift=%.6g\n",
           n, phi, dt, rr.sec_per_sim_s, (unsigned long long)rr.coll, rr.coll_per_s, rr.tunnel, rr.escaped,
           rr.max_overlap, rr.energy_drift);
    bench_scene_free(&s);
    return 0;
}

int main(int argc, char **argv)
{
    opts o;
    int k;
    memset(&o, 0, sizeof o);
    o.max_n = 1000000;
    if (argc < 2) {
        fprintf(stderr, "usage: %s matrix|headline|scaling|features|disks|uses|table|jam|dump-gas ... [--quick] [--csv FILE]\n", argv[0]);
        return 2;
    }
    if (!strcmp(argv[1], "dump-gas") && argc == 4)
        return cmd_dump_gas(atoi(argv[2]), atof(argv[3]));
    if (!strcmp(argv[1], "check-trace") && argc == 5)
        return cmd_check_trace(atoi(argv[2]), atof(argv[3]), argv[4]);
    if (!strcmp(argv[1], "peer") && argc == 6)
        return cmd_peer_line(atoi(argv[2]), atof(argv[3]), atof(argv[4]), atof(argv[5]));
    for (k = 2; k < argc; k++) {
        if (!strcmp(argv[k], "--quick"))
            o.quick = 1;
        else if (!strcmp(argv[k], "--csv") && k + 1 < argc)
            o.csv = argv[++k];
        else if (!strcmp(argv[k], "--max-n") && k + 1 < argc)
            o.max_n = atol(argv[++k]);
        else {
            fprintf(stderr, "bench_world: unknown argument %s\n", argv[k]);
            return 2;
        }
    }
    if (!strcmp(argv[1], "matrix"))
        return cmd_matrix(&o);
    if (!strcmp(argv[1], "headline"))
        return cmd_headline(&o);
    if (!strcmp(argv[1], "scaling"))
        return cmd_scaling(&o);
    if (!strcmp(argv[1], "features"))
        return cmd_features(&o);
    if (!strcmp(argv[1], "uses"))
        return cmd_uses(&o);
    if (!strcmp(argv[1], "disks"))
        return cmd_disks(&o);
    if (!strcmp(argv[1], "table"))
        return cmd_table(&o);
    if (!strcmp(argv[1], "jam"))
        return cmd_jam(&o);
    fprintf(stderr, "bench_world: unknown command %s\n", argv[1]);
    return 2;
}
