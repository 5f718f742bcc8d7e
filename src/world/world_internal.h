/* Private to the world: its memory layout inside the caller's buffer and the functions that the
 * world's source files share. Never installed.
 *
 * Everything lives in the one block given to cc_world_init: the cc_world header first, then
 * arrays found through byte offsets from the header (never pointers), so that the world holds no
 * address at all and works the same wherever the caller put it. */
#ifndef CC_WORLD_INTERNAL_H
#define CC_WORLD_INTERNAL_H

#include "cc_internal.h"

#include <stdint.h>

/* A circle's state, kept lazily: it is at (px, py) at its own time t and moves at (vx, vy) from
 * there, so that an event touches only the bodies it involves. With its grid cell and list link
 * beside it, this is everything a neighbour search reads: one 64-byte cache line per circle. */
typedef struct cc__body {
    double px, py, vx, vy;
    double t;       /* the time at which (px, py) holds */
    double r;       /* radius */
    int32_t cx, cy; /* grid cell */
    int32_t next;   /* next circle filed under the same hash slot (or on the large list) */
    uint32_t count; /* bumped whenever the trajectory changes: invalidates others' events */
} cc__body;

/* What the neighbour search does not need. */
typedef struct cc__cold {
    double m;       /* mass, +INFINITY for an immovable circle */
    int32_t flags;  /* CC__ALIVE, CC__LARGE, ... */
    int32_t prev;   /* previous circle in its list, -1 for the first; a removed circle: the id
                       removed before it (the free stack, world.c) */
} cc__cold;

/* Per-body properties and rolling: what only a world that uses those features reads, kept apart
 * so that the hot and cold lines of a world without them are as in 1.0. Reserved only when the
 * def's uses lists PROPS, SENSORS or ROLLING (off_props != 0, with the walls' props beside it);
 * a world without the block reads the defaults instead (cc__props_reserved). Storage order, like
 * the others (sort.c permutes it). */
typedef struct cc__props {
    double restitution;
    double decel;       /* rolling deceleration; 0 for an immovable circle */
    double roll;        /* the rolling coefficient of its lazy state: decel / (2 |v|) at b->t
                           (0: straight motion, or at rest); see roll.c */
    uint64_t inside;    /* the sensors (by slot) this circle overlaps now */
    uint32_t category, mask;
    int32_t sensor;     /* its sensor slot, or -1 */
} cc__props;

/* What every world needs of the circles beyond the hot and cold lines lives elsewhere: a removed
 * circle's link on the free stack in its cold line's prev (a removed circle is on no grid list:
 * EXACT takes it off, the other modes and a dirty world clear the grid before filing), and a
 * periodic world's count of turns in the wrap block (off_wrap, int32_t[2] per circle: how many
 * periods it has crossed, + along the axis), reserved only when the def has a period. */

typedef struct cc__segment_props {
    double restitution;
    uint32_t category, mask;
} cc__segment_props;

/* What the world's circles and walls use beyond 1.0 (w->features): set when a circle or wall is
 * given such a property, never cleared. Each selects the paths that pay for it. */
#define CC__F_RESTITUTION 1 /* some restitution differs from def.restitution */
#define CC__F_FILTER 2      /* some category or mask differs from the defaults */
#define CC__F_SENSOR 4      /* some circle is or was a sensor */
#define CC__F_ROLL 8        /* some circle decelerates */
#define CC__F_PERIODIC 16   /* the world wraps along an axis (def.period) */
#define CC__F_PREDICT (CC__F_FILTER | CC__F_SENSOR | CC__F_ROLL | CC__F_PERIODIC) /* what predictions read */

#define CC__ALIVE 1
#define CC__LARGE 2  /* wider than a grid cell (immovable only): kept on the large list */
#define CC__MOVED 4   /* moved by an overlap pass: to be re-filed in the grid */
#define CC__TOUCHED 8 /* on the touched list (cc__world_mark) */

/* What a body's predicted hit is. */
#define CC__EV_NONE 0
#define CC__EV_CIRCLE 1  /* partner = circle id, pcount = its count when predicted */
#define CC__EV_SEGMENT 2 /* partner = segment id */
#define CC__EV_BEGIN 3   /* a sensor pair begins overlapping: partner = the other circle */
#define CC__EV_END 4     /* a sensor pair stops overlapping: partner = the other circle */

/* A body's predictions: its earliest hit, and (EXACT with a grid) when it leaves its cell and
 * through which side (dir 0:+x 1:-x 2:+y 3:-y). The hit is searched without a time limit among
 * the circles of the 3x3 cells, so that on a crossing only the newly adjacent cells need a look;
 * walls are searched up to min(hit, crossing) and looked at again after each crossing. */
#define CC__DIR_AGAIN 4 /* t_cross is no crossing: the body looks again then (periodic, large) */
#define CC__DIR_STOP 5  /* t_cross is no crossing: a rolling body comes to rest then */

typedef struct cc__event {
    double t;       /* absolute time of the hit, +INFINITY when none */
    double t_cross; /* absolute time of the cell crossing, +INFINITY when none */
    int16_t kind;   /* CC__EV_* */
    int16_t dir;    /* 0..3, CC__DIR_AGAIN or CC__DIR_STOP */
    int32_t partner;
    uint32_t pcount;
    int32_t id;     /* the API's id of the circle at this storage index (sort.c): kept in the
                       event's line, whose 32 bytes had room for it, rather than in an array */
} cc__event;

/* A heap entry: the body's next event time with its id beside it, so that sifting touches
 * only the heap's own memory. */
typedef struct cc__heap_entry {
    double key;
    int32_t id;
    int32_t pad_;
} cc__heap_entry;

/* Contact handed to the resolver: circle a against circle b (b >= 0) or wall segment. */
typedef struct cc__touch {
    int a;
    int b;       /* the other circle's id, or -1 */
    int segment; /* the wall's id, or -1 */
} cc__touch;

struct cc_world {
    uint32_t magic;
    int mode;
    int max_circles, max_segments;
    double restitution, rest_speed, cell_hint;
    uint64_t max_events;
    cc_contact_fn on_contact;
    void *user;
    cc_sensor_fn on_sensor;
    double rolling_decel;
    int mix;          /* restitution_mix */
    double period[2]; /* > 0: the world wraps along that axis with that period; 0: open */
    int32_t ncell[2]; /* along a periodic axis: its cells (the last one takes what the period
                         leaves over: [(n - 1) cs, period)); 0 along an open axis */
    int features;     /* CC__F_* */
    uint64_t sensor_slots;             /* slots in use */
    int32_t sensor_id[CC_MAX_SENSORS]; /* the circle id of each slot's sensor */

    double now;       /* world time */
    double cs, inv_cs; /* cell size in use and its inverse */
    int use_grid;     /* 0: all pairs (small worlds) */
    int dirty;        /* grid and events must be rebuilt before the next event */
    uintptr_t busy;   /* while a call that fires callbacks runs: the world's own address (cc__busy) */
    int n_circles;    /* live circles */
    int n_segments;
    int id_end;       /* ids in [0, id_end) have been used at least once */
    int free_top, free_head; /* removed ids waiting for reuse, the last (a stack through cold's prev) */
    int heap_n;
    int n_touched;    /* bodies on the touched list */
    uint64_t events_at_sort; /* stats.events when storage was last sorted */
    int large_head;   /* list of CC__LARGE circles */
    uint32_t slot_mask;
    uint32_t tile_bits_x, tile_bits_y; /* log2 of the tile's width and height in cells */
    cc_world_stats stats;

    /* byte offsets from the header to the arrays */
    size_t off_body, off_ev, off_cold, off_heap, off_hpos, off_touched, off_slot, off_seg;
    size_t off_id2idx;             /* a circle's id -> its storage index (see sort.c); back: cc__idx2id */
    size_t off_clu;                /* EXACT: the simultaneous-impact cluster (simultaneous.c) */
    size_t off_props, off_segprops; /* per-body properties (props.c); 0: not reserved */
    size_t off_wrap;                /* periodic: int32_t[2] turns per circle; 0: not reserved */
    unsigned uses;                  /* the def's CC_USES_* */
    size_t off_wallbox, off_wallnode, off_wallorder; /* the walls' tree (walls.c) */
    int wall_tree_n;                /* walls in the tree; those after it are looked at one by one */
    int clu_bodies, clu_contacts;  /* its capacities; 0 when the world has none */
    /* EXACT's event calendar in front of the heap (calendar.c); cal_nb = 0: none */
    size_t off_calhead, off_callink; /* cal_nb + 1 bucket heads (overflow last); next, prev: after hpos */
    int cal_nb, cal_tuned, hpos_stride; /* buckets (a power of two); blocks in use; hpos[id * stride] */
    int cal_n, cal_over;             /* bodies in the buckets (overflow included), in the overflow */
    int64_t cal_cur;                 /* the heap holds the blocks up to this one */
    double cal_w, cal_inv_w, cal_base; /* block width, its inverse, where block 0 begins */
    double cal_t0;                   /* world time and events when the rate was last measured */
    uint64_t cal_e0;
    /* What a step may reach (step.c): reach >= |p| + |v| (now - t) along either axis, speed >=
     * |vx| + |vy|, over the live circles' lazy states; loose, never short (+Inf after a NaN);
     * measured again by the pass over the circles, reach_ticks steps and events ago */
    double reach, speed;
    uint64_t reach_ticks;
};

#define CC__WORLD_MAGIC 0x63637731u /* "ccw1" */
#define CC__ARR(w, type, off) ((type *)(void *)((unsigned char *)(w) + (w)->off))
#define CC__CARR(w, type, off) ((const type *)(const void *)((const unsigned char *)(w) + (w)->off))

/* Largest |cell coordinate|: cell bounds stay exact doubles, and no cell index overflows. */
#define CC__CELL_MAX ((int32_t)1 << 30)

/* ---- the re-entrancy guard ---- */
/* While a call that may fire a callback runs (a step; an add, set or set_circle_props that
 * pushes a pair apart), busy holds the world's own address, a number never followed, and the
 * mutators refuse a world whose busy names itself. A copy of its bytes made meanwhile (a
 * snapshot taken from inside a callback) names the memory it was copied from, not its own: it
 * is not busy. The first call that changes such a copy takes it over (cc__world_own): the guard
 * dropped, and what the interrupted call left half done (events not yet predicted again, a pass
 * over overlaps, the bounds of what a step may reach) made whole by a rebuild at its time. A
 * world whose busy names itself cannot be told from itself inside that call: a snapshot copied
 * back over the very memory it was taken from, untouched, is busy (the header says so). */
static inline uintptr_t cc__self(const cc_world *w) { return (uintptr_t)(const void *)w; }
static inline int cc__busy(const cc_world *w) { return w->busy == cc__self(w); }
static inline void cc__world_own(cc_world *w)
{
    if (w->busy != 0) {
        w->busy = 0;
        w->dirty = 1;
        w->reach = HUGE_VAL; /* the pass over the circles measures it at the next step */
    }
}
static inline void cc__enter(cc_world *w) { w->busy = cc__self(w); }
static inline void cc__leave(cc_world *w) { w->busy = 0; }

/* ---- roll.c: rolling to rest (issue 12) ---- */
/* A body's state at time t along its rolling motion (w->features & CC__F_ROLL). */
void cc__roll_at(const cc_world *w, const cc__body *b, double t, double *x, double *y, double *vx, double *vy);
/* The body carried to t along its rolling motion: its lazy state re-based there. */
void cc__roll_advance(cc_world *w, cc__body *b, double t);
/* decel / (2 |v|): the rolling coefficient of a circle moving at v (0 at rest or without decel). */
double cc__roll_coef(double vx, double vy, double decel);
/* g(tau) = tau (1 - k tau) up to the stop at 1 / (2k), then 1 / (4k); *gd = g'(tau). */
void cc__roll_motion(double k, double tau, double *g, double *gd);
/* The earliest t in [0, t_max] at which two rolling circles (b at dp from a, velocities and
 * coefficients at t = 0) come to R apart while approaching (dir = -1: CC_HIT; CC_OVERLAP when
 * closer now and closing) or while separating (dir = +1: CC_HIT). *n: the unit offset a -> b
 * then. A pair closer than R now (by rounding, after an impact) but parting may still come
 * back as one of them slows: then the contact is when they close at vmin (the caller's least
 * approach that counts) while still closer than R. */
int cc__roll_sweep(double dpx, double dpy, double vax, double vay, double ka, double vbx, double vby, double kb,
                   double R, double t_max, int dir, double vmin, double *t, double *nx, double *ny);
/* A rolling circle against a wall: as cc_sweep_segment, for the motion of roll.c. */
int cc__roll_sweep_segment(const cc_circle *c, double k, const cc_segment *s, double t_max, cc_contact *out);
/* When coordinate x0 moving at v with coefficient k first reaches X (HUGE_VAL: never). */
double cc__roll_reach(double x0, double v, double k, double X);
/* Circle j's position, velocity and rolling coefficient at time t (not re-based). */
void cc__roll_state(const cc_world *w, int j, double t, double *x, double *y, double *vx, double *vy, double *k);
/* Circle j comes to rest now (its stop event): exactly where its motion ends. */
void cc__roll_stop(cc_world *w, int j);
/* Circle j (at now) has a new velocity or deceleration: its rolling coefficient from them. */
void cc__roll_reset(cc_world *w, int j);

/* ---- world.c ---- */
/* Where a struct's field ends: the handshakes' whole-field bounds (defs, props, stats). */
#define CC__END(type, field) (offsetof(type, field) + sizeof(((type *)0)->field))
/* The struct_size handshake: how many of a struct's first n bytes hold whole fields, given the
 * end offsets of its fields in ascending order (a field cut by n is not counted). */
size_t cc__whole_fields(size_t n, const size_t *ends, int count);
/* position of body b at time t (its lazy state carried forward; rolling bodies along their
 * rolling motion, roll.c) */
static inline double cc__bx(const cc_world *w, const cc__body *b, double t)
{
    if (w->features & CC__F_ROLL) {
        double x, y, vx, vy;
        cc__roll_at(w, b, t, &x, &y, &vx, &vy);
        return x;
    }
    return b->px + b->vx * (t - b->t);
}
static inline double cc__by(const cc_world *w, const cc__body *b, double t)
{
    if (w->features & CC__F_ROLL) {
        double x, y, vx, vy;
        cc__roll_at(w, b, t, &x, &y, &vx, &vy);
        return y;
    }
    return b->py + b->vy * (t - b->t);
}
static inline void cc__advance_body(cc_world *w, cc__body *b, double t)
{
    if (b->t != t) {
        if (w->features & CC__F_ROLL) {
            cc__roll_advance(w, b, t);
            return;
        }
        b->px += b->vx * (t - b->t);
        b->py += b->vy * (t - b->t);
        b->t = t;
    }
}
/* The API's id of the circle at storage index k. */
static inline int cc__idx2id(const cc_world *w, int k) { return CC__CARR(w, cc__event, off_ev)[k].id; }
/* Where circle j (storage index) is at time t: its lazy state carried forward, without
 * changing it (for the readers: queries, sensors, the hash). */
static inline void cc__body_pos(const cc_world *w, int j, double t, double *x, double *y)
{
    const cc__body *b = &CC__CARR(w, cc__body, off_body)[j];
    *x = cc__bx(w, b, t);
    *y = cc__by(w, b, t);
}
/* max(bound, x) for those bounds: a NaN x makes the bound +Inf (a NaN one would be lost). */
static inline double cc__reach_max(double bound, double x)
{
    return x <= bound ? bound : x == x ? x : HUGE_VAL;
}
/* Body b has a new position or velocity (set, pushed apart): w->reach and w->speed hold it. */
static inline void cc__reach_note(cc_world *w, const cc__body *b)
{
    double x = fabs(b->px), y = fabs(b->py), vx = fabs(b->vx), vy = fabs(b->vy);
    if (w->now > b->t) { /* (rarely: a body is noted at its own time, now, nearly always) */
        x += vx * (w->now - b->t);
        y += vy * (w->now - b->t);
    }
    w->reach = cc__reach_max(cc__reach_max(w->reach, x), y);
    w->speed = cc__reach_max(w->speed, vx + vy);
}
/* ---- periodic axes (issue 15) ---- */
/* d (a difference of coordinates along axis k) as its nearest image: |d| <= period / 2. One
 * correction is enough: coordinates are kept within a period (to rounding). */
static inline double cc__near_d(const cc_world *w, double d, int k)
{
    double P = w->period[k];
    if (P > 0.0) {
        if (d > 0.5 * P)
            d -= P;
        else if (d < -0.5 * P)
            d += P;
    }
    return d;
}
/* The shift that takes b's coordinate along axis k to its image nearest a's. */
static inline double cc__near_shift(const cc_world *w, double a, double b, int k)
{
    return cc__near_d(w, b - a, k) - (b - a);
}
/* Moves point b to its image nearest point a (periodic worlds; else it stays). */
static inline void cc__near_image(const cc_world *w, cc_vec2 a, cc_vec2 *b)
{
    if (w->features & CC__F_PERIODIC) {
        b->x += cc__near_shift(w, a.x, b->x, 0);
        b->y += cc__near_shift(w, a.y, b->y, 1);
    }
}
/* A logical cell u along axis k (cells numbered on through the periods: u = n * image + cell)
 * as the cell it is and the shift of its image. Along an open axis u is the cell. */
static inline int32_t cc__cell_image(const cc_world *w, int64_t u, int k, double *shift)
{
    int64_t n = w->ncell[k], q;
    *shift = 0.0;
    if (n == 0)
        return (int32_t)u;
    q = u >= 0 ? u / n : -((-u + n - 1) / n); /* floor(u / n) */
    *shift = (double)q * w->period[k];
    return (int32_t)(u - q * n);
}
/* The 3 x 3 cells around (cx, cy), as cells of a periodic world's grid: wrapped, each once (a
 * period may hold only two cells). Writes them to xs[], ys[] and returns how many (<= 9). */
static inline int cc__cells_around(const cc_world *w, int32_t cx, int32_t cy, int32_t *xs, int32_t *ys)
{
    int n = 0, a, b, k;
    for (b = -1; b <= 1; b++)
        for (a = -1; a <= 1; a++) {
            double s;
            int32_t x = cc__cell_image(w, (int64_t)cx + a, 0, &s), y = cc__cell_image(w, (int64_t)cy + b, 1, &s);
            for (k = 0; k < n && (xs[k] != x || ys[k] != y); k++)
                ;
            if (k == n) {
                xs[n] = x;
                ys[n++] = y;
            }
        }
    return n;
}
/* Coordinate x wrapped into [0, period) along a periodic axis k, exactly (as fmod would); the
 * number of periods taken off goes to *turns. */
double cc__wrap_coord(const cc_world *w, double x, int k, int32_t *turns);
/* a + b for counts of turns, saturated at +-2^30 (never an overflow). */
int32_t cc__turns_add(int32_t a, int32_t b);
/* Grid cell size for the current circles (>= largest movable diameter). */
double cc__world_cell_size(const cc_world *w);

/* ---- events.c: indexed 4-ary heap of bodies keyed by (event time, storage index) ---- */
void cc__heap_update(cc_world *w, int id, double key); /* insert or move to its place */
void cc__heap_remove(cc_world *w, int id);
int cc__heap_top(const cc_world *w); /* -1 when empty */
double cc__heap_top_key(const cc_world *w); /* +INFINITY when empty */
/* A large world (EXACT): asks the memory for what the next few events will read, so that it
 * arrives while the current one is processed. Changes nothing. */
void cc__prefetch_ahead(const cc_world *w);

/* ---- calendar.c: EXACT's queue, an event calendar in front of the heap (large worlds) ---- */
/* Buckets of the calendar of a world of this mode and size (0: none, the heap alone). */
int cc__calendar_buckets(int mode, int max_circles);
void cc__queue_update(cc_world *w, int id, double key); /* key: min(ev.t, ev.t_cross), stored */
void cc__queue_remove(cc_world *w, int id);
int cc__queue_top(cc_world *w, double *key); /* the earliest body (-1: none) and its key */
void cc__queue_clear(cc_world *w); /* after the heap was emptied (hpos all -1): buckets emptied */

/* ---- grid.c: hashed uniform cell list ---- */
void cc__grid_clear(cc_world *w);
void cc__grid_insert(cc_world *w, int id); /* files the body by its position at w->now */
void cc__grid_remove(cc_world *w, int id);
void cc__grid_move(cc_world *w, int id, int dir); /* a cell crossing (through a period's edge too) */
void cc__wrap_body(cc_world *w, int id); /* periodic: carried to now, coordinates within the period */
int32_t cc__grid_coord(const cc_world *w, double x, int axis);
/* The table of S = 2^k slots is laid over the plane as tiles of W x H cells (W * H = S, rows of
 * W consecutive slots), so that a compact scene of fewer cells than slots maps its cells to
 * distinct slots and the 3x3 cells around a circle share three runs of slots; each tile starts
 * at a hashed offset, so that larger or elongated scenes spread over the whole table. */
static inline uint32_t cc__grid_slot(const cc_world *w, int32_t cx, int32_t cy)
{
    uint32_t ux = (uint32_t)cx, uy = (uint32_t)cy;
    uint64_t h = (uint64_t)(ux >> w->tile_bits_x) * UINT64_C(0x9E3779B97F4A7C15) ^
                 (uint64_t)(uy >> w->tile_bits_y) * UINT64_C(0xC2B2AE3D27D4EB4F);
    h ^= h >> 29;
    return ((uint32_t)h + (ux & ((1u << w->tile_bits_x) - 1u)) + ((uy & ((1u << w->tile_bits_y) - 1u)) << w->tile_bits_x)) &
           w->slot_mask;
}

/* ---- predict.c: a body's earliest event (EXACT) ---- */
void cc__predict(cc_world *w, int id);
/* after body id crossed into a new cell through side dir: only the new cells are searched */
void cc__predict_crossed(cc_world *w, int id, int dir);
/* cc__predict of moving circles a and b at the instant of their impact, made only when no
 * other circle lies within the radius sum + reach_a of a, or + reach_b of b, now (returns 0);
 * otherwise nothing is changed and 1 is returned (also when either is at rest). The neighbour
 * scans that the predictions make anyway answer the gathering's question (simultaneous.c). */
int cc__predict_pair_alone(cc_world *w, int a, int b, double reach_a, double reach_b);
/* re-predicts every movable body that could meet body id (its neighbourhood) */
void cc__predict_neighbours(cc_world *w, int id);
/* True when approach speed vn (> 0: closing) is a collision: faster than the rounding of the
 * bodies' speeds (their sum is `speeds`), and not a resting contact, which approaches at less
 * than rest_speed * 2^-20 (the sequence of ever smaller impulses that pairwise resolution of
 * bodies pressed together would otherwise produce ends there). */
/* The least approach speed that counts, for circles of summed speeds `speeds`: above rounding
 * (2^-40 of them) and above rest_speed * 2^-20. */
static inline double cc__approach_min(const cc_world *w, double speeds)
{
    double a = 0x1p-40 * speeds, b = w->rest_speed * 0x1p-20;
    return a > b ? a : b;
}
static inline int cc__approaching(const cc_world *w, double vn, double speeds)
{
    return vn > cc__approach_min(w, speeds);
}

/* ---- resolve.c: every impulse goes through here ---- */
/* Resolves the contacts of touch[0..n) that happen at world time w->now; every body named is at
 * w->now already. Applies the impulses (restitution, rest_speed), reports each to the
 * callback, counts collisions and records the overlap at contact. Every body whose velocity
 * changes is marked (cc__world_mark), and the caller predicts the marked bodies again: a
 * resolver that changes more bodies than it was given (issue 5's clusters) needs nothing else.
 * Returns the impulses applied. */
int cc__world_resolve(cc_world *w, const cc__touch *touch, int n);
/* Body id's trajectory changed at w->now: bumps its count (others' events with it go stale) and
 * puts it on the touched list once (cc__world_touch), its new state noted in the bounds of what a
 * step may reach (inline here: the impulse paths pay a few compares). An impulse changes the
 * velocity of a body carried to now, whose position its path already held (w->speed is enough);
 * a push-apart moves it (CC__MOVED, set before the mark): then its position counts too. */
void cc__world_touch(cc_world *w, int id);
static inline void cc__world_mark(cc_world *w, int id)
{
    const cc__body *b = &CC__CARR(w, cc__body, off_body)[id];
    w->speed = cc__reach_max(w->speed, fabs(b->vx) + fabs(b->vy));
    if (CC__CARR(w, cc__cold, off_cold)[id].flags & CC__MOVED)
        cc__reach_note(w, b);
    cc__world_touch(w, id);
}
/* Takes a body off the touched list (-1 when empty). */
int cc__world_take_touched(cc_world *w);
/* Pushes apart body a and circle b (b >= 0) or segment seg when they overlap, then resolves the
 * contact if they approach. Both are at w->now. Returns 1 when anything moved. */
int cc__world_unoverlap(cc_world *w, int a, int b, int seg);

/* ---- near.c: what touches a circle now (for simultaneous-impact resolvers) ---- */
typedef void (*cc__touch_visit)(void *ctx, int j, int seg);
/* Calls visit(ctx, j, -1) for every circle j whose distance from circle k at w->now is at most
 * their radius sum + tol, and visit(ctx, -1, s) for every wall s within k's radius + tol.
 * Indices are storage indices. Returns the number of visits. */
int cc__world_touching(const cc_world *w, int k, double tol, cc__touch_visit visit, void *ctx);

/* ---- simultaneous.c: clusters of impacts at one instant (issue 5, docs/SIMULTANEOUS.md) ---- */
/* Cluster capacities for a world (0 and 0 when its mode gathers no clusters) and the bytes of
 * its cluster block. */
size_t cc__cluster_block(int max_circles, int mode, int *bodies, int *contacts);
/* Resolves the impact(s) touch[0..n) due now together with every body touching them now
 * (transitively, through movable bodies) and the walls those touch, by the simultaneous-impact
 * model. When nothing else touches, this is cc__world_resolve_pairwise. Same contract as
 * cc__world_resolve. */
int cc__world_resolve_cluster(cc_world *w, const cc__touch *touch, int n);
/* resolve.c's pairwise resolution, and the helpers the cluster path shares with it */
int cc__world_resolve_pairwise(cc_world *w, const cc__touch *touch, int n);
/* cc__world_resolve_pairwise of one impact of two circles, the report held back: the contact
 * and impulse for cc__world_report are stored in *k and *impulse instead (when it returns 1). */
int cc__world_resolve_pair_held(cc_world *w, const cc__touch *tc, cc_contact *k, double *impulse);
/* EXACT's plain pair impact of movable circles a and b (exact.c): bounds on the reach within
 * which the gathering of the cluster {a, b} looks for circles touching a and b now, and whether
 * a wall lies near enough to either that the gathering could list it (1: maybe, 0: surely not). */
int cc__cluster_pair_reach(const cc_world *w, int a, int b, double *reach_a, double *reach_b);
void cc__world_report(cc_world *w, int a, int b, int seg, const cc_contact *k, double impulse);
void cc__world_overlap_seen(cc_world *w, double depth);
cc_contact cc__world_wall_contact(const cc_circle *c, const cc_segment *s);

/* ---- sort.c: storage in space-filling-curve order ---- */
/* Inside the library a circle is named by its storage index; the API's ids map to indices
 * through id2idx / cc__idx2id. EXACT sorts storage by grid cell (Morton order) now and then, so
 * that neighbours share cache lines; then every body is refiled and predicted again. */
void cc__sort_bodies(cc_world *w);
/* Sorting is due: enough events since the last one for its cost to be small. */
static inline int cc__sort_due(const cc_world *w)
{
    return w->use_grid && w->stats.events - w->events_at_sort > (uint64_t)w->n_circles * 64u + 1024u;
}

/* ---- props.c: per-body properties, filters, restitution mixing ---- */
/* Whether the world reserved the circles' and walls' properties. Without them every body has
 * its defaults, and no call can give it others (it is refused): the paths that read the block
 * run only behind a w->features flag that such a world can never set. */
static inline int cc__props_reserved(const cc_world *w) { return w->off_props != 0; }
void cc__props_default(const cc_world *w, cc__props *p); /* a new circle's */
/* Whether circles i and j interact (filters; sensors with sensors do not). */
static inline int cc__filter_pass(const cc__props *a, const cc__props *b)
{
    return (a->category & b->mask) != 0 && (b->category & a->mask) != 0;
}
int cc__circles_interact(const cc_world *w, int i, int j);
int cc__wall_interacts(const cc_world *w, int i, int s);
/* The restitution of contact i-j (j < 0: wall s) before rest_speed is applied. */
double cc__contact_restitution(const cc_world *w, int i, int j, int s);

/* ---- sensor.c: sensor events ---- */
/* Whether sensor s and visitor v overlap at w->now (their distance less than the radius sum). */
int cc__sensor_overlaps(const cc_world *w, int s, int v);
/* Circle i (storage index) was added, set, moved or given properties: its sensor overlaps are
 * brought up to date at w->now, each change reported (begin or end). */
void cc__sensor_refresh(cc_world *w, int i);
/* Circle i is removed or stops being a sensor: its overlaps are forgotten (nothing reported
 * when `quiet`, else an end for each). */
void cc__sensor_forget(cc_world *w, int i, int quiet);
/* EXACT: when the sensor pair i-j (one a sensor, the other an admitted visitor; j's image shifted
 * by (sx, sy) in a periodic world) next begins or ends overlapping, at or after w->now:
 * +INFINITY when never. Both at w->now. */
double cc__sensor_next(const cc_world *w, int i, int j, double sx, double sy);
/* EXACT: whether the sensor pair i-j overlaps now by the world's account (its membership). */
int cc__sensor_inside(const cc_world *w, int i, int j);
/* EXACT: the predicted sensor event of i with j (kind CC__EV_BEGIN or CC__EV_END) is due now:
 * reported and recorded, unless the pair is already so (both bodies of a pair predict its
 * events; the second to come finds it done). Returns 1 when reported. */
int cc__sensor_event(cc_world *w, int i, int j, int kind);
/* SWEPT and DISCRETE: every sensor's overlaps brought up to date at the end of the step. */
void cc__sensor_pass(cc_world *w);

/* ---- overlap.c / exact.c / swept.c / discrete.c ---- */
void cc__rebuild(cc_world *w); /* grid, overlaps and (EXACT) every prediction, at w->now */
void cc__settle_body(cc_world *w, int id); /* a body added or set: sensors; overlaps, predictions */
void cc__settle_props(cc_world *w, int id); /* a body given other properties, where it is */
/* sides.c: SWEPT and DISCRETE, at w->now: a centre whose path since its lazy state (or, with
 * from_stash, since the position cc__side_stash kept) crossed a wall is put back on the side it
 * came from, with the wall's impulse. cc__side_stash keeps every body's position now (in its
 * event, which these modes do not use then) before the overlap pass pushes bodies apart. */
void cc__keep_wall_sides(cc_world *w, int from_stash);
void cc__side_stash(cc_world *w);
/* The same for body i alone, from its lazy state (SWEPT, before it is carried to an impact). */
void cc__keep_body_side(cc_world *w, int i);
int cc__step_exact(cc_world *w, double t_end);
int cc__step_swept(cc_world *w, double dt);
int cc__step_discrete(cc_world *w, double dt);

#endif
