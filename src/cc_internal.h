/* Private to the library: the machinery that lets every pair algorithm be written once and
 * compiled for double and for float. Never installed. */
#ifndef CC_INTERNAL_H
#define CC_INTERNAL_H

#include "circlecollide.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define CC__CAT2(a, b) a##b
#define CC__CAT(a, b) CC__CAT2(a, b)

/* Common-case fast paths trade code size for speed; a build optimised for size (-Os, as the
 * embedded one is) keeps one path only. Both paths give bit-identical answers. */
#if defined(__OPTIMIZE_SIZE__)
#define CC__FAST_PATHS 0
#else
#define CC__FAST_PATHS 1
#endif

#endif
