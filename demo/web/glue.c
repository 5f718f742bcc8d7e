/* The page's C side, linked into circlecollide.wasm beside the library (scripts/wasm.sh):
 *   - memory: web_alloc hands out the one block the page reserves at start (world + scratch);
 *   - the world's callbacks, passed on to functions the page imports (env.on_contact,
 *     env.on_sensor), since a function pointer cannot point into JavaScript;
 *   - the calls that take structs as plain numbers are in calls.c (plain C, also linked into the
 *     native replay of the page's journal, tests/web/replay.c).
 * Everything else the page calls directly (cc_world_add_circle, cc_world_step, ...). */
#include "calls.h"

#define WEB_IMPORT(name) __attribute__((import_module("env"), import_name(name)))

WEB_IMPORT("on_contact")
void web_js_contact(int a, int b, int segment, double t, double px, double py, double nx, double ny, double impulse);
WEB_IMPORT("on_sensor")
void web_js_sensor(int sensor, int visitor, int begin, double t);

WEB_EXPORT void *web_alloc(size_t bytes);

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

/* ---- the world's callbacks, passed on to the page ---- */
void web_on_contact(const cc_contact_event *e, void *user)
{
    (void)user;
    web_js_contact(e->a, e->b, e->segment, e->t, e->point.x, e->point.y, e->normal.x, e->normal.y, e->impulse);
}

void web_on_sensor(const cc_sensor_event *e, void *user)
{
    (void)user;
    web_js_sensor(e->sensor, e->visitor, e->begin, e->t);
}
