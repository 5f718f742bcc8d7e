/* The cost of a step with little or nothing to do (EXACT): "a scene pays only for what it uses",
 * so a world of N circles at rest should step about as fast as an empty one, and N circles that
 * move a little per step (a few cell crossings, no collisions) should pay for those events only.
 * What is left is cc_world_step's own work: its checks of what the step may reach (src/world/
 * step.c: decided from bounds the world keeps, in O(1), instead of a pass over every circle).
 *
 * Usage: bench_idle [--quick] [--csv FILE]
 *
 * Variants, each a world of capacity N stepped by dt = 1 ms after one step that builds it:
 *   empty         no circles (the baseline: the ratio column divides by it, round by round)
 *   rest          N circles at rest on a square lattice (spacing 3, radius 0.5, each moved by up
 *                 to 1 along x and y: no contacts, and crossings at a steady rate when they move)
 *   moving        the same circles at velocities up to 1e-3 along each axis: about 0.01 cell
 *                 crossings per step (10,000 circles), no collisions
 * Rounds rotate the variants; each timing is the mean over enough steps to take min_time, the
 * table gives the median over rounds with its spread (min - max). Prints `figure` lines. */
#include "bench_util.h"

#include "bench_scenes.h"
#include "circlecollide.h"

enum { EMPTY, REST, MOVING, N_VARIANTS };
static const char *names[N_VARIANTS] = {"empty world", "N circles at rest", "N circles moving slowly (few events)"};

static uint64_t events(const cc_world *w) { return bench_stats(w).events; }

static void step(cc_world *w, double dt) { bench_step(w, dt, "bench_idle"); }

/* ns per step of variant v with n circles; *ev = events per step */
static double time_variant(int v, int n, double min_time, double *ev)
{
    cc_world_def def;
    cc_world *w;
    void *mem;
    size_t bytes;
    bench_rng rng = {42};
    int side = (int)ceil(sqrt((double)n)), i;
    long steps = 0;
    double t0, spent;
    uint64_t e0;
    cc_world_def_init(&def);
    def.max_circles = n;
    def.mode = CC_MODE_EXACT;
    bytes = cc_world_size(&def);
    mem = bench_alloc(bytes);
    w = cc_world_init(mem, bytes, &def, NULL);
    if (w == NULL) {
        fprintf(stderr, "bench_idle: cc_world_init failed\n");
        exit(1);
    }
    for (i = 0; v != EMPTY && i < n; i++) {
        cc_circle c;
        c.pos.x = 3.0 * (i % side) + bench_uniform(&rng, 0.0, 1.0); /* off the lattice of cells: */
        c.pos.y = 3.0 * (i / side) + bench_uniform(&rng, 0.0, 1.0); /* crossings at a steady rate */
        c.vel.x = v == MOVING ? bench_uniform(&rng, -1e-3, 1e-3) : 0.0;
        c.vel.y = v == MOVING ? bench_uniform(&rng, -1e-3, 1e-3) : 0.0;
        c.radius = 0.5;
        c.mass = 1.0;
        if (cc_world_add_circle(w, &c) != i) {
            fprintf(stderr, "bench_idle: cc_world_add_circle failed\n");
            exit(1);
        }
    }
    step(w, 1e-3); /* the grid and every prediction */
    e0 = events(w);
    t0 = bench_now();
    do {
        for (i = 0; i < 256; i++)
            step(w, 1e-3);
        steps += 256;
        spent = bench_now() - t0;
    } while (spent < min_time);
    *ev = (double)(events(w) - e0) / (double)steps;
    free(mem);
    return spent * 1e9 / (double)steps;
}

int main(int argc, char **argv)
{
    int quick = 0, n, reps, k, v;
    const char *csv_path = NULL;
    double *cost[N_VARIANTS], ev[N_VARIANTS], min_time;
    FILE *csv = NULL;
    for (k = 1; k < argc; k++) {
        if (!strcmp(argv[k], "--quick"))
            quick = 1;
        else if (!strcmp(argv[k], "--csv") && k + 1 < argc)
            csv_path = argv[++k];
        else {
            fprintf(stderr, "usage: %s [--quick] [--csv FILE]\n", argv[0]);
            return 2;
        }
    }
    n = 10000;
    reps = quick ? 3 : 9;
    min_time = quick ? 0.02 : 0.1;
    for (v = 0; v < N_VARIANTS; v++) {
        cost[v] = bench_alloc((size_t)reps * sizeof(double));
        ev[v] = 0.0;
    }
    for (k = 0; k < reps; k++)
        for (v = 0; v < N_VARIANTS; v++) {
            int var = (v + k) % N_VARIANTS;
            double e;
            cost[var][k] = time_variant(var, n, min_time, &e);
            ev[var] += e / reps;
        }
    if (csv_path != NULL && (csv = fopen(csv_path, "w")) != NULL)
        fprintf(csv, "variant,n,ns_per_step,ns_min,ns_max,ratio_to_empty,events_per_step\n");
    printf("EXACT, steps of 1 ms, N = %d, %d rounds\n", n, reps);
    printf("%-40s %12s %22s %16s %14s\n", "variant", "ns/step", "spread", "ratio to empty", "events/step");
    for (v = 0; v < N_VARIANTS; v++) {
        double ratio[64], lo, hi, med, rat;
        for (k = 0; k < reps; k++)
            ratio[k] = cost[v][k] / cost[EMPTY][k]; /* same round: neighbours in time share the noise */
        rat = bench_median(ratio, (size_t)reps);
        bench_range(cost[v], (size_t)reps, &lo, &hi);
        med = bench_median(cost[v], (size_t)reps);
        printf("%-40s %12.1f %10.1f - %-9.1f %16.2f %14.3g\n", names[v], med, lo, hi, rat, ev[v]);
        if (csv != NULL)
            fprintf(csv, "\"%s\",%d,%.6g,%.6g,%.6g,%.6g,%.6g\n", names[v], v == EMPTY ? 0 : n, med, lo, hi, rat, ev[v]);
        if (v == EMPTY)
            bench_figure("idle_empty_step_ns", med);
        if (v == REST)
            bench_figure("idle_rest_n10000_over_empty", rat);
        if (v == MOVING)
            bench_figure("idle_moving_n10000_over_empty", rat);
    }
    if (csv != NULL)
        fclose(csv);
    for (v = 0; v < N_VARIANTS; v++)
        free(cost[v]);
    return 0;
}
