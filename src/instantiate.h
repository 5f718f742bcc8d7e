/* Compiles the template named by CC_TEMPLATE (a *.inc file) twice: once for double, once for
 * float. A source file says `#define CC_TEMPLATE "sweep.inc"` and includes this; that is how the
 * algorithm is written once for both precisions. */
#include "cc_internal.h"

#include "precision_double.h"
#include "helpers.inc"
#include "solver.inc"
#include CC_TEMPLATE
#include "precision_end.h"

#include "precision_float.h"
#include "helpers.inc"
#include "solver.inc"
#include CC_TEMPLATE
#include "precision_end.h"
