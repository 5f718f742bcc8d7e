/* The pool break: a 15-ball rack, every ball touching its neighbours (rows sqrt(3) radii
 * apart), hit head-on on its axis by the cue ball. The table has six cushions with gaps for six
 * pockets; a ball whose centre crosses a cushion line has gone through a gap and is pocketed
 * (removed from the world). Between frames the demo slows the balls down as cloth would, so that
 * the break comes to rest; that energy is booked as the demo's, not the world's. Units: metres,
 * seconds, kilograms (a 9-foot table and regulation balls). */
#include "scene.h"
#include "scene_util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define POOL_L 2.54        /* playing length between cushion noses */
#define POOL_W 1.27
#define POOL_R 0.028575    /* ball radius (57.15 mm balls) */
#define POOL_M 0.17        /* ball mass */
#define POOL_CUE_SPEED 8.0 /* a firm break */
#define POOL_CORNER_GAP 0.075 /* cushion-free length each side of a corner */
#define POOL_SIDE_GAP 0.065   /* half the mouth of a side pocket */
#define POOL_ROLL_DECEL 0.15  /* cloth: constant deceleration, m/s^2 ... */
#define POOL_DRAG 0.2         /* ... plus a proportional drag, 1/s */

typedef struct pool_state {
    int pocketed;
} pool_state;

static void pool_control(demo_show *show, long frame)
{
    demo_stage *s = &show->stage[0];
    pool_state *st = (pool_state *)show->state;
    int i;
    (void)frame;
    for (i = 0; i < s->count; ++i) {
        cc_circle c;
        int id = s->ids[i];
        double v, k;
        if (cc_world_get_circle(s->world, id, &c) != CC_OK)
            continue;
        if (c.pos.x < 0.0 || c.pos.x > POOL_L || c.pos.y < 0.0 || c.pos.y > POOL_W) {
            demo_stage_remove_circle(s, id);
            ++st->pocketed;
            continue;
        }
        v = sqrt(c.vel.x * c.vel.x + c.vel.y * c.vel.y);
        if (v == 0.0)
            continue;
        k = (v * (1.0 - POOL_DRAG * show->dt) - POOL_ROLL_DECEL * show->dt) / v;
        if (k < 0.0)
            k = 0.0;
        c.vel.x *= k;
        c.vel.y *= k;
        demo_stage_set_circle(s, id, &c);
    }
}

static void pool_backdrop(demo_show *show, int stage, demo_canvas *c, const demo_view *v)
{
    static const double pockets[6][2] = {{0.0, 0.0},    {POOL_L / 2, -0.02},    {POOL_L, 0.0},
                                         {0.0, POOL_W}, {POOL_L / 2, POOL_W + 0.02}, {POOL_L, POOL_W}};
    const demo_stage_def *d = &show->stage[stage].def;
    int i;
    /* wooden rails, then the cloth inside the cushion lines, then the pockets */
    demo_canvas_rect(c, demo_view_x(v, d->x0), demo_view_y(v, d->y1), demo_view_x(v, d->x1),
                     demo_view_y(v, d->y0), demo_rgb_make(92.0f, 54.0f, 30.0f), 1.0, DEMO_OVER);
    demo_canvas_rect(c, demo_view_x(v, -0.04), demo_view_y(v, POOL_W + 0.04),
                     demo_view_x(v, POOL_L + 0.04), demo_view_y(v, -0.04),
                     demo_rgb_make(18.0f, 84.0f, 52.0f), 1.0, DEMO_OVER);
    demo_canvas_rect(c, demo_view_x(v, 0.0), demo_view_y(v, POOL_W), demo_view_x(v, POOL_L),
                     demo_view_y(v, 0.0), demo_rgb_make(24.0f, 110.0f, 68.0f), 1.0, DEMO_OVER);
    for (i = 0; i < 6; ++i)
        demo_canvas_disc(c, demo_view_x(v, pockets[i][0]), demo_view_y(v, pockets[i][1]),
                         0.062 * v->scale, demo_rgb_make(8.0f, 8.0f, 10.0f), 1.0, DEMO_OVER);
}

static void pool_caption(demo_show *show, int stage, char *buf, size_t size)
{
    const pool_state *st = (const pool_state *)show->state;
    (void)stage;
    snprintf(buf, size, "POOL BREAK   POCKETED %d", st->pocketed);
}

static void pool_report(demo_show *show, FILE *f)
{
    const pool_state *st = (const pool_state *)show->state;
    fprintf(f, "  pocketed: %d of 16 balls\n", st->pocketed);
}

int demo_scene_pool(demo_show *show)
{
    demo_stage_def d;
    demo_stage *s = &show->stage[0];
    const double cy = 0.5 * POOL_W, foot = 0.75 * POOL_L;
    const double row = sqrt(3.0) * POOL_R; /* rows of touching balls are sqrt(3) radii apart */
    cc_circle cue;
    int k, j, r;

    show->state = calloc(1, sizeof(pool_state));
    if (show->state == NULL)
        return -100;
    d.max_circles = 16;
    d.max_segments = 6;
    d.mode = show->opt->mode;
    d.restitution = 0.95;
    d.rest_speed = 0.01;
    d.x0 = -0.13;
    d.y0 = -0.13;
    d.x1 = POOL_L + 0.13;
    d.y1 = POOL_W + 0.13;
    d.speed_ref = 2.5;
    d.impulse_ref = POOL_M * 2.5;
    d.trail_time = 0.25;
    d.flash_time = 0.12;
    d.flash_radius = 2.2 * POOL_R;
    d.flash_capacity = 512;
    d.label = NULL;
    d.rolling_decel = 0.0;
    d.restitution_mix = CC_MIX_MIN;
    d.on_sensor = NULL;
    d.sensor_user = NULL;
    r = demo_stage_init(s, &d);
    if (r != 0)
        return r;
    show->nstages = 1;

    /* cushions: long sides split by the side pockets, every corner left open */
    demo_stage_add_wall(s, POOL_CORNER_GAP, 0.0, POOL_L / 2 - POOL_SIDE_GAP, 0.0);
    demo_stage_add_wall(s, POOL_L / 2 + POOL_SIDE_GAP, 0.0, POOL_L - POOL_CORNER_GAP, 0.0);
    demo_stage_add_wall(s, POOL_CORNER_GAP, POOL_W, POOL_L / 2 - POOL_SIDE_GAP, POOL_W);
    demo_stage_add_wall(s, POOL_L / 2 + POOL_SIDE_GAP, POOL_W, POOL_L - POOL_CORNER_GAP, POOL_W);
    demo_stage_add_wall(s, 0.0, POOL_CORNER_GAP, 0.0, POOL_W - POOL_CORNER_GAP);
    demo_stage_add_wall(s, POOL_L, POOL_CORNER_GAP, POOL_L, POOL_W - POOL_CORNER_GAP);

    /* the rack: apex on the foot spot, row k holds k + 1 balls, each touching its neighbours */
    for (k = 0; k < 5; ++k)
        for (j = 0; j <= k; ++j) {
            cc_circle b = demo_circle(foot + k * row, cy + (2 * j - k) * POOL_R, 0.0, 0.0, POOL_R,
                                      POOL_M);
            demo_stage_add_circle(s, &b, DEMO_STYLE_SPEED);
        }
    cue = demo_circle(0.25 * POOL_L, cy, POOL_CUE_SPEED, 0.0, POOL_R, POOL_M);
    demo_stage_add_circle(s, &cue, DEMO_STYLE_MARKED);

    show->control = pool_control;
    show->backdrop = pool_backdrop;
    show->caption = pool_caption;
    show->report = pool_report;
    return s->error;
}
