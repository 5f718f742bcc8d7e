/* Undoes precision_double.h / precision_float.h so that the next precision can be bound. */
#undef CC_R
#undef CC_V
#undef CC_CIRCLE
#undef CC_SEGMENT
#undef CC_CONTACT
#undef CC_FN
#undef CC_C
#undef CC_SQRT
#undef CC_FABS
#undef CC_FREXP
#undef CC_LDEXP
#undef CC_EPSILON
#undef CC_INF
#undef CC_MAX_EXP
#undef CC_NORMAL_TOL
#undef CC_SAFE_LO
#undef CC_SAFE_HI
