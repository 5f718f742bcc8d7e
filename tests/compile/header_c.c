/* The public header compiled as strict C (C99 and later) with extra warnings as errors: it must
 * be clean in any user's build. Also records the layout of the public types as C sees it, for
 * the C++ side to compare (header_cxx.cpp). */
#include <circlecollide.h>
#include <circlecollide.h> /* twice: the include guard works */

#include "layout.h"

size_t cc_layout_c(size_t *out, size_t cap)
{
    CC_LAYOUT_LIST(out, cap);
}
