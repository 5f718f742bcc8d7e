/* The reference world: EXACT mode's semantics written as plainly as possible, for the
 * differential tests (tests only, never in the library). No grid, no queue, no caches, no lazy
 * states: every body is kept at the current time, and after every event every pair and every
 * circle-wall pair is swept again with the library's public pair functions (cc_sweep,
 * cc_sweep_segment, cc_respond, cc_respond_segment, cc_separate) and the earliest event is
 * taken: O(N^2) per event, for N <= 64 or so. Simultaneous impacts are gathered by a plain
 * implementation of the world's rule (everything within the touching tolerance, transitively
 * through movable circles) and resolved by the library's cluster model (cluster.h), so that a
 * comparison with the world isolates its machinery: which events happen, in which order, at
 * which times.
 *
 * The API mirrors cc_world_*: the same ids (removed ids reused last-in first-out), the same
 * codes, the same callback. What the reference cannot know exactly is recorded instead: at each
 * event, whether another event came within a near tie, or a pair passed within a graze of
 * contact, so that a comparison can tell a legitimate reordering by rounding from a bug. */
#ifndef CC_REFERENCE_WORLD_H
#define CC_REFERENCE_WORLD_H

#include "circlecollide.h"

#include <stdint.h>

#define RW_MAX_CIRCLES 256
#define RW_MAX_SEGMENTS 64

typedef struct rw_body {
    cc_circle c;          /* state at the world's current time */
    int alive;
    cc_circle_props props; /* "Per-body properties" (sensor: 0 or 1) */
    double roll;           /* "Rolling to rest": decel / (2 |v|) now, 0 at rest or without decel */
} rw_body;

/* What rounding decides in a call (add, set, remove, step): the smallest of each, over every
 * search for the next event and every cluster resolved in it. Reset at the start of each call. */
typedef struct rw_doubt {
    double tie_gap;   /* gap between the earliest candidate event and the next distinct one,
                         relative to |t| + time_scale (+INF when none) */
    double graze_gap; /* relative |closest approach - R| of a circle pair that passes within the
                         call; a wall passed within 1e-6 of the radius counts as 0 (+INF) */
    double slow;      /* |ratio - 1| of an approach speed to its rounding threshold (+INF) */
    double slack;     /* |normal speed| / summed speeds of a contact in a cluster: near 0,
                         whether it takes an impulse is rounding's (+INF) */
    int chain;        /* a push-apart made a new overlap: the order of the pushes decides (0/1) */
    int push;         /* a rolling pair touches (within 1e-6 of R) with a normal speed below 1e-6 of
                         their speeds: one pushes the other, which decelerates more along the
                         normal; its impacts come ever closer (a ball bouncing on a floor), and
                         rounding decides when the next one is (0/1) */
} rw_doubt;

typedef void (*rw_event_fn)(const cc_contact_event *e, void *user);
typedef void (*rw_sensor_fn)(const cc_sensor_event *e, void *user);

typedef struct rw_world {
    double restitution, rest_speed, now;
    uint64_t max_events; /* impacts per step (the world counts every event: its cap comes later) */
    int max_circles, max_segments;
    int n_segments, id_end, free_top, dirty, busy;
    rw_body body[RW_MAX_CIRCLES];
    int free_ids[RW_MAX_CIRCLES];
    cc_segment seg[RW_MAX_SEGMENTS];
    cc_segment_props seg_props[RW_MAX_SEGMENTS];
    int mix;
    double rolling_decel;
    int use_grid;     /* "a world with max_circles <= 32 tests all pairs and has no grid" */
    double period[2]; /* "Periodic boxes": > 0 wraps along that axis */
    double cs, cell_hint; /* "Cells": the cell size of the last rebuild, def.cell_size */
    unsigned char inside[RW_MAX_CIRCLES][RW_MAX_CIRCLES]; /* [sensor][visitor]: they overlap */
    rw_event_fn on_event;
    rw_sensor_fn on_sensor;
    void *user;
    double time_scale; /* the scene's time scale, for relative tie gaps (set by the caller) */
    rw_doubt doubt;    /* of the current (or last) call */
    unsigned long events;
} rw_world;

/* def as for cc_world_init (mode must be EXACT; the callback fields are ignored: events go to
 * on_event). Returns CC_OK or CC_ERR_INVALID. */
int rw_init(rw_world *w, const cc_world_def *def, rw_event_fn on_event, rw_sensor_fn on_sensor, void *user);
int rw_add_circle(rw_world *w, const cc_circle *c);
/* cc_world_add_circles: all checked first, then one add per circle ("Batches"). */
int rw_add_circles(rw_world *w, const cc_circle *c, int n, int *ids_out, int *failed);
int rw_remove_circle(rw_world *w, int id);
int rw_set_circle(rw_world *w, int id, const cc_circle *c);
int rw_add_segment(rw_world *w, const cc_segment *s);
int rw_step(rw_world *w, double dt);
int rw_get_circles(const rw_world *w, int *ids, cc_circle *out, int capacity);
/* Whole structs (struct_size ignored); the same codes as the world's. */
int rw_set_circle_props(rw_world *w, int id, const cc_circle_props *p);
int rw_set_segment_props(rw_world *w, int id, const cc_segment_props *p);

#endif
