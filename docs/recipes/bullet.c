/* Recipe: a bullet through a crowd, without tunnelling (docs/RECIPES.md). A 5 mm pellet at
 * 400 m/s in a 10 x 2 m room of zero-thickness walls, with a crowd of 24 heavy balls (0.1 m,
 * 1 kg) standing in it; frames of 1/60 s, in which the pellet flies 6.7 m, more than half the
 * room. EXACT finds every impact in time order at any speed: the pellet never leaves the room,
 * hits the crowd, and kinetic energy is kept (restitution 1). DISCRETE moves everything by a
 * frame and then looks for overlaps: the walls hold (a centre past a wall is put back on its
 * side, the header's "Walls"), but the pellet flies through the crowd (tunnelling
 * through circles, as the header says of DISCRETE). Checks both; exits 1 if a check fails. */
#include <circlecollide.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define LX 5.0 /* the room is [-LX, LX] x [-LY, LY] */
#define LY 1.0
#define FRAMES 60

static int g_pellet_hits_crowd, g_pellet_hits_wall;

static void on_contact(const cc_contact_event *e, void *user)
{
    (void)user;
    if (e->a == 0 || e->b == 0) { /* the pellet is circle 0 */
        if (e->b >= 0)
            g_pellet_hits_crowd++;
        else
            g_pellet_hits_wall++;
    }
}

static int check(int ok, const char *what)
{
    printf("%s %s\n", ok ? "ok  " : "FAIL", what);
    return ok ? 0 : 1;
}

static double energy(const cc_world *w, int n)
{
    double e = 0.0;
    int i;
    for (i = 0; i < n; i++) {
        cc_circle c;
        cc_world_get_circle(w, i, &c);
        e += 0.5 * c.mass * (c.vel.x * c.vel.x + c.vel.y * c.vel.y);
    }
    return e;
}

/* Runs the scene in `mode` for FRAMES frames; returns the first frame (from 0) after which a
 * circle is outside the room (-1: none), the relative change of kinetic energy and the pellet's
 * final x. */
static int run(int mode, double *drift, double *pellet_x)
{
    static const cc_segment room[4] = {
        {{-LX, -LY}, {LX, -LY}}, {{LX, -LY}, {LX, LY}}, {{LX, LY}, {-LX, LY}}, {{-LX, LY}, {-LX, -LY}}};
    const int n = 25;
    cc_world_def def;
    cc_world *w;
    void *mem;
    size_t bytes;
    int i, f, out = -1;
    double e0;
    cc_circle pellet = {{-4.5, 0.0}, {400.0, 37.0}, 0.0025, 0.001};
    cc_world_def_init(&def);
    def.max_circles = n;
    def.max_segments = 4;
    def.mode = mode;
    def.restitution = 1.0;
    def.on_contact = on_contact;
    bytes = cc_world_size(&def);
    mem = malloc(bytes);
    w = cc_world_init(mem, bytes, &def, NULL);
    if (w == NULL)
        exit(1);
    cc_world_add_circle(w, &pellet); /* id 0 */
    for (i = 0; i < n - 1; i++) { /* the crowd: 8 x 3 balls at rest */
        cc_circle c = {{-3.5 + i % 8, -0.6 + 0.6 * (i / 8)}, {0, 0}, 0.1, 1.0};
        cc_world_add_circle(w, &c);
    }
    for (i = 0; i < 4; i++)
        cc_world_add_segment(w, &room[i]);
    e0 = energy(w, n);
    g_pellet_hits_crowd = g_pellet_hits_wall = 0;
    for (f = 0; f < FRAMES; f++) {
        while (cc_world_step(w, 1.0 / 60) == CC_EVENT_LIMIT)
            ;
        for (i = 0; i < n && out < 0; i++) {
            cc_circle c;
            cc_world_get_circle(w, i, &c);
            if (fabs(c.pos.x) > LX || fabs(c.pos.y) > LY)
                out = f;
        }
    }
    {
        cc_circle c;
        cc_world_get_circle(w, 0, &c);
        *pellet_x = c.pos.x;
    }
    *drift = fabs(energy(w, n) - e0) / e0;
    free(mem);
    return out;
}

int main(void)
{
    double drift, x;
    int out, failures = 0;

    out = run(CC_MODE_EXACT, &drift, &x);
    printf("EXACT: after 1 s the pellet is at x = %.3f; %d hits on the crowd, %d on walls; escaped: %s; "
           "energy drift %.1e\n",
           x, g_pellet_hits_crowd, g_pellet_hits_wall, out < 0 ? "none" : "yes", drift);
    failures += check(out < 0, "EXACT: nothing leaves the room (no tunnelling at 400 m/s through 0-thickness walls)");
    failures += check(g_pellet_hits_crowd > 0 && g_pellet_hits_wall > 0, "EXACT: the pellet hits the crowd and the walls");
    failures += check(drift < 1e-9, "EXACT: kinetic energy kept (restitution 1)");

    {
        int exact_crowd = g_pellet_hits_crowd;
        out = run(CC_MODE_DISCRETE, &drift, &x);
        printf("DISCRETE: after 1 s the pellet is at x = %.3f; %d hits on the crowd, %d on walls; escaped: %s\n", x,
               g_pellet_hits_crowd, g_pellet_hits_wall, out < 0 ? "none" : "yes");
        failures += check(out < 0, "DISCRETE: the walls hold too (a centre past a wall is put back on its side)");
        failures += check(g_pellet_hits_crowd < exact_crowd,
                          "DISCRETE: the pellet flies through the crowd (fewer hits than EXACT's)");
    }
    return failures ? 1 : 0;
}
