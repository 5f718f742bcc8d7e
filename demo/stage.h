/* A stage: one world plus what the pictures need from it: the circles as of the last frame, each
 * circle's recent path (its trail, including the points where it bounced), the contacts of the
 * last moments (the flashes), and an energy ledger that separates what the demo itself did to the
 * bodies (pushing mallets, table friction, pocketing) from what the world's collisions did. */
#ifndef DEMO_STAGE_H
#define DEMO_STAGE_H

#include <circlecollide.h>
#include <stdint.h>

#define DEMO_TRAIL_POINTS 24

typedef struct demo_point {
    double x, y, t;
} demo_point;

typedef struct demo_trail {
    int head, count; /* ring buffer of the newest count points; head is the next slot */
    demo_point p[DEMO_TRAIL_POINTS];
} demo_trail;

typedef struct demo_flash {
    double x, y, t, strength; /* strength in [0, 1]: impulse relative to the stage's reference */
} demo_flash;

/* How a circle is painted. */
#define DEMO_STYLE_SPEED 0 /* filled with its speed colour */
#define DEMO_STYLE_MARKED 1 /* speed colour and a white rim: the cue ball, the puck, the heavy one */
#define DEMO_STYLE_SOLID 2 /* a solid grey body: mallets and other bodies the demo drives */
#define DEMO_STYLE_HIDDEN 3 /* not painted: sensors (the backdrop paints pockets and goals) */

/* Called for every sensor event of the stage's world (cc_world_def.on_sensor), with the
 * stage def's sensor_user. Like the world's callback, it may read the world but not change it:
 * note what happened and act on it in the scene's control hook. */
typedef void (*demo_sensor_fn)(const cc_sensor_event *event, void *user);

typedef struct demo_stage_def {
    int max_circles, max_segments;
    int mode;
    double restitution, rest_speed;
    double x0, y0, x1, y1; /* the world rectangle the picture shows (y up) */
    double speed_ref;      /* speed painted red */
    double impulse_ref;    /* impulse of a full-strength flash */
    double trail_time;     /* how long a trail lasts (world time; 0: no trails) */
    double flash_time;     /* how long a flash lasts (world time; 0: no flashes) */
    double flash_radius;   /* a flash's final radius in world units */
    int flash_capacity;    /* flashes remembered at once (the oldest give way) */
    const char *label;     /* a caption for the stage, or NULL */
    /* the world's 1.1 settings (demo_stage_def_init leaves them off) */
    double rolling_decel;  /* cc_world_def.rolling_decel: the ground's deceleration */
    int restitution_mix;   /* cc_world_def.restitution_mix (CC_MIX_MIN is 0) */
    demo_sensor_fn on_sensor; /* or NULL */
    void *sensor_user;
} demo_stage_def;

typedef struct demo_stage {
    demo_stage_def def;
    cc_vec2 period; /* the world's cc_world_def.period ((0, 0): open), demo_stage_init_periodic */
    cc_world *world;
    void *memory;
    /* the circles at the last snapshot, in increasing id order */
    int count;
    int *ids;
    cc_circle *circles;
    /* per id (ids below max_circles) */
    double *radius_of;
    unsigned char *style_of;
    demo_trail *trails;
    /* walls, copied when added */
    int nwalls;
    cc_segment *walls;
    /* the newest contacts */
    demo_flash *flashes;
    int flash_head, flash_count;
    /* energy ledger */
    double energy0;       /* kinetic energy when the first frame was taken */
    double energy_demo;   /* kinetic energy the demo added (+) or removed (-) since */
    double energy_peak;   /* the most kinetic energy seen at a frame */
    int started;
    uint64_t contacts;    /* contact callbacks seen */
    int error;            /* the first library error met, or 0 */
    const char *error_what;
} demo_stage;

/* The defaults every scene starts from (Box2D's def-struct habit): a frictionless one-material
 * world of 64 circles and no walls in `mode`, restitution 1, the unit square shown, no trails,
 * no flashes, no caption, no sensors. A scene sets only what it needs. */
void demo_stage_def_init(demo_stage_def *def, int mode);

/* Creates the world (memory from malloc). 0, or a negative CC_ERR_* / -100 for out of memory. */
int demo_stage_init(demo_stage *s, const demo_stage_def *def);
/* The same for a periodic box: the world wraps along x when px > 0 and along y when py > 0
 * (cc_world_def.period), and the renderer paints a circle that straddles a wrapped edge on both
 * sides (trails are not wrapped: give such a stage trail_time 0). */
int demo_stage_init_periodic(demo_stage *s, const demo_stage_def *def, double px, double py);
void demo_stage_free(demo_stage *s);

/* Adds a circle or a wall; returns the id or a negative error (also recorded in s->error). */
int demo_stage_add_circle(demo_stage *s, const cc_circle *c, int style);
int demo_stage_add_wall(demo_stage *s, double ax, double ay, double bx, double by);
/* Adds an immovable sensor circle (a pocket, a goal mouth) that is not painted; returns its id
 * or a negative error (also recorded in s->error). */
int demo_stage_add_sensor(demo_stage *s, double x, double y, double radius);
/* Sets the restitution of a circle or a wall through its properties (0 or a negative error,
 * also recorded in s->error). */
int demo_stage_set_circle_restitution(demo_stage *s, int id, double restitution);
int demo_stage_set_wall_restitution(demo_stage *s, int id, double restitution);
/* Replaces a circle's state, booking the change of kinetic energy as the demo's. */
int demo_stage_set_circle(demo_stage *s, int id, const cc_circle *c);
/* Removes a circle (its energy leaves with it, booked as the demo's). */
int demo_stage_remove_circle(demo_stage *s, int id);

/* Steps the world to time t (continuing after CC_EVENT_LIMIT). 0 or a negative error. */
int demo_stage_step_to(demo_stage *s, double t);
/* Reads the circles back and adds their positions to the trails. */
void demo_stage_snapshot(demo_stage *s);

/* Kinetic energy of the circles of the last snapshot (immovable ones excluded). */
double demo_stage_energy(const demo_stage *s);
/* (E_now - E_0 - E_demo) / max(E_0, E_peak): the energy the collisions gained or lost,
 * relative to the most there was (the demo may have added energy, as the mallets do). */
double demo_stage_drift(const demo_stage *s);
/* Index into s->circles of a live id, or -1. */
int demo_stage_find(const demo_stage *s, int id);

#endif
