/* Sizes and field offsets of every public type, written the same way in C and C++ so that the
 * two compilers' views of the ABI can be compared. */
#ifndef CC_COMPILE_LAYOUT_H
#define CC_COMPILE_LAYOUT_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif
size_t cc_layout_c(size_t *out, size_t cap);
#ifdef __cplusplus
}
#endif

#define CC_LAYOUT_PUT(v)                                                                           \
    do {                                                                                           \
        if (n < cap)                                                                               \
            out[n] = (v);                                                                          \
        n++;                                                                                       \
    } while (0)

/* Writes up to cap numbers to out and returns how many there are. */
#define CC_LAYOUT_LIST(out, cap)                                                                   \
    size_t n = 0;                                                                                  \
    CC_LAYOUT_PUT(sizeof(cc_vec2));                                                                \
    CC_LAYOUT_PUT(offsetof(cc_vec2, y));                                                           \
    CC_LAYOUT_PUT(sizeof(cc_circle));                                                              \
    CC_LAYOUT_PUT(offsetof(cc_circle, vel));                                                       \
    CC_LAYOUT_PUT(offsetof(cc_circle, radius));                                                    \
    CC_LAYOUT_PUT(offsetof(cc_circle, mass));                                                      \
    CC_LAYOUT_PUT(sizeof(cc_segment));                                                             \
    CC_LAYOUT_PUT(offsetof(cc_segment, b));                                                        \
    CC_LAYOUT_PUT(sizeof(cc_contact));                                                             \
    CC_LAYOUT_PUT(offsetof(cc_contact, point));                                                    \
    CC_LAYOUT_PUT(offsetof(cc_contact, normal));                                                   \
    CC_LAYOUT_PUT(offsetof(cc_contact, depth));                                                    \
    CC_LAYOUT_PUT(sizeof(cc_circle_soa));                                                          \
    CC_LAYOUT_PUT(sizeof(cc_mode));                                                                \
    CC_LAYOUT_PUT(sizeof(cc_contact_event));                                                       \
    CC_LAYOUT_PUT(offsetof(cc_contact_event, t));                                                  \
    CC_LAYOUT_PUT(offsetof(cc_contact_event, impulse));                                            \
    CC_LAYOUT_PUT(sizeof(cc_world_def));                                                           \
    CC_LAYOUT_PUT(offsetof(cc_world_def, restitution));                                            \
    CC_LAYOUT_PUT(offsetof(cc_world_def, max_events));                                             \
    CC_LAYOUT_PUT(offsetof(cc_world_def, user));                                                   \
    CC_LAYOUT_PUT(sizeof(cc_world_stats));                                                         \
    CC_LAYOUT_PUT(offsetof(cc_world_stats, collisions));                                           \
    CC_LAYOUT_PUT(sizeof(cc_vec2f));                                                               \
    CC_LAYOUT_PUT(sizeof(cc_circlef));                                                             \
    CC_LAYOUT_PUT(offsetof(cc_circlef, mass));                                                     \
    CC_LAYOUT_PUT(sizeof(cc_segmentf));                                                            \
    CC_LAYOUT_PUT(sizeof(cc_contactf));                                                            \
    CC_LAYOUT_PUT(offsetof(cc_contactf, depth));                                                   \
    return n

#endif
