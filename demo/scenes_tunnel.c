/* Tunnelling, side by side: the same box with six bullets (speeds from 3 to 300 box units per
 * second, i.e. from a twentieth of a unit to five units per frame at 60 fps) and three heavier
 * targets, simulated in EXACT, SWEPT and DISCRETE mode. Walls keep their side in every mode, so
 * all nine stay in the box; EXACT finds every impact; SWEPT catches each body's first impact in
 * a frame but misses a second one with a circle, and DISCRETE only sees overlaps at the end of
 * a frame, so there fast bullets fly through the targets and each other. The caption counts the
 * bodies in the box. Units: box 6 x 10. */
#include "scene.h"
#include "scene_util.h"

#include <stdio.h>

#define BOX_W 6.0
#define BOX_H 10.0
#define BULLET_R 0.15
#define TARGET_R 0.5
#define TARGET_M 4.0

static int inside(const demo_stage *s)
{
    int i, n = 0;
    for (i = 0; i < s->count; ++i) {
        const cc_circle *c = &s->circles[i];
        n += c->pos.x > 0.0 && c->pos.x < BOX_W && c->pos.y > 0.0 && c->pos.y < BOX_H;
    }
    return n;
}

static const char *mode_name(int mode)
{
    return mode == CC_MODE_EXACT ? "EXACT" : mode == CC_MODE_SWEPT ? "SWEPT" : "DISCRETE";
}

static void tunnel_caption(demo_show *show, int stage, char *buf, size_t size)
{
    const demo_stage *s = &show->stage[stage];
    snprintf(buf, size, "%s  %d/9 IN", mode_name(s->def.mode), inside(s));
}

static void tunnel_report(demo_show *show, FILE *f)
{
    int k;
    for (k = 0; k < show->nstages; ++k)
        fprintf(f, "  %-8s: %d of 9 bodies still in the box\n", mode_name(show->stage[k].def.mode),
                inside(&show->stage[k]));
}

int demo_scene_tunnel(demo_show *show)
{
    /* directions from Pythagorean triples: exact unit vectors without sin or cos */
    static const double dir[6][2] = {{0.6, 0.8},   {-0.8, 0.6},          {5.0 / 13, 12.0 / 13},
                                     {-0.6, 0.8},  {12.0 / 13, 5.0 / 13}, {-8.0 / 17, 15.0 / 17}};
    static const double speed[6] = {3.0, 8.0, 20.0, 50.0, 120.0, 300.0};
    static const double target[3][2] = {{1.5, 7.0}, {3.0, 7.6}, {4.5, 7.0}};
    int k, i, r;
    for (k = 0; k < 3; ++k) {
        demo_stage_def d;
        demo_stage *s = &show->stage[k];
        demo_stage_def_init(&d, k == 0 ? CC_MODE_EXACT : k == 1 ? CC_MODE_SWEPT : CC_MODE_DISCRETE);
        d.max_circles = 9;
        d.max_segments = 4;
        d.x0 = -0.8;
        d.y0 = -0.8;
        d.x1 = BOX_W + 0.8;
        d.y1 = BOX_H + 1.6; /* room for the caption */
        d.speed_ref = 60.0;
        d.impulse_ref = 60.0;
        d.trail_time = 0.3;
        d.flash_time = 0.15;
        d.flash_radius = 0.4;
        d.flash_capacity = 256;
        r = demo_stage_init(s, &d);
        if (r != 0)
            return r;
        show->nstages = k + 1;
        demo_stage_add_wall(s, 0.0, 0.0, BOX_W, 0.0);
        demo_stage_add_wall(s, BOX_W, 0.0, BOX_W, BOX_H);
        demo_stage_add_wall(s, BOX_W, BOX_H, 0.0, BOX_H);
        demo_stage_add_wall(s, 0.0, BOX_H, 0.0, 0.0);
        for (i = 0; i < 6; ++i) {
            cc_circle b = demo_circle(0.75 + 0.9 * i, 1.5 + 0.3 * (i % 2), speed[i] * dir[i][0],
                                      speed[i] * dir[i][1], BULLET_R, 1.0);
            demo_stage_add_circle(s, &b, DEMO_STYLE_SPEED);
        }
        for (i = 0; i < 3; ++i) {
            cc_circle t = demo_circle(target[i][0], target[i][1], 0.0, 0.0, TARGET_R, TARGET_M);
            demo_stage_add_circle(s, &t, DEMO_STYLE_MARKED);
        }
        if (s->error)
            return s->error;
    }
    show->caption = tunnel_caption;
    show->report = tunnel_report;
    return 0;
}
