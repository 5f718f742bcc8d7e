/* D2: a periodic world given a circle far from the origin (valid: finite coordinates) */
#include <stdio.h>
#include "circlecollide.h"
int main(void) {
  cc_world_def d; cc_world_def_init(&d); d.max_circles = 4; d.period.x = 20; d.period.y = 20;
  static double mem[1<<16]; int st;
  cc_world *w = cc_world_init(mem, cc_world_size(&d), &d, &st);
  cc_circle c = {{1e300, 1}, {0, 0}, 0.5, 1}; cc_circle o; cc_vec2 u;
  printf("add %d\n", cc_world_add_circle(w, &c));
  cc_world_get_circle(w, 0, &o); cc_world_get_unwrapped(w, 0, &u);
  printf("pos %g %g unwrapped %g %g\n", o.pos.x, o.pos.y, u.x, u.y);
  return 0; }
