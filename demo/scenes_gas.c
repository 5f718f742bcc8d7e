/* A gas: 2000 equal circles in a box, all starting at the same speed in random directions, and
 * one heavy disc among them. Collisions spread the speeds into the Maxwell-Boltzmann
 * distribution (the colours go from one green to all hues) and jostle the heavy disc about
 * (Brownian motion). Units: small radius 1. */
#include "scene.h"
#include "scene_util.h"
#include "prng.h"

#include <stdio.h>

#define GAS_N 2000
#define GAS_W 240.0
#define GAS_H 135.0
#define GAS_SPEED 20.0
#define GAS_COLS 60
#define GAS_ROWS 34
#define HEAVY_R 10.0
#define HEAVY_M 25.0 /* equipartition: it ends up at about 1/5 of the small ones' speed */

static void gas_caption(demo_show *show, int stage, char *buf, size_t size)
{
    (void)show;
    (void)stage;
    snprintf(buf, size, "GAS   %d CIRCLES AND A HEAVY ONE", GAS_N);
}

int demo_scene_gas(demo_show *show)
{
    demo_stage_def d;
    demo_stage *s = &show->stage[0];
    demo_rng rng;
    cc_circle heavy;
    int i, j, placed = 0, r;
    const double sx = GAS_W / GAS_COLS, sy = GAS_H / GAS_ROWS;

    demo_stage_def_init(&d, show->opt->mode);
    d.max_circles = GAS_N + 1;
    d.max_segments = 4;
    d.x0 = -2.0;
    d.y0 = -2.0;
    d.x1 = GAS_W + 2.0;
    d.y1 = GAS_H + 2.0;
    d.speed_ref = 2.0 * GAS_SPEED;
    d.impulse_ref = 2.0 * GAS_SPEED;
    d.trail_time = 0.12;
    d.flash_time = 0.1;
    d.flash_radius = 1.6;
    d.flash_capacity = 4096;
    r = demo_stage_init(s, &d);
    if (r != 0)
        return r;
    show->nstages = 1;

    demo_stage_add_wall(s, 0.0, 0.0, GAS_W, 0.0);
    demo_stage_add_wall(s, GAS_W, 0.0, GAS_W, GAS_H);
    demo_stage_add_wall(s, GAS_W, GAS_H, 0.0, GAS_H);
    demo_stage_add_wall(s, 0.0, GAS_H, 0.0, 0.0);

    heavy = demo_circle(0.5 * GAS_W, 0.5 * GAS_H, 0.0, 0.0, HEAVY_R, HEAVY_M);
    demo_stage_add_circle(s, &heavy, DEMO_STYLE_MARKED);

    /* one circle per cell of a grid, jittered by less than half the free space between
       neighbours (cells are about 3.97 x 4 units, diameters 2) so that none overlap; cells too
       close to the heavy disc stay empty */
    demo_rng_seed(&rng, show->opt->seed);
    for (j = 0; j < GAS_ROWS && placed < GAS_N; ++j)
        for (i = 0; i < GAS_COLS && placed < GAS_N; ++i) {
            double x = (i + 0.5) * sx + 0.9 * (2.0 * demo_rng_unit(&rng) - 1.0);
            double y = (j + 0.5) * sy + 0.9 * (2.0 * demo_rng_unit(&rng) - 1.0);
            double dx = x - heavy.pos.x, dy = y - heavy.pos.y, ux, uy;
            cc_circle c;
            if (dx * dx + dy * dy < (HEAVY_R + 2.0) * (HEAVY_R + 2.0))
                continue;
            demo_rng_direction(&rng, &ux, &uy);
            c = demo_circle(x, y, GAS_SPEED * ux, GAS_SPEED * uy, 1.0, 1.0);
            if (demo_stage_add_circle(s, &c, DEMO_STYLE_SPEED) < 0)
                break;
            ++placed;
        }
    show->caption = gas_caption;
    return s->error;
}
