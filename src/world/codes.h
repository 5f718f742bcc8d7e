/* Which result codes a world gives its caller (the header's Results, in CONVENTIONS): 1.2's
 * CC_ERR_RANGE and CC_ERR_BUSY go only to a caller whose def reaches past 1.1's last field, one
 * compiled against the 1.2 header or a later one; a world made from a 1.0 or 1.1 def answers
 * CC_ERR_INVALID in those cases, as those versions promised. Private. */
#ifndef CC_WORLD_CODES_H
#define CC_WORLD_CODES_H

#include "world_internal.h"

/* The end of 1.1's def: a def of that size or smaller came from a 1.0 or 1.1 header. */
#define CC__DEF_1_1 CC__END(cc_world_def, period)

/* Whether a def of this struct_size was compiled against a header that has the 1.2 codes. */
static inline int cc__def_knows_1_2(size_t struct_size) { return struct_size > CC__DEF_1_1; }

/* code (a 1.2 code) as the caller of a def of this struct_size knows it. */
static inline int cc__code_for_def(size_t struct_size, int code)
{
    return cc__def_knows_1_2(struct_size) ? code : CC_ERR_INVALID;
}

/* The world keeps the struct_size of the def it was made from in its own stats' struct_size,
 * which nothing else reads (cc_world_get_stats leaves the caller's struct_size as it is, and the
 * world's copy is never handed out whole): the caller's header, without a field of its own. */
static inline void cc__world_note_def(cc_world *w, size_t def_struct_size) { w->stats.struct_size = def_struct_size; }

/* code (a 1.2 code) as the world's caller knows it. */
static inline int cc__world_code(const cc_world *w, int code)
{
    return cc__code_for_def(w->stats.struct_size, code);
}

#endif
