/* Rolling to rest (rolling.inc) in single precision (suffix f), computing in float only
 * (-Wdouble-promotion is an error here); the solver's entry points are private to this object. */
#include "cc_internal.h"

#include "precision_float.h"
#include "helpers.inc"
#include "solver.inc"
#define CC__ROLL_LINK static
#include "rolling.inc"
