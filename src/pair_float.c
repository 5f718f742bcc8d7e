/* The pair functions in single precision (suffix f): the same templates as pair_double.c,
 * bound to float, computing in float only (-Wdouble-promotion is an error here). */
#include "cc_internal.h"

#include "precision_float.h"
#include "pair_templates.h"
