/* DISCRETE mode (a posteriori): every circle moves by dt along its velocity, then the grid is
 * rebuilt and every overlapping pair (circle-circle and circle-wall) is pushed apart and, when
 * approaching, given its impulse. The cheapest mode; a body that moves more than its own
 * size in one step can pass through another (tunnelling): that is the trade. Walls keep their
 * side at any speed (sides.c). */
#include "world_internal.h"

int cc__step_discrete(cc_world *w, double dt)
{
    w->now += dt; /* the bodies' lazy states carry them there as the rebuild advances them */
    cc__keep_wall_sides(w, 0); /* before the push-out, which would take a centre past a wall outside */
    cc__rebuild(w);
    cc__sensor_pass(w);
    return CC_OK;
}
