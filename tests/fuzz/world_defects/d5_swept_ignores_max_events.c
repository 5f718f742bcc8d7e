/* D5: SWEPT never stops at def.max_events: two impacts in a step with max_events 1, CC_OK */
#include <stdio.h>
#include "circlecollide.h"
int main(void) {
  cc_world_def d; cc_world_def_init(&d); d.max_circles = 4; d.mode = CC_MODE_SWEPT; d.max_events = 1;
  static double mem[1<<16]; int st, rc;
  cc_world *w = cc_world_init(mem, cc_world_size(&d), &d, &st);
  cc_circle a = {{0, 0}, {1, 0}, 0.5, 1}, b = {{2, 0}, {-1, 0}, 0.5, 1}, c = {{0, 5}, {1, 0}, 0.5, 1}, e = {{2, 5}, {-1, 0}, 0.5, 1};
  cc_world_stats s0, s1;
  cc_world_add_circle(w, &a); cc_world_add_circle(w, &b); cc_world_add_circle(w, &c); cc_world_add_circle(w, &e);
  s0.struct_size = s1.struct_size = sizeof s0;
  cc_world_get_stats(w, &s0);
  rc = cc_world_step(w, 1.0);
  cc_world_get_stats(w, &s1);
  printf("step %d (%s), %llu events with max_events 1\n", rc, cc_result_string(rc), (unsigned long long)(s1.events - s0.events));
  return 0; }
