/* Colours of the demo: a speed colour map and the palette of the scenes. */
#ifndef DEMO_COLOUR_H
#define DEMO_COLOUR_H

#include "raster.h"

/* Speed colour: s = speed / reference speed; 0 is deep blue, then cyan, green, yellow, and red
 * from s = 1 on (values outside [0, 1] are clamped; NaN counts as 0). */
demo_rgb demo_speed_colour(double s);

#endif
