/* The batch add (1.2) against the calls it stands for, in the same run: cc_world_add_circles of
 * N circles against N cc_world_add_circle calls, each into a fresh world of the gas's N circles
 * (bench_world's gas at 0.3) whose memory was touched before the clock starts. Medians and
 * spreads over rounds that alternate which goes first; the ratio is per round. Both worlds must
 * end with the same hash.
 *
 *   bench_bulk add [--quick]      N = 1e4 and 1e6 (1e3 and 1e4 with --quick) */
#include "bench_scenes.h"
#include "bench_util.h"

#include "circlecollide.h"

/* A world for s's circles (EXACT, its four walls), in memory touched before the clock starts,
 * so that both variants pay the same page faults outside the timing. */
static cc_world *make_world(const bench_scene *s, void **mem)
{
    cc_world_def d;
    size_t n;
    cc_world *w;
    int i;
    cc_world_def_init(&d);
    d.max_circles = s->n;
    d.max_segments = 4;
    n = cc_world_size(&d);
    *mem = bench_alloc(n);
    memset(*mem, 1, n);
    w = cc_world_init(*mem, n, &d, NULL);
    if (w == NULL) {
        fprintf(stderr, "bench_bulk: cc_world_init failed\n");
        exit(2);
    }
    for (i = 0; i < s->n_walls; i++)
        cc_world_add_segment(w, &s->walls[i]);
    return w;
}

static int cmd_add(int quick)
{
    static const int full[2] = {10000, 1000000}, small[2] = {1000, 10000};
    const int *sizes = quick ? small : full;
    int v;
    printf("%9s %7s %16s %22s %16s %22s %22s\n", "N", "rounds", "singles ns/circ", "spread", "batch ns/circ",
           "spread", "batch/singles [min-max]");
    for (v = 0; v < 2; v++) {
        int n = sizes[v], rounds = n >= 1000000 ? 5 : 15, r;
        double t_one[16], t_all[16], ratio[16], lo[3], hi[3];
        bench_scene s;
        uint64_t h_one = 0, h_all = 0;
        int *ids = bench_alloc((size_t)n * sizeof *ids);
        bench_scene_gas(&s, n, 0.3, 5);
        for (r = 0; r < rounds; r++) {
            int var;
            for (var = 0; var < 2; var++) { /* alternate which goes first */
                int which = (var + r) & 1, i, rc = 0;
                void *mem;
                cc_world *w = make_world(&s, &mem);
                double t0 = bench_now(), t1;
                if (which == 0)
                    for (i = 0; i < n; i++)
                        rc |= cc_world_add_circle(w, &s.c[i]) < 0;
                else
                    rc = cc_world_add_circles(w, s.c, n, ids, NULL) != n;
                t1 = bench_now();
                if (rc) {
                    fprintf(stderr, "bench_bulk: an add failed\n");
                    exit(2);
                }
                (which == 0 ? t_one : t_all)[r] = (t1 - t0) * 1e9 / n;
                if (which == 0)
                    h_one = cc_world_hash(w);
                else
                    h_all = cc_world_hash(w);
                free(mem);
            }
            ratio[r] = t_all[r] / t_one[r];
        }
        bench_range(t_one, (size_t)rounds, &lo[0], &hi[0]);
        bench_range(t_all, (size_t)rounds, &lo[1], &hi[1]);
        bench_range(ratio, (size_t)rounds, &lo[2], &hi[2]);
        printf("%9d %7d %16.1f %10.1f - %-9.1f %16.1f %10.1f - %-9.1f %8.3f [%.3f-%.3f]%s\n", n, rounds,
               bench_median(t_one, (size_t)rounds), lo[0], hi[0], bench_median(t_all, (size_t)rounds), lo[1], hi[1],
               bench_median(ratio, (size_t)rounds), lo[2], hi[2],
               h_one == h_all ? "" : "  (the worlds differ!)");
        {
            char name[64];
            snprintf(name, sizeof name, "add_circles_over_singles_n%d", n);
            bench_figure(name, bench_median(ratio, (size_t)rounds));
        }
        fflush(stdout);
        free(ids);
        bench_scene_free(&s);
    }
    return 0;
}

int main(int argc, char **argv)
{
    int quick = argc > 2 && !strcmp(argv[2], "--quick");
    if (argc >= 2 && !strcmp(argv[1], "add"))
        return cmd_add(quick);
    fprintf(stderr, "usage: %s add [--quick]\n", argv[0]);
    return 2;
}
