/* D1: a step with a valid dt carries a circle past DBL_MAX: CC_OK and a position of +-Inf.
 * usage: d1 MODE PERIOD DT (PERIOD 0: open; on a periodic axis -Inf stays -Inf) */
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include "circlecollide.h"
int main(int argc, char **argv) {
  int mode = argc > 1 ? atoi(argv[1]) : 1; double px = argc > 2 ? atof(argv[2]) : 20.0, dt = argc > 3 ? atof(argv[3]) : 1e308;
  cc_world_def d; cc_world_def_init(&d); d.mode = mode; d.max_circles = 4; d.period.x = px; d.period.y = px;
  static double mem[1<<16]; int st; size_t n = cc_world_size(&d);
  cc_world *w = cc_world_init(mem, n, &d, &st);
  cc_circle c = {{1,1},{-5,-2.5},0.5,1}; cc_circle o;
  printf("add %d\n", cc_world_add_circle(w, &c));
  {int r = cc_world_step(w, dt); printf("step %d time %g\n", r, cc_world_time(w));}
  cc_world_get_circle(w, 0, &o); printf("pos %g %g vel %g %g\n", o.pos.x, o.pos.y, o.vel.x, o.vel.y);
  return 0; }
