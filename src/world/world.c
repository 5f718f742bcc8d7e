/* The world's public API: def handling (the struct_size handshake), the memory layout carved
 * from the caller's buffer, validation, ids, and the circle/segment accessors. Stepping lives
 * in exact.c, swept.c and discrete.c. */
#include "world_internal.h"
#include "codes.h"
#include "walls.h"

#include "precision_double.h"
#include "helpers.inc"
#include "precision_end.h"

#define CC__SMALL_WORLD 32          /* up to this many circles: all pairs, no grid */
#define CC__MAX_CAPACITY (1 << 26)  /* keeps every size computation far from overflow */

/* The def's fields up to and including restitution: what every caller must send. */
#define CC__DEF_MIN (offsetof(cc_world_def, restitution) + sizeof(double))

/* The def of 1.0: its fields end at user. */
#define CC__DEF_1_0 (offsetof(cc_world_def, user) + sizeof(void *))

/* max_events of a def from a 1.0 or 1.1 header, which its programs rely on for long offline steps. */
#define CC__EVENTS_1_1 10000000u

/* The automatic cap of a 1.2 def (max_events = 0): CC__EVENTS_PER_CIRCLE events per circle of
 * max_circles, at least CC__EVENTS_MIN, so that a step that jams returns within a game's patience
 * (the header's "Collapse" has the measured costs) while an ordinary step never meets it. */
#define CC__EVENTS_PER_CIRCLE 32u
#define CC__EVENTS_MIN 10000u

static uint64_t cc__auto_events(int max_circles)
{
    uint64_t n = (uint64_t)CC__EVENTS_PER_CIRCLE * (uint64_t)(max_circles > 0 ? max_circles : 0);
    return n > CC__EVENTS_MIN ? n : CC__EVENTS_MIN;
}

/* Every default into a whole def of this library's size. */
static void cc__def_defaults(cc_world_def *def)
{
    memset(def, 0, sizeof *def);
    def->struct_size = sizeof *def;
    def->max_circles = 64;
    def->max_segments = 0;
    def->mode = CC_MODE_EXACT;
    def->restitution = 1.0;
    def->rest_speed = 0.0;
    def->cell_size = 0.0;
    def->max_events = 0; /* automatic, from max_circles (a 1.0 or 1.1 def: CC__EVENTS_1_1) */
    def->on_contact = NULL;
    def->user = NULL;
    def->rolling_decel = 0.0;
    def->restitution_mix = CC_MIX_MIN;
    def->on_sensor = NULL;
    def->period.x = 0.0;
    def->period.y = 0.0;
    def->uses = CC_USES_ALL;
}



/* Where each field of the def ends: the struct_size handshake of def_init_sized and read_def. */
static const size_t cc__def_ends[] = {
    CC__END(cc_world_def, struct_size), CC__END(cc_world_def, max_circles),
    CC__END(cc_world_def, max_segments), CC__END(cc_world_def, mode),
    CC__END(cc_world_def, restitution), CC__END(cc_world_def, rest_speed),
    CC__END(cc_world_def, cell_size), CC__END(cc_world_def, max_events),
    CC__END(cc_world_def, on_contact), CC__END(cc_world_def, user),
    CC__END(cc_world_def, rolling_decel), CC__END(cc_world_def, restitution_mix),
    CC__END(cc_world_def, on_sensor), CC__END(cc_world_def, period), CC__END(cc_world_def, uses)};

CC_API void cc_world_def_init_sized(cc_world_def *def, size_t struct_size)
{
    cc_world_def d;
    if (def == NULL || struct_size < CC__DEF_1_0)
        return;
    cc__def_defaults(&d);
    /* a def larger than this library's (a newer header): its unknown tail zeroed */
    if (struct_size > sizeof d)
        memset((unsigned char *)def + sizeof d, 0, struct_size - sizeof d);
    else
        memset(def, 0, struct_size);
    if (!cc__def_knows_1_2(struct_size))
        d.max_events = CC__EVENTS_1_1;
    memcpy(def, &d, cc__whole_fields(struct_size, cc__def_ends, (int)(sizeof cc__def_ends / sizeof cc__def_ends[0])));
    def->struct_size = struct_size;
}

/* The function a program built against 1.0 calls (the header's macro of this name calls
 * cc_world_def_init_sized): 1.0's def, no more. */
CC_API void(cc_world_def_init)(cc_world_def *def)
{
    cc_world_def_init_sized(def, CC__DEF_1_0);
}

size_t cc__whole_fields(size_t n, const size_t *ends, int count)
{
    size_t fit = 0;
    int i;
    for (i = 0; i < count && ends[i] <= n; i++)
        fit = ends[i];
    return fit;
}


/* A period: 0 (open), or finite and > 0. */
static int cc__period_ok(double p) { return p == 0.0 || (p > 0.0 && isfinite(p)); }

/* A period wider than def.cell_size ("at least twice the largest diameter plus a cell": the
 * diameters are checked as circles arrive, cc__fits_period); 0 is an open axis. */
static int cc__period_holds_cell(double p, double cell_hint) { return p == 0.0 || p > cell_hint; }

/* The caller's def over our defaults: fields beyond its struct_size (and a field it cuts) keep
 * their default. */
static int cc__read_def(const cc_world_def *in, cc_world_def *out)
{
    if (in == NULL)
        return CC_ERR_INVALID;
    if (in->struct_size < CC__DEF_MIN)
        return CC_ERR_VERSION;
    cc__def_defaults(out);
    if (!cc__def_knows_1_2(in->struct_size))
        out->max_events = CC__EVENTS_1_1; /* also for a def that ends before max_events */
    memcpy(out, in, cc__whole_fields(in->struct_size, cc__def_ends, (int)(sizeof cc__def_ends / sizeof cc__def_ends[0])));
    out->struct_size = sizeof *out;
    if (out->max_circles < 0 || out->max_segments < 0 || out->mode < CC_MODE_EXACT || out->mode > CC_MODE_DISCRETE ||
        !(out->restitution >= 0.0 && out->restitution <= 1.0) ||
        !(out->rest_speed >= 0.0 && isfinite(out->rest_speed)) ||
        !(out->cell_size >= 0.0 && isfinite(out->cell_size)) ||
        (out->max_events == 0 && !cc__def_knows_1_2(in->struct_size)) ||
        !(out->rolling_decel >= 0.0 && isfinite(out->rolling_decel)) || out->restitution_mix < CC_MIX_MIN ||
        out->restitution_mix > CC_MIX_MEAN || !cc__period_ok(out->period.x) || !cc__period_ok(out->period.y) ||
        (out->uses & ~CC_USES_ALL) != 0 || (out->rolling_decel > 0.0 && !(out->uses & CC_USES_ROLLING)))
        return CC_ERR_INVALID;
    /* beyond the documented limits: the capacities (where size_t has 32 bits they must also leave
     * the byte count representable), a period not wider than the cell it must hold */
    if (out->max_circles > CC__MAX_CAPACITY || out->max_segments > CC__MAX_CAPACITY ||
        (size_t)out->max_circles > (SIZE_MAX - 65536u) / 1024u ||
        (size_t)out->max_segments > (SIZE_MAX - 65536u) / 1024u || !cc__period_holds_cell(out->period.x, out->cell_size) ||
        !cc__period_holds_cell(out->period.y, out->cell_size))
        return cc__code_for_def(in->struct_size, CC_ERR_RANGE);
    return CC_OK;
}

/* The block's start needs the alignment of its widest members (double, uint64_t): 8 bytes, what
 * malloc gives on 32-bit systems and a static double array has on a microcontroller. The parts
 * inside are laid out at multiples of 16 from the start, which costs nothing and keeps them
 * line-friendly where the block happens to be 16-aligned. */
#define CC_WORLD_ALIGN 8u
static size_t cc__align16(size_t n) { return (n + 15u) & ~(size_t)15u; }

/* A periodic world always has a grid: its cells are how the images of a circle's neighbours
 * are found. */
static int cc__uses_grid(const cc_world_def *d)
{
    return d->max_circles > CC__SMALL_WORLD || d->period.x > 0.0 || d->period.y > 0.0;
}

/* Hash slots: a power of two >= 2 * max_circles (load <= 1/2) and >= 64, 0 for a world without grid. */
static uint32_t cc__slots(const cc_world_def *d)
{
    uint32_t s = 64;
    if (!cc__uses_grid(d))
        return 0;
    while (s < 2u * (uint32_t)d->max_circles)
        s <<= 1;
    return s;
}

/* Whether a world of this def reserves the properties' blocks (circles' and walls'). */
static int cc__def_props(const cc_world_def *d)
{
    return (d->uses & (CC_USES_PROPS | CC_USES_SENSORS | CC_USES_ROLLING)) != 0;
}

/* Fills the offsets of w (when not NULL) and returns the total size. A block of no bytes (not
 * reserved) that the world tells apart by its offset gets offset 0. */
static size_t cc__layout(const cc_world_def *d, cc_world *w)
{
    size_t n = (size_t)d->max_circles, off = cc__align16(sizeof(cc_world));
    size_t offs[18], sizes[18];
    int props = cc__def_props(d), periodic = d->period.x > 0.0 || d->period.y > 0.0;
    int cal_nb = cc__calendar_buckets(d->mode, d->max_circles);
    int clu_b, clu_c;
    int k;
    sizes[0] = n * sizeof(cc__body);
    sizes[1] = n * sizeof(cc__event);
    sizes[2] = n * sizeof(cc__cold);
    sizes[3] = n * sizeof(cc__heap_entry); /* heap */
    sizes[4] = (cal_nb > 0 ? 3 : 1) * n * sizeof(int32_t); /* heap positions (and calendar links) */
    sizes[5] = n * sizeof(int32_t); /* touched list */
    sizes[6] = (size_t)cc__slots(d) * sizeof(int32_t);
    sizes[7] = (size_t)d->max_segments * sizeof(cc_segment);
    sizes[8] = n * sizeof(int32_t);  /* id -> index */
    sizes[9] = 0; /* index -> id: in the events (cc__idx2id) */
    sizes[10] = cc__cluster_block(d->max_circles, d->mode, &clu_b, &clu_c); /* EXACT's clusters */
    sizes[11] = props ? n * sizeof(cc__props) : 0;
    sizes[12] = props ? (size_t)d->max_segments * sizeof(cc__segment_props) : 0;
    sizes[13] = (size_t)d->max_segments * sizeof(cc__wall_box);        /* the walls' tree */
    sizes[14] = 2 * (size_t)d->max_segments * sizeof(cc__wall_node);
    sizes[15] = (size_t)d->max_segments * sizeof(int32_t);
    sizes[16] = cal_nb > 0 ? ((size_t)cal_nb + 1) * sizeof(int32_t) : 0; /* the calendar's buckets */
    sizes[17] = periodic ? 2 * n * sizeof(int32_t) : 0; /* the turns of a periodic world */
    for (k = 0; k < 18; k++) {
        offs[k] = off;
        off += cc__align16(sizes[k]);
    }
    if (w != NULL) {
        w->off_body = offs[0];
        w->off_ev = offs[1];
        w->off_cold = offs[2];
        w->off_heap = offs[3];
        w->off_hpos = offs[4];
        w->off_touched = offs[5];
        w->off_slot = offs[6];
        w->off_seg = offs[7];
        w->off_id2idx = offs[8];
        w->off_clu = offs[10];
        w->off_props = props ? offs[11] : 0;
        w->off_segprops = props ? offs[12] : 0;
        w->off_wrap = periodic ? offs[17] : 0;
        w->uses = d->uses;
        w->off_wallbox = offs[13];
        w->off_wallnode = offs[14];
        w->off_wallorder = offs[15];
        w->off_calhead = offs[16];
        w->off_callink = offs[4] + sizeof(int32_t);
        w->hpos_stride = cal_nb > 0 ? 3 : 1;
        w->cal_nb = cal_nb;
        w->clu_bodies = clu_b;
        w->clu_contacts = clu_c;
    }
    return off;
}

CC_API size_t cc_world_size(const cc_world_def *def)
{
    cc_world_def d;
    if (cc__read_def(def, &d) != CC_OK)
        return 0;
    return cc__layout(&d, NULL);
}

CC_API cc_world *cc_world_init(void *memory, size_t bytes, const cc_world_def *def, int *status)
{
    cc_world_def d;
    cc_world *w;
    int r = cc__read_def(def, &d);
    if (r == CC_OK && (memory == NULL || ((uintptr_t)memory & (CC_WORLD_ALIGN - 1u)) != 0 ||
                        bytes < cc__layout(&d, NULL)))
        r = CC_ERR_MEMORY;
    if (status != NULL)
        *status = r;
    if (r != CC_OK)
        return NULL;
    w = (cc_world *)memory;
    memset(w, 0, sizeof *w);
    w->magic = CC__WORLD_MAGIC;
    w->mode = d.mode;
    w->max_circles = d.max_circles;
    w->max_segments = d.max_segments;
    w->restitution = d.restitution;
    w->rest_speed = d.rest_speed;
    w->cell_hint = d.cell_size;
    w->max_events = d.max_events != 0 ? d.max_events : cc__auto_events(d.max_circles);
    w->on_contact = d.on_contact;
    w->user = d.user;
    w->on_sensor = d.on_sensor;
    w->rolling_decel = d.rolling_decel;
    w->mix = d.restitution_mix;
    w->features = d.rolling_decel > 0.0 ? CC__F_ROLL : 0;
    if (d.restitution_mix == CC_MIX_PRODUCT && d.restitution != 0.0 && d.restitution != 1.0)
        w->features |= CC__F_RESTITUTION; /* even two defaults make e^2, not e */
    w->now = 0.0;
    w->use_grid = cc__uses_grid(&d);
    w->slot_mask = cc__slots(&d) - 1u;
    w->period[0] = d.period.x;
    w->period[1] = d.period.y;
    if (d.period.x > 0.0 || d.period.y > 0.0)
        w->features |= CC__F_PERIODIC;
    w->reach = 2.0 * (d.period.x > d.period.y ? d.period.x : d.period.y); /* see cc__reach_floor */
    {
        uint32_t bits = 0;
        while (bits < 31 && (1u << (bits + 1)) <= w->slot_mask + 1u)
            bits++;
        w->tile_bits_x = (bits + 1) / 2; /* a square tile (or twice as wide) of all the slots */
        w->tile_bits_y = bits / 2;
    }
    w->dirty = 1;
    w->large_head = -1;
    cc__world_note_def(w, def->struct_size);
    (void)cc__layout(&d, w);
    {
        int32_t *hpos = CC__ARR(w, int32_t, off_hpos);
        int i;
        for (i = 0; i < d.max_circles; i++)
            hpos[i * w->hpos_stride] = -1;
        cc__queue_clear(w);
    }
    if (w->use_grid)
        cc__grid_clear(w);
    return w;
}

static int cc__world_ok(const cc_world *w) { return w != NULL && w->magic == CC__WORLD_MAGIC; }

/* The storage index of live circle id, or -1. */
static int cc__live(const cc_world *w, int id)
{
    int k;
    if (id < 0 || id >= w->id_end)
        return -1;
    k = CC__CARR(w, int32_t, off_id2idx)[id];
    return (CC__CARR(w, cc__cold, off_cold)[k].flags & CC__ALIVE) ? k : -1;
}

/* Cell size for the current circles: at least the largest movable diameter (so that touching
 * circles are never more than one cell apart), with a margin against rounding of the cells;
 * the caller's cell_size when larger. */
double cc__world_cell_size(const cc_world *w)
{
    const cc__body *b = CC__CARR(w, cc__body, off_body);
    const cc__cold *k = CC__CARR(w, cc__cold, off_cold);
    double dmax = 0.0, any = 0.0, cs;
    int i;
    const cc__props *P = CC__CARR(w, cc__props, off_props);
    for (i = 0; i < w->id_end; i++) {
        if (!(k[i].flags & CC__ALIVE))
            continue;
        /* a sensor, even a moving one, touches nothing: wider than the cells, it goes on the
         * large list instead of widening them */
        if (!isinf(k[i].m) && 2.0 * b[i].r > dmax && !((w->features & CC__F_SENSOR) && P[i].sensor >= 0))
            dmax = 2.0 * b[i].r;
        if (2.0 * b[i].r > any)
            any = 2.0 * b[i].r;
    }
    if (dmax == 0.0)
        dmax = any > 0.0 ? any : 1.0;
    cs = dmax * 1.0625;
    return w->cell_hint > cs ? w->cell_hint : cs;
}

/* Writes c into the body at storage index id at the current time and files it. */
static void cc__put(cc_world *w, int id, const cc_circle *c)
{
    cc__body *b = &CC__ARR(w, cc__body, off_body)[id];
    cc__cold *k = &CC__ARR(w, cc__cold, off_cold)[id];
    if (w->off_wrap != 0) { /* where it is put is its unwrapped position (cc__wrap_body) */
        CC__ARR(w, int32_t, off_wrap)[2 * id] = 0;
        CC__ARR(w, int32_t, off_wrap)[2 * id + 1] = 0;
    }
    b->px = c->pos.x;
    b->py = c->pos.y;
    b->vx = c->vel.x;
    b->vy = c->vel.y;
    b->t = w->now;
    b->r = c->radius;
    b->count++;
    if (w->features & CC__F_PERIODIC) /* its image within the period (the turns counted), so that */
        cc__wrap_body(w, id);         /* queries and casts see it there before it is filed (D19) */
    cc__reach_note(w, b);
    k->m = c->mass;
    k->flags = CC__ALIVE;
    if (w->features & CC__F_ROLL)
        cc__roll_reset(w, id);
    else if (cc__props_reserved(w))
        CC__ARR(w, cc__props, off_props)[id].roll = 0.0; /* (read once friction comes: it starts
                                                             with the state written now) */
    /* EXACT: wider than the cells allow, the cell size grows and everything is refiled at the
     * next step (the other modes rebuild their grid every step) */
    if (w->mode == CC_MODE_EXACT && !w->dirty && w->use_grid && 2.0 * c->radius * 1.0625 > w->cs)
        w->dirty = 1;
    cc__settle_body(w, id);
}

/* cc__put with the world marked busy: in EXACT a circle put on top of others is pushed apart and
 * may take an impulse at once, which calls on_contact; from there the mutators must be refused
 * exactly as during a step (the grid and queue are being updated). */
static void cc__put_guarded(cc_world *w, int id, const cc_circle *c)
{
    cc__enter(w);
    cc__put(w, id, c);
    cc__leave(w);
}

/* Periodic: a circle must leave room for its images ("at least twice the largest diameter plus
 * a cell" along each periodic axis; the cell is at least 1.0625 diameters, or def.cell_size). */
static int cc__fits_period(const cc_world *w, const cc_circle *c)
{
    double d = 2.0 * c->radius, cell = 1.0625 * d > w->cell_hint ? 1.0625 * d : w->cell_hint;
    int k;
    for (k = 0; k < 2; k++)
        if (w->period[k] > 0.0 && !(2.0 * d + cell <= w->period[k]))
            return 0;
    return 1;
}

/* What add and set refuse before anything changes: CC_OK or the code. */
static int cc__put_refused(const cc_world *w, const cc_circle *c)
{
    if (!cc__world_ok(w) || !cc__circle_ok(c))
        return CC_ERR_INVALID;
    if (cc__busy(w))
        return cc__world_code(w, CC_ERR_BUSY);
    if (!cc__fits_period(w, c))
        return cc__world_code(w, CC_ERR_RANGE);
    return CC_OK;
}

CC_API int cc_world_add_circle(cc_world *w, const cc_circle *c)
{
    int id, r = cc__put_refused(w, c);
    if (r != CC_OK)
        return r;
    if (w->n_circles >= w->max_circles)
        return CC_ERR_FULL;
    cc__world_own(w);
    if (w->free_top > 0) { /* the last removed id (it keeps its storage index), off the free stack */
        id = w->free_head;
        w->free_head = CC__CARR(w, cc__cold, off_cold)[CC__CARR(w, int32_t, off_id2idx)[id]].prev;
        w->free_top--;
    } else {
        id = w->id_end++;
        CC__ARR(w, int32_t, off_id2idx)[id] = id;
        CC__ARR(w, cc__event, off_ev)[id].id = id;
        CC__ARR(w, cc__body, off_body)[id].count = 0; /* first use of this slot of memory */
    }
    w->n_circles++;
    if (cc__props_reserved(w))
        cc__props_default(w, &CC__ARR(w, cc__props, off_props)[CC__ARR(w, int32_t, off_id2idx)[id]]);
    cc__put_guarded(w, CC__ARR(w, int32_t, off_id2idx)[id], c);
    return id;
}

/* The batch is checked whole before anything is added (each circle as cc_world_add_circle
 * checks it, and the room for all of them), so that a refusal changes nothing; then each is
 * added by cc_world_add_circle, which cannot refuse it any more. */
CC_API int cc_world_add_circles(cc_world *w, const cc_circle *c, int n, int *ids_out, int *failed)
{
    int i, id;
    if (!cc__world_ok(w) || n < 0 || (c == NULL && n > 0)) {
        if (failed != NULL)
            *failed = -1;
        return CC_ERR_INVALID;
    }
    if (cc__busy(w)) { /* no one circle is at fault */
        if (failed != NULL)
            *failed = -1;
        return cc__world_code(w, CC_ERR_BUSY);
    }
    for (i = 0; i < n; i++) {
        int r = cc__put_refused(w, &c[i]);
        if (r == CC_OK && i >= w->max_circles - w->n_circles)
            r = CC_ERR_FULL;
        if (r != CC_OK) {
            if (failed != NULL)
                *failed = i;
            return r;
        }
    }
    for (i = 0; i < n; i++) {
        id = cc_world_add_circle(w, &c[i]);
        if (ids_out != NULL)
            ids_out[i] = id;
    }
    return n;
}

/* Takes body id out of the grid and the queue; its count bump makes others' events stale. */
static void cc__unfile(cc_world *w, int id)
{
    if (w->mode == CC_MODE_EXACT && !w->dirty) {
        cc__queue_remove(w, id);
        cc__grid_remove(w, id);
    }
    CC__ARR(w, cc__body, off_body)[id].count++;
    CC__ARR(w, cc__cold, off_cold)[id].flags &= ~CC__LARGE;
}

CC_API int cc_world_set_circle(cc_world *w, int id, const cc_circle *c)
{
    int k, r = cc__put_refused(w, c);
    if (r != CC_OK)
        return r;
    if ((k = cc__live(w, id)) < 0)
        return CC_ERR_NOT_FOUND;
    cc__world_own(w);
    cc__unfile(w, k);
    cc__put_guarded(w, k, c);
    return CC_OK;
}

CC_API int cc_world_remove_circle(cc_world *w, int id)
{
    int k;
    if (!cc__world_ok(w))
        return CC_ERR_INVALID;
    if (cc__busy(w))
        return cc__world_code(w, CC_ERR_BUSY);
    if ((k = cc__live(w, id)) < 0)
        return CC_ERR_NOT_FOUND;
    cc__world_own(w);
    cc__unfile(w, k);
    cc__sensor_forget(w, k, 1); /* a removed circle's overlaps are forgotten, not reported */
    CC__ARR(w, cc__cold, off_cold)[k].flags = 0;
    CC__ARR(w, cc__cold, off_cold)[k].prev = w->free_head; /* onto the free stack */
    w->free_head = id;
    w->free_top++;
    w->n_circles--;
    return CC_OK;
}

CC_API int cc_world_add_segment(cc_world *w, const cc_segment *s)
{
    if (!cc__world_ok(w) || !cc__segment_ok(s))
        return CC_ERR_INVALID;
    if (cc__busy(w))
        return cc__world_code(w, CC_ERR_BUSY);
    if (w->n_segments >= w->max_segments)
        return CC_ERR_FULL;
    cc__world_own(w);
    CC__ARR(w, cc_segment, off_seg)[w->n_segments] = *s;
    if (cc__props_reserved(w)) {
        cc__segment_props *q = &CC__ARR(w, cc__segment_props, off_segprops)[w->n_segments];
        q->restitution = w->restitution;
        q->category = 1u;
        q->mask = 0xFFFFFFFFu;
    }
    w->dirty = 1; /* every body may now meet it: predictions are redone at the next step */
    return w->n_segments++;
}

static void cc__get(const cc_world *w, int id, cc_circle *out)
{
    const cc__body *b = &CC__CARR(w, cc__body, off_body)[id];
    out->pos.x = cc__bx(w, b, w->now);
    out->pos.y = cc__by(w, b, w->now);
    out->vel.x = b->vx;
    out->vel.y = b->vy;
    if (w->features & CC__F_ROLL) { /* slowed since its state was written */
        double x, y, k;
        cc__roll_state(w, id, w->now, &x, &y, &out->vel.x, &out->vel.y, &k);
    }
    if (w->features & CC__F_PERIODIC) { /* within the period, where its lazy state may have left it */
        int32_t turns;
        if (w->period[0] > 0.0)
            out->pos.x = cc__wrap_coord(w, out->pos.x, 0, &turns);
        if (w->period[1] > 0.0)
            out->pos.y = cc__wrap_coord(w, out->pos.y, 1, &turns);
    }
    out->radius = b->r;
    out->mass = CC__CARR(w, cc__cold, off_cold)[id].m;
}

CC_API int cc_world_get_circle(const cc_world *w, int id, cc_circle *out)
{
    int k;
    if (!cc__world_ok(w) || out == NULL)
        return CC_ERR_INVALID;
    if ((k = cc__live(w, id)) < 0)
        return CC_ERR_NOT_FOUND;
    cc__get(w, k, out);
    return CC_OK;
}

/* The unwrapped position of the body at storage index k: its lazy position plus the periods
 * counted off it. */
static void cc__unwrapped(const cc_world *w, int k, cc_vec2 *out)
{
    const cc__body *b = &CC__CARR(w, cc__body, off_body)[k];
    const int32_t *turns = w->off_wrap != 0 ? &CC__CARR(w, int32_t, off_wrap)[2 * k] : NULL;
    out->x = cc__bx(w, b, w->now) + (turns != NULL ? (double)turns[0] * w->period[0] : 0.0);
    out->y = cc__by(w, b, w->now) + (turns != NULL ? (double)turns[1] * w->period[1] : 0.0);
}

CC_API int cc_world_get_unwrapped(const cc_world *w, int id, cc_vec2 *out)
{
    int k;
    if (!cc__world_ok(w) || out == NULL)
        return CC_ERR_INVALID;
    if ((k = cc__live(w, id)) < 0)
        return CC_ERR_NOT_FOUND;
    cc__unwrapped(w, k, out);
    return CC_OK;
}

/* What the bulk readers share: the live circles in increasing id order, the first capacity of
 * them written (their ids into ids, their row by put into out, either skipped when NULL); the
 * number of live circles. */
typedef void (*cc__row_fn)(const cc_world *w, int k, void *out, int row);

static void cc__circle_row(const cc_world *w, int k, void *out, int row) { cc__get(w, k, (cc_circle *)out + row); }
static void cc__unwrapped_row(const cc_world *w, int k, void *out, int row) { cc__unwrapped(w, k, (cc_vec2 *)out + row); }

static int cc__live_rows(const cc_world *w, int *ids, void *out, int capacity, cc__row_fn put)
{
    int i, k = 0, idx;
    if (!cc__world_ok(w) || capacity < 0)
        return CC_ERR_INVALID;
    for (i = 0; i < w->id_end; i++) {
        if ((idx = cc__live(w, i)) < 0)
            continue;
        if (k < capacity) {
            if (ids != NULL)
                ids[k] = i;
            if (out != NULL)
                put(w, idx, out, k);
        }
        k++;
    }
    return k;
}

CC_API int cc_world_get_unwrapped_all(const cc_world *w, int *ids, cc_vec2 *out, int capacity)
{
    return cc__live_rows(w, ids, out, capacity, cc__unwrapped_row);
}

CC_API int cc_world_get_circles(const cc_world *w, int *ids, cc_circle *out, int capacity)
{
    return cc__live_rows(w, ids, out, capacity, cc__circle_row);
}

CC_API int cc_world_get_segment(const cc_world *w, int id, cc_segment *out)
{
    if (!cc__world_ok(w) || out == NULL)
        return CC_ERR_INVALID;
    if (id < 0 || id >= w->n_segments)
        return CC_ERR_NOT_FOUND;
    *out = CC__CARR(w, cc_segment, off_seg)[id];
    return CC_OK;
}

CC_API double cc_world_time(const cc_world *w) { return cc__world_ok(w) ? w->now : (double)NAN; }
