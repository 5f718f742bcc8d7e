/* Time of impact: circle against circle and circle against segment, in double and float. */
#define CC_TEMPLATE "sweep.inc"
#include "instantiate.h"
