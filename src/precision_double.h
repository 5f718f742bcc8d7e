/* Binds the precision-generic names used by the *.inc templates to double. Included by
 * pair_double.c and sweep_many.c, before the templates. */
#define CC_R double
#define CC_V cc_vec2
#define CC_CIRCLE cc_circle
#define CC_SEGMENT cc_segment
#define CC_CONTACT cc_contact
#define CC_FN(name) name            /* public and private names of the double path */
#define CC_C(x) x                   /* a literal of this precision */
#define CC_SQRT sqrt
#define CC_FABS fabs
#define CC_FREXP frexp
#define CC_LDEXP ldexp
#define CC_EPSILON DBL_EPSILON
#define CC_INF HUGE_VAL
#define CC_MAX_EXP DBL_MAX_EXP
/* |n| may differ from 1 by this much in a caller's contact normal (cc_respond*) */
#define CC_NORMAL_TOL 1e-6
/* lengths and speeds inside (LO, HI) keep fourth-order products normal: no rescaling needed */
#define CC_SAFE_LO 0x1p-200
#define CC_SAFE_HI 0x1p200
