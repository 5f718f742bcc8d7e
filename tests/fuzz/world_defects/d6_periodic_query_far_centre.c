/* D6: a query whose centre lies outside [0, period) misses a circle whose nearest image is inside */
#include <stdio.h>
#include <stdlib.h>
#include "circlecollide.h"
int main(int argc, char **argv) {
  int mode; double qy = argc > 1 ? atof(argv[1]) : 9.8;
  for (mode = 0; mode < 3; mode++) {
    cc_world_def d; cc_world_def_init(&d); d.max_circles = 4; d.mode = mode; d.period.y = 4.6;
    static double mem[1<<16]; int st, ids[4], step;
    cc_world *w = cc_world_init(mem, cc_world_size(&d), &d, &st);
    cc_circle c = {{-2, 0.1}, {0, 0}, 0.36, 1};
    cc_vec2 q = {-3.7, qy};
    cc_world_add_circle(w, &c);
    for (step = 0; step < 2; step++) {
      printf("mode %d %s: query_circle at (%g, %g) r 2.47: %d;", mode, step ? "after a step" : "before a step", q.x, q.y,
             cc_world_query_circle(w, q, 2.47, ~0u, ids, 4));
      q.y -= 9.2;
      printf(" at (%g, %g) (two periods down): %d\n", q.x, q.y, cc_world_query_circle(w, q, 2.47, ~0u, ids, 4));
      q.y += 9.2;
      cc_world_step(w, 0.5);
    }
  }
  return 0; }
