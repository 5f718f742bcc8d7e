/* The world fuzzer (issue 11 "A world fuzzer", issue 19 "callbacks fired from add and set"):
 * one input is a world def and a sequence of world API calls, each checked against
 * include/circlecollide.h. A violation prints "fuzz_world: ..." and calls abort().
 *
 * Input layout (missing bytes read as 0, so every input is valid):
 *   byte 0  mode (% 8: 0-2 EXACT/SWEPT/DISCRETE, 3-6 again, 7 an invalid mode 3)
 *   byte 1  max_circles % 41, byte 2 max_segments % 9
 *   byte 3  flags: bit 0 on_contact, bit 1 on_sensor, bit 2 periodic x, bit 3 periodic y,
 *           bit 4 a def of 1.0's size (the 1.1 fields hold garbage the library must ignore),
 *           bits 5-6 restitution_mix (with byte 4 bit 7: the invalid mix 4)
 *   byte 4  bits 0-3: which of rest_speed, cell_size, rolling_decel are nonzero; bits 4-5 the def's
 *           uses (0: CC_USES_ALL, 1: 0, 2: SENSORS, 3: PROPS | ROLLING); bit 6: the def is a later
 *           header's (struct_size past this one's: the 1.2 codes); bit 7 see above
 *   then    values: restitution, rest_speed, cell_size, rolling_decel, period x, period y (each
 *           a "value", below), max_events (2 bytes: 1 + v % 1000, v = 0xFFFF gives 0: a 1.2 def's automatic cap,
 *           invalid for a 1.0 def)
 *   then    calls: one opcode byte each (% OP_COUNT), then that call's arguments.
 * A value is one byte b: b < 12 a hostile double (NaN, +-Inf, 1e300, 1e-300, subnormals, -0,
 * DBL_MAX, ...) chosen by the next byte; b = 12 or 13 the raw 8 bytes that follow; otherwise an
 * ordinary number of the kind wanted (position, velocity, radius, mass, ...).
 *
 * Checked after every call: the result is in the call's documented set, and the one the model
 * predicts where the contract fixes it (ids given LIFO, NOT_FOUND for ids not live, INVALID for
 * invalid input, FULL, VERSION for short struct_size); outputs untouched on errors; the world's
 * circles equal the model's ids, radii, masses and properties, every state finite, positions in
 * [0, period) on periodic axes; world time never decreases (and a step that returns CC_OK
 * advances it by dt); read-only calls and failed calls leave cc_world_hash unchanged; a step
 * processes at most max_events events; stats counters never decrease; guard bytes before and
 * after the world's memory untouched; queries and casts agree with a brute-force look at the
 * circles (up to a relative 1e-9 at the boundary); in EXACT with rest_speed 0, a step that
 * starts with no overlap leaves none between movable circles (nor with walls) deeper than a
 * generous 1e-9 of the size of the numbers involved (the header promises 1e-13 near the
 * origin); kinetic energy never grows across a step (1e-9 relative) unless an immovable circle
 * moves; a world copied with memcpy mid-sequence gives the same results and hash on the next
 * call as the original; a batch add (cc_world_add_circles) of k circles ends as k single adds
 * on a copy of the world do (ids, callbacks' events bit for bit, hash) or refuses as the first
 * refused single add does and changes nothing; cc_world_get_unwrapped_all gives what
 * cc_world_get_unwrapped gives for each live circle. The callbacks check their events, that they fire only from the calls
 * the header lists, and try every mutator from inside: each must return CC_ERR_BUSY (CC_ERR_INVALID
 * in a world made from a 1.0 or 1.1 def: the header's Results) and change nothing (the hash). */
#include "fuzz_world_checks.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "circlecollide.h"

#define MAXC 40
#define MAXS 8
#define GUARD 64
#define MAX_OPS 400
#define PAT 0xA5u
#define UNTOUCHED 0xCDu

const char *fuzz_world_input_name;
fuzz_world_counts fuzz_world_counted;

/* ---- input ---------------------------------------------------------------------------------- */

typedef struct reader {
    const uint8_t *p;
    size_t n;
} reader;

static unsigned byte(reader *r)
{
    unsigned b;
    if (r->n == 0)
        return 0;
    b = r->p[0];
    r->p++, r->n--;
    return b;
}

static const double hostile[32] = {NAN,
                                   -NAN,
                                   INFINITY,
                                   -INFINITY,
                                   1e300,
                                   -1e300,
                                   1e-300,
                                   -1e-300,
                                   4.9406564584124654e-324,
                                   1.1125369292536007e-308,
                                   -0.0,
                                   0.0,
                                   -1.0,
                                   -0.5,
                                   1e308,
                                   DBL_MAX,
                                   0.5,
                                   1.0,
                                   2.0,
                                   3.0,
                                   10.0,
                                   0.25,
                                   1e-3,
                                   100.0,
                                   1e6,
                                   1e15,
                                   -2.0,
                                   0.1,
                                   0.999,
                                   1.0000000000000002,
                                   7.5,
                                   1e-9};

enum kind { K_POS, K_VEL, K_RAD, K_MASS, K_UNIT, K_DT, K_SMALL };

static double value(reader *r, enum kind k)
{
    unsigned b = byte(r);
    double u;
    if (b < 12)
        return hostile[byte(r) % 32];
    if (b < 14) {
        uint8_t raw[8] = {0};
        double x;
        int i;
        for (i = 0; i < 8; i++)
            raw[i] = (uint8_t)byte(r);
        memcpy(&x, raw, 8);
        return x;
    }
    u = (double)(b - 14) / 241.0; /* [0, 1] */
    switch (k) {
    case K_POS: return 20.0 * u - 10.0;
    case K_VEL: return 10.0 * u - 5.0;
    case K_RAD: return 0.2 + 1.3 * u;
    case K_MASS: return b >= 245 ? INFINITY : 0.5 + 4.0 * u;
    case K_UNIT: return u;
    case K_DT: return 2.0 * u;
    default: return 5.0 * u;
    }
}

static uint32_t bits32(reader *r)
{
    unsigned b = byte(r);
    if (b & 0x80u)
        return 0xFFFFFFFFu;
    return b & 0x0Fu;
}

/* ---- the model of one world ------------------------------------------------------------------ */

typedef struct model {
    unsigned char *block; /* GUARD + bytes + GUARD */
    size_t bytes;
    cc_world *w;
    int maxc, maxs, mode, mix;
    double restitution, rest_speed, cell_size, decel, period[2];
    uint64_t max_events;
    int has_contact_cb, has_sensor_cb;
    uint64_t evhash; /* the callbacks' events of the call running, folded in order (FNV-1a) */
    int nev;
    int live[MAXC + 1];
    double radius[MAXC + 1], mass[MAXC + 1];
    cc_circle_props props[MAXC + 1];
    int freestack[MAXC + 1], nfree, next_new, count;
    int nsegs;
    cc_segment segs[MAXS + 1];
    cc_segment_props segprops[MAXS + 1];
    double time;
    cc_world_stats stats; /* as last read in full */
    /* the call running, for the callbacks */
    int dead;     /* the input stops here (D7; a jam, below) */
    int capped;   /* steps that ended at CC_EVENT_LIMIT */
    int op, huge; /* huge: a live circle's coordinate or velocity is beyond 1e150 (D7) */
    int fast;     /* a live circle crosses a cell within one ulp of the world time (D18, D20) */
    double rmin;  /* the smallest radius ever placed: the world's cells are at least its diameter */
    double placing; /* the mass of the circle an add or set call places (0 otherwise) */
    double call_t0;
    int ncb;
    int range_code, busy_code; /* CC_ERR_RANGE and CC_ERR_BUSY as this world's def knows them */
    unsigned uses;             /* the def's CC_USES_* (ALL for a def too short to hold it) */
} model;

static model *g_cur; /* the world whose call is running (the callbacks find it here) */
static int g_user;   /* the def's user pointer points here */

static void fail(const model *m, const char *what)
{
    fprintf(stderr, "fuzz_world: %s (input %s, mode %d, op %d, time %.17g)\n", what,
            fuzz_world_input_name ? fuzz_world_input_name : "?", m ? m->mode : -1, m ? m->op : -1,
            m ? m->time : 0.0);
    abort();
}
#define REQUIRE(m, cond, what)                                                                          \
    do {                                                                                                \
        if (!(cond))                                                                                    \
            fail((m), what);                                                                            \
    } while (0)

static void fill_guards(unsigned char *block, size_t bytes)
{
    memset(block, (int)PAT, GUARD);
    memset(block + GUARD + bytes, (int)PAT, GUARD);
}

static void check_guards(const model *m)
{
    size_t i;
    for (i = 0; i < GUARD; i++) {
        REQUIRE(m, m->block[i] == PAT, "a guard byte before the world's memory was written");
        REQUIRE(m, m->block[GUARD + m->bytes + i] == PAT, "a guard byte after the world's memory was written");
    }
}

static int circle_valid(const cc_circle *c)
{
    return isfinite(c->pos.x) && isfinite(c->pos.y) && isfinite(c->vel.x) && isfinite(c->vel.y) &&
           isfinite(c->radius) && c->radius > 0.0 && c->mass > 0.0 && !isnan(c->mass);
}

/* the library's own rule (src/world/world.c cc__fits_period), as the header states it */
static int fits_period(const model *m, const cc_circle *c)
{
    double d = 2.0 * c->radius, cell = 1.0625 * d > m->cell_size ? 1.0625 * d : m->cell_size;
    int k;
    for (k = 0; k < 2; k++)
        if (m->period[k] > 0.0 && !(2.0 * d + cell <= m->period[k]))
            return 0;
    return 1;
}

static int live_id(const model *m, int id) { return id >= 0 && id < m->maxc && m->live[id]; }

static int filters_meet(uint32_t ca, uint32_t ma, uint32_t cb, uint32_t mb) { return (ca & mb) && (cb & ma); }

static double wrapd(const model *m, int k, double d)
{
    if (m->period[k] > 0.0)
        d -= m->period[k] * floor(d / m->period[k] + 0.5);
    return d;
}

/* ---- callbacks ---------------------------------------------------------------------------------- */

enum op {
    OP_ADD, OP_REMOVE, OP_SET, OP_GET, OP_ADD_SEG, OP_GET_SEG, OP_SET_PROPS, OP_GET_PROPS,
    OP_SET_SEGPROPS, OP_GET_SEGPROPS, OP_STEP, OP_STEP2, OP_CAST, OP_QUERY_CIRCLE, OP_QUERY_BOX,
    OP_HASH, OP_STATS, OP_UNWRAPPED, OP_GET_CIRCLES, OP_COPY, OP_STEP_SMALL, OP_ADD2, OP_ADD_BATCH,
    OP_UNWRAPPED_ALL, OP_COUNT
};

/* an add: one circle (OP_ADD, OP_ADD2) or a batch of them (cc_world_add_circles) */
static int is_add(int op) { return op == OP_ADD || op == OP_ADD2 || op == OP_ADD_BATCH; }

/* From inside a callback: every mutator must be refused and change nothing. */
static void try_mutators(model *m, int id)
{
    cc_world *w = m->w;
    uint64_t h = cc_world_hash(w);
    double t = cc_world_time(w);
    cc_circle c = {{1e6, 1e6}, {0, 0}, 1.0, 1.0}, got;
    cc_segment s = {{1e6, 0}, {1e6, 1}};
    cc_circle_props p;
    cc_segment_props q;
    if (m->ncb > 8)
        return; /* enough for one call: the first events of each call are tried */
    REQUIRE(m, cc_world_add_circle(w, &c) == m->busy_code, "add_circle from a callback not refused");
    {
        int one = -9, at = 5;
        REQUIRE(m, cc_world_add_circles(w, &c, 1, &one, &at) == m->busy_code && at == -1 && one == -9,
                "add_circles from a callback not refused with no circle at fault (failed -1, ids untouched)");
    }
    REQUIRE(m, cc_world_add_segment(w, &s) == m->busy_code, "add_segment from a callback not refused");
    REQUIRE(m, cc_world_step(w, 0.0) == m->busy_code, "step(0) from a callback not refused");
    REQUIRE(m, cc_world_step(w, 1.0) == m->busy_code, "step(1) from a callback not refused");
    if (live_id(m, id)) {
        REQUIRE(m, cc_world_get_circle(w, id, &got) == CC_OK, "get_circle from a callback failed");
        got.vel.x += 1.0;
        REQUIRE(m, cc_world_set_circle(w, id, &got) == m->busy_code, "set_circle from a callback not refused");
        REQUIRE(m, cc_world_remove_circle(w, id) == m->busy_code, "remove_circle from a callback not refused");
        p = m->props[id];
        p.restitution = 0.5, p.sensor = !p.sensor, p.mask = 0;
        REQUIRE(m, cc_world_set_circle_props(w, id, &p) == m->busy_code,
                "set_circle_props from a callback not refused");
    }
    if (m->nsegs > 0) {
        q = m->segprops[0];
        q.restitution = 0.25, q.mask = 0;
        REQUIRE(m, cc_world_set_segment_props(w, 0, &q) == m->busy_code,
                "set_segment_props from a callback not refused");
    }
    REQUIRE(m, cc_world_hash(w) == h, "a refused call from a callback changed the world (hash)");
    REQUIRE(m, cc_world_time(w) == t || (isnan(t) && isnan(cc_world_time(w))),
            "a refused call from a callback changed the time");
    fuzz_world_counted.refused++;
}

static void fold(model *m, const void *p, size_t n)
{
    const unsigned char *b = (const unsigned char *)p;
    size_t i;
    for (i = 0; i < n; i++)
        m->evhash = (m->evhash ^ b[i]) * UINT64_C(0x100000001B3);
}

static void fold_int(model *m, int v) { fold(m, &v, sizeof v); }
static void fold_double(model *m, double v) { fold(m, &v, sizeof v); }

static void on_contact(const cc_contact_event *e, void *user)
{
    model *m = g_cur;
    double ln;
    REQUIRE(m, m != NULL, "a contact callback outside any call");
    REQUIRE(m, user == &g_user, "the contact callback got another user pointer");
    REQUIRE(m, m->has_contact_cb, "on_contact called though the def had none");
    REQUIRE(m, m->op == OP_STEP || m->op == OP_STEP2 || m->op == OP_STEP_SMALL || m->op == OP_SET_PROPS ||
                   ((is_add(m->op) || m->op == OP_SET) && m->mode == CC_MODE_EXACT),
            "on_contact fired from a call the header does not list");
    m->ncb++;
    m->nev++;
    fold_int(m, e->a), fold_int(m, e->b), fold_int(m, e->segment), fold_double(m, e->t);
    fold_double(m, e->point.x), fold_double(m, e->point.y), fold_double(m, e->normal.x);
    fold_double(m, e->normal.y), fold_double(m, e->impulse);
    fuzz_world_counted.contacts++;
    REQUIRE(m, live_id(m, e->a) || is_add(m->op), "contact event: a not a live circle");
    REQUIRE(m, (e->b >= 0) != (e->segment >= 0), "contact event: neither or both of b and segment");
    REQUIRE(m, e->b < 0 || e->b != e->a, "contact event: a circle against itself");
    REQUIRE(m, e->segment < 0 || e->segment < m->nsegs, "contact event: a wall that does not exist");
    REQUIRE(m, e->b < 0 || e->b < m->maxc, "contact event: b out of range");
    REQUIRE(m, !isnan(e->t) && e->t >= m->call_t0, "contact event: time before the call's start");
    ln = hypot(e->normal.x, e->normal.y);
    REQUIRE(m, fabs(ln - 1.0) <= 1e-6, "contact event: normal not a unit vector");
    REQUIRE(m, !isnan(e->impulse) && e->impulse >= 0.0, "contact event: negative or NaN impulse");
    if (isinf(e->impulse)) { /* the header: +INFINITY only beyond DBL_MAX, so with a mass near it (D17) */
        int i, heavy = 0;
        for (i = 0; i < m->maxc; i++)
            heavy |= m->live[i] && isfinite(m->mass[i]) && m->mass[i] > 1e150;
        heavy |= isfinite(m->placing) && m->placing > 1e150;
#ifndef FUZZ_WORLD_STRICT
        heavy |= m->huge;
#endif
        REQUIRE(m, heavy, "contact event: an infinite impulse without a mass beyond 1e150");
    }
    if (isnan(e->point.x) || isnan(e->point.y) || getenv("FUZZ_WORLD_TRACE"))
        fprintf(stderr, "fuzz_world: contact a %d b %d segment %d t %.17g point (%.17g, %.17g) normal (%.17g, %.17g) "
                        "impulse %.17g\n", e->a, e->b, e->segment, e->t, e->point.x, e->point.y, e->normal.x,
                e->normal.y, e->impulse);
#ifndef FUZZ_WORLD_STRICT
    if (!m->huge)
#endif
        REQUIRE(m, !isnan(e->point.x) && !isnan(e->point.y), "contact event: NaN point");
    try_mutators(m, live_id(m, e->a) ? e->a : -1);
}

static void on_sensor(const cc_sensor_event *e, void *user)
{
    model *m = g_cur;
    REQUIRE(m, m != NULL, "a sensor callback outside any call");
    REQUIRE(m, user == &g_user, "the sensor callback got another user pointer");
    REQUIRE(m, m->has_sensor_cb, "on_sensor called though the def had none");
    REQUIRE(m, m->op == OP_STEP || m->op == OP_STEP2 || m->op == OP_STEP_SMALL || m->op == OP_SET_PROPS ||
                   is_add(m->op) || m->op == OP_SET,
            "on_sensor fired from a call the header does not list");
    m->ncb++;
    m->nev++;
    fold_int(m, -1), fold_int(m, e->sensor), fold_int(m, e->visitor), fold_int(m, e->begin), fold_double(m, e->t);
    fuzz_world_counted.sensors++;
    REQUIRE(m, e->begin == 0 || e->begin == 1, "sensor event: begin not 0 or 1");
    REQUIRE(m, e->sensor != e->visitor, "sensor event: a circle senses itself");
    REQUIRE(m, e->sensor >= 0 && e->sensor < m->maxc && e->visitor >= 0 && e->visitor < m->maxc,
            "sensor event: id out of range");
    REQUIRE(m, !isnan(e->t) && e->t >= m->call_t0, "sensor event: time before the call's start");
    try_mutators(m, live_id(m, e->visitor) ? e->visitor : -1);
}

/* ---- whole-world checks ----------------------------------------------------------------------- */

typedef struct snap {
    int n, ids[MAXC + 1];
    cc_circle c[MAXC + 1];
    cc_circle_props p[MAXC + 1];
} snap;

static void take(model *m, snap *s)
{
    int i;
    s->n = cc_world_get_circles(m->w, s->ids, s->c, MAXC + 1);
    REQUIRE(m, s->n == m->count, "get_circles: count differs from the live circles");
    for (i = 0; i < s->n; i++) {
        s->p[i].struct_size = sizeof s->p[i];
        REQUIRE(m, cc_world_get_circle_props(m->w, s->ids[i], &s->p[i]) == CC_OK, "get_circle_props of a live id");
    }
}

static void check_world(model *m, snap *s)
{
    int i, k, prev = -1;
    double t = cc_world_time(m->w);
    check_guards(m);
    REQUIRE(m, !isnan(t) && t >= m->time, "world time went backwards");
    m->time = t;
    take(m, s);
    for (i = 0; i < s->n; i++) {
        int id = s->ids[i];
        const cc_circle *c = &s->c[i];
        REQUIRE(m, id > prev, "get_circles: ids not increasing");
        prev = id;
        REQUIRE(m, live_id(m, id), "get_circles: an id that is not live");
        if (!(isfinite(c->pos.x) && isfinite(c->pos.y) && isfinite(c->vel.x) && isfinite(c->vel.y))) {
#ifndef FUZZ_WORLD_STRICT
            if (m->huge) { /* D7: impulses on velocities near DBL_MAX overflow; this input ends here */
                m->dead = 1;
                return;
            }
#endif
            fprintf(stderr, "fuzz_world: circle %d at (%.17g, %.17g) moving (%.17g, %.17g), radius %.17g, mass %.17g\n",
                    id, c->pos.x, c->pos.y, c->vel.x, c->vel.y, c->radius, c->mass);
            fail(m, "a live circle's position or velocity is not finite");
        }
        REQUIRE(m, c->radius == m->radius[id] && (c->mass == m->mass[id]), "a circle's radius or mass changed");
        for (k = 0; k < 2; k++)
            if (m->period[k] > 0.0)
                REQUIRE(m, (k ? c->pos.y : c->pos.x) >= 0.0 && (k ? c->pos.y : c->pos.x) < m->period[k],
                        "a position outside [0, period)");
        REQUIRE(m, s->p[i].restitution == m->props[id].restitution &&
                       s->p[i].rolling_decel == m->props[id].rolling_decel &&
                       s->p[i].category == m->props[id].category && s->p[i].mask == m->props[id].mask &&
                       s->p[i].sensor == m->props[id].sensor,
                "a circle's properties differ from those set");
    }
}

static double g_vmax; /* the largest speed in the world before or after the step */
static int g_loud;    /* overlaps() prints the pair it finds (the check after a step) */
static int g_fixed;   /* overlaps() counts a movable circle overlapping an immovable one too */

static double overlap_tol(const cc_circle *a, const cc_circle *b, double t)
{
    double scale = a->radius + b->radius + fabs(a->pos.x) + fabs(a->pos.y) + fabs(b->pos.x) + fabs(b->pos.y) +
                   (fabs(a->vel.x) + fabs(a->vel.y) + fabs(b->vel.x) + fabs(b->vel.y) + 2.0 * g_vmax) * (1.0 + fabs(t));
    return 1e-9 * scale;
}

/* deepest overlap (beyond the tolerance) between interacting movable non-sensor circles and
 * between such circles and walls; 0 when none */
/* Whether circle a, shifted by -1, 0 or +1 period along each periodic axis, meets wall s. */
static int wall_meets_image(const model *m, const cc_circle *a, const cc_segment *s)
{
    int u, v;
    for (u = -1; u <= 1; u++)
        for (v = -1; v <= 1; v++) {
            cc_vec2 c = a->pos, q;
            if ((u != 0 && !(m->period[0] > 0.0)) || (v != 0 && !(m->period[1] > 0.0)))
                continue;
            c.x += u * m->period[0];
            c.y += v * m->period[1];
            q = cc_closest_point_on_segment(c, s);
            if (hypot(q.x - c.x, q.y - c.y) < a->radius)
                return 1;
        }
    return 0;
}

static int overlaps(const model *m, const snap *s, const char **what)
{
    int i, j, k;
    for (i = 0; i < s->n; i++) {
        const cc_circle *a = &s->c[i];
        if ((isinf(a->mass) && !g_fixed) || s->p[i].sensor)
            continue;
        for (j = i + 1; j < s->n; j++) {
            const cc_circle *b = &s->c[j];
            double dx, dy, d;
            if ((isinf(b->mass) && (!g_fixed || isinf(a->mass))) || s->p[j].sensor ||
                !filters_meet(s->p[i].category, s->p[i].mask, s->p[j].category, s->p[j].mask))
                continue;
#ifndef FUZZ_WORLD_STRICT
            if (!(fabs(a->pos.x) + fabs(a->pos.y) + a->radius + fabs(b->pos.x) + fabs(b->pos.y) + b->radius < 1e150))
                continue; /* D12 (D3's and D7's class): radii and coordinates near 1e300 overflow */
#endif
            dx = wrapd(m, 0, b->pos.x - a->pos.x), dy = wrapd(m, 1, b->pos.y - a->pos.y);
            d = hypot(dx, dy);
            if (a->radius + b->radius - d > overlap_tol(a, b, m->time)) {
                if (g_loud)
                    fprintf(stderr, "fuzz_world: circles %d (%.17g, %.17g) r %.17g m %.17g and %d (%.17g, %.17g) r %.17g m %.17g: "
                                "overlap %.17g\n", s->ids[i], a->pos.x, a->pos.y, a->radius, a->mass, s->ids[j], b->pos.x,
                        b->pos.y, b->radius, b->mass, a->radius + b->radius - d);
                *what = "EXACT: two movable circles overlap deeper than the tolerance after a step";
                return 1;
            }
        }
        for (k = 0; k < m->nsegs && !isinf(a->mass); k++) {
            cc_vec2 q;
            double d;
            if (!filters_meet(s->p[i].category, s->p[i].mask, m->segprops[k].category, m->segprops[k].mask))
                continue;
            if (m->period[0] > 0.0 || m->period[1] > 0.0) {
                /* walls are not repeated: after a step leave the images alone; before it (g_fixed),
                 * a circle that any image of meets a wall makes the world unclean, since the step's
                 * push-out may move it into a circle it touches (D22, a false alarm without this) */
                if (g_fixed && wall_meets_image(m, a, &m->segs[k])) {
                    *what = "a circle (an image of it) overlaps a wall before the step";
                    return 1;
                }
                continue;
            }
            q = cc_closest_point_on_segment(a->pos, &m->segs[k]);
            d = hypot(q.x - a->pos.x, q.y - a->pos.y);
            if (a->radius - d > overlap_tol(a, a, m->time) + 1e-9 * (fabs(q.x) + fabs(q.y))) {
                *what = "EXACT: a movable circle overlaps a wall deeper than the tolerance after a step";
                return 1;
            }
        }
    }
    return 0;
}

static double kinetic(const snap *s, int *kinematic)
{
    double e = 0.0;
    int i;
    *kinematic = 0;
    for (i = 0; i < s->n; i++) {
        const cc_circle *c = &s->c[i];
        if (isinf(c->mass)) {
            if (c->vel.x != 0.0 || c->vel.y != 0.0)
                *kinematic = 1;
            continue;
        }
        e += 0.5 * c->mass * (c->vel.x * c->vel.x + c->vel.y * c->vel.y);
    }
    return e;
}

static void read_stats(model *m, cc_world_stats *st)
{
    st->struct_size = sizeof *st;
    REQUIRE(m, cc_world_get_stats(m->w, st) == CC_OK, "get_stats failed");
}

/* ---- one call ------------------------------------------------------------------------------------ */

static cc_circle read_circle(reader *r)
{
    cc_circle c;
    c.pos.x = value(r, K_POS);
    c.pos.y = value(r, K_POS);
    c.vel.x = value(r, K_VEL);
    c.vel.y = value(r, K_VEL);
    c.radius = value(r, K_RAD);
    c.mass = value(r, K_MASS);
    return c;
}

static int read_id(reader *r, const model *m)
{
    static const int odd[8] = {-1, INT_MIN, INT_MAX, 0, 1, 41, 1000, -2};
    unsigned b = byte(r);
    if (b < 8)
        return b == 3 ? m->maxc : b == 4 ? m->maxc + 1 : odd[b];
    return (int)(b % (unsigned)(m->maxc + 1));
}

static size_t pick_size(reader *r, const size_t *sizes)
{
    return sizes[byte(r) % 8];
}

static int bytes_untouched(const unsigned char *p, size_t from, size_t to)
{
    size_t i;
    for (i = from; i < to; i++)
        if (p[i] != UNTOUCHED)
            return 0;
    return 1;
}

static size_t fit(size_t n, const size_t *ends, int count)
{
    size_t f = 0;
    int i;
    for (i = 0; i < count && ends[i] <= n; i++)
        f = ends[i];
    return f;
}

#define END(type, field) (offsetof(type, field) + sizeof(((type *)0)->field))

static const size_t circle_props_ends[] = {END(cc_circle_props, struct_size), END(cc_circle_props, restitution),
                                           END(cc_circle_props, rolling_decel), END(cc_circle_props, category),
                                           END(cc_circle_props, mask), END(cc_circle_props, sensor)};
static const size_t segment_props_ends[] = {END(cc_segment_props, struct_size), END(cc_segment_props, restitution),
                                            END(cc_segment_props, category), END(cc_segment_props, mask)};
static const size_t stats_ends[] = {END(cc_world_stats, struct_size), END(cc_world_stats, collisions),
                                    END(cc_world_stats, events), END(cc_world_stats, stale_events),
                                    END(cc_world_stats, pairs_tested), END(cc_world_stats, cell_crossings),
                                    END(cc_world_stats, max_overlap), END(cc_world_stats, virial),
                                    END(cc_world_stats, wall_impulse)};

static int rc_step_ok(int rc) { return rc == CC_OK || rc == CC_EVENT_LIMIT || rc == CC_ERR_INVALID || rc == CC_ERR_RANGE; }

/* Known defects (reported to the lead), which the harness steps around unless built with
 * -DFUZZ_WORLD_STRICT (then it makes these calls and the violation shows):
 * D1  fixed: a step whose dt is valid (the time stays finite) but carried a circle past DBL_MAX
 *     returned CC_OK and left it at +-Inf; the header now says a step whose straight paths pass
 *     2^1017 is refused, and do_step checks it (step_range);
 * D2  a periodic world given a coordinate more than 2^31 periods from the origin (a circle added
 *     or set there, or carried there by a step) converts the number of periods to int32_t
 *     (src/world/grid.c cc__wrap_coord): undefined behaviour (UBSan: float-cast-overflow);
 * D3  fixed: the queries compared dx * dx + dy * dy < R * R (src/world/query.c), both sides Inf
 *     above about 1e154; they now scale by 2^-600 first (test_world_fuzz_defects.c);
 * D4  a periodic world whose period holds more than 2^31 cells (period 20, a circle of radius 1e-9,
 *     or an empty world whose def.cell_size is 1e-300)
 *     converts the cell count to int32_t at the step's rebuild (src/world/overlap.c, w->ncell):
 *     undefined behaviour, every mode; SWEPT's periodic sweep converts the cell range to int64_t
 *     likewise (src/world/swept.c:172, cc__sweep_body_periodic): a circle whose reach in the step
 *     spans more than 2^63 cells (a kinematic circle at 1e300 along the open axis of a channel);
 * D5  SWEPT never stops at max_events (src/world/swept.c cc__step_swept counts events but has no
 *     cap; the header's "no step processes more than def.max_events events" reads as every mode):
 *     a step with max_events 3 processes 4 and returns CC_OK. Code or header to change;
 * D6  fixed: a query in a periodic world whose centre lies more than half a period outside
 *     [0, period) missed circles (cc__near_d shifts by one period at most); judged again with
 *     query_tol's tolerance, which is the period's, not the coordinate's;
 * D7  EXACT, a circle added on top of others (and a wall), one of which moves at 1e308: contact
 *     events with a NaN point, and that circle left with velocity (Inf, -Inf) and a NaN position
 *     (tests/fuzz/world_defects/d7-*): the impulse arithmetic overflows (the pair functions
 *     promise finite results only below 2^1016). While a coordinate or velocity is beyond 1e150
 *     the harness does not check contact points, and a non-finite state ends the input; circles
 *     with a velocity component beyond 1e300 are not added or set (in a periodic world the NaN
 *     position then reaches D2's conversion: world_defects/d7-periodic-dbl-max-velocity);
 * D10 a periodic world at world time 1e300 gave a NaN position (world_defects/d10-*, not
 *     minimized): steps are kept below a world time of 1e15;
 * D11 a query in a world of period 6e300 missed a circle (world_defects/d11-*, not minimized):
 *     queries are not checked against brute force with periods beyond 1e9;
 * D9, D13 fixed (the rolling sweep lost a pushed pair at a touch; tests/test_world_fuzz_defects.c):
 *     no longer stepped around;
 * D14 EXACT: a circle set with radius 1e300 on top of others and a wall: the wall's push-out
 *     gives an Inf impulse and a NaN contact point (D7's and D12's class: squares of lengths near
 *     1e300 overflow; world_defects/d14-huge-radius-wall-nan-point): while a circle's coordinates,
 *     velocity or radius exceed 1e150 (or a call places such a circle) contact points are not
 *     checked;
 * D18 EXACT, periodic: a circle moving at 4e299 crosses a cell in less than an ulp of the world
 *     time, so its crossing events (1000, up to the cap) advance neither time nor position but
 *     each wraps its stored coordinate by a period: 47 periods out, where the queries' nearest
 *     image (one shift) no longer reaches it, and query_circle missed it (D7's class, speeds
 *     beyond the header's Range; world_defects/d18-*): while a coordinate or velocity is beyond
 *     1e150 in a periodic world, queries are not checked against brute force;
 * D20 D18's cause at ordinary scale (a speed of 1e21 at world time 9: 2e6 per ulp of the time,
 *     cells of 2.3): once a circle crosses a cell within one ulp of the world time it may be filed
 *     ahead of its position (the header's Range), and queries are not checked from then on;
 * D16 fixed: a circle moving slower than 1 given rolling_decel DBL_MAX got a NaN velocity (2k
 *     overflowed in the rolling motion's g'); D17 fixed: a circle of mass 1e308 in a cluster
 *     struck by a kinematic one got an Inf velocity and the contact a NaN point (the cluster
 *     solver's impulse overflowed); neither was stepped around; contact impulses may be
 *     +INFINITY (the header's rule) only while some circle's mass exceeds 1e150;
 * D8  fixed: SWEPT, periodic: a step that carried a circle more than a period was accepted and
 *     query_box then missed that circle; SWEPT now refuses a step carrying a circle half a period
 *     (swept_too_long checks it); DISCRETE's steps keep to the header's precondition. */
static int far_on_axis(const model *m, int k, double x)
{
#ifdef FUZZ_WORLD_STRICT
    (void)m, (void)k, (void)x;
    return 0;
#else
    if (m->period[k] > 0.0)
        return !(fabs(x) < 1e9 * m->period[k]);
    return 0; /* open axis: D1 fixed, the library refuses a step past 2^1017 (checked in do_step) */
#endif
}

static int step_overflows(const model *m, const snap *s, double dt)
{
    int i, k;
    /* the header: in SWEPT and DISCRETE "a step must not carry a circle half a period" (a
     * precondition the library does not check: D8 when broken) */
    if (m->mode == CC_MODE_DISCRETE) /* (SWEPT refuses such a step: do_step checks it, D8) */
        for (i = 0; i < s->n; i++)
            for (k = 0; k < 2; k++)
                if (m->period[k] > 0.0 && !(fabs(k ? s->c[i].vel.y : s->c[i].vel.x) * dt < 0.5 * m->period[k]))
                    return 1;
#ifndef FUZZ_WORLD_STRICT
    double dm = 0.0, da = 0.0, cs;
    for (i = 0; i < s->n; i++) {
        da = fmax(da, 2.0 * s->c[i].radius);
        if (!isinf(s->c[i].mass))
            dm = fmax(dm, 2.0 * s->c[i].radius);
    }
    cs = fmax(m->cell_size, 1.0625 * (dm > 0.0 ? dm : da));
    for (i = 0; i < 2; i++)
        if (cs > 0.0 && m->period[i] > 0.0 && !(m->period[i] / cs < 0x1p29))
            return 1; /* D4 */
    if (m->mode == CC_MODE_SWEPT && (m->period[0] > 0.0 || m->period[1] > 0.0))
        for (i = 0; i < s->n; i++)
            if (!((fabs(s->c[i].pos.x) + fabs(s->c[i].pos.y) + 4.0 * (fabs(s->c[i].vel.x) + fabs(s->c[i].vel.y)) * dt) /
                      cs < 0x1p60))
                return 1; /* D4, SWEPT */
#endif
    for (i = 0; i < s->n; i++) {
        const cc_circle *c = &s->c[i];
        if (far_on_axis(m, 0, fabs(c->pos.x) + fabs(c->vel.x) * dt) ||
            far_on_axis(m, 1, fabs(c->pos.y) + fabs(c->vel.y) * dt))
            return 1;
    }
    return 0;
}

static int place_ub(model *m, const cc_circle *c)
{
#ifndef FUZZ_WORLD_STRICT
    if (circle_valid(c) && (fabs(c->vel.x) > 1e300 || fabs(c->vel.y) > 1e300))
        return 1; /* D7: velocities near DBL_MAX (1e308, DBL_MAX) overflow the impulses */
    if (circle_valid(c) && !(fabs(c->pos.x) + fabs(c->pos.y) + fabs(c->vel.x) + fabs(c->vel.y) + c->radius < 1e150))
        m->huge = 1; /* D14: the call itself may give a contact a NaN point (D7's class) */
#endif
    if (circle_valid(c) && c->radius < m->rmin)
        m->rmin = c->radius;
    return circle_valid(c) && ((m->period[0] > 0.0 && far_on_axis(m, 0, c->pos.x)) ||
                               (m->period[1] > 0.0 && far_on_axis(m, 1, c->pos.y)));
}

/* The header's range of a step: 1 when some circle's straight path (p + v dt) passes 2^1017
 * along an axis (the step must be refused), -1 when every one stays clear of it by a margin
 * for rounding (it must not be), 0 in between. */
static int step_range(const snap *s, double dt)
{
    const double lim = 0x1p1017;
    int i, far = 0;
    for (i = 0; i < s->n; i++) {
        double x = fabs(s->c[i].pos.x) + fabs(s->c[i].vel.x) * dt, y = fabs(s->c[i].pos.y) + fabs(s->c[i].vel.y) * dt;
        if (!(x < lim * (1.0 + 1e-9) && y < lim * (1.0 + 1e-9)))
            return 1;
        if (!(x < lim * (1.0 - 1e-9) && y < lim * (1.0 - 1e-9)))
            far = 1;
    }
    return far ? 0 : -1;
}

/* SWEPT in a periodic world (D8 fixed: the header refuses a step that carries a circle half a
 * period): 1 when some circle, none rolling, goes beyond half a period (it must be refused), -1
 * when every straight path stays short of it by a margin (it must not be), 0 otherwise. */
static int swept_too_long(const model *m, const snap *s, double dt)
{
    int i, k, near = 0, rolls = 0;
    for (i = 0; i < s->n; i++) {
        rolls |= s->p[i].rolling_decel > 0.0 && !isinf(s->c[i].mass);
        for (k = 0; k < 2; k++) {
            double d = fabs(k ? s->c[i].vel.y : s->c[i].vel.x) * dt, h = 0.5 * m->period[k];
            if (m->period[k] > 0.0 && !(d < h * (1.0 - 1e-9)))
                near = 1;
            if (m->period[k] > 0.0 && !(d < h * (1.0 + 1e-9)) && !rolls)
                return 1;
        }
    }
    return near || rolls ? (near ? 0 : -1) : -1;
}

static void do_step(model *m, double dt, const snap *before)
{
    int range;
    cc_world_stats s0, s1;
    int kin, rc, clean = 0;
    double e0 = kinetic(before, &kin), e1, t0 = m->time;
    const char *what = NULL;
    snap after;
    uint64_t h0 = cc_world_hash(m->w);
    if (dt >= 0.0 && isfinite(dt) && step_overflows(m, before, dt))
        return;
#ifndef FUZZ_WORLD_STRICT
    if (!(t0 + dt < 1e15) && isfinite(t0 + dt) && dt >= 0.0)
        return; /* D10: at world times near 1e300 positions become NaN */
#endif
    g_vmax = 0.0;
    /* clean: nothing overlaps before the step, immovable circles included: the step's push-apart
     * of a circle from an immovable one (pending after a wide circle was added) makes one pass and
     * may leave the circle in a chain overlapping another, which then drifts apart (the header's
     * Overlaps: "heals"; D21, a false alarm of the check without them) */
    g_fixed = 1;
    if (m->mode == CC_MODE_EXACT && m->rest_speed == 0.0)
        clean = !overlaps(m, before, &what);
    g_fixed = 0;
    read_stats(m, &s0);
    rc = cc_world_step(m->w, dt);
    if (getenv("FUZZ_WORLD_TRACE"))
        fprintf(stderr, "step %.17g: %d\n", dt, rc);
    fuzz_world_counted.steps++;
    REQUIRE(m, rc_step_ok(rc), "step: a result outside OK, EVENT_LIMIT, INVALID, RANGE");
    REQUIRE(m, rc != CC_ERR_RANGE || m->range_code == CC_ERR_RANGE, "step: RANGE for a 1.0 or 1.1 def");
    if (!(dt >= 0.0) || isinf(dt))
        REQUIRE(m, rc == CC_ERR_INVALID, "step: an invalid dt not refused");
    else if (!isfinite(t0 + dt))
        REQUIRE(m, rc == m->range_code, "step: a world time that overflows not refused as a range");
    else if (m->mode == CC_MODE_SWEPT && swept_too_long(m, before, dt) > 0)
        REQUIRE(m, rc == m->range_code, "step: SWEPT, periodic: a step carrying a circle half a period not refused");
    else if (m->mode == CC_MODE_SWEPT && swept_too_long(m, before, dt) == 0)
        ; /* within rounding of half a period, or rolling: either answer */
    else if ((range = step_range(before, dt)) > 0)
        REQUIRE(m, rc == m->range_code, "step: a step carrying a circle past 2^1017 not refused");
    else if (range < 0)
        REQUIRE(m, rc >= 0, "step: a valid dt refused");
    if (rc < 0)
        REQUIRE(m, cc_world_hash(m->w) == h0, "step: a refused step changed the world");
    read_stats(m, &s1);
#ifndef FUZZ_WORLD_STRICT
    if (m->mode != CC_MODE_EXACT)
        s1.events = s0.events; /* D5: SWEPT ignores max_events */
#endif
    if (!(s1.events - s0.events <= m->max_events))
        fprintf(stderr, "fuzz_world: %llu events in a step, max_events %llu, dt %.17g, result %d\n",
                (unsigned long long)(s1.events - s0.events), (unsigned long long)m->max_events, dt, rc);
    REQUIRE(m, s1.events - s0.events <= m->max_events, "step: more events than max_events");
    if (rc == CC_EVENT_LIMIT)
        REQUIRE(m, s1.events - s0.events == m->max_events, "step: EVENT_LIMIT without max_events events");
    check_world(m, &after);
    if (rc == CC_OK)
        REQUIRE(m, m->time == t0 + dt, "step: CC_OK but the time is not t + dt");
    if (rc == CC_EVENT_LIMIT)
        REQUIRE(m, m->time <= t0 + dt, "step: EVENT_LIMIT past t + dt");
    /* a jam (the header's "Pushing": a circle pushed by one that decelerates less) reaches the
     * cap at every step, each up to 1000 events of rolling sweeps (clusters of several contacts,
     * about 1.5 ms an event under coverage and sanitizers): after the first such step of a
     * rolling world, or the second of any (its checks below made), the input ends, so that the
     * run stays within libFuzzer's timeout */
    if (rc == CC_EVENT_LIMIT) {
        int i, rolls = 0;
        for (i = 0; i < after.n; i++)
            rolls |= after.p[i].rolling_decel > 0.0;
        if (++m->capped >= 2 || rolls)
            m->dead = 1;
    }
    e1 = kinetic(&after, &kin);
    {
        int i;
        g_vmax = 0.0;
        for (i = 0; i < before->n; i++)
            g_vmax = fmax(g_vmax, fabs(before->c[i].vel.x) + fabs(before->c[i].vel.y));
        for (i = 0; i < after.n; i++)
            g_vmax = fmax(g_vmax, fabs(after.c[i].vel.x) + fabs(after.c[i].vel.y));
    }
    g_loud = 1;
    if (rc >= 0 && clean && overlaps(m, &after, &what))
        fail(m, what);
    g_loud = 0;
    if (rc >= 0 && !kin && isfinite(e0) && isfinite(e1)) {
        if (!(e1 <= e0 * (1.0 + 1e-9) + 1e-300)) {
            fprintf(stderr, "fuzz_world: kinetic energy %.17g -> %.17g\n", e0, e1);
            fail(m, "step: kinetic energy grew");
        }
    }
}

static void do_props(model *m, reader *r, int set)
{
    static const size_t sizes[8] = {sizeof(cc_circle_props), sizeof(cc_circle_props), 16, 24, 32, 36, 8,
                                    sizeof(cc_circle_props) + 16};
    union {
        cc_circle_props p;
        unsigned char b[sizeof(cc_circle_props) + 16];
    } u;
    int id = read_id(r, m), rc;
    size_t n = pick_size(r, sizes), f = fit(n, circle_props_ends, 6);
    uint64_t h0 = cc_world_hash(m->w);
    memset(u.b, (int)UNTOUCHED, sizeof u.b);
    u.p.struct_size = n;
    if (set) {
        int valid;
        cc_circle_props want;
        u.p.restitution = value(r, K_UNIT);
        u.p.rolling_decel = byte(r) & 1u ? value(r, K_SMALL) : 0.0;
        u.p.category = bits32(r);
        u.p.mask = bits32(r);
        u.p.sensor = (int)(byte(r) % 4u == 0u) * (int)(1 + byte(r) % 3u);
        want = live_id(m, id) ? m->props[id] : u.p;
        if (f >= END(cc_circle_props, restitution))
            want.restitution = u.p.restitution;
        if (f >= END(cc_circle_props, rolling_decel))
            want.rolling_decel = u.p.rolling_decel;
        if (f >= END(cc_circle_props, category))
            want.category = u.p.category;
        if (f >= END(cc_circle_props, mask))
            want.mask = u.p.mask;
        if (f >= END(cc_circle_props, sensor))
            want.sensor = u.p.sensor != 0;
        valid = want.restitution >= 0.0 && want.restitution <= 1.0 && want.rolling_decel >= 0.0 &&
                isfinite(want.rolling_decel);
        m->op = OP_SET_PROPS;
        rc = cc_world_set_circle_props(m->w, id, &u.p);
        if (getenv("FUZZ_WORLD_TRACE"))
            fprintf(stderr, "set_circle_props %d size %zu: restitution %.17g decel %.17g category %x mask %x sensor %d: %d\n",
                    id, n, u.p.restitution, u.p.rolling_decel, u.p.category, u.p.mask, u.p.sensor, rc);
        REQUIRE(m, u.p.struct_size == n, "set_circle_props changed struct_size");
        if (!live_id(m, id))
            REQUIRE(m, rc == CC_ERR_NOT_FOUND || ((n < 16 || !valid) && (rc == CC_ERR_VERSION || rc == CC_ERR_INVALID)),
                    "set_circle_props: a dead id not NOT_FOUND");
        else if (n < 16)
            REQUIRE(m, rc == CC_ERR_VERSION, "set_circle_props: a short struct_size not VERSION");
        else if (!valid)
            REQUIRE(m, rc == CC_ERR_INVALID, "set_circle_props: invalid values not INVALID");
        else if (((want.restitution != m->props[id].restitution || want.category != m->props[id].category ||
                   want.mask != m->props[id].mask) &&
                  !(m->uses & CC_USES_PROPS)) ||
                 (want.rolling_decel != m->props[id].rolling_decel && !(m->uses & (CC_USES_PROPS | CC_USES_ROLLING))) ||
                 (!want.sensor != !m->props[id].sensor && !(m->uses & CC_USES_SENSORS)))
            REQUIRE(m, rc == CC_ERR_INVALID, "set_circle_props: what the world did not reserve not INVALID");
        else
            REQUIRE(m, rc == CC_OK || rc == CC_ERR_FULL, "set_circle_props: valid call failed");
        if (rc == CC_OK) {
            want.struct_size = sizeof want;
            m->props[id] = want;
        } else
            REQUIRE(m, cc_world_hash(m->w) == h0, "set_circle_props: a failed call changed the world");
        return;
    }
    rc = cc_world_get_circle_props(m->w, id, &u.p);
    REQUIRE(m, u.p.struct_size == n, "get_circle_props changed struct_size");
    if (!live_id(m, id))
        REQUIRE(m, rc == CC_ERR_NOT_FOUND || (n < 16 && rc == CC_ERR_VERSION), "get_circle_props: dead id");
    else if (n < 16)
        REQUIRE(m, rc == CC_ERR_VERSION, "get_circle_props: a short struct_size not VERSION");
    else
        REQUIRE(m, rc == CC_OK, "get_circle_props: a live id failed");
    if (rc != CC_OK)
        f = sizeof(size_t);
    /* the padding after sensor may be written with the whole struct; bytes beyond it may not */
    REQUIRE(m, bytes_untouched(u.b, f, n < sizeof(cc_circle_props) ? sizeof u.b : END(cc_circle_props, sensor)) &&
                   bytes_untouched(u.b, n > sizeof(cc_circle_props) ? sizeof(cc_circle_props) : sizeof u.b, sizeof u.b),
            "get_circle_props wrote beyond the whole fields that fit");
    if (rc == CC_OK && f >= END(cc_circle_props, restitution))
        REQUIRE(m, u.p.restitution == m->props[id].restitution, "get_circle_props: restitution differs");
}

static void do_segprops(model *m, reader *r, int set)
{
    static const size_t sizes[8] = {sizeof(cc_segment_props), sizeof(cc_segment_props), 16, 20, 8, 0, 12,
                                    sizeof(cc_segment_props) + 16};
    union {
        cc_segment_props p;
        unsigned char b[sizeof(cc_segment_props) + 16];
    } u;
    int id = read_id(r, m) % (MAXS + 3), rc, ok = id >= 0 && id < m->nsegs;
    size_t n = pick_size(r, sizes), f = fit(n, segment_props_ends, 4);
    uint64_t h0 = cc_world_hash(m->w);
    memset(u.b, (int)UNTOUCHED, sizeof u.b);
    u.p.struct_size = n;
    if (set) {
        cc_segment_props want;
        int valid;
        u.p.restitution = value(r, K_UNIT);
        u.p.category = bits32(r);
        u.p.mask = bits32(r);
        want = ok ? m->segprops[id] : u.p;
        if (f >= END(cc_segment_props, restitution))
            want.restitution = u.p.restitution;
        if (f >= END(cc_segment_props, category))
            want.category = u.p.category;
        if (f >= END(cc_segment_props, mask))
            want.mask = u.p.mask;
        valid = want.restitution >= 0.0 && want.restitution <= 1.0;
        m->op = OP_SET_SEGPROPS;
        rc = cc_world_set_segment_props(m->w, id, &u.p);
        if (getenv("FUZZ_WORLD_TRACE"))
            fprintf(stderr, "set_segment_props %d size %u: restitution %.17g category %x mask %x: %d\n", id,
                    (unsigned)n, u.p.restitution, (unsigned)u.p.category, (unsigned)u.p.mask, rc);
        if (!ok)
            REQUIRE(m, rc == CC_ERR_NOT_FOUND || ((n < 16 || !valid) && (rc == CC_ERR_VERSION || rc == CC_ERR_INVALID)),
                    "set_segment_props: a missing wall not NOT_FOUND");
        else if (n < 16)
            REQUIRE(m, rc == CC_ERR_VERSION, "set_segment_props: a short struct_size not VERSION");
        else if (!valid)
            REQUIRE(m, rc == CC_ERR_INVALID, "set_segment_props: invalid values not INVALID");
        else if (!(m->uses & CC_USES_PROPS) &&
                 (want.restitution != m->segprops[id].restitution || want.category != m->segprops[id].category ||
                  want.mask != m->segprops[id].mask))
            REQUIRE(m, rc == CC_ERR_INVALID, "set_segment_props: a world without props not INVALID");
        else
            REQUIRE(m, rc == CC_OK, "set_segment_props: a valid call failed");
        if (rc == CC_OK) {
            want.struct_size = sizeof want;
            m->segprops[id] = want;
        } else
            REQUIRE(m, cc_world_hash(m->w) == h0, "set_segment_props: a failed call changed the world");
        return;
    }
    rc = cc_world_get_segment_props(m->w, id, &u.p);
    if (!ok)
        REQUIRE(m, rc == CC_ERR_NOT_FOUND || (n < 16 && rc == CC_ERR_VERSION), "get_segment_props: missing wall");
    else if (n < 16)
        REQUIRE(m, rc == CC_ERR_VERSION, "get_segment_props: a short struct_size not VERSION");
    else
        REQUIRE(m, rc == CC_OK, "get_segment_props: a valid call failed");
    if (rc != CC_OK)
        f = sizeof(size_t);
    REQUIRE(m, bytes_untouched(u.b, f, n < sizeof(cc_segment_props) ? sizeof u.b : sizeof(cc_segment_props)) &&
                   bytes_untouched(u.b, sizeof(cc_segment_props), sizeof u.b),
            "get_segment_props wrote beyond the whole fields that fit");
    if (rc == CC_OK) {
        const cc_segment_props *w = &m->segprops[id];
        REQUIRE(m, u.p.restitution == w->restitution, "get_segment_props: restitution differs");
        if (f >= END(cc_segment_props, mask))
            REQUIRE(m, u.p.category == w->category && u.p.mask == w->mask, "get_segment_props: filter differs");
    }
}

static void do_stats(model *m, reader *r)
{
    static const size_t sizes[8] = {sizeof(cc_world_stats), 8, 16, 56, 60, 64, sizeof(cc_world_stats) + 16, 0};
    union {
        cc_world_stats s;
        unsigned char b[sizeof(cc_world_stats) + 16];
    } u;
    size_t n = pick_size(r, sizes), f = fit(n, stats_ends, 9);
    int rc;
    memset(u.b, (int)UNTOUCHED, sizeof u.b);
    u.s.struct_size = n;
    rc = cc_world_get_stats(m->w, &u.s);
    REQUIRE(m, u.s.struct_size == n, "get_stats changed struct_size");
    REQUIRE(m, n < 16 ? rc == CC_ERR_VERSION : rc == CC_OK, "get_stats: wrong result for its struct_size");
    if (rc != CC_OK)
        f = sizeof(size_t);
    REQUIRE(m, bytes_untouched(u.b, f, sizeof u.b), "get_stats wrote beyond the whole fields that fit");
    if (n == sizeof(cc_world_stats)) {
        const cc_world_stats *a = &m->stats, *b = &u.s;
        REQUIRE(m, b->collisions >= a->collisions && b->events >= a->events && b->stale_events >= a->stale_events &&
                       b->pairs_tested >= a->pairs_tested && b->cell_crossings >= a->cell_crossings &&
                       !(b->max_overlap < a->max_overlap),
                "get_stats: a counter went down");
        REQUIRE(m, b->stale_events <= b->events, "get_stats: more stale events than events");
#ifndef FUZZ_WORLD_STRICT
        if (!m->huge) /* (D7's class: Inf impulses at speeds near DBL_MAX) */
#endif
            REQUIRE(m, !isnan(b->virial) && !isnan(b->wall_impulse) && !(b->virial < a->virial) &&
                           !(b->wall_impulse < a->wall_impulse),
                    "get_stats: virial or wall_impulse NaN or decreasing (sums of impulses >= 0)");
        m->stats = u.s;
    }
}

static double dist_box(double x, double lo, double hi) { return x < lo ? lo - x : x > hi ? x - hi : 0.0; }

/* A cast's or query's mask (bits32's byte) and the circle its filter (1.2) leaves out, from the
 * byte's bits 4-6 (unused by bits32): 0 is the 1.1 call (-2 here), else the filtered one with
 * ignore = bits - 2 (-1: none; ids 0 to 5, live or not). */
static uint32_t mask_and_ignore(reader *r, int *ignore)
{
    unsigned b = r->n > 0 ? r->p[0] : 0u;
    *ignore = b & 0x80u ? -2 : (int)((b >> 4) & 7u) - 2;
    return bits32(r);
}

static cc_query_filter filter_of(uint32_t mask, int ignore)
{
    cc_query_filter f = CC_QUERY_FILTER_DEFAULT;
    f.mask = mask;
    f.ignore = ignore;
    return f;
}

/* The boundary's tolerance of a query: a relative 1e-9 of the numbers that make the distance
 * within the period (the circle's coordinates, the radii, the box's width, the period), plus,
 * along a periodic axis, the rounding of taking the query's coordinates into the period (2^-48
 * of their size: a few ulps). A query centred a million periods out is then judged to 1e-9 of
 * the period, not to 1e-9 of its coordinate (which was the whole period at 1e9 periods); once
 * that rounding passes a thousandth of the period the query has lost its place in it (the
 * header's "about 1e15 periods": there beyond 1e12) and -1 says so. */
static double query_tol(const model *m, double lim, const cc_circle *k, cc_vec2 c, cc_vec2 h, int box)
{
    double t = 1e-9 * (lim + fabs(k->pos.x) + fabs(k->pos.y)), v[2];
    int a;
    v[0] = fabs(c.x) + (box ? fabs(h.x) : 0.0);
    v[1] = fabs(c.y) + (box ? fabs(h.y) : 0.0);
    for (a = 0; a < 2; a++) {
        if (m->period[a] > 0.0) {
            double wrap = 0x1p-48 * v[a];
            if (wrap > 1e-3 * m->period[a])
                return -1.0;
            t += wrap + 1e-9 * m->period[a] + (box ? 1e-9 * fabs((a ? h.y - c.y : h.x - c.x)) : 0.0);
        } else {
            t += 1e-9 * v[a];
        }
    }
    return t;
}

static void do_query(model *m, reader *r, int box, const snap *s)
{
    int ids[MAXC + 8], cap, rc, i, j;
    unsigned cb = byte(r);
    cc_vec2 c, h;
    double rad = 0.0;
    int ignore;
    uint32_t mask = mask_and_ignore(r, &ignore);
    cc_query_filter f = filter_of(mask, ignore);
    c.x = value(r, K_POS), c.y = value(r, K_POS);
    if (box) {
        h.x = c.x + value(r, K_SMALL) * (byte(r) & 1u ? 1.0 : -0.1);
        h.y = c.y + value(r, K_SMALL);
    } else
        rad = value(r, K_SMALL), h.x = h.y = 0.0;
    cap = cb == 255 ? -1 : (int)(cb % (MAXC + 2));
    for (i = 0; i < MAXC + 8; i++)
        ids[i] = -77;
    if (ignore == -2)
        rc = box ? cc_world_query_box(m->w, c, h, mask, cb == 254 ? NULL : ids, cap)
                 : cc_world_query_circle(m->w, c, rad, mask, cb == 254 ? NULL : ids, cap);
    else
        rc = box ? cc_world_query_box_filtered(m->w, c, h, &f, cb == 254 ? NULL : ids, cap)
                 : cc_world_query_circle_filtered(m->w, c, rad, &f, cb == 254 ? NULL : ids, cap);
    if (cap < 0 || (cb == 254 && cap > 0) || !isfinite(c.x) || !isfinite(c.y) ||
        (box ? (!isfinite(h.x) || !isfinite(h.y) || !(c.x <= h.x) || !(c.y <= h.y)) : (!isfinite(rad) || rad < 0.0))) {
        REQUIRE(m, rc == CC_ERR_INVALID, "query: invalid arguments not INVALID");
        for (i = 0; i < MAXC + 8; i++)
            REQUIRE(m, ids[i] == -77, "query: an invalid call wrote ids");
        return;
    }
    REQUIRE(m, rc >= 0 && rc <= m->count, "query: a count outside [0, live circles]");
    for (i = (rc < cap ? rc : cap); i < MAXC + 8; i++)
        REQUIRE(m, ids[i] == -77, "query: wrote beyond the count or the capacity");
    if (cb == 254)
        return;
    /* brute force, with a relative 1e-9 margin at the boundary */
    for (i = 0, j = 0; i < s->n; i++) {
        const cc_circle *k = &s->c[i];
        double dx, dy, d, lim, tol;
        int in_out, sure_in, sure_out, listed;
        if (!(s->p[i].category & mask) || s->ids[i] == ignore)
            continue;
        if (box) {
            double cx = (c.x + h.x) * 0.5, cy = (c.y + h.y) * 0.5;
            dx = dist_box(cx + wrapd(m, 0, k->pos.x - cx), c.x, h.x);
            dy = dist_box(cy + wrapd(m, 1, k->pos.y - cy), c.y, h.y);
            lim = k->radius;
        } else {
            dx = wrapd(m, 0, k->pos.x - c.x), dy = wrapd(m, 1, k->pos.y - c.y);
            lim = k->radius + rad;
        }
        d = hypot(dx, dy);
        tol = query_tol(m, lim, k, c, h, box);
        sure_in = tol >= 0.0 && d < lim - tol;
        sure_out = tol >= 0.0 && d > lim + tol;
#ifndef FUZZ_WORLD_STRICT
        if ((m->period[0] > 0.0 && !(m->period[0] < 1e9)) || (m->period[1] > 0.0 && !(m->period[1] < 1e9)))
            sure_in = sure_out = 0; /* D11 */
        if (m->huge && (m->period[0] > 0.0 || m->period[1] > 0.0))
            sure_in = sure_out = 0; /* D18: at speeds beyond 1e150 stored positions leave the period */
        if (m->fast)
            sure_in = sure_out = 0; /* D20: the header's Range: filed ahead of its position */
#endif
        in_out = 0;
        listed = 0;
        while (j < rc && j < cap && ids[j] < s->ids[i])
            j++;
        if (j < rc && j < cap && ids[j] == s->ids[i])
            listed = 1;
        if ((sure_in && !listed && rc <= cap) || (sure_out && listed))
            fprintf(stderr, "fuzz_world: circle %d at (%.17g, %.17g) radius %.17g; query (%.17g, %.17g)-(%.17g, %.17g) "
                            "radius %.17g, mask %x, category %x; distance %.17g, limit %.17g; periods %g %g\n",
                    s->ids[i], k->pos.x, k->pos.y, k->radius, c.x, c.y, h.x, h.y, rad, mask, s->p[i].category, d, lim,
                    m->period[0], m->period[1]);
        if (rc <= cap) {
            if (sure_in && !listed)
                fail(m, box ? "query_box: missed a circle inside" : "query_circle: missed a circle inside");
        }
        if (sure_out && listed)
            fail(m, box ? "query_box: listed a circle outside" : "query_circle: listed a circle outside");
        (void)in_out;
    }
    for (i = 1; i < (rc < cap ? rc : cap); i++)
        REQUIRE(m, ids[i] > ids[i - 1], "query: ids not increasing");
    for (i = 0; i < (rc < cap ? rc : cap); i++)
        REQUIRE(m, live_id(m, ids[i]) && ids[i] != ignore, "query: an id that is not live, or the one left out");
}

/* ---- the casts' brute force -------------------------------------------------------------------- */

/* What a brute force over the public pair functions says of a cast: the earliest contact it is
 * sure of (t_sure, HUGE_VAL for none), and whether (t, object) is one it found at all, sure or
 * within rounding (a graze, a touch at the start, a ray at a wall's end). */
typedef struct cast_bf {
    double t_sure, tol;
    int n;
    struct { double t; int wall, id, sure; } cand[4 * (MAXC + MAXS) + 64];
} cast_bf;

static void bf_note(cast_bf *b, double t, int wall, int id, int sure)
{
    if (sure && t < b->t_sure)
        b->t_sure = t;
    if (b->n < (int)(sizeof b->cand / sizeof b->cand[0])) {
        b->cand[b->n].t = t, b->cand[b->n].wall = wall, b->cand[b->n].id = id, b->cand[b->n].sure = sure;
        b->n++;
    } else if (!sure) {
        b->n = -1000000; /* more unsure candidates than room: cannot judge */
    }
}

/* How many images of each circle the library counts for a cast (src/world/cast.c, the header's
 * "Periodic boxes": a cast past CC__CAST_IMAGES, 16384, looks at nearest images only, in every
 * mode and state): the pieces half a period (or the radius) long times the images each piece's
 * box holds. */
static double cast_looks(const model *m, cc_vec2 d, double rad)
{
    double pmin = HUGE_VAL, piece, n, looks = 1.0, len = hypot(d.x, d.y);
    int k;
    for (k = 0; k < 2; k++)
        if (m->period[k] > 0.0 && m->period[k] < pmin)
            pmin = m->period[k];
    if (pmin == HUGE_VAL)
        return 0.0;
    piece = 0.5 * pmin > rad ? 0.5 * pmin : rad;
    n = len / piece < 1.0 ? 1.0 : ceil(len / piece);
    for (k = 0; k < 2; k++)
        if (m->period[k] > 0.0)
            looks *= (fabs(k == 0 ? d.x : d.y) / n + 2.0 * (rad + 0.25 * pmin)) / m->period[k] + 2.0;
    return n * looks;
}

/* Image index range along axis k of the centres within R of [lo, hi] (one more either side). */
static void bf_range(const model *m, int k, double q, double lo, double hi, double R, double *n0, double *n1)
{
    if (m->period[k] > 0.0) {
        *n0 = floor((lo - R - q) / m->period[k]) - 1.0;
        *n1 = ceil((hi + R - q) / m->period[k]) + 1.0;
    } else
        *n0 = *n1 = 0.0;
}

/* One image of a circle against the cast: cc_sweep with the sum of the radii split between the
 * two (a ray has radius 0: only the sum counts), sure unless it grazes or starts touching. */
static void bf_image(cast_bf *b, cc_vec2 p, double rad, cc_vec2 d, double qx, double qy, double rb, int id)
{
    cc_circle me, im;
    cc_contact h;
    double R = rad + rb, ex = qx - p.x, ey = qy - p.y, dd = d.x * d.x + d.y * d.y, u, cx, cy, dmin, d0;
    int res, graze;
    me.pos = p, me.vel = d, me.radius = rad + 0.5 * rb, me.mass = 1.0;
    im.pos.x = qx, im.pos.y = qy, im.vel.x = im.vel.y = 0.0, im.radius = 0.5 * rb, im.mass = 1.0;
    if (!(im.radius > 0.0))
        im.radius = rb, me.radius = rad > 0.0 ? rad : rb; /* (a subnormal radius: unsure below) */
    res = cc_sweep(&me, &im, 1.0, &h);
    u = dd > 0.0 ? (ex * d.x + ey * d.y) / dd : 0.0;
    u = u < 0.0 ? 0.0 : u > 1.0 ? 1.0 : u;
    cx = ex - u * d.x, cy = ey - u * d.y;
    dmin = hypot(cx, cy);
    d0 = hypot(ex, ey);
    /* both solvers work in the pair's own frame: their rounding is of the pair's numbers (L), and
     * hit or miss is rounding's where the squares of the closest (or the first) distance and of R
     * are within 1e-9 L^2 (beyond, the entry time's error stays near an ulp of L) */
    {
        double L = d0 + sqrt(dd) + R, g = 1e-9 * L * L;
        graze = fabs((dmin - R) * (dmin + R)) <= g || fabs((d0 - R) * (d0 + R)) <= g || !(0.5 * rb > 0.0);
    }
    if (res == CC_HIT)
        bf_note(b, h.t, 0, id, !graze && h.t > b->tol && h.t < 1.0 - b->tol);
    else if (res == CC_OVERLAP)
        bf_note(b, 0.0, 0, id, !graze);
    else if (graze && dmin <= R * (1.0 + 1e-6))
        bf_note(b, h.t, 0, id, 0); /* (t: any; only the object is matched below) */
}

/* 1: b holds the brute force of the cast; 0: the cast is beyond what it can judge (values
 * beyond the header's Range, periods beyond 1e9, a path past the images the library promises,
 * a ray along a wall's line). */
static int cast_brute(const model *m, const snap *s, cc_vec2 p, double rad, cc_vec2 d, uint32_t mask, int ignore,
                      cast_bf *b)
{
    double S = fabs(p.x) + fabs(p.y) + fabs(d.x) + fabs(d.y) + rad, lo[2], hi[2];
    int i, k;
    if (m->huge || m->fast || m->time > 1e9 || !(S < 1e12) || m->period[0] >= 1e9 || m->period[1] >= 1e9)
        return 0;
    if (m->period[0] > 0.0 || m->period[1] > 0.0) {
        if (!(cast_looks(m, d, rad) <= 8192.0))
            return 0;
        if (m->rmin < 1e-6 * (m->period[0] + m->period[1]))
            return 0; /* millions of cells a period: the images of the grid's ring stay exact, but slow to brute-force */
    }
    memset(b, 0, sizeof *b);
    b->t_sure = HUGE_VAL;
    b->tol = 1e-9 * (S + m->period[0] + m->period[1] + 1.0) / (hypot(d.x, d.y) + rad + 1e-300);
    if (b->tol > 1e-3)
        return 0;
    lo[0] = d.x < 0.0 ? p.x + d.x : p.x, hi[0] = d.x < 0.0 ? p.x : p.x + d.x;
    lo[1] = d.y < 0.0 ? p.y + d.y : p.y, hi[1] = d.y < 0.0 ? p.y : p.y + d.y;
    for (i = 0; i < s->n; i++) {
        const cc_circle *c = &s->c[i];
        double R = rad + c->radius, a0, a1, a, k0, k1, kk;
        if (s->ids[i] == ignore || s->p[i].sensor || !(s->p[i].category & mask))
            continue;
        if (!(c->radius < 1e12 && fabs(c->pos.x) < 1e12 && fabs(c->pos.y) < 1e12))
            return 0;
        bf_range(m, 0, c->pos.x, lo[0], hi[0], R, &a0, &a1);
        for (a = a0; a <= a1; a++) {
            double qx = c->pos.x + a * m->period[0], y0 = lo[1], y1 = hi[1];
            if (m->period[0] > 0.0 && d.x != 0.0) { /* the part of the path within R of this column */
                double t0 = (qx - R - p.x) / d.x, t1 = (qx + R - p.x) / d.x, tt;
                if (t0 > t1)
                    tt = t0, t0 = t1, t1 = tt;
                t0 = t0 < 0.0 ? 0.0 : t0 > 1.0 ? 1.0 : t0;
                t1 = t1 < 0.0 ? 0.0 : t1 > 1.0 ? 1.0 : t1;
                y0 = p.y + t0 * d.y, y1 = p.y + t1 * d.y;
                if (y0 > y1)
                    tt = y0, y0 = y1, y1 = tt;
            }
            bf_range(m, 1, c->pos.y, y0, y1, R, &k0, &k1);
            for (kk = k0; kk <= k1; kk++)
                bf_image(b, p, rad, d, qx, c->pos.y + kk * m->period[1], c->radius, s->ids[i]);
        }
    }
    for (k = 0; k < m->nsegs; k++) {
        const cc_segment *g = &m->segs[k];
        if (!(m->segprops[k].category & mask))
            continue;
        if (!(fabs(g->a.x) + fabs(g->a.y) + fabs(g->b.x) + fabs(g->b.y) < 1e12))
            return 0;
        if (rad > 0.0) {
            cc_circle me;
            cc_contact h;
            int res;
            me.pos = p, me.vel = d, me.radius = rad, me.mass = 1.0;
            res = cc_sweep_segment(&me, g, 1.0, &h); /* the library's own call: the same answer */
            if (res == CC_HIT)
                bf_note(b, h.t, 1, k, h.t > b->tol && h.t < 1.0 - b->tol);
            else if (res == CC_OVERLAP)
                bf_note(b, 0.0, 1, k, 1);
        } else {
            double ux = g->b.x - g->a.x, uy = g->b.y - g->a.y, ax = g->a.x - p.x, ay = g->a.y - p.y;
            double den = d.x * uy - d.y * ux, t, v, e = 1e-9;
            if (den == 0.0) {
                if (ax * d.y - ay * d.x == 0.0)
                    return 0; /* a ray along the wall's own line */
                continue;
            }
            t = (ax * uy - ay * ux) / den;
            v = (ax * d.y - ay * d.x) / den;
            if (t >= -e && t <= 1.0 + e && v >= -e && v <= 1.0 + e)
                bf_note(b, t < 0.0 ? 0.0 : t, 1, k, t > e && t < 1.0 - e && v > e && v < 1.0 - e);
        }
    }
    return b->n >= 0;
}

/* The cast's answer against the brute force: nothing the brute force is sure of comes before it
 * (a miss: nothing sure at all), and what it names is among the brute force's contacts near its t. */
static void check_cast_brute(const model *m, const snap *s, cc_vec2 p, double rad, cc_vec2 d, uint32_t mask, int ignore,
                             int rc, const cc_cast_hit *out)
{
    static cast_bf b;
    int i, named = 0;
    double t = rc == CC_MISS ? HUGE_VAL : out->t, tol;
    if (!cast_brute(m, s, p, rad, d, mask, ignore, &b))
        return;
    fuzz_world_counted.casts_judged++;
    fuzz_world_counted.casts_judged_periodic += m->period[0] > 0.0 || m->period[1] > 0.0;
    tol = 1e3 * b.tol; /* the solver's answers in two frames: a few ulps of the numbers, far inside this */
    if (b.t_sure < t - tol) {
        fprintf(stderr, "fuzz_world: cast p (%.17g, %.17g) radius %.17g d (%.17g, %.17g): %s t %.17g, the brute force a contact at %.17g\n",
                p.x, p.y, rad, d.x, d.y, rc == CC_MISS ? "miss" : "hit", t, b.t_sure);
        fail(m, rc == CC_MISS ? "cast: missed a contact the brute force finds" : "cast: a later contact than the brute force's earliest");
    }
    if (rc == CC_MISS)
        return;
    for (i = 0; i < b.n && !named; i++)
        named = b.cand[i].wall == (out->segment >= 0) && b.cand[i].id == (out->segment >= 0 ? out->segment : out->circle) &&
                (!b.cand[i].sure || fabs(b.cand[i].t - t) <= tol);
    if (!named) {
        fprintf(stderr, "fuzz_world: cast p (%.17g, %.17g) radius %.17g d (%.17g, %.17g): %s %d at t %.17g, not among the brute force's contacts\n",
                p.x, p.y, rad, d.x, d.y, out->segment >= 0 ? "wall" : "circle", out->segment >= 0 ? out->segment : out->circle, t);
        fail(m, "cast: hit something the brute force does not touch");
    }
}

static void do_cast(model *m, reader *r, const snap *s)
{
    cc_cast_hit out, keep;
    cc_vec2 p, d;
    double rad;
    int rc, ignore;
    uint32_t mask = mask_and_ignore(r, &ignore);
    cc_query_filter f = filter_of(mask, ignore);
    p.x = value(r, K_POS), p.y = value(r, K_POS);
    d.x = 4.0 * value(r, K_VEL), d.y = 4.0 * value(r, K_VEL);
    rad = byte(r) & 1u ? value(r, K_RAD) : 0.0;
    memset(&out, (int)UNTOUCHED, sizeof out);
    keep = out;
    if (getenv("FUZZ_WORLD_TRACE"))
        fprintf(stderr, "cast p (%.17g, %.17g) radius %.17g d (%.17g, %.17g) mask %x\n", p.x, p.y, rad, d.x, d.y,
                (unsigned)mask);
    rc = ignore == -2 ? cc_world_cast_circle(m->w, p, rad, d, mask, &out)
                      : cc_world_cast_circle_filtered(m->w, p, rad, d, &f, &out);
    if (!isfinite(p.x) || !isfinite(p.y) || !isfinite(d.x) || !isfinite(d.y) || !isfinite(rad) || rad < 0.0) {
        REQUIRE(m, rc == CC_ERR_INVALID, "cast: invalid arguments not INVALID");
        REQUIRE(m, memcmp(&out, &keep, sizeof out) == 0, "cast: an invalid call wrote out");
        return;
    }
    REQUIRE(m, rc == CC_HIT || rc == CC_MISS || rc == CC_OVERLAP, "cast: a result outside HIT, MISS, OVERLAP");
    check_cast_brute(m, s, p, rad, d, mask, ignore, rc, &out);
    if (rc == CC_MISS) {
        REQUIRE(m, memcmp(&out, &keep, sizeof out) == 0, "cast: a miss wrote out");
        return;
    }
    REQUIRE(m, (out.circle >= 0) != (out.segment >= 0), "cast: neither or both of circle and segment");
    REQUIRE(m, out.t >= 0.0 && out.t <= 1.0, "cast: t outside [0, 1]");
    if (rc == CC_OVERLAP)
        REQUIRE(m, out.t == 0.0, "cast: an overlap with t != 0");
    REQUIRE(m, out.segment < m->nsegs, "cast: a wall that does not exist");
    if (out.circle >= 0) {
        REQUIRE(m, live_id(m, out.circle), "cast: hit a circle that is not live");
        REQUIRE(m, out.circle != ignore, "cast: hit the circle its filter leaves out");
        REQUIRE(m, !m->props[out.circle].sensor, "cast: hit a sensor");
        REQUIRE(m, (m->props[out.circle].category & mask) != 0, "cast: hit a circle its mask excludes");
    } else
        REQUIRE(m, (m->segprops[out.segment].category & mask) != 0, "cast: hit a wall its mask excludes");
    if (isfinite(hypot(out.normal.x, out.normal.y)))
        REQUIRE(m, fabs(hypot(out.normal.x, out.normal.y) - 1.0) <= 1e-6, "cast: normal not a unit vector");
}

/* Runs one call on m; returns 0 when the input is exhausted. */
static int one_call(model *m, reader *r, int op);

/* One cc_world_add_circle of c, its result checked against the model's rules (the header's) and
 * the model updated when it is added. Returns the result. */
static int add_checked(model *m, const cc_circle *cp)
{
    cc_circle c = *cp;
    int rc, expect = m->nfree > 0 ? m->freestack[m->nfree - 1] : m->next_new;
    uint64_t h0 = cc_world_hash(m->w);
    if (getenv("FUZZ_WORLD_TRACE"))
        fprintf(stderr, "add (%.17g, %.17g) v (%.17g, %.17g) r %.17g m %.17g\n", c.pos.x, c.pos.y, c.vel.x,
                c.vel.y, c.radius, c.mass);
    m->placing = c.mass;
    rc = cc_world_add_circle(m->w, &c);
    m->placing = 0.0;
    if (!circle_valid(&c))
        REQUIRE(m, rc == CC_ERR_INVALID, "add_circle: an invalid circle not INVALID");
    else if (m->count == m->maxc)
        REQUIRE(m, rc == CC_ERR_FULL || (!fits_period(m, &c) && rc == m->range_code), "add_circle: not FULL");
    else if (!fits_period(m, &c))
        REQUIRE(m, rc == m->range_code, "add_circle: a circle too wide for the period not RANGE");
    else
        REQUIRE(m, rc == expect, "add_circle: not the id the header's reuse rule gives");
    if (rc >= 0) {
        REQUIRE(m, rc < m->maxc && !m->live[rc], "add_circle: an id out of range or live");
        if (m->nfree > 0)
            m->nfree--;
        else
            m->next_new++;
        m->live[rc] = 1, m->count++;
        m->radius[rc] = c.radius, m->mass[rc] = c.mass;
        m->props[rc].struct_size = sizeof(cc_circle_props);
        m->props[rc].restitution = m->restitution;
        m->props[rc].rolling_decel = m->decel;
        m->props[rc].category = 1u, m->props[rc].mask = 0xFFFFFFFFu, m->props[rc].sensor = 0;
    } else
        REQUIRE(m, cc_world_hash(m->w) == h0, "add_circle: a failed call changed the world");
    return rc;
}

#define MAXB 8 /* circles in one batch add */

/* cc_world_add_circles of k circles (the header's Batches): the same k circles are first added
 * one cc_world_add_circle at a time to a memcpy of the world (each checked as OP_ADD is), then
 * in one call to the world itself, which must end exactly as the copy did: the same ids, the
 * same callbacks' events in the same order (bit for bit), the same hash. Or, when a single add
 * refused circle i, the batch must refuse with that add's code, write i to *failed, write no id,
 * fire no callback and change nothing. Bad arguments (n < 0, c NULL) are INVALID with failed -1.
 * Bytes: k (% 9), flags (bit 0: ids_out NULL, bit 1: failed NULL, bit 2: mostly valid circles
 * near the others, as OP_ADD2; bits 5-7 = 7: n = -1, = 6: c NULL), then the k circles. */
static void do_add_batch(model *m, reader *r, uint64_t h0)
{
    unsigned kb = byte(r), fl = byte(r);
    int k = (int)(kb % (MAXB + 1)), n = k, i, rc, at = -77, fail_at = -1, fail_code = 0, bad = 0;
    int ids[MAXB + 2], single[MAXB];
    cc_circle c[MAXB];
    double heavy = 0.0;
    uint64_t h_single, ev_single;
    int nev_single;
    unsigned char *copy;
    cc_world *orig = m->w;
    model keep;
    for (i = 0; i < k; i++) {
        c[i] = read_circle(r);
        if (fl & 4u)
            c[i].radius = fabs(c[i].radius) > 0.0 && isfinite(c[i].radius) ? fabs(c[i].radius) : 0.5,
            c[i].mass = c[i].mass > 0.0 ? c[i].mass : 1.0;
    }
    for (i = 0; i < k; i++)
        if (place_ub(m, &c[i]))
            return; /* D2 */
    for (i = 0; i < k; i++)
        if (!isnan(c[i].mass) && c[i].mass > heavy)
            heavy = c[i].mass;
    if ((fl >> 5) == 7u)
        n = -1 - (int)(kb % 3u), bad = 1;
    else if ((fl >> 5) == 6u && k > 0)
        bad = 1;
    keep = *m;
    h_single = h0, ev_single = UINT64_C(0xCBF29CE484222325), nev_single = 0;
    if (!bad) { /* the singles, on a copy */
        copy = (unsigned char *)malloc(m->bytes);
        if (copy == NULL)
            return;
        memcpy(copy, m->block + GUARD, m->bytes);
        m->w = (cc_world *)(void *)copy;
        m->evhash = UINT64_C(0xCBF29CE484222325), m->nev = 0, m->ncb = 0;
        for (i = 0; i < k; i++) {
            single[i] = add_checked(m, &c[i]);
            if (single[i] < 0) {
                fail_at = i, fail_code = single[i];
                break;
            }
        }
        h_single = cc_world_hash(m->w), ev_single = m->evhash, nev_single = m->nev;
        m->w = orig;
        free(copy);
        if (fail_at >= 0) { /* the model as it was: the batch must add none */
            keep.huge = m->huge, keep.rmin = m->rmin;
            *m = keep;
        }
    }
    for (i = 0; i < MAXB + 2; i++)
        ids[i] = -77;
    m->evhash = UINT64_C(0xCBF29CE484222325), m->nev = 0, m->ncb = 0;
    m->placing = heavy;
    if (getenv("FUZZ_WORLD_TRACE"))
        fprintf(stderr, "add_circles n %d%s%s%s\n", n, (fl >> 5) == 6u && k > 0 ? " c NULL" : "",
                fl & 1u ? " ids NULL" : "", fl & 2u ? " failed NULL" : "");
    rc = cc_world_add_circles(m->w, (fl >> 5) == 6u && k > 0 ? NULL : c, n, fl & 1u ? NULL : ids, fl & 2u ? NULL : &at);
    m->placing = 0.0;
    if (getenv("FUZZ_WORLD_TRACE"))
        fprintf(stderr, "add_circles: %d (failed %d; the singles: %d at %d)\n", rc, at, fail_code, fail_at);
    for (i = rc == k && !bad && fail_at < 0 ? k : 0; i < MAXB + 2; i++)
        REQUIRE(m, ids[i] == -77, "add_circles: wrote an id it was not to (beyond n, or on an error)");
    if (bad || fail_at >= 0) {
        REQUIRE(m, rc == (bad ? CC_ERR_INVALID : fail_code),
                bad ? "add_circles: n < 0 or c NULL not INVALID"
                    : "add_circles: not the code of the first circle cc_world_add_circle refuses");
        REQUIRE(m, (fl & 2u) || at == (bad ? -1 : fail_at), "add_circles: *failed not the index the single adds refused");
        REQUIRE(m, cc_world_hash(m->w) == h0, "add_circles: a refused batch changed the world (hash)");
        REQUIRE(m, m->nev == 0, "add_circles: a refused batch fired a callback");
        return;
    }
    REQUIRE(m, rc == k, "add_circles: not n where every single add was accepted");
    REQUIRE(m, at == -77, "add_circles: a success wrote *failed");
    if (!(fl & 1u))
        for (i = 0; i < k; i++)
            REQUIRE(m, ids[i] == single[i], "add_circles: ids not those of the single adds");
    REQUIRE(m, m->nev == nev_single && m->evhash == ev_single,
            "add_circles: the callbacks' events differ from the single adds' (count, order or bits)");
    REQUIRE(m, cc_world_hash(m->w) == h_single, "add_circles: the world differs from the single adds' (hash)");
}

/* cc_world_get_unwrapped_all: the live circles in id order, as cc_world_get_unwrapped gives
 * each, up to capacity, nothing written beyond (bytes: capacity - 1 (% 44), which of ids/out NULL). */
static void do_unwrapped_all(model *m, reader *r, const snap *s)
{
    int cap = (int)(byte(r) % 44u) - 1, which = (int)(byte(r) % 4u), n, i;
    int ids[MAXC + 4];
    cc_vec2 u[MAXC + 4];
    memset(ids, (int)UNTOUCHED, sizeof ids);
    memset(u, (int)UNTOUCHED, sizeof u);
    n = cc_world_get_unwrapped_all(m->w, which & 1 ? NULL : ids, which & 2 ? NULL : u, cap);
    if (cap < 0) {
        REQUIRE(m, n == CC_ERR_INVALID, "get_unwrapped_all: a negative capacity not INVALID");
        n = 0, cap = 0;
    } else
        REQUIRE(m, n == m->count, "get_unwrapped_all: not the number of live circles");
    REQUIRE(m, bytes_untouched((const unsigned char *)ids, (size_t)(n < cap ? n : cap) * sizeof(int), sizeof ids) &&
                   bytes_untouched((const unsigned char *)u, (size_t)(n < cap ? n : cap) * sizeof(cc_vec2), sizeof u),
            "get_unwrapped_all: wrote beyond the count or the capacity");
    for (i = 0; i < n && i < cap; i++) {
        cc_vec2 one;
        REQUIRE(m, cc_world_get_unwrapped(m->w, s->ids[i], &one) == CC_OK, "get_unwrapped of a live id");
        if (!(which & 1))
            REQUIRE(m, ids[i] == s->ids[i], "get_unwrapped_all: ids not the live ones in increasing order");
        if (!(which & 2))
            REQUIRE(m, memcmp(&u[i], &one, sizeof one) == 0, "get_unwrapped_all: not what get_unwrapped gives");
    }
}


static void copy_test(model *m, reader *r)
{
    /* the world copied (memcpy) to other memory works identically: the next call on both */
    model a = *m, b = *m, save_m = *m;
    reader ra = *r, rb = *r;
    unsigned op;
    if (r->n == 0)
        return;
    op = r->p[0] % OP_COUNT;
    if (op == OP_COPY)
        return;
    fuzz_world_counted.copies++;
    b.block = malloc(m->bytes + 2 * GUARD);
    if (b.block == NULL)
        return;
    fill_guards(b.block, b.bytes);
    memcpy(b.block + GUARD, m->block + GUARD, m->bytes);
    b.w = (cc_world *)(void *)(b.block + GUARD);
    REQUIRE(m, cc_world_hash(b.w) == cc_world_hash(m->w), "copy: the copy's hash differs at once");
    byte(&ra);
    one_call(&a, &ra, (int)op);
    byte(&rb);
    one_call(&b, &rb, (int)op);
    REQUIRE(m, cc_world_hash(a.w) == cc_world_hash(b.w), "copy: a memcpy'd world parted from the original");
    REQUIRE(m, cc_world_time(a.w) == cc_world_time(b.w), "copy: times differ");
    REQUIRE(m, memcmp(a.live, b.live, sizeof a.live) == 0 && a.nsegs == b.nsegs, "copy: the models differ");
    /* go on with the copy; the original's memory is scribbled over, to show nothing points there */
    memset(save_m.block + GUARD, 0x5A, save_m.bytes);
    free(save_m.block);
    *r = rb;
    *m = b;
}

static int one_call(model *m, reader *r, int op)
{
    snap before;
    int rc, id;
    uint64_t h0;
    g_cur = m;
    m->op = op;
    m->call_t0 = m->time;
    m->ncb = 0;
    check_world(m, &before);
    if (m->dead)
        return 0;
    h0 = cc_world_hash(m->w);
    fuzz_world_counted.calls++;
    {
        int i;
        double vmax = 0.0, tick = nextafter(fabs(m->time), INFINITY) - fabs(m->time);
        m->huge = 0;
        for (i = 0; i < before.n; i++) {
            if (!(fabs(before.c[i].pos.x) + fabs(before.c[i].pos.y) + fabs(before.c[i].vel.x) + fabs(before.c[i].vel.y) +
                      before.c[i].radius < 1e150)) /* (the radius too: D12, D14) */
                m->huge = 1;
            vmax = fmax(vmax, fabs(before.c[i].vel.x) + fabs(before.c[i].vel.y));
        }
        /* D18, D20 (the header's Range): a circle that crosses a cell (at least the smallest
         * diameter ever placed, or def.cell_size) within one ulp of the world time may be filed
         * ahead of its position; the flag stays for the rest of the input once set, because the
         * filing catches up only at the circle's next crossings */
        if (!(vmax * tick * 16.0 < fmax(2.0 * m->rmin, m->cell_size)))
            m->fast = 1;
    }
    if (getenv("FUZZ_WORLD_TRACE")) {
        int i;
        fprintf(stderr, "op %d at time %.17g, %d circles:\n", op, m->time, before.n);
        for (i = 0; i < before.n; i++)
            fprintf(stderr, "  %d: (%.17g, %.17g) v (%.17g, %.17g) r %.17g m %.17g%s\n", before.ids[i],
                    before.c[i].pos.x, before.c[i].pos.y, before.c[i].vel.x, before.c[i].vel.y, before.c[i].radius,
                    before.c[i].mass, before.p[i].sensor ? " sensor" : "");
    }
    switch (op) {
    case OP_ADD:
    case OP_ADD2: {
        cc_circle c = read_circle(r);
        if (op == OP_ADD2) /* mostly valid: a circle near the others, for collisions */
            c.radius = fabs(c.radius) > 0.0 && isfinite(c.radius) ? fabs(c.radius) : 0.5,
            c.mass = c.mass > 0.0 ? c.mass : 1.0;
        if (place_ub(m, &c))
            break; /* D2 */
        add_checked(m, &c);
        break;
    }
    case OP_ADD_BATCH: do_add_batch(m, r, h0); break;
    case OP_UNWRAPPED_ALL: do_unwrapped_all(m, r, &before); break;
    case OP_REMOVE:
        id = read_id(r, m);
        rc = cc_world_remove_circle(m->w, id);
        REQUIRE(m, rc == (live_id(m, id) ? CC_OK : CC_ERR_NOT_FOUND), "remove_circle: wrong result");
        if (rc == CC_OK) {
            m->live[id] = 0, m->count--;
            m->freestack[m->nfree++] = id;
        } else
            REQUIRE(m, cc_world_hash(m->w) == h0, "remove_circle: a failed call changed the world");
        break;
    case OP_SET: {
        cc_circle c;
        id = read_id(r, m);
        c = read_circle(r);
        if (byte(r) & 1u && live_id(m, id)) { /* often a nudge of the circle as it is */
            cc_circle now;
            cc_world_get_circle(m->w, id, &now);
            now.vel = c.vel;
            c = now;
        }
        if (place_ub(m, &c))
            break; /* D2 */
        m->placing = c.mass;
        rc = cc_world_set_circle(m->w, id, &c);
        m->placing = 0.0;
        if (!live_id(m, id))
            REQUIRE(m, rc == CC_ERR_NOT_FOUND || (!circle_valid(&c) && rc == CC_ERR_INVALID) ||
                           (circle_valid(&c) && !fits_period(m, &c) && rc == m->range_code),
                    "set_circle: a dead id not NOT_FOUND");
        else if (!circle_valid(&c))
            REQUIRE(m, rc == CC_ERR_INVALID, "set_circle: an invalid circle not INVALID");
        else if (!fits_period(m, &c))
            REQUIRE(m, rc == m->range_code, "set_circle: a circle too wide for the period not RANGE");
        else
            REQUIRE(m, rc == CC_OK, "set_circle: a valid call failed");
        if (rc == CC_OK)
            m->radius[id] = c.radius, m->mass[id] = c.mass;
        else
            REQUIRE(m, cc_world_hash(m->w) == h0, "set_circle: a failed call changed the world");
        break;
    }
    case OP_GET: {
        cc_circle out, keep;
        id = read_id(r, m);
        memset(&out, (int)UNTOUCHED, sizeof out);
        keep = out;
        rc = cc_world_get_circle(m->w, id, &out);
        REQUIRE(m, rc == (live_id(m, id) ? CC_OK : CC_ERR_NOT_FOUND), "get_circle: wrong result");
        if (rc != CC_OK)
            REQUIRE(m, memcmp(&out, &keep, sizeof out) == 0, "get_circle: an error wrote out");
        break;
    }
    case OP_ADD_SEG: {
        cc_segment s;
        s.a.x = value(r, K_POS), s.a.y = value(r, K_POS);
        s.b.x = byte(r) & 1u ? s.a.x : value(r, K_POS), s.b.y = value(r, K_POS);
        rc = cc_world_add_segment(m->w, &s);
        if (getenv("FUZZ_WORLD_TRACE"))
            fprintf(stderr, "add_segment (%.17g, %.17g) (%.17g, %.17g): %d\n", s.a.x, s.a.y, s.b.x, s.b.y, rc);
        if (!(isfinite(s.a.x) && isfinite(s.a.y) && isfinite(s.b.x) && isfinite(s.b.y)))
            REQUIRE(m, rc == CC_ERR_INVALID, "add_segment: an invalid wall not INVALID");
        else if (m->nsegs == m->maxs)
            REQUIRE(m, rc == CC_ERR_FULL, "add_segment: not FULL");
        else
            REQUIRE(m, rc == m->nsegs, "add_segment: not the next id");
        if (rc >= 0) {
            m->segs[rc] = s;
            m->segprops[rc].struct_size = sizeof(cc_segment_props);
            m->segprops[rc].restitution = m->restitution;
            m->segprops[rc].category = 1u, m->segprops[rc].mask = 0xFFFFFFFFu;
            m->nsegs++;
        } else
            REQUIRE(m, cc_world_hash(m->w) == h0, "add_segment: a failed call changed the world");
        break;
    }
    case OP_GET_SEG: {
        cc_segment out, keep;
        id = read_id(r, m) % (MAXS + 3);
        memset(&out, (int)UNTOUCHED, sizeof out);
        keep = out;
        rc = cc_world_get_segment(m->w, id, &out);
        if (id >= 0 && id < m->nsegs)
            REQUIRE(m, rc == CC_OK && memcmp(&out, &m->segs[id], sizeof out) == 0, "get_segment: not the wall added");
        else
            REQUIRE(m, rc == CC_ERR_NOT_FOUND && memcmp(&out, &keep, sizeof out) == 0, "get_segment: a missing wall");
        break;
    }
    case OP_SET_PROPS: do_props(m, r, 1); break;
    case OP_GET_PROPS: do_props(m, r, 0); break;
    case OP_SET_SEGPROPS: do_segprops(m, r, 1); break;
    case OP_GET_SEGPROPS: do_segprops(m, r, 0); break;
    case OP_STEP:
    case OP_STEP2: do_step(m, value(r, K_DT), &before); break;
    case OP_STEP_SMALL: do_step(m, 0.01 * (double)(byte(r) % 64u), &before); break;
    case OP_CAST: do_cast(m, r, &before); break;
    case OP_QUERY_CIRCLE: do_query(m, r, 0, &before); break;
    case OP_QUERY_BOX: do_query(m, r, 1, &before); break;
    case OP_HASH: REQUIRE(m, cc_world_hash(m->w) == h0, "hash: two calls differ"); break;
    case OP_STATS: do_stats(m, r); break;
    case OP_UNWRAPPED: {
        cc_vec2 u = {-7.0, -7.0};
        cc_circle c;
        id = read_id(r, m);
        rc = cc_world_get_unwrapped(m->w, id, &u);
        REQUIRE(m, rc == (live_id(m, id) ? CC_OK : CC_ERR_NOT_FOUND), "get_unwrapped: wrong result");
        if (rc != CC_OK)
            REQUIRE(m, u.x == -7.0 && u.y == -7.0, "get_unwrapped: an error wrote out");
        else {
            REQUIRE(m, cc_world_get_circle(m->w, id, &c) == CC_OK, "get_circle of a live id");
            if (m->period[0] == 0.0)
                REQUIRE(m, u.x == c.pos.x, "get_unwrapped: differs along an open axis");
            if (m->period[1] == 0.0)
                REQUIRE(m, u.y == c.pos.y, "get_unwrapped: differs along an open axis");
            REQUIRE(m, isfinite(u.x) && isfinite(u.y), "get_unwrapped: not finite");
        }
        break;
    }
    case OP_GET_CIRCLES: {
        int cap = (int)(byte(r) % 44u) - 1, n;
        int ids[MAXC + 4];
        memset(ids, 0xCD, sizeof ids);
        n = cc_world_get_circles(m->w, ids, NULL, cap);
        REQUIRE(m, cap < 0 ? n == CC_ERR_INVALID : n == m->count, "get_circles: wrong result");
        if (cap >= 0)
            REQUIRE(m, bytes_untouched((const unsigned char *)ids, (size_t)(n < cap ? n : cap) * sizeof(int), sizeof ids),
                    "get_circles: wrote beyond the count or the capacity");
        break;
    }
    case OP_COPY: copy_test(m, r); return 1;
    default: break;
    }
    if (!is_add(op) && op != OP_REMOVE && op != OP_SET && op != OP_ADD_SEG &&
        op != OP_SET_PROPS && op != OP_SET_SEGPROPS && op != OP_STEP && op != OP_STEP2 && op != OP_STEP_SMALL)
        REQUIRE(m, cc_world_hash(m->w) == h0, "a read-only call changed the world (hash)");
    m->op = -1;
    check_world(m, &before);
    return 1;
}

/* ---- the def ------------------------------------------------------------------------------------ */

static void check_init_fails(const cc_world_def *def, size_t bytes, size_t offset, int expect, const char *what)
{
    static double mem[4096 / 8 + 2];
    unsigned char *p = (unsigned char *)mem;
    int st = 12345;
    cc_world *w;
    if (bytes > 4096)
        return;
    memset(mem, (int)UNTOUCHED, sizeof mem);
    w = cc_world_init(p + offset, bytes, def, &st);
    REQUIRE(NULL, w == NULL && st == expect, what);
    REQUIRE(NULL, bytes_untouched(p, 0, sizeof mem), "a failed cc_world_init wrote into the memory");
}

void fuzz_world_one(const uint8_t *data, size_t size)
{
    reader r = {data, size};
    model *m = calloc(1, sizeof *m);
    struct { /* the def, with room for a later header's fields after it */
        cc_world_def def;
        unsigned char later[32];
    } xd;
    unsigned mode_b, flags, nz;
    int valid, in_range = 1, old_size, later, st = 0, ops;
    size_t bytes;
    if (m == NULL)
        return;
    fuzz_world_counted.inputs++;
    mode_b = byte(&r) % 8u;
    cc_world_def_init(&xd.def);
    xd.def.mode = mode_b == 7u ? 3 : (int)(mode_b % 3u);
    xd.def.max_circles = (int)(byte(&r) % (MAXC + 1));
    xd.def.max_segments = (int)(byte(&r) % (MAXS + 1));
    flags = byte(&r);
    nz = byte(&r);
    xd.def.restitution = value(&r, K_UNIT);
    xd.def.rest_speed = value(&r, K_SMALL);
    xd.def.cell_size = value(&r, K_SMALL);
    xd.def.rolling_decel = value(&r, K_SMALL) * 0.5;
    xd.def.period.x = value(&r, K_SMALL) * 6.0;
    xd.def.period.y = value(&r, K_SMALL) * 6.0;
    if (!(nz & 1u))
        xd.def.rest_speed = 0.0;
    if (!(nz & 2u))
        xd.def.cell_size = 0.0;
    if (!(nz & 12u))
        xd.def.rolling_decel = 0.0;
    if (!(flags & 4u))
        xd.def.period.x = 0.0;
    if (!(flags & 8u))
        xd.def.period.y = 0.0;
    {
        unsigned v = byte(&r);
        v = v * 256u + byte(&r);
        xd.def.max_events = v == 0xFFFFu ? 0u : 1u + v % 1000u;
    }
    xd.def.restitution_mix = nz & 0x80u ? 4 : (int)((flags >> 5) & 3u);
    {
        static const unsigned uses_of[4] = {CC_USES_ALL, 0u, CC_USES_SENSORS, CC_USES_PROPS | CC_USES_ROLLING};
        xd.def.uses = uses_of[(nz >> 4) & 3u];
    }
    xd.def.on_contact = flags & 1u ? on_contact : NULL;
    xd.def.on_sensor = flags & 2u ? on_sensor : NULL;
    xd.def.user = &g_user;
    old_size = (flags & 16u) != 0;
    memset(xd.later, 0x77, sizeof xd.later); /* what the library must not read as this def's */
    if (old_size)
        xd.def.struct_size = offsetof(cc_world_def, rolling_decel);
    else if (nz & 0x40u)
        xd.def.struct_size = sizeof xd;
    /* the 1.2 codes go to a def past 1.1's last field (the header's Results) */
    later = xd.def.struct_size > offsetof(cc_world_def, period) + sizeof(cc_vec2);
    m->range_code = later ? CC_ERR_RANGE : CC_ERR_INVALID;
    m->busy_code = later ? CC_ERR_BUSY : CC_ERR_INVALID;

    m->maxc = xd.def.max_circles, m->maxs = xd.def.max_segments, m->mode = xd.def.mode;
    m->restitution = xd.def.restitution, m->rest_speed = xd.def.rest_speed, m->cell_size = xd.def.cell_size;
    m->rmin = INFINITY, m->fast = 0;
    m->max_events = xd.def.max_events;
    if (m->max_events == 0 && later) /* a 1.2 def's automatic cap (the header's Collapse) */
        m->max_events = m->maxc > 312 ? 32u * (uint64_t)m->maxc : 10000u;
    m->has_contact_cb = xd.def.on_contact != NULL;
    m->uses = CC_USES_ALL;
    if (!old_size) {
        m->uses = xd.def.uses;
        m->decel = xd.def.rolling_decel, m->mix = xd.def.restitution_mix;
        m->period[0] = xd.def.period.x, m->period[1] = xd.def.period.y;
        m->has_sensor_cb = xd.def.on_sensor != NULL;
    } else {
        /* garbage the library must not read */
        xd.def.rolling_decel = -1.0, xd.def.restitution_mix = 99, xd.def.on_sensor = NULL;
        xd.def.period.x = NAN, xd.def.period.y = -3.0;
    }
    m->op = -1;
    valid = xd.def.mode >= 0 && xd.def.mode <= 2 && m->restitution >= 0.0 && m->restitution <= 1.0 &&
            m->rest_speed >= 0.0 && isfinite(m->rest_speed) && m->cell_size >= 0.0 && isfinite(m->cell_size) &&
            m->max_events >= 1 && m->decel >= 0.0 && isfinite(m->decel) && m->mix >= 0 && m->mix <= 3 &&
            !(m->decel > 0.0 && !(m->uses & CC_USES_ROLLING));
    {
        int k;
        for (k = 0; k < 2; k++) {
            double p = m->period[k];
            if (!(p == 0.0 || (p > 0.0 && isfinite(p))))
                valid = 0;
            else if (p > 0.0 && !(p > m->cell_size))
                in_range = 0; /* a period must hold a cell: beyond that limit */
        }
        bytes = cc_world_size(&xd.def);
    }
    /* a def too short to be one */
    {
        cc_world_def shortdef = xd.def;
        shortdef.struct_size = 8;
        REQUIRE(NULL, cc_world_size(&shortdef) == 0, "cc_world_size of a too short def not 0");
        check_init_fails(&shortdef, 4096, 0, CC_ERR_VERSION, "init with a too short def not VERSION");
    }
    if (!valid || !in_range) {
        REQUIRE(NULL, bytes == 0, "cc_world_size of an invalid def not 0");
        check_init_fails(&xd.def, 4096, 0, valid ? m->range_code : CC_ERR_INVALID,
                         valid ? "init with a period not wider than its cell not RANGE" : "init with an invalid def not INVALID");
        free(m);
        return;
    }
    REQUIRE(NULL, bytes > 0, "cc_world_size of a valid def is 0");
    check_init_fails(&xd.def, bytes - 1, 0, CC_ERR_MEMORY, "init with one byte too few not MEMORY");
    check_init_fails(&xd.def, bytes, 4, CC_ERR_MEMORY, "init with misaligned memory not MEMORY");
    {
        int s2 = 0;
        REQUIRE(NULL, cc_world_init(NULL, bytes, &xd.def, &s2) == NULL && s2 == CC_ERR_MEMORY, "init of NULL memory");
    }
    m->bytes = bytes;
    m->block = malloc(bytes + 2 * GUARD);
    if (m->block == NULL) {
        free(m);
        return;
    }
    fill_guards(m->block, bytes);
    memset(m->block + GUARD, 0x3C, bytes);
    m->w = cc_world_init(m->block + GUARD, bytes, &xd.def, &st);
    REQUIRE(m, m->w == (cc_world *)(void *)(m->block + GUARD) && st == CC_OK, "init of a valid def failed");
    REQUIRE(m, cc_world_time(m->w) == 0.0, "a new world's time is not 0");
    check_guards(m);
    m->stats.struct_size = sizeof m->stats;
    fuzz_world_counted.worlds++;
    if (getenv("FUZZ_WORLD_TRACE"))
        fprintf(stderr, "def: mode %d, %d circles, %d walls, restitution %.17g, rest_speed %.17g, cell_size %.17g, "
                        "max_events %llu, rolling %.17g, mix %d, period (%.17g, %.17g), callbacks %d %d, 1.0 size %d, "
                        "1.2 codes %d\n",
                m->mode, m->maxc, m->maxs, m->restitution, m->rest_speed, m->cell_size,
                (unsigned long long)m->max_events, m->decel, m->mix, m->period[0], m->period[1], m->has_contact_cb,
                m->has_sensor_cb, old_size, later);
    for (ops = 0; ops < MAX_OPS && r.n > 0 && !m->dead; ops++)
        one_call(m, &r, (int)(byte(&r) % OP_COUNT));
    g_cur = NULL;
    free(m->block);
    free(m);
}
