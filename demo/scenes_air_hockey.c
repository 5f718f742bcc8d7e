/* Air hockey: a light, fast puck on a rink with chamfered corners and a goal in each end rail,
 * between two heavy mallets that the demo drives like two simple players (guard the goal, strike
 * when the puck comes into their half). The mallets are ordinary circles whose velocity is set
 * every frame, so the puck's bounces off them are real collisions. A puck that enters a goal is
 * removed and a new one is served from the centre. Each goal is a sensor circle behind its goal
 * line (1.1): a disc so wide that, near the mouth, its edge follows the line one puck radius
 * behind it, so its begin event means the puck has wholly crossed the line between the posts; the
 * callback notes the goal and the demo scores it, removes the puck and serves before the next
 * step. Units: metres, seconds, kilograms. */
#include "scene.h"
#include "scene_util.h"
#include "prng.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define RINK_L 2.0
#define RINK_W 1.0
#define RINK_CHAMFER 0.1
#define GOAL_HALF 0.15
#define PUCK_R 0.04
#define PUCK_M 0.03
#define PUCK_SERVE 5.0  /* serve speed */
#define MALLET_R 0.06
#define MALLET_M 1.0
#define MALLET_VMAX 4.5 /* fastest a player moves a mallet */
#define GOAL_SENSOR_R 1.0 /* the goals' sensor discs: wide, so nearly straight at the mouth */

typedef struct hockey_state {
    demo_rng rng;
    int puck;       /* its id */
    int mallet[2];  /* left, right */
    int goals[2];   /* goals scored by left, right */
    int serves;
    int goal_sensor[2]; /* ids of the sensors behind the left and the right goal line */
    int scored_in;      /* the goal (0 left, 1 right) the puck entered in the last step, or -1 */
} hockey_state;

/* Only notes the goal: the world may not be changed from inside its callback. */
static void hockey_on_sensor(const cc_sensor_event *e, void *user)
{
    hockey_state *st = (hockey_state *)user;
    if (e->begin && e->visitor == st->puck && st->scored_in < 0)
        st->scored_in = e->sensor == st->goal_sensor[0]   ? 0
                        : e->sensor == st->goal_sensor[1] ? 1
                                                          : -1;
}

static void serve(demo_show *show)
{
    hockey_state *st = (hockey_state *)show->state;
    double dx, dy;
    cc_circle p;
    demo_rng_direction(&st->rng, &dx, &dy);
    if (fabs(dx) < 0.5) { /* serve towards a player, not into a rail */
        dx = dx < 0.0 ? -0.5 : 0.5;
        dy = dy < 0.0 ? -sqrt(0.75) : sqrt(0.75);
    }
    p = demo_circle(0.5 * RINK_L, 0.5 * RINK_W, PUCK_SERVE * dx, PUCK_SERVE * dy, PUCK_R, PUCK_M);
    st->puck = demo_stage_add_circle(&show->stage[0], &p, DEMO_STYLE_MARKED);
    ++st->serves;
}

static double clamp(double v, double lo, double hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}

/* One player: guards its goal, and charges at the puck when the puck is in its half. */
static void drive_mallet(demo_show *show, int side, const cc_circle *puck)
{
    hockey_state *st = (hockey_state *)show->state;
    demo_stage *s = &show->stage[0];
    double margin = MALLET_R + 0.04; /* clear of the rails and of the corner chamfers */
    double xlo = side == 0 ? margin : 0.5 * RINK_L + margin;
    double xhi = side == 0 ? 0.5 * RINK_L - margin : RINK_L - margin;
    double home = side == 0 ? 0.2 : RINK_L - 0.2;
    double tx, ty, vx, vy, v;
    cc_circle m;
    if (cc_world_get_circle(s->world, st->mallet[side], &m) != CC_OK)
        return;
    if (puck != NULL && (side == 0 ? puck->pos.x < 0.5 * RINK_L : puck->pos.x > 0.5 * RINK_L)) {
        /* aim a little behind the puck so that the hit sends it up the rink */
        tx = puck->pos.x + (side == 0 ? -0.5 : 0.5) * PUCK_R;
        ty = puck->pos.y;
    } else {
        tx = home;
        ty = 0.5 * RINK_W + 0.6 * ((puck != NULL ? puck->pos.y : 0.5 * RINK_W) - 0.5 * RINK_W);
    }
    /* the box of the mallet's half is convex, so moving in a straight line towards a target
       inside it keeps the mallet inside it for the whole frame */
    tx = clamp(tx, xlo, xhi);
    ty = clamp(ty, margin, RINK_W - margin);
    vx = (tx - clamp(m.pos.x, xlo, xhi)) / show->dt;
    vy = (ty - clamp(m.pos.y, margin, RINK_W - margin)) / show->dt;
    v = sqrt(vx * vx + vy * vy);
    if (v > MALLET_VMAX) {
        vx *= MALLET_VMAX / v;
        vy *= MALLET_VMAX / v;
    }
    m.vel.x = vx;
    m.vel.y = vy;
    demo_stage_set_circle(s, st->mallet[side], &m);
}

static void hockey_control(demo_show *show, long frame)
{
    hockey_state *st = (hockey_state *)show->state;
    demo_stage *s = &show->stage[0];
    cc_circle p;
    int have = st->puck >= 0 && cc_world_get_circle(s->world, st->puck, &p) == CC_OK;
    (void)frame;
    if (have && st->scored_in >= 0) {
        ++st->goals[st->scored_in == 0 ? 1 : 0]; /* the left goal is the right player's point */
        st->scored_in = -1;
        demo_stage_remove_circle(s, st->puck);
        st->puck = -1;
        have = 0;
        serve(show);
    } else if (have && (p.pos.y < -PUCK_R || p.pos.y > RINK_W + PUCK_R)) {
        /* cannot happen in EXACT mode; in DISCRETE mode a fast puck may tunnel out */
        demo_stage_remove_circle(s, st->puck);
        st->puck = -1;
        have = 0;
        serve(show);
    }
    drive_mallet(show, 0, have ? &p : NULL);
    drive_mallet(show, 1, have ? &p : NULL);
}

static void hockey_backdrop(demo_show *show, int stage, demo_canvas *c, const demo_view *v)
{
    demo_rgb line = demo_rgb_make(170.0f, 60.0f, 70.0f);
    demo_rgb goal = demo_rgb_make(4.0f, 5.0f, 8.0f);
    double hw = 0.004 * v->scale;
    (void)show;
    (void)stage;
    demo_canvas_rect(c, demo_view_x(v, 0.0), demo_view_y(v, RINK_W), demo_view_x(v, RINK_L),
                     demo_view_y(v, 0.0), demo_rgb_make(34.0f, 44.0f, 62.0f), 1.0, DEMO_OVER);
    demo_canvas_capsule(c, demo_view_x(v, 0.5 * RINK_L), demo_view_y(v, 0.0),
                        demo_view_x(v, 0.5 * RINK_L), demo_view_y(v, RINK_W), hw, line, 0.8,
                        DEMO_OVER);
    demo_canvas_ring(c, demo_view_x(v, 0.5 * RINK_L), demo_view_y(v, 0.5 * RINK_W), 0.15 * v->scale,
                     hw, line, 0.8, DEMO_OVER);
    demo_canvas_rect(c, demo_view_x(v, -0.06), demo_view_y(v, 0.5 * RINK_W + GOAL_HALF),
                     demo_view_x(v, 0.0), demo_view_y(v, 0.5 * RINK_W - GOAL_HALF), goal, 1.0,
                     DEMO_OVER);
    demo_canvas_rect(c, demo_view_x(v, RINK_L), demo_view_y(v, 0.5 * RINK_W + GOAL_HALF),
                     demo_view_x(v, RINK_L + 0.06), demo_view_y(v, 0.5 * RINK_W - GOAL_HALF), goal,
                     1.0, DEMO_OVER);
}

static void hockey_caption(demo_show *show, int stage, char *buf, size_t size)
{
    const hockey_state *st = (const hockey_state *)show->state;
    (void)stage;
    snprintf(buf, size, "AIR HOCKEY   %d : %d", st->goals[0], st->goals[1]);
}

static void hockey_report(demo_show *show, FILE *f)
{
    const hockey_state *st = (const hockey_state *)show->state;
    fprintf(f, "  score: %d : %d, pucks served: %d\n", st->goals[0], st->goals[1], st->serves);
}

int demo_scene_air_hockey(demo_show *show)
{
    demo_stage_def d;
    demo_stage *s = &show->stage[0];
    hockey_state *st;
    const double c = RINK_CHAMFER, L = RINK_L, W = RINK_W, g = GOAL_HALF;
    cc_circle m;
    int r;

    st = (hockey_state *)calloc(1, sizeof *st);
    if (st == NULL)
        return -100;
    show->state = st;
    demo_rng_seed(&st->rng, show->opt->seed);
    st->scored_in = -1;
    demo_stage_def_init(&d, show->opt->mode);
    d.max_circles = 5; /* two mallets, the puck, the two goals' sensors */
    d.max_segments = 10;
    d.restitution = 0.9;
    d.x0 = -0.1;
    d.y0 = -0.1;
    d.x1 = L + 0.1;
    d.y1 = W + 0.1;
    d.speed_ref = 8.0;
    d.impulse_ref = PUCK_M * 8.0;
    d.trail_time = 0.15;
    d.flash_time = 0.12;
    d.flash_radius = 2.0 * PUCK_R;
    d.flash_capacity = 256;
    d.on_sensor = hockey_on_sensor;
    d.sensor_user = st;
    r = demo_stage_init(s, &d);
    if (r != 0)
        return r;
    show->nstages = 1;

    /* rails: long sides, chamfered corners, end rails broken by the goal mouths */
    demo_stage_add_wall(s, c, 0.0, L - c, 0.0);
    demo_stage_add_wall(s, c, W, L - c, W);
    demo_stage_add_wall(s, 0.0, c, c, 0.0);
    demo_stage_add_wall(s, L - c, 0.0, L, c);
    demo_stage_add_wall(s, 0.0, W - c, c, W);
    demo_stage_add_wall(s, L - c, W, L, W - c);
    demo_stage_add_wall(s, 0.0, c, 0.0, 0.5 * W - g);
    demo_stage_add_wall(s, 0.0, 0.5 * W + g, 0.0, W - c);
    demo_stage_add_wall(s, L, c, L, 0.5 * W - g);
    demo_stage_add_wall(s, L, 0.5 * W + g, L, W - c);

    m = demo_circle(0.2, 0.5 * W, 0.0, 0.0, MALLET_R, MALLET_M);
    st->mallet[0] = demo_stage_add_circle(s, &m, DEMO_STYLE_SOLID);
    m.pos.x = L - 0.2;
    st->mallet[1] = demo_stage_add_circle(s, &m, DEMO_STYLE_SOLID);
    /* the goals: sensor discs behind the goal lines, their edge on the rink's axis one puck
       radius behind the line (begin: the puck's centre is a radius past the line); every
       mallet stays far out of them */
    st->goal_sensor[0] =
        demo_stage_add_sensor(s, -(GOAL_SENSOR_R + 2.0 * PUCK_R), 0.5 * W, GOAL_SENSOR_R);
    st->goal_sensor[1] =
        demo_stage_add_sensor(s, L + GOAL_SENSOR_R + 2.0 * PUCK_R, 0.5 * W, GOAL_SENSOR_R);
    serve(show);

    show->control = hockey_control;
    show->backdrop = hockey_backdrop;
    show->caption = hockey_caption;
    show->report = hockey_report;
    return s->error;
}
