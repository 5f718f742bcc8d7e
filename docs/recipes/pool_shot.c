/* Recipe: a pool shot from aim to rest (docs/RECIPES.md). A table of 2.54 x 1.27 m with four
 * cushions (restitution 0.75) and six pockets (sensors), balls of 57.15 mm (restitution 0.95)
 * rolling on cloth (0.15 m/s^2). The cue ball is aimed with the ghost-ball rule to send the
 * object ball into the bottom right pocket; the aiming line is checked with a cast; then the
 * shot is played until every ball rests. Checks what it prints, and exits 1 if a check fails. */
#include <circlecollide.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define W 2.54
#define H 1.27
#define R 0.028575       /* ball radius */
#define POCKET 0.06      /* a ball whose centre comes this close to a pocket's centre drops */
#define MOUTH 0.12       /* cushions stop this far from a corner (and from a side pocket) */
#define BALL_CAT 1u
#define POCKET_CAT 2u

static int g_potted[16], g_n_potted;

/* A pocket's sensor begins to overlap a ball: the ball drops. Only noted here (a callback may
 * read the world, not change it); removed between steps. */
static void on_sensor(const cc_sensor_event *e, void *user)
{
    (void)user;
    if (e->begin && g_n_potted < 16)
        g_potted[g_n_potted++] = e->visitor;
}

static int check(int ok, const char *what)
{
    printf("%s %s\n", ok ? "ok  " : "FAIL", what);
    return ok ? 0 : 1;
}

int main(void)
{
    static const double pockets[6][2] = {{0, 0}, {W / 2, 0}, {W, 0}, {0, H}, {W / 2, H}, {W, H}};
    cc_world_def def;
    cc_world *w;
    void *mem;
    size_t bytes;
    int i, cue, object, failures = 0, steps = 0, moving = 1;
    cc_vec2 C = {0.6, 0.5}, O = {1.5, 0.4}, P = {W, 0.0}, G, d;
    cc_cast_hit hit;
    double len;

    cc_world_def_init(&def);
    def.max_circles = 16;
    def.max_segments = 8;
    def.rolling_decel = 0.15;              /* cloth */
    def.restitution = 0.95;                /* every ball (and, by default, every wall) */
    def.restitution_mix = CC_MIX_MIN;      /* ball-cushion: the cushion's 0.75 */
    def.on_sensor = on_sensor;
    bytes = cc_world_size(&def);
    mem = malloc(bytes);
    w = cc_world_init(mem, bytes, &def, NULL);
    if (w == NULL)
        return 1;

    /* cushions: each long side in two halves around the side pocket, each short side whole,
     * all stopping short of the pockets' mouths; restitution 0.75 through their props */
    {
        const cc_segment cushions[6] = {
            {{MOUTH, 0}, {W / 2 - MOUTH / 2, 0}}, {{W / 2 + MOUTH / 2, 0}, {W - MOUTH, 0}},
            {{MOUTH, H}, {W / 2 - MOUTH / 2, H}}, {{W / 2 + MOUTH / 2, H}, {W - MOUTH, H}},
            {{0, MOUTH}, {0, H - MOUTH}},         {{W, MOUTH}, {W, H - MOUTH}}};
        for (i = 0; i < 6; i++) {
            cc_segment_props sp;
            int id = cc_world_add_segment(w, &cushions[i]);
            sp.struct_size = sizeof sp;
            cc_world_get_segment_props(w, id, &sp);
            sp.restitution = 0.75;
            cc_world_set_segment_props(w, id, &sp);
        }
    }
    /* pockets: immovable sensor circles; a ball's centre within POCKET of the pocket's centre
     * means the two discs overlap when the sensor's radius is POCKET - R */
    for (i = 0; i < 6; i++) {
        cc_circle p = {{pockets[i][0], pockets[i][1]}, {0, 0}, POCKET - R, INFINITY};
        cc_circle_props pp;
        int id = cc_world_add_circle(w, &p);
        pp.struct_size = sizeof pp;
        cc_world_get_circle_props(w, id, &pp);
        pp.sensor = 1;
        pp.category = POCKET_CAT;
        cc_world_set_circle_props(w, id, &pp);
    }
    {
        cc_circle ob = {{O.x, O.y}, {0, 0}, R, 0.17};
        object = cc_world_add_circle(w, &ob);
    }

    /* aim: the ghost ball G touches the object ball on the far side from the pocket */
    d.x = P.x - O.x, d.y = P.y - O.y;
    len = sqrt(d.x * d.x + d.y * d.y);
    G.x = O.x - 2 * R * d.x / len;
    G.y = O.y - 2 * R * d.y / len;
    d.x = G.x - C.x, d.y = G.y - C.y;      /* the cue ball's path to G */
    {   /* cast a little beyond G (a touch exactly at the path's end is rounding's to see) */
        cc_vec2 beyond = {2.0 * d.x, 2.0 * d.y};
        if (cc_world_cast_circle(w, C, R, beyond, BALL_CAT, &hit) != CC_HIT)
            return check(0, "the aiming cast hits something");
    }
    printf("aiming line: the cue ball first touches circle %d at t = %.15f of the path; the object "
           "ball leaves along (%.6f, %.6f), the pocket is along (%.6f, %.6f)\n",
           hit.circle, hit.t, hit.normal.x, hit.normal.y, (P.x - O.x) / len, (P.y - O.y) / len);
    failures += check(hit.circle == object, "the cast finds the object ball first");
    failures += check(fabs(hit.t - 0.5) < 1e-12, "the touch is at the ghost ball (half the doubled path)");
    failures += check(fabs(hit.normal.x - (P.x - O.x) / len) < 1e-12 && fabs(hit.normal.y - (P.y - O.y) / len) < 1e-12,
                      "the object ball's line points at the pocket");

    /* shoot at 2 m/s along the aiming line */
    {
        cc_circle cb = {{C.x, C.y}, {2.0 * d.x / sqrt(d.x * d.x + d.y * d.y), 2.0 * d.y / sqrt(d.x * d.x + d.y * d.y)}, R, 0.17};
        cue = cc_world_add_circle(w, &cb);
    }
    while (moving && steps < 6000) { /* 60 Hz for up to 100 s */
        cc_world_step(w, 1.0 / 60);
        steps++;
        for (i = 0; i < g_n_potted; i++)
            cc_world_remove_circle(w, g_potted[i]);
        g_n_potted = 0;
        moving = 0;
        for (i = 0; i < 2; i++) {
            cc_circle c;
            int id = i ? object : cue;
            if (cc_world_get_circle(w, id, &c) == CC_OK && (c.vel.x != 0.0 || c.vel.y != 0.0))
                moving = 1;
        }
    }
    {
        cc_circle c;
        int object_gone = cc_world_get_circle(w, object, &c) == CC_ERR_NOT_FOUND;
        int cue_here = cc_world_get_circle(w, cue, &c) == CC_OK;
        printf("after %.2f s: object ball %s; cue ball %s at (%.4f, %.4f)\n", steps / 60.0,
               object_gone ? "potted" : "on the table", cue_here ? "at rest" : "potted", c.pos.x, c.pos.y);
        failures += check(object_gone, "the object ball drops into the bottom right pocket");
        failures += check(cue_here && c.vel.x == 0.0 && c.vel.y == 0.0 && c.pos.x > 0 && c.pos.x < W && c.pos.y > 0 && c.pos.y < H,
                          "the cue ball rolls to rest on the table");
        failures += check(!moving, "everything rests within 100 s");
    }
    free(mem);
    return failures ? 1 : 0;
}
