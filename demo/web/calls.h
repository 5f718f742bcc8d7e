/* The page's plain-C calls (calls.c), exported from the page's module; the callbacks they give
 * the world are defined by whoever links them: glue.c passes them on to the page, the native
 * replay (tests/web/replay.c) ignores them. */
#ifndef CC_WEB_CALLS_H
#define CC_WEB_CALLS_H

#include "circlecollide.h"

#include <stddef.h>
#include <stdint.h>

#define WEB_EXPORT __attribute__((visibility("default")))

WEB_EXPORT void web_def(int max_circles, int max_segments, int mode, double restitution, double rest_speed,
                        double rolling_decel, int restitution_mix, int callbacks);
WEB_EXPORT size_t web_world_size(void);
WEB_EXPORT cc_world *web_world_init(void *memory, size_t bytes);
WEB_EXPORT int web_status(void);
WEB_EXPORT int web_circle_restitution(cc_world *w, int id, double restitution);
WEB_EXPORT int web_circle_sensor(cc_world *w, int id);
WEB_EXPORT int web_circle_category(cc_world *w, int id, uint32_t category);
WEB_EXPORT int web_segment_restitution(cc_world *w, int id, double restitution);
WEB_EXPORT int web_cast_circle(const cc_world *w, double px, double py, double radius, double dx, double dy,
                               uint32_t mask, int ignore, cc_cast_hit *out);
WEB_EXPORT size_t web_sizeof(int what);

/* the world's callbacks while a def made with callbacks is in use */
void web_on_contact(const cc_contact_event *e, void *user);
void web_on_sensor(const cc_sensor_event *e, void *user);

#endif
