/* Hard disks: 1040 equal disks in a periodic box (no walls) at area fraction 0.70, near the
 * fluid-solid transition of hard disks (the liquid turns hexatic at about 0.70 to 0.72). They
 * start on a triangular lattice spread out to fill the box, with random velocities of zero total
 * momentum, and melt into a dense fluid that keeps rattling in the cages of its neighbours.
 * Each disk has its speed colour; one straddling an edge is painted on both sides. The caption
 * gives the pressure from the world's virial (cc_world_stats.virial):
 *     Z = P A / (N kT) = 1 + (virial(t1) - virial(t0)) / (2 (t1 - t0) N kT),  kT = E_kin / N
 * over the last second of world time (fewer frames at the start). Units: radius 1, mass 1. */
#include "scene.h"
#include "scene_util.h"
#include "prng.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define HD_COLS 40 /* lattice columns: 40 x 26 keeps the box at 16:9 */
#define HD_ROWS 26 /* even, so that the triangular lattice wraps in y */
#define HD_N (HD_COLS * HD_ROWS)
#define HD_ETA 0.70
#define HD_KT 100.0       /* thermal speed sqrt(kT / m) = 10 radii per unit of time */
#define HD_WINDOW 1.0     /* the pressure is measured over this much world time */
#define HD_SAMPLES 4096   /* (time, virial) at each frame, a ring */
#define HD_PI 3.14159265358979323846

typedef struct hd_state {
    double lx, ly;
    int head, count;
    double t[HD_SAMPLES], virial[HD_SAMPLES];
} hd_state;

static double virial_of(const demo_stage *s)
{
    cc_world_stats st;
    memset(&st, 0, sizeof st);
    st.struct_size = sizeof st;
    if (cc_world_get_stats(s->world, &st) != CC_OK)
        return 0.0;
    return st.virial;
}

/* Before the step to frame f: the world is at frame f - 1's time; remember its virial. */
static void hd_control(demo_show *show, long frame)
{
    hd_state *st = (hd_state *)show->state;
    demo_stage *s = &show->stage[0];
    (void)frame;
    st->t[st->head] = cc_world_time(s->world);
    st->virial[st->head] = virial_of(s);
    st->head = (st->head + 1) % HD_SAMPLES;
    if (st->count < HD_SAMPLES)
        ++st->count;
}

/* Z over the last HD_WINDOW of world time (the oldest sample not older than that); 0 when there
 * is no interval yet. *span gets the interval's length. */
static double hd_pressure(demo_show *show, double *span)
{
    const hd_state *st = (const hd_state *)show->state;
    const demo_stage *s = &show->stage[0];
    double now = cc_world_time(s->world), kt, t0 = now, v0 = 0.0;
    int k, found = 0;
    for (k = st->count; k >= 1; --k) { /* oldest first */
        int i = (st->head - k + HD_SAMPLES) % HD_SAMPLES;
        if (now - st->t[i] <= HD_WINDOW + 1e-9) {
            t0 = st->t[i];
            v0 = st->virial[i];
            found = 1;
            break;
        }
    }
    *span = now - t0;
    kt = s->count > 0 ? demo_stage_energy(s) / s->count : 0.0;
    if (!found || !(now > t0) || !(kt > 0.0))
        return 0.0;
    return 1.0 + (virial_of(s) - v0) / (2.0 * (now - t0) * s->count * kt);
}

static void hd_caption(demo_show *show, int stage, char *buf, size_t size)
{
    double span, z = hd_pressure(show, &span);
    int n = 0;
    (void)stage;
    /* the long form where it fits (at 640 pixels), a short one in a thumbnail */
    if (show->opt->width >= 320)
        n = snprintf(buf, size, "%d HARD DISKS   AREA FRACTION %.2f", HD_N, HD_ETA);
    else
        n = snprintf(buf, size, "HARD DISKS %.2f", HD_ETA);
    if (z > 0.0 && n > 0 && (size_t)n < size)
        snprintf(buf + n, size - (size_t)n, show->opt->width >= 320 ? "   PRESSURE Z = %.2f"
                                                                      : "  Z %.2f", z);
}

static void hd_report(demo_show *show, FILE *f)
{
    double span, z = hd_pressure(show, &span);
    const demo_stage *s = &show->stage[0];
    if (z > 0.0)
        fprintf(f,
                "  pressure Z = PA/(N kT) = %.3f over the last %.3f of world time (N = %d, area "
                "fraction %.2f, kT = %.2f)\n",
                z, span, s->count, HD_ETA, demo_stage_energy(s) / s->count);
}

int demo_scene_hard_disks(demo_show *show)
{
    demo_stage_def d;
    demo_stage *s = &show->stage[0];
    demo_rng rng;
    hd_state *st;
    double a, lx, ly, px = 0.0, py = 0.0, e = 0.0, k;
    double *vx, *vy;
    int i, j, n, r;

    /* eta = N pi r^2 / (Lx Ly) with Lx Ly = N a^2 sqrt(3) / 2: the lattice spacing a */
    a = sqrt(2.0 * HD_PI / (sqrt(3.0) * HD_ETA));
    lx = HD_COLS * a;
    ly = HD_ROWS * a * 0.5 * sqrt(3.0);

    st = (hd_state *)calloc(1, sizeof *st);
    vx = (double *)malloc(HD_N * sizeof *vx);
    vy = (double *)malloc(HD_N * sizeof *vy);
    if (st == NULL || vx == NULL || vy == NULL) {
        free(st);
        free(vx);
        free(vy);
        return -100;
    }
    st->lx = lx;
    st->ly = ly;
    show->state = st;

    demo_stage_def_init(&d, show->opt->mode);
    d.max_circles = HD_N;
    d.x0 = 0.0;
    d.y0 = 0.0;
    d.x1 = lx;
    d.y1 = ly;
    d.speed_ref = 3.0 * sqrt(HD_KT); /* Rayleigh speeds: red is about the fastest 1% */
    d.impulse_ref = 1.0;
    d.trail_time = 0.0;  /* thousands of collisions a frame: no trails, no flashes */
    r = demo_stage_init_periodic(s, &d, lx, ly);
    if (r != 0) {
        free(vx);
        free(vy);
        return r;
    }
    show->nstages = 1;

    /* random velocities, then the mean taken off (zero momentum) and scaled to E = N kT */
    demo_rng_seed(&rng, show->opt->seed);
    for (i = 0; i < HD_N; ++i) {
        vx[i] = 2.0 * demo_rng_unit(&rng) - 1.0;
        vy[i] = 2.0 * demo_rng_unit(&rng) - 1.0;
        px += vx[i];
        py += vy[i];
    }
    for (i = 0; i < HD_N; ++i) {
        vx[i] -= px / HD_N;
        vy[i] -= py / HD_N;
        e += 0.5 * (vx[i] * vx[i] + vy[i] * vy[i]);
    }
    k = sqrt(HD_N * HD_KT / e);
    n = 0;
    for (j = 0; j < HD_ROWS; ++j)
        for (i = 0; i < HD_COLS; ++i, ++n) {
            double x = (i + 0.25 + 0.5 * (j % 2)) * a, y = (j + 0.5) * a * 0.5 * sqrt(3.0);
            cc_circle c = demo_circle(x, y, k * vx[n], k * vy[n], 1.0, 1.0);
            if (demo_stage_add_circle(s, &c, DEMO_STYLE_SPEED) < 0)
                break;
        }
    free(vx);
    free(vy);
    show->control = hd_control;
    show->caption = hd_caption;
    show->report = hd_report;
    return s->error;
}
