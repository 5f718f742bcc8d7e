/* Closest point on a segment, in double and float. */
#define CC_TEMPLATE "segment.inc"
#include "instantiate.h"
