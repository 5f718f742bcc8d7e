/* D9: EXACT with rolling friction (decel 2.04, restitution 0.029): a step that starts without
 * overlaps ends (at CC_EVENT_LIMIT) with two movable circles overlapping by 6.6e-4 of their radius sum */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "circlecollide.h"
int main(int argc, char **argv) {
  cc_world_def d; cc_world_def_init(&d);
  static double mem[1<<16]; int st, rc, i;
  cc_world *w; cc_circle c[3], o1, o2; cc_world_stats s; double dist;
  cc_circle a = {{9.0871369294605806, -0.53941908713692932}, {-0.43568464730290479, -4.7095435684647304}, 1.1925311203319502, 2.4253112033195023};
  cc_circle b = {{-0.62240663900414894, 1.9502074688796682}, {-3.1327800829875518, 2.5103734439834025}, 0.79875518672199175, 3.9190871369294604};
  cc_circle e = {{10, 10}, {-1.5560165975103732, -2.2614107883817427}, 100, 1.2136929460580914};
  d.max_circles = 14; d.max_segments = 1; d.restitution = 0.029045643153526972; d.rolling_decel = 2.0435684647302903;
  d.max_events = argc > 1 ? strtoull(argv[1], 0, 10) : 2026;
  w = cc_world_init(mem, cc_world_size(&d), &d, &st);
  cc_world_add_circle(w, &a);
  cc_world_step(w, 0.39000000000000001);
  cc_world_add_circle(w, &b);
  cc_world_add_circle(w, &e);
  cc_world_get_circle(w, 1, &o1); cc_world_get_circle(w, 2, &o2);
  dist = hypot(o2.pos.x - o1.pos.x, o2.pos.y - o1.pos.y);
  printf("before the step: overlap of 1 and 2: %.3g\n", o1.radius + o2.radius - dist);
  rc = cc_world_step(w, 0.84647302904564314);
  cc_world_get_circle(w, 1, &o1); cc_world_get_circle(w, 2, &o2);
  dist = hypot(o2.pos.x - o1.pos.x, o2.pos.y - o1.pos.y);
  s.struct_size = sizeof s; cc_world_get_stats(w, &s);
  printf("step %d at time %.17g: overlap of 1 and 2: %.3g (max_overlap %.3g, events %llu)\n", rc, cc_world_time(w),
         o1.radius + o2.radius - dist, s.max_overlap, (unsigned long long)s.events);
  (void)c; (void)i; return 0; }
