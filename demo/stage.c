/* Keeps a world and the memory of its recent past (trails, flashes) for the renderer, and books
 * every change of kinetic energy that the demo itself makes, so that the summary's energy drift
 * measures the library alone. */
#include "stage.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static double energy_of(const cc_circle *c)
{
    if (!(c->mass < INFINITY))
        return 0.0;
    return 0.5 * c->mass * (c->vel.x * c->vel.x + c->vel.y * c->vel.y);
}

static void note_error(demo_stage *s, int code, const char *what)
{
    if (s->error == 0) {
        s->error = code;
        s->error_what = what;
    }
}

static void trail_push(demo_stage *s, int id, double x, double y, double t)
{
    demo_trail *tr;
    if (id < 0 || id >= s->def.max_circles || s->def.trail_time <= 0.0)
        return;
    tr = &s->trails[id];
    tr->p[tr->head].x = x;
    tr->p[tr->head].y = y;
    tr->p[tr->head].t = t;
    tr->head = (tr->head + 1) % DEMO_TRAIL_POINTS;
    if (tr->count < DEMO_TRAIL_POINTS)
        ++tr->count;
}

static void on_contact(const cc_contact_event *e, void *user)
{
    demo_stage *s = (demo_stage *)user;
    ++s->contacts;
    if (s->def.flash_time > 0.0 && s->def.flash_capacity > 0) {
        demo_flash *f = &s->flashes[s->flash_head];
        double k = s->def.impulse_ref > 0.0 ? e->impulse / s->def.impulse_ref : 1.0;
        f->x = e->point.x;
        f->y = e->point.y;
        f->t = e->t;
        f->strength = k > 1.0 ? 1.0 : (k > 0.0 ? k : 0.0);
        s->flash_head = (s->flash_head + 1) % s->def.flash_capacity;
        if (s->flash_count < s->def.flash_capacity)
            ++s->flash_count;
    }
    /* the centres at the moment of contact, so that a trail bends exactly where the body
       bounced even when that happened between two frames */
    if (e->a >= 0 && e->a < s->def.max_circles) {
        double r = s->radius_of[e->a];
        trail_push(s, e->a, e->point.x - e->normal.x * r, e->point.y - e->normal.y * r, e->t);
    }
    if (e->b >= 0 && e->b < s->def.max_circles) {
        double r = s->radius_of[e->b];
        trail_push(s, e->b, e->point.x + e->normal.x * r, e->point.y + e->normal.y * r, e->t);
    }
}

static void on_sensor(const cc_sensor_event *e, void *user)
{
    demo_stage *s = (demo_stage *)user;
    if (s->def.on_sensor != NULL)
        s->def.on_sensor(e, s->def.sensor_user);
}

void demo_stage_def_init(demo_stage_def *def, int mode)
{
    memset(def, 0, sizeof *def); /* no trails, flashes, caption, sensor; rolling 0, CC_MIX_MIN */
    def->max_circles = 64;
    def->mode = mode;
    def->restitution = 1.0;
    def->x1 = def->y1 = 1.0;
    def->speed_ref = def->impulse_ref = 1.0;
    def->restitution_mix = CC_MIX_MIN;
}

int demo_stage_init(demo_stage *s, const demo_stage_def *def)
{
    return demo_stage_init_periodic(s, def, 0.0, 0.0);
}

int demo_stage_init_periodic(demo_stage *s, const demo_stage_def *def, double px, double py)
{
    cc_world_def wd;
    size_t bytes;
    int status = 0;
    size_t n;
    memset(s, 0, sizeof *s);
    s->def = *def;
    s->period.x = px > 0.0 ? px : 0.0;
    s->period.y = py > 0.0 ? py : 0.0;
    n = (size_t)def->max_circles;
    cc_world_def_init(&wd);
    wd.max_circles = def->max_circles;
    wd.max_segments = def->max_segments;
    wd.mode = def->mode;
    wd.restitution = def->restitution;
    wd.rest_speed = def->rest_speed;
    wd.on_contact = on_contact;
    wd.user = s;
    wd.rolling_decel = def->rolling_decel;
    wd.restitution_mix = def->restitution_mix;
    wd.on_sensor = def->on_sensor != NULL ? on_sensor : NULL;
    wd.period = s->period;
    bytes = cc_world_size(&wd);
    if (bytes == 0)
        return CC_ERR_INVALID;
    s->memory = malloc(bytes);
    s->ids = (int *)calloc(n, sizeof *s->ids);
    s->circles = (cc_circle *)calloc(n, sizeof *s->circles);
    s->radius_of = (double *)calloc(n, sizeof *s->radius_of);
    s->style_of = (unsigned char *)calloc(n, 1);
    s->trails = (demo_trail *)calloc(n, sizeof *s->trails);
    s->walls = (cc_segment *)calloc((size_t)def->max_segments + 1u, sizeof *s->walls);
    s->flashes = (demo_flash *)calloc((size_t)def->flash_capacity + 1u, sizeof *s->flashes);
    if (!s->memory || !s->ids || !s->circles || !s->radius_of || !s->style_of || !s->trails ||
        !s->walls || !s->flashes) {
        demo_stage_free(s);
        return -100;
    }
    s->world = cc_world_init(s->memory, bytes, &wd, &status);
    if (s->world == NULL) {
        demo_stage_free(s);
        return status < 0 ? status : CC_ERR_INVALID;
    }
    return 0;
}

void demo_stage_free(demo_stage *s)
{
    free(s->memory);
    free(s->ids);
    free(s->circles);
    free(s->radius_of);
    free(s->style_of);
    free(s->trails);
    free(s->walls);
    free(s->flashes);
    memset(s, 0, sizeof *s);
}

int demo_stage_add_circle(demo_stage *s, const cc_circle *c, int style)
{
    int id = cc_world_add_circle(s->world, c);
    if (id < 0) {
        note_error(s, id, "cc_world_add_circle");
        return id;
    }
    if (id < s->def.max_circles) {
        s->radius_of[id] = c->radius;
        s->style_of[id] = (unsigned char)style;
        s->trails[id].count = 0;
        s->trails[id].head = 0;
    }
    if (s->started)
        s->energy_demo += energy_of(c);
    return id;
}

int demo_stage_add_wall(demo_stage *s, double ax, double ay, double bx, double by)
{
    cc_segment seg;
    int id;
    seg.a.x = ax;
    seg.a.y = ay;
    seg.b.x = bx;
    seg.b.y = by;
    id = cc_world_add_segment(s->world, &seg);
    if (id < 0) {
        note_error(s, id, "cc_world_add_segment");
        return id;
    }
    if (s->nwalls < s->def.max_segments)
        s->walls[s->nwalls++] = seg;
    return id;
}

int demo_stage_add_sensor(demo_stage *s, double x, double y, double radius)
{
    cc_circle c;
    cc_circle_props p;
    int id, r;
    c.pos.x = x;
    c.pos.y = y;
    c.vel.x = 0.0;
    c.vel.y = 0.0;
    c.radius = radius;
    c.mass = INFINITY;
    id = demo_stage_add_circle(s, &c, DEMO_STYLE_HIDDEN);
    if (id < 0)
        return id;
    p.struct_size = sizeof p;
    r = cc_world_get_circle_props(s->world, id, &p);
    if (r == CC_OK) {
        p.sensor = 1;
        r = cc_world_set_circle_props(s->world, id, &p);
    }
    if (r != CC_OK) {
        note_error(s, r, "cc_world_set_circle_props (sensor)");
        return r;
    }
    return id;
}

int demo_stage_set_circle_restitution(demo_stage *s, int id, double restitution)
{
    cc_circle_props p;
    int r;
    p.struct_size = sizeof p;
    r = cc_world_get_circle_props(s->world, id, &p);
    if (r == CC_OK) {
        p.restitution = restitution;
        r = cc_world_set_circle_props(s->world, id, &p);
    }
    if (r != CC_OK)
        note_error(s, r, "cc_world_set_circle_props");
    return r;
}

int demo_stage_set_wall_restitution(demo_stage *s, int id, double restitution)
{
    cc_segment_props p;
    int r;
    p.struct_size = sizeof p;
    r = cc_world_get_segment_props(s->world, id, &p);
    if (r == CC_OK) {
        p.restitution = restitution;
        r = cc_world_set_segment_props(s->world, id, &p);
    }
    if (r != CC_OK)
        note_error(s, r, "cc_world_set_segment_props");
    return r;
}

int demo_stage_set_circle(demo_stage *s, int id, const cc_circle *c)
{
    cc_circle old;
    int r = cc_world_get_circle(s->world, id, &old);
    if (r == CC_OK)
        r = cc_world_set_circle(s->world, id, c);
    if (r != CC_OK) {
        note_error(s, r, "cc_world_set_circle");
        return r;
    }
    s->energy_demo += energy_of(c) - energy_of(&old);
    if (id < s->def.max_circles)
        s->radius_of[id] = c->radius;
    return r;
}

int demo_stage_remove_circle(demo_stage *s, int id)
{
    cc_circle old;
    int r = cc_world_get_circle(s->world, id, &old);
    if (r == CC_OK)
        r = cc_world_remove_circle(s->world, id);
    if (r != CC_OK) {
        note_error(s, r, "cc_world_remove_circle");
        return r;
    }
    s->energy_demo -= energy_of(&old);
    if (id < s->def.max_circles)
        s->trails[id].count = 0;
    return r;
}

int demo_stage_step_to(demo_stage *s, double t)
{
    int guard;
    /* a step that hits the event cap stops early; continue from where it stopped, but give up
       after many caps rather than loop for ever on a jammed scene */
    for (guard = 0; guard < 1000; ++guard) {
        double now = cc_world_time(s->world);
        int r;
        if (!(now < t))
            return 0;
        r = cc_world_step(s->world, t - now);
        if (r == CC_OK)
            return 0;
        if (r != CC_EVENT_LIMIT) {
            note_error(s, r, "cc_world_step");
            return r;
        }
    }
    note_error(s, CC_EVENT_LIMIT, "cc_world_step (1000 event caps in one frame)");
    return CC_EVENT_LIMIT;
}

void demo_stage_snapshot(demo_stage *s)
{
    int n = cc_world_get_circles(s->world, s->ids, s->circles, s->def.max_circles);
    double now = cc_world_time(s->world);
    int i;
    if (n < 0) {
        note_error(s, n, "cc_world_get_circles");
        n = 0;
    }
    s->count = n < s->def.max_circles ? n : s->def.max_circles;
    for (i = 0; i < s->count; ++i)
        trail_push(s, s->ids[i], s->circles[i].pos.x, s->circles[i].pos.y, now);
    if (!s->started) {
        s->started = 1;
        s->energy0 = demo_stage_energy(s);
    }
    if (demo_stage_energy(s) > s->energy_peak)
        s->energy_peak = demo_stage_energy(s);
}

double demo_stage_energy(const demo_stage *s)
{
    double e = 0.0;
    int i;
    for (i = 0; i < s->count; ++i)
        e += energy_of(&s->circles[i]);
    return e;
}

double demo_stage_drift(const demo_stage *s)
{
    double ref = s->energy0 > s->energy_peak ? s->energy0 : s->energy_peak;
    if (!(ref > 0.0))
        return 0.0;
    return (demo_stage_energy(s) - s->energy0 - s->energy_demo) / ref;
}

int demo_stage_find(const demo_stage *s, int id)
{
    int lo = 0, hi = s->count - 1;
    while (lo <= hi) { /* ids come in increasing order */
        int mid = lo + (hi - lo) / 2;
        if (s->ids[mid] == id)
            return mid;
        if (s->ids[mid] < id)
            lo = mid + 1;
        else
            hi = mid - 1;
    }
    return -1;
}
