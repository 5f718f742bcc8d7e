/* The pool break: a 15-ball rack, every ball touching its neighbours (rows sqrt(3) radii
 * apart), hit head-on on its axis by the cue ball. The table has six cushions with gaps for six
 * pockets. The world does the table's physics with its 1.1 properties: the cloth is the world's
 * rolling deceleration, the balls have restitution 0.95 and the cushions 0.75 (the smaller of
 * the two sides counts: CC_MIX_MIN), and each pocket is an immovable sensor circle of radius
 * (pocket radius - ball radius), so that its begin event means the ball's centre is over the
 * hole: the sensor callback notes the ball and the demo removes it before the next step (the
 * callback may not change the world). Behind each pocket mouth the pocket's back (walls along
 * its rim) keeps a ball that misses the hole on the table. Units: metres, seconds, kilograms
 * (a 9-foot table and regulation balls). */
#include "scene.h"
#include "scene_util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define POOL_L 2.54        /* playing length between cushion noses */
#define POOL_W 1.27
#define POOL_R 0.028575    /* ball radius (57.15 mm balls) */
#define POOL_M 0.17        /* ball mass */
#define POOL_BALLS 16
#define POOL_CUE_SPEED 8.0 /* a firm break */
#define POOL_CORNER_GAP 0.075 /* cushion-free length each side of a corner */
#define POOL_SIDE_GAP 0.065   /* half the mouth of a side pocket */
#define POOL_SIDE_DROP 0.02   /* a side pocket's centre lies this far behind the cushion line */
#define POOL_POCKET_R 0.062   /* radius of a pocket's hole */
#define POOL_ROLL_DECEL 0.15  /* cloth: the constant deceleration of a rolling ball, m/s^2 */
#define POOL_BALL_E 0.95      /* restitution of a ball ... */
#define POOL_CUSHION_E 0.75   /* ... and of a cushion */
#define POOL_CORNER_PIECES 9  /* walls along the back of a corner pocket (270 degrees) */
#define POOL_SIDE_PIECES 8    /* ... and of a side pocket (the part behind the cushion line) */
#define POOL_WALLS (6 + 4 * POOL_CORNER_PIECES + 2 * POOL_SIDE_PIECES)

#define POOL_PI 3.14159265358979323846

/* the pockets' centres: the four corners, then the two sides */
static const double pool_pockets[6][2] = {
    {0.0, 0.0}, {POOL_L, 0.0}, {0.0, POOL_W}, {POOL_L, POOL_W},
    {POOL_L / 2, -POOL_SIDE_DROP}, {POOL_L / 2, POOL_W + POOL_SIDE_DROP}};

/* the cushions: long sides split by the side pockets, every corner left open */
static const double cushions[6][4] = {
    {POOL_CORNER_GAP, 0.0, POOL_L / 2 - POOL_SIDE_GAP, 0.0},
    {POOL_L / 2 + POOL_SIDE_GAP, 0.0, POOL_L - POOL_CORNER_GAP, 0.0},
    {POOL_CORNER_GAP, POOL_W, POOL_L / 2 - POOL_SIDE_GAP, POOL_W},
    {POOL_L / 2 + POOL_SIDE_GAP, POOL_W, POOL_L - POOL_CORNER_GAP, POOL_W},
    {0.0, POOL_CORNER_GAP, 0.0, POOL_W - POOL_CORNER_GAP},
    {POOL_L, POOL_CORNER_GAP, POOL_L, POOL_W - POOL_CORNER_GAP}};

typedef struct pool_state {
    int pocketed;
    int lost;                       /* balls that left the table through a cushion (tunnelled) */
    int sensor_lo, sensor_hi;       /* the pockets' ids: [lo, hi] */
    unsigned char in_pocket[32];    /* per ball id: its centre went over a hole (callback) */
    unsigned char removed[32];      /* per ball id: taken off the table (control) */
    double moving_until;            /* the last frame time at which a ball on the table moved */
} pool_state;

/* Only notes the ball: the world may not be changed from inside its callback. */
static void pool_on_sensor(const cc_sensor_event *e, void *user)
{
    pool_state *st = (pool_state *)user;
    if (e->begin && e->sensor >= st->sensor_lo && e->sensor <= st->sensor_hi && e->visitor >= 0 &&
        e->visitor < 32)
        st->in_pocket[e->visitor] = 1;
}

/* Between steps: the balls that went over a hole during the last step leave the table. */
static void pool_control(demo_show *show, long frame)
{
    demo_stage *s = &show->stage[0];
    pool_state *st = (pool_state *)show->state;
    int id, i;
    (void)frame;
    for (id = 0; id < 32; ++id)
        if (st->in_pocket[id] && !st->removed[id]) {
            st->removed[id] = 1;
            if (demo_stage_remove_circle(s, id) == CC_OK)
                ++st->pocketed;
        }
    for (i = 0; i < s->count; ++i) { /* the circles of the last frame */
        const cc_circle *c = &s->circles[i];
        id = s->ids[i];
        if (id < 32 && !st->removed[id] &&
            (c->pos.x < s->def.x0 || c->pos.x > s->def.x1 || c->pos.y < s->def.y0 ||
             c->pos.y > s->def.y1)) {
            /* beyond the rails: it passed through a cushion, which EXACT never lets happen
               but a fast ball may do in DISCRETE or SWEPT mode */
            st->removed[id] = 1;
            if (demo_stage_remove_circle(s, id) == CC_OK)
                ++st->lost;
            continue;
        }
        if (c->vel.x != 0.0 || c->vel.y != 0.0)
            st->moving_until = cc_world_time(s->world);
    }
}

/* The back of a pocket: walls along its rim from angle a0 through span (degrees). */
static void pool_pocket_back(demo_stage *s, int pocket, double a0, double span, int pieces)
{
    const double cx = pool_pockets[pocket][0], cy = pool_pockets[pocket][1];
    int k;
    for (k = 0; k < pieces; ++k) {
        double u = (a0 + span * k / pieces) * (POOL_PI / 180.0);
        double w = (a0 + span * (k + 1) / pieces) * (POOL_PI / 180.0);
        int id = demo_stage_add_wall(s, cx + POOL_POCKET_R * cos(u), cy + POOL_POCKET_R * sin(u),
                                     cx + POOL_POCKET_R * cos(w), cy + POOL_POCKET_R * sin(w));
        if (id >= 0)
            demo_stage_set_wall_restitution(s, id, POOL_CUSHION_E);
    }
}

static void pool_backdrop(demo_show *show, int stage, demo_canvas *c, const demo_view *v)
{
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
        demo_canvas_disc(c, demo_view_x(v, pool_pockets[i][0]),
                         demo_view_y(v, pool_pockets[i][1]), POOL_POCKET_R * v->scale,
                         demo_rgb_make(8.0f, 8.0f, 10.0f), 1.0, DEMO_OVER);
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
    const demo_stage *s = &show->stage[0];
    int i, rolling = 0;
    for (i = 0; i < s->count; ++i)
        if (s->circles[i].vel.x != 0.0 || s->circles[i].vel.y != 0.0)
            ++rolling;
    fprintf(f, "  pocketed: %d of 16 balls; ", st->pocketed);
    if (st->lost > 0)
        fprintf(f, "%d passed through a cushion (tunnelled) and left the table; ", st->lost);
    if (rolling > 0)
        fprintf(f, "%d still rolling\n", rolling);
    else
        fprintf(f, "every ball at rest (the last one still moved at the frame of t = %.2f s)\n",
                st->moving_until);
}

int demo_scene_pool(demo_show *show)
{
    demo_stage_def d;
    demo_stage *s = &show->stage[0];
    const double cy = 0.5 * POOL_W, foot = 0.75 * POOL_L;
    const double row = sqrt(3.0) * POOL_R; /* rows of touching balls are sqrt(3) radii apart */
    pool_state *st;
    cc_circle cue;
    double side;
    int k, j, r;

    st = (pool_state *)calloc(1, sizeof *st);
    if (st == NULL)
        return -100;
    show->state = st;
    demo_stage_def_init(&d, show->opt->mode);
    d.max_circles = POOL_BALLS + 6; /* the balls and the six pockets */
    d.max_segments = POOL_WALLS;
    d.restitution = POOL_BALL_E; /* what every circle and wall starts with */
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
    d.rolling_decel = POOL_ROLL_DECEL;
    d.restitution_mix = CC_MIX_MIN; /* ball on ball min(0.95, 0.95), ball on cushion 0.75 */
    d.on_sensor = pool_on_sensor;
    d.sensor_user = st;
    r = demo_stage_init(s, &d);
    if (r != 0)
        return r;
    show->nstages = 1;

    /* cushions: long sides split by the side pockets, every corner left open */
    for (k = 0; k < 6; ++k) {
        r = demo_stage_add_wall(s, cushions[k][0], cushions[k][1], cushions[k][2], cushions[k][3]);
        if (r >= 0)
            demo_stage_set_wall_restitution(s, r, POOL_CUSHION_E);
    }
    /* the pockets' backs: the part of each rim outside the cushion lines (a corner's three
       quarters; a side pocket's rim below the line, which it meets asin(drop / R) above the
       horizontal) */
    pool_pocket_back(s, 0, 90.0, 270.0, POOL_CORNER_PIECES);
    pool_pocket_back(s, 1, 180.0, 270.0, POOL_CORNER_PIECES);
    pool_pocket_back(s, 2, 0.0, 270.0, POOL_CORNER_PIECES);
    pool_pocket_back(s, 3, 270.0, 270.0, POOL_CORNER_PIECES);
    side = asin(POOL_SIDE_DROP / POOL_POCKET_R) * (180.0 / POOL_PI);
    pool_pocket_back(s, 4, 180.0 - side, 180.0 + 2.0 * side, POOL_SIDE_PIECES);
    pool_pocket_back(s, 5, -side, 180.0 + 2.0 * side, POOL_SIDE_PIECES);

    /* the rack: apex on the foot spot, row k holds k + 1 balls, each touching its neighbours */
    for (k = 0; k < 5; ++k)
        for (j = 0; j <= k; ++j) {
            cc_circle b = demo_circle(foot + k * row, cy + (2 * j - k) * POOL_R, 0.0, 0.0, POOL_R,
                                      POOL_M);
            int id = demo_stage_add_circle(s, &b, DEMO_STYLE_SPEED);
            if (id >= 0)
                demo_stage_set_circle_restitution(s, id, POOL_BALL_E);
        }
    cue = demo_circle(0.25 * POOL_L, cy, POOL_CUE_SPEED, 0.0, POOL_R, POOL_M);
    r = demo_stage_add_circle(s, &cue, DEMO_STYLE_MARKED);
    if (r >= 0)
        demo_stage_set_circle_restitution(s, r, POOL_BALL_E);

    /* the pockets: a sensor begin means the ball's centre is over the hole */
    for (k = 0; k < 6; ++k) {
        r = demo_stage_add_sensor(s, pool_pockets[k][0], pool_pockets[k][1],
                                  POOL_POCKET_R - POOL_R);
        if (k == 0)
            st->sensor_lo = r;
        st->sensor_hi = r;
    }

    show->control = pool_control;
    show->backdrop = pool_backdrop;
    show->caption = pool_caption;
    show->report = pool_report;
    return s->error;
}
