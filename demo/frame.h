/* Composes one frame of a show: its stages side by side, their captions and a status line. */
#ifndef DEMO_FRAME_H
#define DEMO_FRAME_H

#include "raster.h"
#include "scene.h"

void demo_frame_render(demo_canvas *c, demo_show *show);

#endif
