/* Binds the precision-generic names used by the *.inc templates to float: every literal and
 * every math call is single precision, so the float path never promotes to double
 * (-Wdouble-promotion clean). */
#define CC_R float
#define CC_V cc_vec2f
#define CC_CIRCLE cc_circlef
#define CC_SEGMENT cc_segmentf
#define CC_CONTACT cc_contactf
#define CC_FN(name) CC__CAT(name, f)
#define CC_C(x) CC__CAT(x, f)
#define CC_SQRT sqrtf
#define CC_FABS fabsf
#define CC_FREXP frexpf
#define CC_LDEXP ldexpf
#define CC_EPSILON FLT_EPSILON
#define CC_INF HUGE_VALF
#define CC_MAX_EXP FLT_MAX_EXP
#define CC_NORMAL_TOL 1e-4f
#define CC_SAFE_LO 0x1p-25f
#define CC_SAFE_HI 0x1p25f
