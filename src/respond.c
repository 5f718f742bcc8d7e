/* Collision response (impulses), in double and float. */
#define CC_TEMPLATE "respond.inc"
#include "instantiate.h"
