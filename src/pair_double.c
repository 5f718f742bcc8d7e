/* The pair functions in double precision. One translation unit per precision, so that the
 * private helpers they share are compiled once (this matters on microcontrollers). */
#include "cc_internal.h"

#include "precision_double.h"
#include "pair_templates.h"
