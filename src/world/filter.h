/* The query filter of casts and queries (cc_query_filter, 1.2): its struct_size handshake and the
 * circle it leaves out, as a storage index. Private. */
#ifndef CC_WORLD_FILTER_H
#define CC_WORLD_FILTER_H

#include "world_internal.h"

/* The filter's mask and the storage index of the circle it leaves out (-1: none, also for an id
 * not in use) into *mask and *ignore. NULL is the default filter. CC_OK, or CC_ERR_VERSION for a
 * struct_size that does not reach `ignore`. */
static inline int cc__filter_read(const cc_world *w, const cc_query_filter *f, uint32_t *mask, int *ignore)
{
    int id = -1;
    *mask = 0xFFFFFFFFu;
    *ignore = -1;
    if (f != NULL) {
        if (f->struct_size < CC__END(cc_query_filter, ignore))
            return CC_ERR_VERSION;
        *mask = f->mask;
        id = f->ignore;
    }
    if (id >= 0 && id < w->id_end) {
        int k = CC__CARR(w, int32_t, off_id2idx)[id];
        if (CC__CARR(w, cc__cold, off_cold)[k].flags & CC__ALIVE)
            *ignore = k;
    }
    return CC_OK;
}

/* A filter of the 1.1 calls: their mask, nothing left out. */
static inline cc_query_filter cc__filter_of_mask(uint32_t mask)
{
    cc_query_filter f;
    f.struct_size = sizeof f;
    f.mask = mask;
    f.ignore = -1;
    return f;
}

#endif
