/* Recipe: air hockey (docs/RECIPES.md). A 2 x 1 m table with a goal mouth 0.3 m wide in each
 * short side and a box behind it; a puck floating without friction; two mallets that the players
 * drive: kinematic circles (mass INFINITY, velocity set every frame), which push the puck and
 * pass through walls, so each player keeps its own mallet in its half. Each goal is a sensor
 * circle that senses the puck only (filters): its begin is the goal.
 * Player A strikes the resting puck straight at B's goal; B, the goalie, tracks the puck but is
 * slower than the shot. Checks that the strike gives the puck (1 + e) times the mallet's speed,
 * that A scores, and at what time. Exits 1 if a check fails. */
#include <circlecollide.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define W 2.0
#define H 1.0
#define MOUTH 0.3  /* goal mouth, centred on y = H / 2 */
#define DEPTH 0.2  /* goal box behind the line */
#define RP 0.04    /* puck */
#define RM 0.05    /* mallet */
#define E 0.9      /* puck-mallet and puck-wall restitution */
#define PUCK 1u    /* categories */
#define MALLET 2u
#define GOAL 4u
#define FRAME (1.0 / 120)

static int g_struck = -1, g_goal_for = -1; /* events noted by the callbacks */
static double g_goal_t;
static int g_mallet_a, g_mallet_b, g_goal_a, g_goal_b, g_puck;

static void on_contact(const cc_contact_event *e, void *user)
{
    (void)user;
    if (g_struck < 0 && e->b >= 0 && (e->a == g_puck || e->b == g_puck))
        g_struck = e->a == g_puck ? e->b : e->a; /* the first mallet to touch the puck */
}

static void on_sensor(const cc_sensor_event *e, void *user)
{
    (void)user;
    if (e->begin && e->visitor == g_puck && g_goal_for < 0) {
        g_goal_for = e->sensor == g_goal_b ? 0 : 1; /* the puck in B's goal: a point for A */
        g_goal_t = e->t;
    }
}

static int check(int ok, const char *what)
{
    printf("%s %s\n", ok ? "ok  " : "FAIL", what);
    return ok ? 0 : 1;
}

static int add(cc_world *w, double x, double y, double r, double m, uint32_t cat, uint32_t mask, int sensor)
{
    cc_circle c;
    cc_circle_props p;
    int id;
    c.pos.x = x, c.pos.y = y, c.vel.x = c.vel.y = 0.0, c.radius = r, c.mass = m;
    id = cc_world_add_circle(w, &c);
    p.struct_size = sizeof p;
    cc_world_get_circle_props(w, id, &p);
    p.category = cat, p.mask = mask, p.sensor = sensor;
    cc_world_set_circle_props(w, id, &p);
    return id;
}

/* A player's hand: the mallet goes at velocity v for the next frame, kept in x range [lo, hi]
 * (a kinematic circle passes through walls: the player's arm keeps it on its side). */
static void drive(cc_world *w, int id, double vx, double vy, double lo, double hi)
{
    cc_circle m;
    cc_world_get_circle(w, id, &m);
    if ((m.pos.x <= lo && vx < 0) || (m.pos.x >= hi && vx > 0))
        vx = 0.0;
    if ((m.pos.y <= RM && vy < 0) || (m.pos.y >= H - RM && vy > 0))
        vy = 0.0;
    m.vel.x = vx, m.vel.y = vy;
    cc_world_set_circle(w, id, &m);
}

int main(void)
{
    static const cc_segment walls[] = {
        {{0, 0}, {W, 0}}, {{W, H}, {0, H}},                                          /* long sides */
        {{0, 0}, {0, (H - MOUTH) / 2}}, {{0, (H + MOUTH) / 2}, {0, H}},             /* A's end */
        {{W, 0}, {W, (H - MOUTH) / 2}}, {{W, (H + MOUTH) / 2}, {W, H}},             /* B's end */
        {{0, (H - MOUTH) / 2}, {-DEPTH, (H - MOUTH) / 2}}, {{-DEPTH, (H - MOUTH) / 2}, {-DEPTH, (H + MOUTH) / 2}},
        {{-DEPTH, (H + MOUTH) / 2}, {0, (H + MOUTH) / 2}},                          /* A's goal box */
        {{W, (H - MOUTH) / 2}, {W + DEPTH, (H - MOUTH) / 2}}, {{W + DEPTH, (H - MOUTH) / 2}, {W + DEPTH, (H + MOUTH) / 2}},
        {{W + DEPTH, (H + MOUTH) / 2}, {W, (H + MOUTH) / 2}}};                      /* B's goal box */
    const int n_walls = (int)(sizeof walls / sizeof walls[0]);
    const double strike = 3.0; /* A's mallet speed, m/s */
    const double goalie = 0.6; /* B's top speed */
    cc_world_def def;
    cc_world *w;
    void *mem;
    size_t bytes;
    int i, frame, failures = 0;
    double puck_speed = -1.0, aim_x, aim_y, len;
    cc_circle puck;

    cc_world_def_init(&def);
    def.max_circles = 8;
    def.max_segments = n_walls;
    def.restitution = E;
    def.on_contact = on_contact;
    def.on_sensor = on_sensor;
    bytes = cc_world_size(&def);
    mem = malloc(bytes);
    w = cc_world_init(mem, bytes, &def, NULL);
    if (w == NULL)
        return 1;
    for (i = 0; i < n_walls; i++)
        cc_world_add_segment(w, &walls[i]);
    /* the goals: the puck's centre crossing the goal line begins the overlap (sensor radius
     * DEPTH / 2, centred DEPTH / 2 + RP behind the line: distance < DEPTH / 2 + RP there) */
    g_goal_a = add(w, -DEPTH / 2 - RP, H / 2, DEPTH / 2, INFINITY, GOAL, PUCK, 1);
    g_goal_b = add(w, W + DEPTH / 2 + RP, H / 2, DEPTH / 2, INFINITY, GOAL, PUCK, 1);
    g_puck = add(w, 0.6, 0.42, RP, 0.02, PUCK, PUCK | MALLET | GOAL, 0); /* walls are category 1 = PUCK */
    /* A's mallet behind the puck on the line from B's goal centre through the puck */
    aim_x = W - 0.6, aim_y = H / 2 - 0.42;
    len = sqrt(aim_x * aim_x + aim_y * aim_y);
    aim_x /= len, aim_y /= len;
    g_mallet_a = add(w, 0.6 - 0.2 * aim_x, 0.42 - 0.2 * aim_y, RM, INFINITY, MALLET, PUCK, 0);
    g_mallet_b = add(w, W - 0.25, 0.85, RM, INFINITY, MALLET, PUCK, 0); /* B, out of position */

    for (frame = 0; frame < 240 && g_goal_for < 0; frame++) {
        cc_circle b;
        cc_world_get_circle(w, g_puck, &puck);
        cc_world_get_circle(w, g_mallet_b, &b);
        /* A: drive through the puck until it is struck, then stop */
        if (g_struck < 0)
            drive(w, g_mallet_a, strike * aim_x, strike * aim_y, RM, W / 2 - RM);
        else
            drive(w, g_mallet_a, 0.0, 0.0, RM, W / 2 - RM);
        /* B: follow the puck's y at up to `goalie` m/s */
        drive(w, g_mallet_b, 0.0, fmax(-goalie, fmin(goalie, (puck.pos.y - b.pos.y) / FRAME)), W / 2 + RM, W - RM);
        cc_world_step(w, FRAME);
        if (g_struck >= 0 && puck_speed < 0) {
            cc_world_get_circle(w, g_puck, &puck);
            puck_speed = sqrt(puck.vel.x * puck.vel.x + puck.vel.y * puck.vel.y);
            printf("frame %d: mallet %s strikes the puck at %.2f m/s: the puck leaves at %.6f m/s\n", frame,
                   g_struck == g_mallet_a ? "A" : "B", strike, puck_speed);
        }
    }
    cc_world_get_circle(w, g_puck, &puck);
    if (g_goal_for >= 0)
        printf("goal for %s at t = %.4f s (puck at (%.3f, %.3f) at the end of that frame)\n", g_goal_for == 0 ? "A" : "B",
               g_goal_t, puck.pos.x, puck.pos.y);
    failures += check(g_struck == g_mallet_a, "A's mallet strikes first");
    failures += check(fabs(puck_speed - (1.0 + E) * strike) <= 1e-9 * strike,
                      "a head-on strike by a kinematic mallet: puck speed (1 + e) times the mallet's");
    failures += check(g_goal_for == 0, "A scores: the puck's begin in B's goal sensor");
    /* the strike comes after 0.2 - RM - RP = 0.11 m of the mallet's travel (within a frame: EXACT
     * finds the instant); then the puck's centre goes len metres straight to the goal line's
     * middle, where it begins to overlap the sensor */
    failures += check(fabs(g_goal_t - (0.11 / strike + len / ((1.0 + E) * strike))) <= 1e-12,
                      "at the time the straight shot takes (0.11 m / 3 m/s + 1.4023 m / 5.7 m/s)");
    free(mem);
    return failures ? 1 : 0;
}
