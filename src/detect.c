/* Static overlap and push-apart, in double and float. */
#define CC_TEMPLATE "detect.inc"
#include "instantiate.h"
