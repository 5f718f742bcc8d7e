/* D3: query_circle misses a huge circle that covers the query disc */
#include <stdio.h>
#include <stdlib.h>
#include "circlecollide.h"
int main(int argc, char **argv) {
  double R = argc > 1 ? atof(argv[1]) : 1e300;
  int mode;
  for (mode = 0; mode < 3; mode++) {
    cc_world_def d; cc_world_def_init(&d); d.max_circles = 4; d.mode = mode;
    static double mem[1<<16]; int st, ids[4];
    cc_world *w = cc_world_init(mem, cc_world_size(&d), &d, &st);
    cc_circle c = {{0.2 * R, 0.1 * R}, {0, 0}, R, 1};
    cc_vec2 q = {0, 0}, lo = {-1, -1}, hi = {1, 1}, dir = {1, 0};
    cc_cast_hit hit;
    cc_world_add_circle(w, &c);
    printf("mode %d R %g: query_circle %d, query_box %d, cast %d", mode, R, cc_world_query_circle(w, q, 1.0, ~0u, ids, 4),
           cc_world_query_box(w, lo, hi, ~0u, ids, 4), cc_world_cast_circle(w, q, 1.0, dir, ~0u, &hit));
    cc_world_step(w, 1.0);
    printf(" | after a step: query_circle %d, query_box %d\n", cc_world_query_circle(w, q, 1.0, ~0u, ids, 4),
           cc_world_query_box(w, lo, hi, ~0u, ids, 4));
  }
  return 0; }
