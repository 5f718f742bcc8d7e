/* Paints a stage into a rectangle of the canvas: walls, trails, circles, contact flashes. */
#ifndef DEMO_RENDER_H
#define DEMO_RENDER_H

#include "raster.h"
#include "stage.h"

/* Maps the stage's world rectangle into a pixel rectangle, uniformly scaled and centred (y up in
 * the world, down in the picture). */
typedef struct demo_view {
    double scale;  /* pixels per world unit */
    double ox, oy; /* pixel position of world (x0, y1), the top-left corner */
    double x0, y1;
    double vx, vy, vw, vh; /* the pixel rectangle */
} demo_view;

demo_view demo_view_fit(const demo_stage_def *d, double vx, double vy, double vw, double vh);
double demo_view_x(const demo_view *v, double x);
double demo_view_y(const demo_view *v, double y);

/* Walls, trails, circles and flashes of s as of world time now. */
void demo_render_stage(demo_canvas *c, const demo_stage *s, const demo_view *v, double now);

/* Caption text centred at the top of the view, on a dark band (left out when too wide). */
void demo_render_caption(demo_canvas *c, const demo_view *v, const char *text, int scale);

#endif
