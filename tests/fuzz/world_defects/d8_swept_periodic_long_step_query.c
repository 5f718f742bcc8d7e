/* D8: SWEPT, periodic: after a step that carries a circle more than a period (the header says a
 * SWEPT/DISCRETE step "must not carry a circle half a period", but the step is accepted), query_box
 * misses it. usage: d8 DT MODE (DT 5 and up misses in mode 1) */
#include <stdio.h>
#include <stdlib.h>
#include "circlecollide.h"
int main(int argc, char **argv) {
  double dt = argc > 1 ? atof(argv[1]) : 1e6; int mode = argc > 2 ? atoi(argv[2]) : 1, n, i, ids[8];
  cc_world_def d; cc_world_def_init(&d); d.max_circles = 8; d.mode = mode; d.period.x = 20.0415; d.period.y = 16.0581;
  static double mem[1<<16]; int st; cc_circle o;
  cc_world *w = cc_world_init(mem, cc_world_size(&d), &d, &st);
  cc_circle c = {{5, 10}, {3.7966804979253119, -4.5435684647302903}, 0.34, 3.1};
  cc_vec2 lo = {4.6887966804979264, 5.8506224066390029}, hi = {5.6639004149377605, 9.834024896265559};
  cc_world_add_circle(w, &c);
  cc_world_step(w, 1.0);
  cc_world_step(w, dt);
  cc_world_get_circle(w, 0, &o);
  lo.x = o.pos.x - 0.4; hi.x = o.pos.x + 0.4; hi.y = o.pos.y - 0.2; lo.y = hi.y - 4;
  n = cc_world_query_box(w, lo, hi, ~0u, ids, 8);
  printf("mode %d dt %g: circle at (%.17g, %.17g) r 0.34, box (%g,%g)-(%g,%g): query_box %d\n", mode, dt, o.pos.x, o.pos.y, lo.x, lo.y, hi.x, hi.y, n);
  (void)i; return 0; }
