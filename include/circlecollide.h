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
 *              default. cc_result_string() names every code (0 is both CC_OK and CC_MISS: its
 *              text says what it means for an action and for a test).
 *              1.2 names two causes that 1.0 and 1.1 reported as CC_ERR_INVALID: CC_ERR_RANGE
 *              (a value beyond a documented limit) and CC_ERR_BUSY (a call that changes a
 *              world, made from inside one of its callbacks). A world gives them only to a
 *              caller that can know them: one whose cc_world_def reaches past 1.1's last field
 *              (period), i.e. whose struct_size says it was compiled against the 1.2 header or
 *              a later one; cc_world_size and cc_world_init judge the def they are given the
 *              same way. A world made from a 1.0 or 1.1 def (as a program built against those
 *              headers makes it) returns CC_ERR_INVALID in those cases, as it always did. A
 *              program recompiled against 1.2 that compared such a result with CC_ERR_INVALID
 *              should compare it with < 0, or handle the new codes. Functions that take no def
 *              (the pair functions, cc_sweep_many) keep CC_ERR_INVALID for every bad input.
 * Untouched    On any error and on CC_MISS, every output argument is left exactly as it was
 *              (bit for bit). Bad input is reported, never undefined behaviour.
 * Batches      A call that takes an array of inputs (cc_world_add_circles, 1.2) checks all of
 *              them before it changes anything: when one is refused nothing changes, neither
 *              for the inputs before it nor after, and the call says which one through its own
 *              out argument (the one output an error writes); else it does what the calls of
 *              one element each, in order, would do.
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
#define CC_VERSION_MINOR 2 /* bumped when symbols or struct fields are added */
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
/* 1.2, for a world made from a 1.2 def (see Results in CONVENTIONS; else CC_ERR_INVALID): */
#define CC_ERR_RANGE (-6) /* a value beyond a documented limit: a capacity above 2^26, a period not
                             wider than def.cell_size, a circle too wide for the world's period, a
                             step whose world time or paths would leave what the world allows */
#define CC_ERR_BUSY (-7)  /* a call that changes a world, made from inside its contact or sensor
                             callback: record what you need, act after that call returns */

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

/* ---- Rolling to rest (1.1): exact motion with constant deceleration ------------------------- */

/* A rolling circle with velocity v (speed s = |v| > 0) and deceleration decel >= 0 (length per
 * time^2) slows along its direction of motion until it stops at t_stop = s / decel:
 *     p(t) = pos + v (t - decel t^2 / (2 s))   for 0 <= t <= t_stop, velocity v (1 - t / t_stop)
 *     p(t) = pos + v t_stop / 2                 for t >= t_stop (at rest)
 * decel = 0, or a circle at rest, is the straight motion of cc_sweep. decel must be finite and
 * >= 0 (else CC_ERR_INVALID); everything else is validated as by cc_sweep.
 *
 * cc_sweep_rolling: the first contact of two rolling circles, with cc_sweep's codes, contact
 * (normal a -> b, point at distance ra from a's centre at time t, depth 0) and untouched-output
 * rules. A hit is the earliest t in [0, t_max] at which the distance equals ra + rb while it
 * decreases: two circles that come to rest exactly touching do not hit (when their motion ends
 * within the rounding of the lengths of a touch, the rest positions decide). "Decreases" means
 * an approach speed > 0 at that instant, as for cc_sweep's "touching at t = 0 and approaching":
 * a second-order touch, touching at t = 0 with approach speed 0 while the distance falls at once
 * (equal velocities along the normal, the circle in front decelerating more: a push, as after an
 * impact at restitution 0), is no hit, for cc_respond has no approach to reverse there (it
 * returns CC_MISS); the pair overlaps from then on, and the answer is the first later instant at
 * which, parted again, it comes back to ra + rb approaching (else CC_MISS). A caller that steps
 * such pairs needs a least approach or a push-apart, as the world does (see "Pushing" below).
 * Touching and closing at any speed > 0, however small, is a hit at t = 0. When neither circle
 * rolls (both decels 0, or at rest), the answer is cc_sweep's, bit for bit. Most misses end at a
 * first bound, before any set-up: each circle moves along a straight path, and a pair whose
 * paths never come within R of each other's line, or come near it only at different times,
 * cannot touch (cross products, one division, g's inverse; bounds rounded outward). While both
 * move, the distance is a quartic in t: outside the times at which each circle is within R of
 * the other's path there is no contact; inside, each piece of motion (between
 * stops) is stepped toward its first crossing by steps that skip no root (the distance's
 * curvature is bounded there), to the first t at which the distance as computed is <= ra + rb;
 * where they cannot settle it (a graze), its roots are isolated through its derivatives and
 * refined on their brackets (safeguarded Newton) to the point bisection to the last bit gives,
 * all evaluated in the relative frame. With one circle at rest the offset moves along a line:
 * cc_sweep's solver in the mover's path parameter, taken back to t. */
CC_API int cc_sweep_rolling(const cc_circle *a, double decel_a, const cc_circle *b, double decel_b, double t_max,
                            cc_contact *out);

/* The same for a rolling circle against a static segment (cc_sweep_segment's rules and normal;
 * decel = 0 or a circle at rest gives its bits; a circle coming to rest touching it does not hit). */
CC_API int cc_sweep_segment_rolling(const cc_circle *c, double decel, const cc_segment *s, double t_max,
                                    cc_contact *out);

/* Moves c to time t >= 0 (finite) along its rolling motion: position as above, velocity
 * v (1 - t / t_stop), exactly 0 from the stop on. Returns CC_OK; CC_ERR_INVALID (c untouched)
 * for invalid input or a position beyond the representable plane. */
CC_API int cc_rolling_advance(cc_circle *c, double decel, double t);

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
 *           memory of the same size and used from there (while a call that fires callbacks
 *           runs it holds its own address as a number, never followed: see "Snapshots"). It keeps no pointer to the caller's
 *           defs, circles or segments (it copies them). About 157 (N = 1e6) to 165 (N = 1e4)
 *           bytes per circle in EXACT for a world of def.uses = 0 (one 64-byte line of hot state,
 *           the predicted event, queue and grid entries; 148 to 154 in SWEPT and DISCRETE), 48 more where uses
 *           lists CC_USES_PROPS, SENSORS or ROLLING (the properties: every world of a 1.0 or 1.1
 *           def, and the default), 8 more in a periodic world (its count of turns); plus about
 *           200 per wall (the wall and its place in the walls' tree, and with those uses its
 *           properties); EXACT adds one block of at most 15 KB for simultaneous impacts (see
 *           below).
 * Uses      def.uses (CC_USES_*, 1.2) lists what a world may use, and cc_world_size reserves
 *           memory only for that. A call that needs what the world did not reserve returns
 *           CC_ERR_INVALID and changes nothing: cc_world_set_circle_props that would give a
 *           circle another restitution, category or mask without CC_USES_PROPS, another rolling
 *           deceleration without PROPS or ROLLING, or make or unmake a sensor without
 *           CC_USES_SENSORS; cc_world_set_segment_props that would change a wall's without
 *           PROPS; a def with rolling_decel > 0 without CC_USES_ROLLING is invalid (size 0).
 *           Reading properties gives the defaults, and setting the values a body has is CC_OK.
 *           uses = 0 is 1.0's world: the least memory and the fastest path (1.0's, which a world
 *           of CC_USES_ALL takes too while it uses nothing more); a scene that uses nothing more
 *           runs bit for bit alike (the same hash) with uses = 0 and CC_USES_ALL.
 * Snapshots A memcpy of the world is a snapshot wherever it is taken, also from inside a
 *           callback: a world is busy (its mutators and cc_world_step refused: CC_ERR_BUSY, or
 *           CC_ERR_INVALID for a 1.0 or 1.1 def) only at
 *           the address of the world whose call is running, so a copy in other memory is a world
 *           of its own at once. Taken inside a callback it is the world as the callback sees it,
 *           at that contact's time, with what the call had still to do left undone; the first
 *           call that changes the copy (a step, a mutator) makes it whole (every prediction made
 *           again at its time, as after an added wall) and the copy goes on from there (not bit
 *           for bit the run it was taken from; two copies of it treated alike end alike). Only
 *           its bytes copied back over the very world it was taken from cannot be told from that
 *           world inside its call, and are busy there: to keep such a snapshot for later, call
 *           cc_world_step(copy, 0) once where it was copied to (the world itself refuses that
 *           call from its callback); from then on it is an ordinary world, to be copied anywhere.
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
 * Walls     Walls keep their side in every mode, at any speed: EXACT finds every wall impact;
 *           SWEPT finds a circle's first impact of the step and DISCRETE none, and there a centre
 *           whose straight path since its last impulse (or the step's start) crossed a wall's
 *           segment, or that a push-apart carried across one, is put back a radius from the
 *           wall's line on the side it came from and takes the wall's impulse (up to 4 walls per
 *           circle and step, so that a corner holds). A centre passing beyond a wall's end went
 *           round it; a point wall (a == b) has no sides: a circle is pushed off it towards where
 *           its centre is. A circle still passes through other circles in SWEPT and DISCRETE
 *           (see cc_mode); bench_world table counts escapes against |v| dt / r (0 in every mode
 *           up to 16 radii a step, docs/BENCHMARKS.md).
 * EXACT     Every impact is found and processed in time order, at any speed: no tunnelling.
 *           Each moving circle holds one predicted event (an impact with a circle or a wall, or
 *           leaving its grid cell) in a priority queue; an impact changes the velocities of the
 *           two bodies involved, which predict again; events predicted against a body whose
 *           trajectory has since changed are found stale (per-body counters) and re-predicted.
 *           Circles are kept in a uniform grid (a cell list hashed into a table sized from
 *           max_circles, so the plane is unbounded): a circle is tested against the circles of
 *           the 3x3 cells around its own, and the cost per event is O(log N). Only what a scene
 *           holds costs anything: a world with max_circles <= 32 tests all pairs and has no
 *           grid; a world without walls tests no walls, and walls are kept in a tree of their
 *           boxes (built at the step after walls were added) so that a circle looks only at the
 *           walls near its path; circles at rest predict nothing (what
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
 * Range     Impacts square lengths and multiply speeds by times: with coordinates, radii or
 *           speeds beyond about 2^500 (1e150) they may overflow (an Inf impulse, a NaN contact
 *           point, an overlap left behind), and world times near 1e300 lose positions; keep
 *           scenes below that (the world fuzzer's D7, D10, D12, D14, D18 in
 *           tests/fuzz/world_defects/). The world time is one double: a circle that crosses
 *           a grid cell in less than one rounding step of it (speed * ulp(time) > cell size,
 *           e.g. speed 20 with cells of 1 at time 1e15) may be filed ahead of its position and
 *           a grid query may miss it (D18, D20); restart the clock (a new world) long before. Queries compare scaled squares and hold at any size; a
 *           step that would carry a circle past 2^1017 is refused (cc_world_step). Masses may
 *           be any the contract allows (up to DBL_MAX): velocities after impacts are computed
 *           from mass ratios and stay finite, but an impulse beyond DBL_MAX (a circle of mass
 *           1e308 struck at speed 1) is reported as +INFINITY, and cc_world_stats.virial and
 *           wall_impulse are +INFINITY from then on.
 * Overlaps  Overlaps the caller makes are resolved, never ignored: in EXACT, a circle added or
 *           set on top of others is pushed apart from each at once with cc_separate (shares
 *           inverse to the masses), then given the impact if the pair approaches; a circle
 *           overlapping a wall is pushed out along the wall's normal. Before the first step,
 *           and after a wall or a circle wider than the cells was added, this happens for all
 *           circles at the next step instead (which also rebuilds the grid). One pass is
 *           made; an overlap it leaves (chains of circles) heals as described above (an
 *           approaching pair is an impact, a separating one drifts apart; two circles left
 *           overlapping at equal velocities stay so until something changes one of them).
 *           SWEPT does this at the start of each step, DISCRETE at the end.
 * Collapse  With restitution < 1 a group of bodies can collide infinitely often in a finite
 *           time (inelastic collapse), and bodies pressed together would exchange ever smaller
 *           impulses. Two remedies: approaches slower than def.rest_speed get restitution 0
 *           (and those slower than rest_speed * 2^-20 none at all), and no EXACT step processes
 *           more than def.max_events events (SWEPT and DISCRETE make a bounded number of passes
 *           per step and do not count against it): it then returns CC_EVENT_LIMIT with the world
 *           consistent at the time of the last event processed; the next cc_world_step
 *           continues from there. A body squeezed between an immovable circle moving towards
 *           a wall (an impossible scene) hits that cap at every call. The cap (1.2): a def from
 *           this header leaves max_events at 0, the automatic cap, fixed at cc_world_init to 32
 *           events per circle of max_circles and at least 10,000; a value >= 1 is that cap; a
 *           def from the 1.0 or 1.1 header keeps its default of 10,000,000 (0 is invalid for
 *           it). How long a capped step takes: the events of a step that jams (see "Pushing")
 *           cost 6 to 12 us each on a desktop core, 50 to 70 times an event of a plain gas
 *           (bench_world jam), so the automatic cap ends a jammed step of 100 circles in about
 *           0.08 s and one of 1,000 in about 0.2 s (0.2 s and 0.7 s under AddressSanitizer),
 *           while a cap of 1e7 runs about 100 s. Ordinary steps stay far below it: a periodic
 *           gas of 1,000 disks stepped 4 collisions per disk per call takes at most 3.4 events
 *           per circle, a pool break in one call 91 events. A long offline step (a whole run in
 *           one call, a circle crossing thousands of cells) sets a larger cap, or steps again
 *           by what is left of its dt while the result is CC_EVENT_LIMIT.
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
                            without predicting again; a second impact of a circle with a circle
                            within one step is missed (it is left overlapping until the next
                            step), one with a wall is not (see "Walls") */
    CC_MODE_DISCRETE = 2 /* move every circle by dt, then push apart every overlapping pair
                            and wall contact and give approaching pairs their impulse; a circle
                            moving more than its size per step can pass through other circles,
                            never through a wall (see "Walls") */
} cc_mode;

/* Passed to the contact callback for every impulse the world applies. */
typedef struct cc_contact_event {
    int a;          /* circle id */
    int b;          /* the other circle's id, or -1 for a wall */
    int segment;    /* the wall's segment id, or -1 for a circle */
    double t;       /* world time of the contact */
    cc_vec2 point;  /* contact point */
    cc_vec2 normal; /* unit normal from a towards b (or the wall) */
    double impulse; /* magnitude of the normal impulse applied (mass * velocity); never NaN,
                       +INFINITY when it exceeds DBL_MAX (a mass near DBL_MAX: the velocities
                       are computed without it and stay finite; see "Range") */
} cc_contact_event;

/* Called for each impulse, from inside the call that applied it: cc_world_step (every mode),
 * and in EXACT also cc_world_add_circle, cc_world_set_circle and cc_world_set_circle_props (a
 * circle put on top of another, or a filter change that makes an overlapping pair interact: the
 * pair is pushed apart and, when it approaches, given its impulse at once). No other call fires
 * it (nor on_sensor: see "Per-body properties"). It may read the world (get_circle, get_circles,
 * time, stats, props, queries, casts, hash) but not change it: add, set, remove, add_segment,
 * step and the props setters called from inside return CC_ERR_BUSY (CC_ERR_INVALID in a world
 * made from a 1.0 or 1.1 def) and do nothing, whichever call fired it (the world fuzzer tries
 * each from both callbacks). Record what you need and act on it after that call returns (e.g.
 * remove a pocketed ball after the step); a memcpy of the world taken there is a world of its
 * own, not refused (see "Snapshots"). */
typedef void (*cc_contact_fn)(const cc_contact_event *event, void *user);

/* Passed to the sensor callback when a circle begins or stops overlapping a sensor circle (see
 * "Per-body properties" below). */
typedef struct cc_sensor_event {
    int sensor;  /* the sensor circle's id */
    int visitor; /* the other circle's id */
    int begin;   /* 1: they began to overlap at t; 0: they stopped overlapping */
    double t;    /* world time */
} cc_sensor_event;

/* Called like cc_contact_fn (from the same calls, with the same rules: it may read the world but
 * not change it), for every sensor event, in time order with the impacts. */
typedef void (*cc_sensor_fn)(const cc_sensor_event *event, void *user);

/* How the restitution of a contact is made from its two sides' (cc_world_def.restitution_mix). */
#define CC_MIX_MIN 0     /* the smaller of the two (the default) */
#define CC_MIX_MAX 1     /* the larger */
#define CC_MIX_PRODUCT 2 /* their product */
#define CC_MIX_MEAN 3    /* their mean */

/* Fill with cc_world_def_init, then change what you need. struct_size comes first so that a
 * library newer than the caller's header uses defaults for the fields the caller lacks; every
 * def must reach at least up to and including restitution. Capacities are at most 2^26 (and
 * small enough that the world's size fits in a size_t); beyond, cc_world_init says
 * CC_ERR_RANGE (for a 1.2 def; see Results in CONVENTIONS). */
typedef struct cc_world_def {
    size_t struct_size;       /* sizeof(cc_world_def) as the caller compiled it */
    int max_circles;          /* capacity for circles, >= 0 (default 64) */
    int max_segments;         /* capacity for walls, >= 0 (default 0: a scene without walls pays nothing) */
    int mode;                 /* a cc_mode (default CC_MODE_EXACT) */
    double restitution;       /* [0, 1]: the restitution every circle and wall starts with (default
                                 1); a contact's is restitution_mix of its two sides' (see
                                 Restitution under "Per-body properties") */
    double rest_speed;        /* >= 0: approach speeds below this collide with restitution 0: the
                                 remedy for inelastic collapse when restitution < 1 (default 0) */
    double cell_size;         /* >= 0: smallest grid cell size; 0 = derived from the radii (default 0) */
    uint64_t max_events;      /* cap on events per EXACT cc_world_step: >= 1, or 0 (the default)
                                 for the automatic cap; a 1.0 or 1.1 def: >= 1, default
                                 10000000; the rule and what a capped step costs: "Collapse" */
    cc_contact_fn on_contact; /* called for every impulse, or NULL (default NULL) */
    void *user;               /* passed to on_contact and on_sensor */
    /* ---- 1.1 (a def of 1.0's size gets these defaults) ---- */
    double rolling_decel;     /* >= 0: deceleration of every movable circle rolling on the
                                 ground, length / time^2 (default 0: no friction); see
                                 "Rolling to rest" */
    int restitution_mix;      /* a CC_MIX_*: a contact's restitution from its sides' (default MIN) */
    cc_sensor_fn on_sensor;   /* called for every sensor event, or NULL (default NULL) */
    cc_vec2 period;           /* a component > 0 makes the world wrap along that axis with that
                                 period, positions kept in [0, period); 0 leaves it open (default
                                 (0, 0)); see "Periodic boxes" */
    /* ---- 1.2 (a def of 1.0's or 1.1's size gets CC_USES_ALL) ---- */
    unsigned uses;            /* CC_USES_* bits: what this world may use (default CC_USES_ALL); see
                                 "World memory" */
} cc_world_def;

/* What a world may use (cc_world_def.uses, 1.2): cc_world_size reserves memory only for what
 * uses lists, and a call that needs what the world did not reserve returns CC_ERR_INVALID and
 * changes nothing. uses = 0 is 1.0's world: the least memory and the fastest path (see "Uses"). */
#define CC_USES_PROPS 1u   /* per-body properties: restitution, filters, per-circle decel */
#define CC_USES_SENSORS 2u /* sensor circles */
#define CC_USES_ROLLING 4u /* rolling_decel or per-circle deceleration */
#define CC_USES_CLOTH 8u   /* spin (cloth) */
#define CC_USES_ALL 0xffffu

/* Defaults for every field that fits in struct_size bytes (whole fields; the bytes of fields
 * this library does not know are zeroed), and sets def->struct_size = struct_size; does nothing
 * for NULL or a struct_size below 1.0's def. What cc_world_def_init calls; bindings over an FFI
 * call it with the size of their own def. (1.1) */
CC_API void cc_world_def_init_sized(cc_world_def *def, size_t struct_size);

/* Defaults for every field; sets struct_size = sizeof(cc_world_def). Does nothing for NULL.
 * A macro over cc_world_def_init_sized with the size of the def this header declares (zlib's
 * handshake): the exported function of this name, which a program built against 1.0 calls,
 * cannot know the caller's size, so it fills 1.0's def only (its size in struct_size, the 1.1
 * fields taking their defaults in the world). Taken by address, it is that 1.0 function. */
CC_API void cc_world_def_init(cc_world_def *def);
#define cc_world_def_init(def) cc_world_def_init_sized((def), sizeof(cc_world_def))

/* Bytes of memory cc_world_init needs for def (its capacities), or 0 when def is invalid or
 * its struct_size is too small. The memory must be aligned to 8 bytes (as malloc's memory and a
 * static array of double are). */
CC_API size_t cc_world_size(const cc_world_def *def);

/* Builds an empty world at time 0 inside memory[0, bytes). Never writes outside it, never
 * allocates, keeps no pointer into any other caller memory. Returns the world (== memory) and
 * *status = CC_OK, or NULL and *status = CC_ERR_INVALID (bad def), CC_ERR_RANGE (a 1.2 def
 * whose capacity exceeds 2^26, or whose period is not wider than its cell_size), CC_ERR_VERSION
 * (struct_size too small to be a def), CC_ERR_MEMORY (memory NULL, misaligned or bytes too few);
 * a failed call writes nothing into memory. status may be NULL. To discard a world, stop using its
 * memory. */
CC_API cc_world *cc_world_init(void *memory, size_t bytes, const cc_world_def *def, int *status);

/* Adds a circle whose state c holds at the current world time. Returns its id (>= 0, stable for
 * its lifetime; removed ids may be reused), CC_ERR_FULL, CC_ERR_INVALID (NULL, invalid circle),
 * CC_ERR_RANGE (a circle too wide for the world's period) or CC_ERR_BUSY (called from a
 * callback); a world made from a 1.0 or 1.1 def says CC_ERR_INVALID for the last two. See "Overlaps" above for a circle added on top
 * of others: in EXACT that may call the contact callback before this returns. */
CC_API int cc_world_add_circle(cc_world *w, const cc_circle *c);

/* Adds n circles (n >= 0; c may be NULL when n is 0), with what n calls of cc_world_add_circle
 * for c[0], c[1], ... in that order would do: the same ids, written to ids_out[0..n) when
 * ids_out is not NULL, the same overlaps resolved and callbacks fired, the same state after
 * (cc_world_hash). Returns n, or an error and adds none of them (see "Batches" above): the
 * first circle cc_world_add_circle would refuse decides, with its code (CC_ERR_INVALID for an
 * invalid circle, CC_ERR_RANGE for one too wide for the period, CC_ERR_FULL for the first that
 * finds the world full), and its index is written to *failed (when failed is not NULL); -1 when
 * no one circle is at fault (CC_ERR_INVALID for NULL w, n < 0 or c NULL with n > 0;
 * CC_ERR_BUSY when called from a callback). ids_out and, on success, failed are
 * left untouched otherwise. One call for a whole scene: a binding crosses its FFI once. (1.2) */
CC_API int cc_world_add_circles(cc_world *w, const cc_circle *c, int n, int *ids_out, int *failed);

/* Adds a static wall (a == b: a point). Returns its id (0, 1, ... in order of addition),
 * CC_ERR_FULL, CC_ERR_INVALID or CC_ERR_BUSY (from a callback). Walls cannot be removed. */
CC_API int cc_world_add_segment(cc_world *w, const cc_segment *s);

/* Removes a circle (a pocketed ball); other ids are unchanged. CC_OK, CC_ERR_NOT_FOUND,
 * CC_ERR_INVALID (NULL w) or CC_ERR_BUSY (called from a callback). */
CC_API int cc_world_remove_circle(cc_world *w, int id);

/* Advances world time by dt >= 0 in the world's mode. Returns CC_OK; CC_EVENT_LIMIT when an
 * EXACT step processed max_events events and stopped early (the world is consistent, its time is that
 * of the last event processed, and another call continues); CC_ERR_INVALID for dt < 0, NaN or
 * Inf; CC_ERR_RANGE for a world time that would overflow, a step along whose straight path
 * (p + v dt from now) a circle would pass 2^1017 (about 1.4e306) in either coordinate, where the
 * arithmetic would overflow, or a SWEPT step of a periodic world that would carry a circle half
 * a period (see "Periodic boxes"); CC_ERR_BUSY for a call from a callback (CC_ERR_INVALID for
 * both in a world made from a 1.0 or 1.1 def); nothing changes on any of them. dt = 0 resolves pending
 * overlaps and the impacts due now. Those limits cost O(1) per step, not a look at every circle:
 * the world keeps bounds on its circles' coordinates and speeds, and looks at each circle only
 * when the bounds come within a factor 4/3 of 2^1017 or reach half a period, a look that also
 * tightens them (after a fast or far circle was slowed, moved back or removed, say). */
CC_API int cc_world_step(cc_world *w, double dt);

/* The circle's state at the current world time (pos is where it is now). CC_OK,
 * CC_ERR_NOT_FOUND or CC_ERR_INVALID (NULL). */
CC_API int cc_world_get_circle(const cc_world *w, int id, cc_circle *out);

/* Replaces a circle's state at the current world time (position, velocity, radius and mass may
 * all change; the id stays). CC_OK, CC_ERR_NOT_FOUND, CC_ERR_INVALID, CC_ERR_RANGE or
 * CC_ERR_BUSY (as add). Like add, in EXACT
 * it may call the contact callback before it returns. */
CC_API int cc_world_set_circle(cc_world *w, int id, const cc_circle *c);

/* Copies up to capacity live circles in increasing id order into ids[] and out[] (either may be
 * NULL to skip it). Returns the number of live circles (which may exceed capacity), or
 * CC_ERR_INVALID (NULL w, capacity < 0). */
CC_API int cc_world_get_circles(const cc_world *w, int *ids, cc_circle *out, int capacity);

/* The wall with this id. CC_OK, CC_ERR_NOT_FOUND or CC_ERR_INVALID. */
CC_API int cc_world_get_segment(const cc_world *w, int id, cc_segment *out);

/* Periodic boxes (1.1): a world whose def.period has a component > 0 wraps along that axis.
 * Positions are kept in [0, period) (cc_world_get_circle gives them so; a circle added or set
 * anywhere is taken to its image there), distances are to the nearest image, and a circle
 * crossing the edge keeps its predicted impacts (EXACT finds them through the images of its
 * neighbours' cells). Periodic in x and open in y, with walls, is a channel. Each period must be
 * at least twice the largest circle diameter plus a cell (1.0625 diameters, or def.cell_size):
 * a circle too wide for it is CC_ERR_RANGE (CC_ERR_INVALID for a 1.0 or 1.1 def). Walls are not repeated: along a periodic axis a
 * wall should span the period (a channel's sides, reaching a radius beyond both ends) or keep
 * away from its edges. A periodic world always has a grid, also with max_circles <= 32. SWEPT
 * and DISCRETE take the nearest image of each pair: a step must not carry a circle half a
 * period (SWEPT refuses such a step: CC_ERR_RANGE, nothing changes). Casts see every image
 * along their path, in every mode, before the first step as after it, whatever period the path
 * starts in; queries report each circle once (its image nearest the query; a query box
 * as wide as the period holds every coordinate along it). Beyond about 1e15 periods from the
 * origin a coordinate has lost its place within the period: a cast from there looks at every
 * circle's nearest image and may hit or miss, at the cost of one look at each; so does a cast
 * that would look at more than 16384 images of each circle (its path cut in pieces half a period
 * long, or its radius long when wider, times the images each piece's box holds: a path of some
 * 8,000 periods, or a radius of some 60), so that its cost stays bounded. */

/* Rolling to rest (1.1): a movable circle with a deceleration a > 0 (def.rolling_decel, or its
 * own cc_circle_props.rolling_decel) slows along its direction of motion and stops: moving at
 * v (speed s) from p, it is at p + v (t - a t^2 / (2 s)) until t_stop = s / a, and at
 * p + v t_stop / 2 from then on. After an impulse it decelerates along its new velocity. An
 * immovable circle (mass +INFINITY) never decelerates; a world whose circles all keep a = 0
 * runs exactly as without friction.
 * EXACT   Impacts between decelerating circles (and with walls) are found exactly on those
 *         paths (the distance is a quartic in t between the stop times: its first falling root,
 *         approached by steps that skip no root, or isolated and bisected to the last bit where
 *         they cannot settle it); a circle comes to rest at its exact stop time
 *         and costs nothing from then on until something hits it. Two circles that come to rest
 *         exactly touching do not collide. Pairs of which neither decelerates cost what they
 *         cost without friction; a decelerating pair costs 2.9 to 3.0 times a straight one on a
 *         quiet core (2.4 to 2.5 on a busy one), and a world in which every circle rolls about
 *         3.5 times one without friction per collision (docs/BENCHMARKS.md: bench_pair_rolling,
 *         bench_world features).
 * SWEPT, DISCRETE  Move and sweep along the same paths, at the end of each step as before.
 * Pushing  1.1 has no carried contacts: a circle pushed by one that decelerates less along their
 *         normal (a kinematic circle driving into a rolling one, a circle with less friction
 *         behind one with more, or a pair leaving each other at an angle after a collision at
 *         restitution < 1 or below rest_speed) is a ball bouncing on a floor: its impacts come
 *         ever closer in time, and cc_world_step returns CC_EVENT_LIMIT (see there) once it
 *         reaches def.max_events, the pair left touching within the tolerance (see Tolerance;
 *         a contact parting slower than rounding resolves is watched until it closes again at
 *         the least approach that counts). Circles of one deceleration moving apart after an elastic
 *         impact (billiards) do not meet this. */

/* The position of circle id without wrapping: where it would be had the periods not been taken
 * off (for diffusion: the mean squared displacement). Along an open axis, its position. The
 * count of periods taken off saturates at 2^30 either way (a circle set 1e300 away keeps its
 * exact image, not that count). CC_OK, CC_ERR_NOT_FOUND or CC_ERR_INVALID (NULL). */
CC_API int cc_world_get_unwrapped(const cc_world *w, int id, cc_vec2 *out);

/* cc_world_get_unwrapped for every live circle, as cc_world_get_circles copies them: up to
 * capacity in increasing id order into ids[] and out[] (either may be NULL to skip it). Returns
 * the number of live circles (which may exceed capacity), or CC_ERR_INVALID (NULL w, capacity
 * < 0). With cc_world_get_circles, the images of a periodic box: (unwrapped - pos) / period. (1.2) */
CC_API int cc_world_get_unwrapped_all(const cc_world *w, int *ids, cc_vec2 *out, int capacity);

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
    /* ---- 1.1 (a stats struct of 1.0's size does not get these) ---- */
    double virial;           /* sum over circle-circle impulses of impulse * the distance between
                                the centres at contact, since init: with it the pressure of a
                                hard-disk fluid in a periodic box is P A = N kT + virial / (2 t) */
    double wall_impulse;     /* sum of the impulses on walls since init (the force on them, times
                                the time) */
} cc_world_stats;

/* Fills the fields that fit in out->struct_size bytes (whole fields only; struct_size itself is
 * left as the caller set it). CC_OK, CC_ERR_INVALID (NULL) or CC_ERR_VERSION (struct_size
 * smaller than the first two fields). */
CC_API int cc_world_get_stats(const cc_world *w, cc_world_stats *out);

/* ---- Per-body properties: restitution, filters, sensors (1.1) ------------------------------- */
/* Every circle and wall carries properties. A new circle gets def.restitution,
 * def.rolling_decel, category 1, mask 0xFFFFFFFF and is not a sensor; a new wall gets
 * def.restitution, category 1 and mask 0xFFFFFFFF. A default is a value like any other: a side
 * that keeps it is mixed as one given that value. A world whose circles and walls keep these
 * runs exactly as it would without them (the same events, bit for bit, at the same cost), its
 * contacts at the restitution its mix makes of def.restitution with itself (see Restitution).
 *
 * Restitution  A contact's restitution is def.restitution_mix of the two sides' (a circle's and
 *           a wall's for a wall contact); approaches slower than def.rest_speed still get 0.
 *           The mix is of the sides' values, wherever they came from: between two sides of
 *           def.restitution e, MIN, MAX and MEAN give e itself, PRODUCT gives e * e (0.81 for
 *           0.9: with it, def.restitution is each material's factor, not the contact's). A
 *           simultaneous impact (see "Simultaneous") uses the smallest restitution of the
 *           contacts in its cluster: a cue ball into a rack of one material behaves as before,
 *           a ball into a corner of two cushions of 0.75 and 0.6 gets 0.6 at both, and kinetic
 *           energy never grows (docs/SIMULTANEOUS.md).
 * Filters   Two circles interact only when (a.category & b.mask) != 0 and (b.category & a.mask)
 *           != 0; a circle and a wall likewise. Pairs that do not interact pass through each
 *           other: no impulse, no callback, no push-apart, no sensor event.
 * Sensors   A sensor circle moves like any other (usually it is immovable: a pocket, a goal, a
 *           trigger zone) but takes and gives no impulses and touches no wall. With every
 *           non-sensor circle its filter admits it reports begin when their distance becomes less
 *           than the sum of the radii and end when it is no longer less, through def.on_sensor:
 *           in EXACT at the exact times, in time order with the impacts; in SWEPT and DISCRETE
 *           at the end of the step. Sensors do not sense sensors. A pocket that swallows a ball
 *           whose centre enters it is a sensor of radius (pocket radius - ball radius). A world
 *           holds at most CC_MAX_SENSORS sensors at once. A circle added, set or given
 *           properties where it overlaps a sensor (or stops overlapping one) gets its begin (or
 *           end) at once, from inside that call; a circle removed gets none: its overlaps are
 *           forgotten.
 * Callbacks cc_world_set_circle_props may fire on_contact (a filter change that makes an
 *           overlapping pair interact pushes it apart, as set does) and on_sensor. */
#define CC_MAX_SENSORS 64

typedef struct cc_circle_props {
    size_t struct_size;   /* sizeof(cc_circle_props) as the caller compiled it */
    double restitution;   /* [0, 1] */
    double rolling_decel; /* >= 0 and finite; ignored for an immovable circle */
    uint32_t category;    /* the bits this circle is */
    uint32_t mask;        /* the bits it interacts with */
    int sensor;           /* nonzero: a sensor (reads back as 1) */
} cc_circle_props;

typedef struct cc_segment_props {
    size_t struct_size; /* sizeof(cc_segment_props) as the caller compiled it */
    double restitution; /* [0, 1] */
    uint32_t category;
    uint32_t mask;
} cc_segment_props;

/* The properties of circle id: fills the whole fields that fit in out->struct_size (struct_size
 * itself is left as the caller set it). CC_OK, CC_ERR_NOT_FOUND, CC_ERR_INVALID (NULL) or
 * CC_ERR_VERSION (struct_size smaller than its first two fields). */
CC_API int cc_world_get_circle_props(const cc_world *w, int id, cc_circle_props *out);

/* Sets the properties of circle id from the whole fields of p that fit in p->struct_size (the
 * others keep their current value), at the current world time. CC_OK; CC_ERR_INVALID (NULL, a
 * value out of range), CC_ERR_BUSY (called from a callback) or CC_ERR_VERSION (struct_size too
 * small), and nothing changed; CC_ERR_NOT_FOUND; CC_ERR_FULL when it would make a sensor of the
 * world's CC_MAX_SENSORS + 1st. CC_ERR_INVALID too, nothing changed, for a change that needs what
 * the world's def.uses did not reserve (see "Uses" above). */
CC_API int cc_world_set_circle_props(cc_world *w, int id, const cc_circle_props *p);

/* The same for wall id. */
CC_API int cc_world_get_segment_props(const cc_world *w, int id, cc_segment_props *out);
CC_API int cc_world_set_segment_props(cc_world *w, int id, const cc_segment_props *p);

/* ---- Queries and state (1.1) ------------------------------------------------------------------ */
/* Questions put to the world as it is at the current time, everything held still. They read the
 * world only (and may be called from a callback); their cost follows the region they cover, not
 * the size of the world (in EXACT, between steps; in SWEPT and DISCRETE, and before a world's
 * first step, every circle is looked at: by a periodic cast, once for each half period of its
 * path, as in EXACT by one longer than a cell per circle). Positions are those
 * cc_world_get_circle gives. */

typedef struct cc_cast_hit {
    int circle;     /* id of the circle hit, or -1 */
    int segment;    /* id of the wall hit, or -1 */
    double t;       /* in [0, 1]: the cast circle's centre is at p + d * t at contact */
    cc_vec2 point;  /* contact point */
    cc_vec2 normal; /* unit normal from the cast circle towards what it hit */
} cc_cast_hit;

/* The first circle or wall that a circle of `radius` (finite, >= 0; 0 is a ray) moving from p to
 * p + d touches: the earliest t in [0, 1] at which it touches one while approaching it, found
 * with cc_sweep's solver (cc_sweep_segment's for walls) and its accuracy. Only circles and walls
 * whose category meets `mask` (category & mask != 0); sensors are skipped. Returns CC_HIT (out
 * filled), CC_MISS (out untouched), CC_OVERLAP when the cast circle already overlaps something at
 * p (out names it, t = 0, the normal from p towards its centre or nearest point), or
 * CC_ERR_INVALID (NULL, a non-finite p or d, radius < 0 or not finite). Equal times go to the
 * lowest circle id, then to the lowest wall id; an overlap comes before a touch at t = 0. A ray
 * (radius 0) hits a wall where it crosses it, a circle where it enters it. The cue ball's aiming
 * line: cast it, then the object ball moves off along out->normal. */
CC_API int cc_world_cast_circle(const cc_world *w, cc_vec2 p, double radius, cc_vec2 d, uint32_t mask,
                                cc_cast_hit *out);

/* The ids of the circles that overlap the disc of centre c and `radius` (their distance less
 * than the sum of the radii; radius 0: the circles whose interior holds c), whose category meets
 * `mask`, sensors included, written in increasing id order into ids[0..capacity). Returns how
 * many there are (which may exceed capacity), or CC_ERR_INVALID (NULL w, c or radius not finite,
 * radius < 0, capacity < 0, ids NULL with capacity > 0). */
CC_API int cc_world_query_circle(const cc_world *w, cc_vec2 c, double radius, uint32_t mask, int *ids,
                                 int capacity);

/* The same for the circles that meet the closed box [lo, hi] (the closed disc against the box,
 * exactly: a circle whose distance from the box equals its radius counts). lo <= hi in both
 * coordinates, all finite, else CC_ERR_INVALID. */
CC_API int cc_world_query_box(const cc_world *w, cc_vec2 lo, cc_vec2 hi, uint32_t mask, int *ids, int capacity);

/* Query filters (1.2): which circles and walls a cast or query looks at. The three functions
 * above take a mask only; their _filtered twins take a filter, so that a cast from a circle of
 * the world (the cue ball's aiming line) can leave that circle out:
 *
 *     cc_query_filter f = CC_QUERY_FILTER_DEFAULT;
 *     f.ignore = cue;
 *     r = cc_world_cast_circle_filtered(w, cue_pos, radius, d, &f, &hit);
 *
 * Set struct_size (CC_QUERY_FILTER_DEFAULT does) so that a later library knows which fields
 * the caller has; a filter whose struct_size does not reach `ignore` is CC_ERR_VERSION. A NULL
 * filter is the default: every category, nothing left out. cc_world_cast_circle(w, p, radius,
 * d, mask, out) is cc_world_cast_circle_filtered with {mask, ignore -1}, bit for bit, and so
 * for the queries. */
typedef struct cc_query_filter {
    size_t struct_size; /* sizeof(cc_query_filter) as the caller compiled it */
    uint32_t mask;      /* only circles (and walls) whose category meets it (default 0xFFFFFFFF) */
    int ignore;         /* the id of a circle to leave out, or -1 (default): none. An id not in
                           use leaves nothing out. Walls are never left out. */
} cc_query_filter;

/* The default filter, as an initializer: every category, nothing left out. */
#define CC_QUERY_FILTER_DEFAULT {sizeof(cc_query_filter), 0xFFFFFFFFu, -1}

/* cc_world_cast_circle, cc_world_query_circle and cc_world_query_box with a filter (1.2): the
 * same results, codes and rules, the circle named by filter->ignore never hit nor listed. */
CC_API int cc_world_cast_circle_filtered(const cc_world *w, cc_vec2 p, double radius, cc_vec2 d,
                                         const cc_query_filter *filter, cc_cast_hit *out);
CC_API int cc_world_query_circle_filtered(const cc_world *w, cc_vec2 c, double radius, const cc_query_filter *filter,
                                          int *ids, int capacity);
CC_API int cc_world_query_box_filtered(const cc_world *w, cc_vec2 lo, cc_vec2 hi, const cc_query_filter *filter,
                                       int *ids, int capacity);

/* A 64-bit hash of the simulation state: the world time, every live circle's id, position and
 * velocity (as cc_world_get_circle gives them), radius, mass and properties, its sensor overlaps,
 * every wall and its properties, and the def's settings (not the callbacks or user pointer).
 * Equal states give equal hashes wherever the memory lives (after a memcpy, on another world fed
 * the same calls, on another machine with IEEE doubles); a state differing in one bit of any of
 * these gives another hash (with the probability of a good 64-bit hash). For replays and
 * lock-step networking: compare hashes to find the step where two runs part. 0 for NULL. */
CC_API uint64_t cc_world_hash(const cc_world *w);

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
CC_API int cc_sweep_rollingf(const cc_circlef *a, float decel_a, const cc_circlef *b, float decel_b, float t_max,
                             cc_contactf *out);
CC_API int cc_sweep_segment_rollingf(const cc_circlef *c, float decel, const cc_segmentf *s, float t_max,
                                     cc_contactf *out);
CC_API int cc_rolling_advancef(cc_circlef *c, float decel, float t);

#ifdef __cplusplus
}
#endif

#endif /* CIRCLECOLLIDE_H */
