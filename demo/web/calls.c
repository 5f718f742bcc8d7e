/* The page's calls that are plain C (no WebAssembly in them): the def and the world's making,
 * the props changed one field at a time, the cast that takes vectors by value, the sizes the page
 * lays its arrays out with. Linked into the page's module (scripts/wasm.sh) and into the native
 * replay of the page's journal (tests/web/replay.c), so that the replay runs this very code. */
#include "calls.h"

/* ---- the world's def and its callbacks ---- */
static cc_world_def web_d;
static int web_last_status;

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
    web_d.on_contact = callbacks ? web_on_contact : NULL;
    web_d.on_sensor = callbacks ? web_on_sensor : NULL;
}

size_t web_world_size(void) { return cc_world_size(&web_d); }

cc_world *web_world_init(void *memory, size_t bytes)
{
    return cc_world_init(memory, bytes, &web_d, &web_last_status);
}

int web_status(void) { return web_last_status; }

/* ---- properties: read, change one field, write back (as the demo's stage does) ---- */
enum { WEB_RESTITUTION, WEB_SENSOR, WEB_CATEGORY };

static int web_circle_prop(cc_world *w, int id, int what, double restitution, uint32_t category)
{
    cc_circle_props p;
    int r;
    p.struct_size = sizeof p;
    r = cc_world_get_circle_props(w, id, &p);
    if (r != CC_OK)
        return r;
    if (what == WEB_RESTITUTION)
        p.restitution = restitution;
    else if (what == WEB_SENSOR)
        p.sensor = 1;
    else
        p.category = category;
    return cc_world_set_circle_props(w, id, &p);
}

int web_circle_restitution(cc_world *w, int id, double restitution)
{
    return web_circle_prop(w, id, WEB_RESTITUTION, restitution, 0);
}

int web_circle_sensor(cc_world *w, int id) { return web_circle_prop(w, id, WEB_SENSOR, 0.0, 0); }

int web_circle_category(cc_world *w, int id, uint32_t category)
{
    return web_circle_prop(w, id, WEB_CATEGORY, 0.0, category);
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

/* ---- the aiming line: cc_world_cast_circle_filtered takes its two vectors by value, and the
 * filter (its mask, and the circle it leaves out: the cue ball casting from where it is) ---- */
int web_cast_circle(const cc_world *w, double px, double py, double radius, double dx, double dy, uint32_t mask,
                    int ignore, cc_cast_hit *out)
{
    cc_vec2 p, d;
    cc_query_filter f = CC_QUERY_FILTER_DEFAULT;
    p.x = px;
    p.y = py;
    d.x = dx;
    d.y = dy;
    f.mask = mask;
    f.ignore = ignore;
    return cc_world_cast_circle_filtered(w, p, radius, d, &f, out);
}

/* the sizes the page lays its arrays out with: 0 cc_circle, 1 cc_cast_hit */
size_t web_sizeof(int what)
{
    return what == 0 ? sizeof(cc_circle) : what == 1 ? sizeof(cc_cast_hit) : 0;
}
