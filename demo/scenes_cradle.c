/* Newton's cradle without strings: three lanes, each a row of five equal balls touching in a line
 * between two end walls. In lane k (k = 1, 2, 3) the first k balls arrive together and strike
 * the 5 - k at rest: a correct impact sends exactly k balls out of the far end at the incoming
 * speed and leaves the rest still. The walls send them back, so the cradle keeps swinging.
 * Units: ball radius 1. */
#include "scene.h"
#include "scene_util.h"

#include <stdio.h>

#define CRADLE_L 32.0     /* lane length */
#define CRADLE_LANE 6.0   /* lane height */
#define CRADLE_SPEED 10.0 /* incoming speed */

static void cradle_caption(demo_show *show, int stage, char *buf, size_t size)
{
    (void)show;
    (void)stage;
    snprintf(buf, size, "NEWTON'S CRADLE   1, 2 AND 3 BALLS IN");
}

static void cradle_report(demo_show *show, FILE *f)
{
    const demo_stage *s = &show->stage[0];
    int i, moving = 0;
    for (i = 0; i < s->count; ++i)
        moving += s->circles[i].vel.x != 0.0 || s->circles[i].vel.y != 0.0;
    fprintf(f, "  balls moving at the end: %d (1 + 2 + 3 = 6 in a correct cradle)\n", moving);
}

int demo_scene_cradle(demo_show *show)
{
    demo_stage_def d;
    demo_stage *s = &show->stage[0];
    int lane, j, r;

    demo_stage_def_init(&d, show->opt->mode);
    d.max_circles = 15;
    d.max_segments = 8;
    d.x0 = -0.6;
    d.y0 = -0.6;
    d.x1 = CRADLE_L + 0.6;
    d.y1 = 3.0 * CRADLE_LANE + 0.6;
    d.speed_ref = CRADLE_SPEED;
    d.impulse_ref = 2.0 * CRADLE_SPEED;
    d.trail_time = 0.2;
    d.flash_time = 0.15;
    d.flash_radius = 1.6;
    d.flash_capacity = 256;
    r = demo_stage_init(s, &d);
    if (r != 0)
        return r;
    show->nstages = 1;

    /* the end walls span all lanes; the lane dividers are never touched (the balls move exactly
       along x), they only frame the picture */
    demo_stage_add_wall(s, 0.0, 0.0, 0.0, 3.0 * CRADLE_LANE);
    demo_stage_add_wall(s, CRADLE_L, 0.0, CRADLE_L, 3.0 * CRADLE_LANE);
    for (lane = 0; lane <= 3; ++lane)
        demo_stage_add_wall(s, 0.0, lane * CRADLE_LANE, CRADLE_L, lane * CRADLE_LANE);

    for (lane = 0; lane < 3; ++lane) {
        int in = 3 - lane; /* top lane: 1 ball in, then 2, then 3 */
        double y = (lane + 0.5) * CRADLE_LANE;
        for (j = 0; j < 5; ++j) {
            /* the row at rest is centred; the incoming ones start 4 units to the left, touching
               each other (2 radii apart), all at the same speed */
            double x = 0.5 * CRADLE_L - 4.0 + 2.0 * j;
            cc_circle b = j < in ? demo_circle(x - 4.0, y, CRADLE_SPEED, 0.0, 1.0, 1.0)
                                 : demo_circle(x, y, 0.0, 0.0, 1.0, 1.0);
            demo_stage_add_circle(s, &b, DEMO_STYLE_SPEED);
        }
    }
    show->caption = cradle_caption;
    show->report = cradle_report;
    return s->error;
}
