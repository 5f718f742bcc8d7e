/* D4: SWEPT periodic world, a tiny circle that moves: the cell range is converted to int64_t from
 * a double far out of range (src/world/swept.c:172) */
#include <stdio.h>
#include "circlecollide.h"
int main(void) {
  cc_world_def d; cc_world_def_init(&d); d.max_circles = 4; d.mode = CC_MODE_SWEPT; /* every mode: the rebuild at the step */ d.period.x = 20; d.period.y = 20;
  static double mem[1<<16]; int st;
  cc_world *w = cc_world_init(mem, cc_world_size(&d), &d, &st);
  cc_circle a = {{1, 1}, {1, 0}, 1e-9, 1}, b = {{5, 5}, {0, 0}, 1e-9, 1};
  printf("add %d %d\n", cc_world_add_circle(w, &a), cc_world_add_circle(w, &b));
  printf("step %d\n", cc_world_step(w, 1.0));
  return 0; }
