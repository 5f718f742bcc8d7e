/* The list of scenes by name, and freeing a show. */
#include "scene.h"

#include <stdlib.h>
#include <string.h>

static const demo_scene scenes[] = {
    {"pool", demo_scene_pool},         {"air-hockey", demo_scene_air_hockey},
    {"cradle", demo_scene_cradle},     {"gas", demo_scene_gas},
    {"tunnel", demo_scene_tunnel},     {"hard-disks", demo_scene_hard_disks},
};

const demo_scene *demo_find_scene(const char *name)
{
    size_t i;
    if (name == NULL)
        return NULL;
    for (i = 0; i < sizeof scenes / sizeof scenes[0]; ++i)
        if (strcmp(scenes[i].name, name) == 0)
            return &scenes[i];
    return NULL;
}

void demo_show_free(demo_show *show)
{
    int i;
    for (i = 0; i < show->nstages; ++i)
        demo_stage_free(&show->stage[i]);
    free(show->state);
    show->state = NULL;
    show->nstages = 0;
}
