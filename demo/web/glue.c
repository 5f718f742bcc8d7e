/* The page's C side, linked into circlecollide.wasm beside the library (scripts/wasm.sh):
 *   - memory: web_alloc hands out the one block the page reserves at start (world + scratch);
 *   - the world's callbacks, passed on to functions the page imports (env.on_contact,
 *     env.on_sensor), since a function pointer cannot point into JavaScript;
 *   - calls that take a struct by value (cc_world_cast_circle's cc_vec2) or a struct the page
 *     would otherwise lay out itself (the def, the props), as plain numbers.
 * Everything else the page calls directly (cc_world_add_circle, cc_world_step, ...). The replay
 * of the page's journal (tests/web/replay.c) does what each of these does, natively. */
#include "circlecollide.h"

#include <stddef.h>
#include <stdint.h>

#define WEB_EXPORT __attribute__((visibility("default")))
#define WEB_IMPORT(name) __attribute__((import_module("env"), import_name(name)))

WEB_IMPORT("on_contact")
void web_js_contact(int a, int b, int segment, double t, double px, double py, double nx, double ny, double impulse);
WEB_IMPORT("on_sensor")
void web_js_sensor(int sensor, int visitor, int begin, double t);

WEB_EXPORT void *web_alloc(size_t bytes);
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
                               uint32_t mask, cc_cast_hit *out);
WEB_EXPORT size_t web_sizeof(int what);

/* ---- memory: the heap starts after the module's data and stack (wasm-ld's __heap_base) ---- */
extern unsigned char __heap_base;
static uintptr_t web_top;

void *web_alloc(size_t bytes)
{
    uintptr_t start, end, have;
    if (web_top == 0)
        web_top = (uintptr_t)&__heap_base;
    start = (web_top + 15u) & ~(uintptr_t)15u; /* the world wants 16-byte alignment */
    if (bytes > SIZE_MAX - start)
        return NULL;
    end = start + bytes;
    have = (uintptr_t)__builtin_wasm_memory_size(0) * 65536u;
    if (end > have && __builtin_wasm_memory_grow(0, (end - have + 65535u) / 65536u) == (size_t)-1)
        return NULL;
    web_top = end;
    return (void *)start;
}

/* ---- the world's def and its callbacks ---- */
static cc_world_def web_d;
static int web_last_status;

static void web_contact(const cc_contact_event *e, void *user)
{
    (void)user;
    web_js_contact(e->a, e->b, e->segment, e->t, e->point.x, e->point.y, e->normal.x, e->normal.y, e->impulse);
}

static void web_sensor(const cc_sensor_event *e, void *user)
{
    (void)user;
    web_js_sensor(e->sensor, e->visitor, e->begin, e->t);
}

void web_def(int max_circles, int max_segments, int mode, double restitution, double rest_speed,
             double rolling_decel, int restitution_mix, int callbacks)
{
    cc_world_def_init(&web_d);
    web_d.max_circles = max_circles;
    web_d.max_segments = max_segments;
    web_d.mode = mode;
    web_d.restitution = restitution;
    web_d.rest_speed = rest_speed;
    web_d.rolling_decel = rolling_decel;
    web_d.restitution_mix = restitution_mix;
    web_d.on_contact = callbacks ? web_contact : NULL;
    web_d.on_sensor = callbacks ? web_sensor : NULL;
}

size_t web_world_size(void) { return cc_world_size(&web_d); }

cc_world *web_world_init(void *memory, size_t bytes)
{
    return cc_world_init(memory, bytes, &web_d, &web_last_status);
}

int web_status(void) { return web_last_status; }

/* ---- properties: read, change one field, write back (as the demo's stage does) ---- */
int web_circle_restitution(cc_world *w, int id, double restitution)
{
    cc_circle_props p;
    int r;
    p.struct_size = sizeof p;
    r = cc_world_get_circle_props(w, id, &p);
    if (r != CC_OK)
        return r;
    p.restitution = restitution;
    return cc_world_set_circle_props(w, id, &p);
}

int web_circle_sensor(cc_world *w, int id)
{
    cc_circle_props p;
    int r;
    p.struct_size = sizeof p;
    r = cc_world_get_circle_props(w, id, &p);
    if (r != CC_OK)
        return r;
    p.sensor = 1;
    return cc_world_set_circle_props(w, id, &p);
}

int web_circle_category(cc_world *w, int id, uint32_t category)
{
    cc_circle_props p;
    int r;
    p.struct_size = sizeof p;
    r = cc_world_get_circle_props(w, id, &p);
    if (r != CC_OK)
        return r;
    p.category = category;
    return cc_world_set_circle_props(w, id, &p);
}

int web_segment_restitution(cc_world *w, int id, double restitution)
{
    cc_segment_props p;
    int r;
    p.struct_size = sizeof p;
    r = cc_world_get_segment_props(w, id, &p);
    if (r != CC_OK)
        return r;
    p.restitution = restitution;
    return cc_world_set_segment_props(w, id, &p);
}

/* ---- the aiming line: cc_world_cast_circle takes its two vectors by value ---- */
int web_cast_circle(const cc_world *w, double px, double py, double radius, double dx, double dy, uint32_t mask,
                    cc_cast_hit *out)
{
    cc_vec2 p, d;
    p.x = px;
    p.y = py;
    d.x = dx;
    d.y = dy;
    return cc_world_cast_circle(w, p, radius, d, mask, out);
}

/* the sizes the page lays its arrays out with: 0 cc_circle, 1 cc_cast_hit */
size_t web_sizeof(int what)
{
    return what == 0 ? sizeof(cc_circle) : what == 1 ? sizeof(cc_cast_hit) : 0;
}
