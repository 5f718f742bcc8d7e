/* Undoes precision_double.h / precision_float.h: a world source that borrows the double helpers
 * ends with it, so that nothing of the templates' vocabulary leaks into the rest of the file. */
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
