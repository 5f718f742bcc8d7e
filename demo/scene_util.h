/* Small helpers shared by the scene files. */
#ifndef DEMO_SCENE_UTIL_H
#define DEMO_SCENE_UTIL_H

#include <circlecollide.h>

static inline cc_circle demo_circle(double x, double y, double vx, double vy, double r, double m)
{
    cc_circle c;
    c.pos.x = x;
    c.pos.y = y;
    c.vel.x = vx;
    c.vel.y = vy;
    c.radius = r;
    c.mass = m;
    return c;
}

#endif
