/* The scenes: how each one builds its stages and what it does between frames. A show is one
 * run of a scene: its stages (one world each; the tunnel has three side by side) and hooks. */
#ifndef DEMO_SCENE_H
#define DEMO_SCENE_H

#include "args.h"
#include "render.h"
#include "stage.h"

#include <stddef.h>
#include <stdio.h>

#define DEMO_MAX_STAGES 3

typedef struct demo_show demo_show;
struct demo_show {
    const demo_options *opt;
    demo_stage stage[DEMO_MAX_STAGES];
    int nstages;
    double dt;   /* world time per frame */
    void *state; /* the scene's own data, from malloc (freed by demo_show_free) */
    /* Called before stepping the worlds from frame - 1 to frame (frame >= 1): drive bodies,
       apply friction, pocket balls. May be NULL. */
    void (*control)(demo_show *show, long frame);
    /* Paints what lies under the bodies (table felt, pockets, goal mouths). May be NULL. */
    void (*backdrop)(demo_show *show, int stage, demo_canvas *c, const demo_view *v);
    /* Writes a stage's caption (or leaves buf empty). May be NULL. */
    void (*caption)(demo_show *show, int stage, char *buf, size_t size);
    /* Adds scene-specific lines to the summary. May be NULL. */
    void (*report)(demo_show *show, FILE *f);
};

typedef struct demo_scene {
    const char *name;
    /* Fills show (already zeroed, opt and dt set). 0, or a negative error after printing why. */
    int (*build)(demo_show *show);
} demo_scene;

const demo_scene *demo_find_scene(const char *name);
void demo_show_free(demo_show *show);

int demo_scene_pool(demo_show *show);
int demo_scene_air_hockey(demo_show *show);
int demo_scene_cradle(demo_show *show);
int demo_scene_gas(demo_show *show);
int demo_scene_tunnel(demo_show *show);
int demo_scene_hard_disks(demo_show *show);

#endif
