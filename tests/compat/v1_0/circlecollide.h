/* circlecollide: exact continuous collision of moving circles, in C99.
 *
 * The only public header. Everything exported is declared here, marked CC_API and prefixed cc_
 * (types cc_*, macros CC_*). The library never allocates: all memory comes from the caller.
 *
 * ============================================================================================
 * CONVENTIONS
 * --------------------------------------------------------------------------------------------
 * Units        Any consistent units. Positions and radii in length, velocities in length per
 *              unit time, times in that unit, masses in any mass unit. Nothing is scaled
 *              internally: a scene scaled by 1e-9 or 1e9 gives the scaled answer.
 * Motion       A circle moves at constant velocity from its position at t = 0:
 *              p(t) = pos + vel * t. Circles do not rotate.
 * Times        Sweeps look at t in [0, t_max] (t_max >= 0, finite or +INFINITY). A contact is
 *              reported at the earliest t with |pb(t) - pa(t)| = ra + rb while the distance is
 *              decreasing. Touching at t = 0 and approaching is a hit at t = 0. Touching
 *              exactly is not overlapping.
 * Normal       cc_contact.normal is a unit vector at the contact time pointing from a towards b
 *              (or from the circle towards the wall). Concentric circles get (+1, 0).
 * Immovable    mass = +INFINITY: an obstacle that no impulse and no push-apart moves. Two
 *              immovable circles cannot respond to each other (CC_ERR_INVALID).
 * Valid input  Coordinates and velocities finite; radius finite and > 0; mass > 0 and either
 *              finite or +INFINITY; t_max >= 0 and not NaN; restitution in [0, 1]; pointers
 *              not NULL unless a function says otherwise.
 * Results      Functions return an int: CC_MISS (0), CC_HIT (1), CC_OVERLAP (2) for tests,
 *              CC_OK (0) for actions, CC_EVENT_LIMIT (3) for a world step cut short; negative
 *              values are errors (CC_ERR_*). New codes get new values, so switch with a
 *              default. cc_result_string() names every code.
 * Untouched    On any error and on CC_MISS, every output argument is left exactly as it was
 *              (bit for bit). Bad input is reported, never undefined behaviour.
 * Precision    Each pair function has a single-precision twin with the suffix f (as in libm),
 *              on field-for-field float copies of the types; the algorithm is the same, and the
 *              float path computes in float only.
 * Threads      Pair functions are pure and re-entrant. A world may be used by one thread at a
 *              time; different worlds are independent. There is no global state.
 * ============================================================================================
 */
#ifndef CIRCLECOLLIDE_H
#define CIRCLECOLLIDE_H

#include <stddef.h>
#include <stdint.h>

/* Export macro. Build the shared library with CC_BUILD_SHARED defined; define CC_STATIC when
 * linking the static library on Windows. Elsewhere symbols are hidden by default
 * (-fvisibility=hidden) and CC_API makes the public ones visible. */
#if defined(_WIN32) || defined(__CYGWIN__)
#  if defined(CC_STATIC)
#    define CC_API
#  elif defined(CC_BUILD_SHARED)
#    define CC_API __declspec(dllexport)
#  else
#    define CC_API __declspec(dllimport)
#  endif
#elif defined(__GNUC__) || defined(__clang__)
#  define CC_API __attribute__((visibility("default")))
#else
#  define CC_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Version ------------------------------------------------------------------------------ */

#define CC_VERSION_MAJOR 1 /* bumped only on an ABI break: also the SONAME */
#define CC_VERSION_MINOR 0 /* bumped when symbols or struct fields are added */
#define CC_VERSION_PATCH 0
#define CC_VERSION ((CC_VERSION_MAJOR << 16) | (CC_VERSION_MINOR << 8) | CC_VERSION_PATCH)

/* (MAJOR << 16) | (MINOR << 8) | PATCH of the library actually loaded: compare its major with
 * CC_VERSION_MAJOR to detect a header/library mismatch. */
CC_API unsigned cc_version(void);
/* "MAJOR.MINOR.PATCH" of the library loaded; a static string. */
CC_API const char *cc_version_string(void);

/* ---- Result codes ------------------------------------------------------------------------- */

#define CC_MISS 0        /* no contact in [0, t_max] / no overlap */
#define CC_OK 0          /* an action succeeded (same value as CC_MISS) */
#define CC_HIT 1         /* first contact at out->t, the bodies approaching there */
#define CC_OVERLAP 2     /* already overlapping at t = 0 (distance < sum of radii) */
#define CC_EVENT_LIMIT 3 /* cc_world_step stopped at the per-step event cap; see cc_world_step */
#define CC_ERR_INVALID (-1)   /* NULL, NaN/Inf, radius or mass <= 0, t_max < 0, e outside [0,1] */
#define CC_ERR_NOT_FOUND (-2) /* a world id that is not (or no longer) in use */
#define CC_ERR_FULL (-3)      /* the world holds max_circles circles or max_segments segments */
#define CC_ERR_MEMORY (-4)    /* memory given to cc_world_init is NULL, too small or misaligned */
#define CC_ERR_VERSION (-5)   /* a struct_size the library does not know (too small) */

/* A static English name for a code ("CC_HIT: ..."); unknown codes give "unknown result code". */
CC_API const char *cc_result_string(int code);

/* ---- Value types (layout frozen: they cross the ABI by value and by pointer) ---------------- */

typedef struct cc_vec2 {
    double x, y;
} cc_vec2;

typedef struct cc_circle {
    cc_vec2 pos;   /* centre at the start of the interval (t = 0) */
    cc_vec2 vel;   /* constant velocity: displacement per unit time */
    double radius; /* finite, > 0 */
    double mass;   /* finite and > 0, or +INFINITY for an immovable circle */
} cc_circle;

typedef struct cc_segment {
    cc_vec2 a, b; /* static wall; a == b is a point obstacle */
} cc_segment;

typedef struct cc_contact {
    double t;       /* time of first contact in [0, t_max]; 0 for CC_OVERLAP */
    cc_vec2 point;  /* contact point at time t */
    cc_vec2 normal; /* unit normal at time t, pointing from a (or the circle) towards b (or the wall) */
    double depth;   /* penetration depth at time t: 0 for CC_HIT, > 0 for CC_OVERLAP */
} cc_contact;

/* ---- Pair functions (pure, re-entrant, no allocation, no global state) ---------------------- */

/* Static overlap test. Returns CC_OVERLAP when |pb - pa| < ra + rb, else CC_MISS (touching is
 * not overlapping). Velocities and masses are validated but not used. When out is not NULL and
 * the circles overlap, writes t = 0, depth = ra + rb - |pb - pa|, the normal from a to b ((+1, 0)
 * for concentric circles) and the point midway through the overlap region along the normal. */
CC_API int cc_detect_static(const cc_circle *a, const cc_circle *b, cc_contact *out);

/* Static push-apart. When a and b overlap, moves their positions apart along the centre line
 * (along +x for concentric circles) until they just touch, each by a share inversely
 * proportional to its mass (an immovable circle stays put; equal masses move equally) and
 * returns CC_OVERLAP. Returns CC_MISS and changes nothing when they do not overlap.
 * Velocities are not touched. Two immovable circles: CC_ERR_INVALID. After the call the
 * distance equals ra + rb up to rounding of the positions. */
CC_API int cc_separate(cc_circle *a, cc_circle *b);

/* Continuous collision of two circles moving at constant velocity from t = 0.
 * CC_OVERLAP  they overlap at t = 0: out gets t = 0 and the cc_detect_static contact.
 * CC_HIT      first contact at out->t in [0, t_max] with the distance decreasing; out->depth = 0,
 *             out->point lies on the centre line at distance ra from a's centre.
 * CC_MISS     no such contact: parallel motion, moving apart, tangent, closest approach too far,
 *             or contact after t_max. out untouched.
 * Computed in the relative frame without cancellation: the answer is accurate to a few ulps
 * times the problem's condition number, also far from the origin (see docs/NUMERICS.md). */
CC_API int cc_sweep(const cc_circle *a, const cc_circle *b, double t_max, cc_contact *out);

/* The same for a moving circle against a static segment (its interior and both end points; a
 * degenerate segment a == b is a point). The circle's mass is validated but not used. The
 * normal points from the circle's centre towards the contact point on the segment. */
CC_API int cc_sweep_segment(const cc_circle *c, const cc_segment *s, double t_max, cc_contact *out);

/* Collision impulse along contact->normal with coefficient of restitution e in [0, 1]: the
 * relative normal velocity after is -e times before, the tangential velocities are unchanged,
 * momentum is conserved, and kinetic energy too for e = 1. An immovable circle keeps its
 * velocity. Returns CC_HIT when it applied an impulse; CC_MISS (nothing changed) when the
 * bodies are not approaching along the normal. Positions are not touched: advance them to
 * contact->t first. contact->normal must be a unit vector (|n| within 1e-6 of 1, else
 * CC_ERR_INVALID). Two immovable circles: CC_ERR_INVALID. */
CC_API int cc_respond(cc_circle *a, cc_circle *b, const cc_contact *contact, double restitution);

/* The same against an immovable wall whose normal (from the circle towards the wall) is
 * contact->normal: v' = v - (1 + e) (v.n) n when v.n > 0. The circle's mass is not used, but an
 * immovable circle against an immovable wall is CC_ERR_INVALID, as for two immovable circles. */
CC_API int cc_respond_segment(cc_circle *c, const cc_contact *contact, double restitution);

/* The point of segment s closest to p; for a == b that point. Returns p itself (copied) when p
 * or s holds NaN, and (0, 0) when s is NULL: a pure geometric helper with no error channel. */
CC_API cc_vec2 cc_closest_point_on_segment(cc_vec2 p, const cc_segment *s);

/* ---- Batch sweep (structure of arrays, for vector units and bindings) ----------------------- */

/* Columns of n circles: positions, velocities and radii (masses are not needed to sweep). */
typedef struct cc_circle_soa {
    const double *px, *py, *vx, *vy, *radius;
} cc_circle_soa;

/* For i in [0, n): t_out[i] = the cc_sweep time of (a[i], b[i]) for CC_HIT, 0 for CC_OVERLAP,
 * +INFINITY for CC_MISS; result_out[i] (result_out may be NULL) = that code. Returns the number
 * of pairs that hit or overlap, or CC_ERR_INVALID (and writes nothing) when any pointer is NULL,
 * any input is invalid or t_max is invalid. Bit-identical to calling cc_sweep per pair. */
CC_API long cc_sweep_many(size_t n, const cc_circle_soa *a, const cc_circle_soa *b, double t_max,
                          double *t_out, int *result_out);

/* ---- The world: many circles and walls in caller-owned memory ------------------------------ */

/* A world simulates up to max_circles circles and max_segments static walls in one block of
 * memory that the caller provides (cc_world_size / cc_world_init); it never allocates.
 *
 * Memory    Everything lives inside [memory, memory + bytes): the world stores no address, not
 *           even into its own block, so a world may be copied (memcpy) to other 8-byte aligned
 *           memory of the same size and used from there. It keeps no pointer to the caller's
 *           defs, circles or segments (it copies them). About 160 bytes per circle (one 64-byte
 *           line of hot state, the predicted event, queue and grid entries) plus 32 per wall;
 *           EXACT adds one block of at most 15 KB for simultaneous impacts (see below).
 * Ids       cc_world_add_circle returns the most recently removed id when there is one (removed
 *           ids are reused last-in first-out), else the lowest never-used id. An id stays valid
 *           and names the same circle until it is removed; others are never renumbered.
 * Time      Each circle moves along a straight line between impacts. cc_world_get_circle gives
 *           its state at the world time. Times are absolute (world time), in the scene's units.
 *           Nothing depends on the unit of length: a scene scaled by a power of two (with
 *           rest_speed and cell_size scaled alike) runs through the same events and ends at the
 *           scaled state, bit for bit.
 * Modes     CC_MODE_EXACT (event-driven, see below), CC_MODE_SWEPT and CC_MODE_DISCRETE (see
 *           cc_mode). All three use the same pair functions (cc_sweep, cc_sweep_segment,
 *           cc_respond, cc_respond_segment, cc_separate) and the same grid.
 * EXACT     Every impact is found and processed in time order, at any speed: no tunnelling.
 *           Each moving circle holds one predicted event (an impact with a circle or a wall, or
 *           leaving its grid cell) in a priority queue; an impact changes the velocities of the
 *           two bodies involved, which predict again; events predicted against a body whose
 *           trajectory has since changed are found stale (per-body counters) and re-predicted.
 *           Circles are kept in a uniform grid (a cell list hashed into a table sized from
 *           max_circles, so the plane is unbounded): a circle is tested against the circles of
 *           the 3x3 cells around its own, and the cost per event is O(log N). Only what a scene
 *           holds costs anything: a world with max_circles <= 32 tests all pairs and has no
 *           grid; a world without walls tests no walls; circles at rest predict nothing (what
 *           moves towards them finds them); immovable circles are obstacles, never queued.
 * Cells     The cell size is 1.0625 times the largest diameter of a movable circle (or of any
 *           circle when none is movable), or def.cell_size when that is larger. It is
 *           recomputed, and the grid rebuilt, at the next step after a larger circle was added
 *           or set. An immovable circle wider than a cell is kept on a list that every moving
 *           circle checks. Cells are counted up to 2^30 from the origin in each direction
 *           (beyond, circles share the outermost cells: correct, but slower).
 * Tolerance Impacts are computed from rounded positions, so two bodies touching after an impact
 *           may overlap by rounding: about 1e-13 of their radius sum for coordinates within a
 *           few thousand radii of the origin, growing with |coordinates| / radius (the tests
 *           require less than 1e-10; cc_world_stats.max_overlap reports the deepest seen). Such
 *           an overlap is harmless: an overlapping pair that approaches is an impact at once,
 *           one that separates is left to drift apart. An approach slower than 2^-40 times the
 *           two bodies' summed speeds (rounding), or slower than rest_speed * 2^-20 (a resting
 *           contact), is not an impact.
 * Overlaps  Overlaps the caller makes are resolved, never ignored: in EXACT, a circle added or
 *           set on top of others is pushed apart from each at once with cc_separate (shares
 *           inverse to the masses), then given the impact if the pair approaches; a circle
 *           overlapping a wall is pushed out along the wall's normal. Before the first step,
 *           and after a wall or a circle wider than the cells was added, this happens for all
 *           circles at the next step instead (which also rebuilds the grid). One pass is
 *           made; an overlap it leaves (chains of circles) heals as described above.
 *           SWEPT does this at the start of each step, DISCRETE at the end.
 * Collapse  With restitution < 1 a group of bodies can collide infinitely often in a finite
 *           time (inelastic collapse), and bodies pressed together would exchange ever smaller
 *           impulses. Two remedies: approaches slower than def.rest_speed get restitution 0
 *           (and those slower than rest_speed * 2^-20 none at all), and no step processes more
 *           than def.max_events events: it then returns CC_EVENT_LIMIT with the world
 *           consistent at the time of the last event processed; the next cc_world_step
 *           continues from there. A body squeezed between an immovable circle moving towards
 *           a wall (an impossible scene) hits that cap at every call.
 * Simultaneous  In EXACT, an impact is resolved together with everything touching the two
 *           bodies at that instant: circles and walls whose gap is below 2^-40 of the size of
 *           the numbers involved (coordinates, radii, speeds times |world time|), found
 *           transitively through movable circles (immovable ones take impulses, pass none on).
 *           This also gathers impacts predicted for the same instant up to rounding. The
 *           cluster is resolved at once by generalized reflections (Smith et al., "Reflections
 *           on Simultaneous Impact", 2012): momentum kept, kinetic energy kept at restitution
 *           1, mirror-symmetric scenes stay symmetric to rounding, an impact runs through a
 *           chain of touching circles (Newton's cradle sends out exactly one ball), and the
 *           outcome does not depend on the order in which circles were added. With restitution
 *           e < 1 it is e times that plus 1 - e times the perfectly inelastic outcome; when no
 *           contact approaches faster than rest_speed, the inelastic one. Each contact that
 *           takes an impulse is one collision and one callback (its total impulse), all at
 *           that instant. An impact touching nothing else is the ordinary pair impact. Up to
 *           24 circles and 48 contacts per cluster; beyond, what is left approaching is
 *           resolved right after. SWEPT and DISCRETE resolve impacts one pair at a time.
 *           docs/SIMULTANEOUS.md has the model, its limits and the tolerances.
 * Immovable Circles of mass +INFINITY: obstacles that nothing moves. They may have a velocity
 *           (kinematic bodies): they then move and push others, but pass through other
 *           immovable circles and through walls.
 * Threads   One thread at a time per world; distinct worlds are independent.
 * Determinism  Identical calls give bit-identical results, wherever the world's memory is:
 *           ties between events are broken by the circles' storage order, never by addresses.
 *           (EXACT keeps circles stored in the order of their grid cells, re-sorted from time to
 *           time, so that neighbours share cache lines; ids are not affected.) */

typedef struct cc_world cc_world; /* opaque; lives inside the memory given to cc_world_init */

typedef enum cc_mode {
    CC_MODE_EXACT = 0,   /* event-driven: every collision in time order, no tunnelling */
    CC_MODE_SWEPT = 1,   /* once per step: the grid is rebuilt (overlaps pushed apart), each
                            circle's first impact in the step is found from the motions at the
                            start of the step, and the impacts are resolved in time order
                            without predicting again; a second impact of a circle within one
                            step is missed (it is left overlapping until the next step) */
    CC_MODE_DISCRETE = 2 /* move every circle by dt, then push apart every overlapping pair
                            and wall contact and give approaching pairs their impulse; a circle
                            moving more than its size per step can pass through others */
} cc_mode;

/* Passed to the contact callback for every impulse the world applies. */
typedef struct cc_contact_event {
    int a;          /* circle id */
    int b;          /* the other circle's id, or -1 for a wall */
    int segment;    /* the wall's segment id, or -1 for a circle */
    double t;       /* world time of the contact */
    cc_vec2 point;  /* contact point */
    cc_vec2 normal; /* unit normal from a towards b (or the wall) */
    double impulse; /* magnitude of the normal impulse applied (mass * velocity) */
} cc_contact_event;

/* Called during cc_world_step. It may read the world (get_circle, time, stats) but not change
 * it: add, set, remove and step called from inside return CC_ERR_INVALID and do nothing. Record
 * what you need and act on it after the step (e.g. remove a pocketed ball). */
typedef void (*cc_contact_fn)(const cc_contact_event *event, void *user);

/* Fill with cc_world_def_init, then change what you need. struct_size comes first so that a
 * library newer than the caller's header uses defaults for the fields the caller lacks; every
 * def must reach at least up to and including restitution. Capacities are at most 2^26 (and
 * small enough that the world's size fits in a size_t). */
typedef struct cc_world_def {
    size_t struct_size;       /* sizeof(cc_world_def) as the caller compiled it */
    int max_circles;          /* capacity for circles, >= 0 (default 64) */
    int max_segments;         /* capacity for walls, >= 0 (default 0: a scene without walls pays nothing) */
    int mode;                 /* a cc_mode (default CC_MODE_EXACT) */
    double restitution;       /* coefficient of restitution of every contact, [0, 1] (default 1) */
    double rest_speed;        /* >= 0: approach speeds below this collide with restitution 0: the
                                 remedy for inelastic collapse when restitution < 1 (default 0) */
    double cell_size;         /* >= 0: smallest grid cell size; 0 = derived from the radii (default 0) */
    uint64_t max_events;      /* >= 1: cap on events per cc_world_step (default 10000000) */
    cc_contact_fn on_contact; /* called for every impulse, or NULL (default NULL) */
    void *user;               /* passed to on_contact */
} cc_world_def;

/* Defaults for every field; sets struct_size = sizeof(cc_world_def). Does nothing for NULL. */
CC_API void cc_world_def_init(cc_world_def *def);

/* Bytes of memory cc_world_init needs for def (its capacities), or 0 when def is invalid or
 * its struct_size is too small. The memory must be aligned to 8 bytes (as malloc's memory and a
 * static array of double are). */
CC_API size_t cc_world_size(const cc_world_def *def);

/* Builds an empty world at time 0 inside memory[0, bytes). Never writes outside it, never
 * allocates, keeps no pointer into any other caller memory. Returns the world (== memory) and
 * *status = CC_OK, or NULL and *status = CC_ERR_INVALID (bad def), CC_ERR_VERSION (struct_size
 * too small to be a def), CC_ERR_MEMORY (memory NULL, misaligned or bytes too few); a failed
 * call writes nothing into memory. status may be NULL. To discard a world, stop using its
 * memory. */
CC_API cc_world *cc_world_init(void *memory, size_t bytes, const cc_world_def *def, int *status);

/* Adds a circle whose state c holds at the current world time. Returns its id (>= 0, stable for
 * its lifetime; removed ids may be reused), CC_ERR_FULL, or CC_ERR_INVALID (NULL, invalid
 * circle, or called from the contact callback). See "Overlaps" above for a circle added on top
 * of others. */
CC_API int cc_world_add_circle(cc_world *w, const cc_circle *c);

/* Adds a static wall (a == b: a point). Returns its id (0, 1, ... in order of addition),
 * CC_ERR_FULL or CC_ERR_INVALID. Walls cannot be removed. */
CC_API int cc_world_add_segment(cc_world *w, const cc_segment *s);

/* Removes a circle (a pocketed ball); other ids are unchanged. CC_OK, CC_ERR_NOT_FOUND or
 * CC_ERR_INVALID (NULL w, or called from the contact callback). */
CC_API int cc_world_remove_circle(cc_world *w, int id);

/* Advances world time by dt >= 0 in the world's mode. Returns CC_OK; CC_EVENT_LIMIT when the
 * step processed max_events events and stopped early (the world is consistent, its time is that
 * of the last event processed, and another call continues); CC_ERR_INVALID for dt < 0, NaN or
 * Inf, a world time that would overflow, or a call from the contact callback (nothing
 * changes). dt = 0 resolves pending overlaps and the impacts due now. */
CC_API int cc_world_step(cc_world *w, double dt);

/* The circle's state at the current world time (pos is where it is now). CC_OK,
 * CC_ERR_NOT_FOUND or CC_ERR_INVALID (NULL). */
CC_API int cc_world_get_circle(const cc_world *w, int id, cc_circle *out);

/* Replaces a circle's state at the current world time (position, velocity, radius and mass may
 * all change; the id stays). CC_OK, CC_ERR_NOT_FOUND, CC_ERR_INVALID (as add). */
CC_API int cc_world_set_circle(cc_world *w, int id, const cc_circle *c);

/* Copies up to capacity live circles in increasing id order into ids[] and out[] (either may be
 * NULL to skip it). Returns the number of live circles (which may exceed capacity), or
 * CC_ERR_INVALID (NULL w, capacity < 0). */
CC_API int cc_world_get_circles(const cc_world *w, int *ids, cc_circle *out, int capacity);

/* The wall with this id. CC_OK, CC_ERR_NOT_FOUND or CC_ERR_INVALID. */
CC_API int cc_world_get_segment(const cc_world *w, int id, cc_segment *out);

/* Current world time (0 after init); NaN when w is NULL. */
CC_API double cc_world_time(const cc_world *w);

typedef struct cc_world_stats {
    size_t struct_size;      /* the caller sets sizeof(cc_world_stats) before the call */
    uint64_t collisions;     /* impulses applied since init: circle-circle and circle-wall */
    uint64_t events;         /* events processed: impacts, cell crossings, stale events */
    uint64_t stale_events;   /* predicted events found invalid when their time came */
    uint64_t pairs_tested;   /* pair tests made (sweeps and static tests) */
    uint64_t cell_crossings; /* grid cell changes processed (EXACT) */
    double max_overlap;      /* deepest overlap seen: at each impact (EXACT, SWEPT), or before
                                pushing apart (overlaps made by the caller, DISCRETE) */
} cc_world_stats;

/* Fills the fields that fit in out->struct_size bytes (whole fields only; struct_size itself is
 * left as the caller set it). CC_OK, CC_ERR_INVALID (NULL) or CC_ERR_VERSION (struct_size
 * smaller than the first two fields). */
CC_API int cc_world_get_stats(const cc_world *w, cc_world_stats *out);

/* ---- Single precision: the same contract in float ------------------------------------------ */
/* Field for field the double types with float, and each function the double one's twin (same
 * codes, same outputs left untouched, same semantics), computed in float only: for
 * microcontrollers with a single-precision FPU. Differences: cc_respondf and
 * cc_respond_segmentf accept a normal whose length is within 1e-4 of 1 (double: 1e-6), and the
 * accuracy is that of float (docs/NUMERICS.md gives the measured error of each). */

typedef struct cc_vec2f {
    float x, y;
} cc_vec2f;

typedef struct cc_circlef {
    cc_vec2f pos;
    cc_vec2f vel;
    float radius;
    float mass;
} cc_circlef;

typedef struct cc_segmentf {
    cc_vec2f a, b;
} cc_segmentf;

typedef struct cc_contactf {
    float t;
    cc_vec2f point;
    cc_vec2f normal;
    float depth;
} cc_contactf;

CC_API int cc_detect_staticf(const cc_circlef *a, const cc_circlef *b, cc_contactf *out);
CC_API int cc_separatef(cc_circlef *a, cc_circlef *b);
CC_API int cc_sweepf(const cc_circlef *a, const cc_circlef *b, float t_max, cc_contactf *out);
CC_API int cc_sweep_segmentf(const cc_circlef *c, const cc_segmentf *s, float t_max, cc_contactf *out);
CC_API int cc_respondf(cc_circlef *a, cc_circlef *b, const cc_contactf *contact, float restitution);
CC_API int cc_respond_segmentf(cc_circlef *c, const cc_contactf *contact, float restitution);
CC_API cc_vec2f cc_closest_point_on_segmentf(cc_vec2f p, const cc_segmentf *s);

#ifdef __cplusplus
}
#endif

#endif /* CIRCLECOLLIDE_H */
