/* The textbook time of impact in double and float (see textbook.h); the algorithm is in
 * textbook.inc, compiled once per precision. */
#include "textbook.h"

#include <math.h>

#define TB_R double
#define TB_V cc_vec2
#define TB_CIRCLE cc_circle
#define TB_SEGMENT cc_segment
#define TB_CONTACT cc_contact
#define TB_FN(name) name
#define TB_C(x) x
#define TB_SQRT sqrt
#define TB_FABS fabs
#include "textbook.inc"
#undef TB_R
#undef TB_V
#undef TB_CIRCLE
#undef TB_SEGMENT
#undef TB_CONTACT
#undef TB_FN
#undef TB_C
#undef TB_SQRT
#undef TB_FABS

#define TB_CAT2(a, b) a##b
#define TB_CAT(a, b) TB_CAT2(a, b)
#define TB_R float
#define TB_V cc_vec2f
#define TB_CIRCLE cc_circlef
#define TB_SEGMENT cc_segmentf
#define TB_CONTACT cc_contactf
#define TB_FN(name) TB_CAT(name, f)
#define TB_C(x) TB_CAT(x, f)
#define TB_SQRT sqrtf
#define TB_FABS fabsf
#include "textbook.inc"
