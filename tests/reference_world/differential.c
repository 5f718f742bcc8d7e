/* Differential runs (see differential.h): random scenes, the simulators they are played through,
 * and the comparison of what each call did. */
#include "differential.h"

#include "reference_world.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DW_LOG_MAX 64      /* contact events compared per call (a step, an add, a set) */
#define DW_MAX_CIRCLES 128 /* circles in a scene, at most */
#define DW_BATCH 4         /* circles in one batch add (cc_world_add_circles), at most */

/* What rounding may explain (see the comparison below). Times and positions are compared
 * relative to the scene's scales: T = L / V, L = its extent, V = its largest speed. */
#define DW_TIE 1e-6      /* two events closer than this * (|t| + T): their order is rounding's */
#define DW_GRAZE 1e-6    /* a pair passing within this * R of contact: hit or miss is rounding's */
#define DW_SLOW 1e-3     /* an approach within this ratio of the rounding threshold */
#define DW_SLACK 1e-6    /* a contact of a cluster with a normal speed below this * its speeds */
#define DW_APART 1e-9    /* states further apart than this * L: no longer the same scene */
#define DW_T_TOL 1e-9    /* matched events: times within this * (|t| + T) */
#define DW_J_TOL 1e-7    /* impulses within this * (|J| + m V), normals within this */
#define DW_FRESH 1e-13   /* states this close: only rounding separates them (for the figures) */
#define DW_GROW 1e6      /* what one event may make of a difference in the states before it */

int dw_trace;

/* ---- random numbers (SplitMix64: the same sequence everywhere) ----------------------------- */

typedef struct dw_rng {
    uint64_t s;
} dw_rng;

static uint64_t rng_next(dw_rng *r)
{
    uint64_t z = (r->s += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

static double rng_unit(dw_rng *r) { return (double)(rng_next(r) >> 11) * 0x1p-53; }
static int rng_int(dw_rng *r, int n) { return (int)(rng_next(r) % (uint64_t)n); } /* [0, n) */
static double rng_range(dw_rng *r, double lo, double hi) { return lo + (hi - lo) * rng_unit(r); }
static double rng_log(dw_rng *r, double lo, double hi) { return lo * pow(hi / lo, rng_unit(r)); }

/* ---- the simulators and what each call did ----------------------------------------------- */

typedef struct dw_event {
    cc_contact_event e;
    int n;           /* circles in the snapshot */
    cc_vec2 pos[DW_MAX_CIRCLES]; /* every circle's position at the event, in id order */
    cc_vec2 vel[DW_MAX_CIRCLES]; /* and velocity (before or after the impulse: the same in both) */
} dw_event;

typedef struct dw_sim {
    const char *name;
    cc_world *w;    /* a world, or NULL for the reference */
    void *mem;
    rw_world *r;
    int n_events;   /* events of the current call (the first DW_LOG_MAX are kept) */
    dw_event log[DW_LOG_MAX];
    int n_sensed;   /* sensor events of the current call (the first DW_LOG_MAX are kept) */
    cc_sensor_event sensed[DW_LOG_MAX];
    int batch_ids[DW_BATCH], batch_failed; /* a batch add's ids and *failed (-77: unwritten) */
} dw_sim;

static int sim_get(const dw_sim *s, int *ids, cc_circle *c, int cap)
{
    return s->w != NULL ? cc_world_get_circles(s->w, ids, c, cap) : rw_get_circles(s->r, ids, c, cap);
}

static void snapshot(dw_sim *s, const cc_contact_event *e)
{
    cc_circle c[DW_MAX_CIRCLES];
    dw_event *ev;
    int i, n;
    if (s->n_events++ >= DW_LOG_MAX)
        return;
    ev = &s->log[s->n_events - 1];
    ev->e = *e;
    n = sim_get(s, NULL, c, DW_MAX_CIRCLES);
    ev->n = n < DW_MAX_CIRCLES ? n : DW_MAX_CIRCLES;
    for (i = 0; i < ev->n; i++) {
        ev->pos[i] = c[i].pos;
        ev->vel[i] = c[i].vel;
    }
}

static void on_contact(const cc_contact_event *e, void *user) { snapshot((dw_sim *)user, e); }

static void on_sensor(const cc_sensor_event *e, void *user)
{
    dw_sim *s = (dw_sim *)user;
    if (s->n_sensed < DW_LOG_MAX)
        s->sensed[s->n_sensed] = *e;
    s->n_sensed++;
}

static int sim_make(dw_sim *s, const char *name, const cc_world_def *def, int reference)
{
    memset(s, 0, sizeof *s);
    s->name = name;
    if (reference) {
        s->r = (rw_world *)malloc(sizeof *s->r);
        return s->r != NULL && rw_init(s->r, def, on_contact, on_sensor, s) == CC_OK;
    } else {
        cc_world_def d = *def;
        /* the reference's cap counts impacts, the world's every event: a world that stops where
         * the reference does not is in error; except in a rolling scene, where a pushed circle's
         * impacts without end are a known jam (see dw_run_scene), found as well at a lower cap */
        d.max_events = def->rolling_decel > 0.0 ? 5000 : 100000;
        size_t n = cc_world_size(&d);
        d.on_contact = on_contact;
        d.on_sensor = on_sensor;
        d.user = s;
        s->mem = malloc(n);
        s->w = s->mem != NULL ? cc_world_init(s->mem, n, &d, NULL) : NULL;
        return s->w != NULL;
    }
}

static void sim_free(dw_sim *s)
{
    free(s->mem);
    free(s->r);
}

/* ---- a scene ------------------------------------------------------------------------------ */

typedef struct dw_scene {
    dw_rng rng;
    double box;          /* circles are placed in [-box, box]^2 */
    double rmin, rmax;   /* radii of new circles */
    double vmax;         /* largest speed */
    double L, T, J;      /* scales: length, time, impulse */
    double period[2];    /* a periodic scene: its periods (0: open) */
    int props;           /* the scene sets per-body properties */
    int batch;           /* the scene adds its circles in batches (cc_world_add_circles) */
    int to_place;        /* circles of the first round still to place (batch scenes) */
    int may_fill;        /* a batch may find the world full (not when the two worlds' capacities
                            differ: all pairs against the grid) */
    double decel;        /* a rolling scene: its typical deceleration (0: none) */
    cc_segment seg[64];
    int n_seg;
} dw_scene;

/* |a - b| along axis k, through the nearest image in a periodic scene. */
static double diff(const dw_scene *sc, double a, double b, int k)
{
    double d = a - b, P = sc->period[k];
    if (P > 0.0) {
        d = fmod(d, P);
        if (d > 0.5 * P)
            d -= P;
        else if (d < -0.5 * P)
            d += P;
    }
    return fabs(d);
}

/* Does c (placed among the circles of sim, ids ex1 and ex2 excluded) overlap a circle or a wall?
 * How many circles it overlaps goes to *n_over (the last one to *which). */
static int overlaps(const dw_scene *sc, const dw_sim *sim, const cc_circle *c, int ex1, int ex2, int *n_over,
                    int *which)
{
    cc_circle all[DW_MAX_CIRCLES];
    int ids[DW_MAX_CIRCLES], n = sim_get(sim, ids, all, DW_MAX_CIRCLES), i, walls = 0;
    *n_over = 0;
    for (i = 0; i < n; i++) {
        double dx = diff(sc, all[i].pos.x, c->pos.x, 0), dy = diff(sc, all[i].pos.y, c->pos.y, 1);
        double R = all[i].radius + c->radius;
        if (ids[i] == ex1 || ids[i] == ex2)
            continue;
        /* a margin of 1% of R: "touching" is not what these scenes test */
        if (dx * dx + dy * dy < R * R * 1.0201) {
            ++*n_over;
            *which = ids[i];
        }
    }
    for (i = 0; i < sc->n_seg; i++) {
        cc_vec2 q = cc_closest_point_on_segment(c->pos, &sc->seg[i]);
        double dx = q.x - c->pos.x, dy = q.y - c->pos.y;
        walls += dx * dx + dy * dy < c->radius * c->radius * 1.0201;
    }
    return *n_over > 0 || walls > 0;
}

/* A random circle; immovable ones now and then, some at rest, speeds spread 1:1e4. */
static cc_circle random_circle(dw_scene *sc)
{
    cc_circle c;
    double u = rng_unit(&sc->rng), speed, angle = rng_range(&sc->rng, 0.0, 6.283185307179586);
    c.radius = rng_log(&sc->rng, sc->rmin, sc->rmax);
    c.pos.x = rng_range(&sc->rng, -sc->box + c.radius, sc->box - c.radius);
    c.pos.y = rng_range(&sc->rng, -sc->box + c.radius, sc->box - c.radius);
    c.mass = rng_log(&sc->rng, 0.1, 10.0) * c.radius * c.radius;
    speed = u < 0.15 ? 0.0 : rng_log(&sc->rng, sc->vmax * 1e-4, sc->vmax);
    c.vel.x = speed * cos(angle);
    c.vel.y = speed * sin(angle);
    if (rng_unit(&sc->rng) < 0.08) {
        c.mass = HUGE_VAL; /* an obstacle, or (when moving) a kinematic body */
        /* a rolling scene has no kinematic pushers: a circle pushed by one is a ball bouncing on
         * a floor (ever faster impacts, inelastic collapse: CC_EVENT_LIMIT), which 1.1 does not
         * model (docs/TESTING.md) */
        if (sc->decel > 0.0)
            c.vel.x = c.vel.y = 0.0;
    }
    return c;
}

/* A circle placed where it overlaps nothing, or (when `onto`) exactly one circle and no wall:
 * overlaps that the world pushes apart, isolated so that the order of the pushes is not in
 * question. Returns 0 when no place was found. */
static int place(dw_scene *sc, const dw_sim *sim, int self, int onto, cc_circle *out, cc_circle *pushed)
{
    int tries, n_over, which = -1;
    for (tries = 0; tries < 200; tries++) {
        cc_circle c = random_circle(sc);
        if (onto) {
            cc_circle all[DW_MAX_CIRCLES];
            int ids[DW_MAX_CIRCLES], n = sim_get(sim, ids, all, DW_MAX_CIRCLES), k;
            double a = rng_range(&sc->rng, 0.0, 6.283185307179586), d;
            if (n == 0)
                return 0;
            k = rng_int(&sc->rng, n);
            if (ids[k] == self || (isinf(all[k].mass) && isinf(c.mass)))
                continue;
            d = (all[k].radius + c.radius) * rng_range(&sc->rng, 0.5, 0.97);
            c.pos.x = all[k].pos.x + d * cos(a);
            c.pos.y = all[k].pos.y + d * sin(a);
            /* onto circle k alone, and the push-apart must make no second overlap with a circle or
             * a wall (the order of the pushes would then decide, and that is the world's to
             * choose) */
            if (!overlaps(sc, sim, &c, self, ids[k], &n_over, &which)) {
                cc_circle pa = c, pb = all[k];
                if (cc_separate(&pa, &pb) == CC_OVERLAP && !overlaps(sc, sim, &pa, self, ids[k], &n_over, &which) &&
                    !overlaps(sc, sim, &pb, self, ids[k], &n_over, &which)) {
                    *out = c;
                    if (pushed != NULL)
                        pushed[0] = pa, pushed[1] = pb;
                    return 1;
                }
            }
            continue;
        }
        if (!overlaps(sc, sim, &c, self, self, &n_over, &which)) {
            *out = c;
            if (pushed != NULL)
                pushed[0] = pushed[1] = c;
            return 1;
        }
    }
    return 0;
}

/* ---- comparing two simulators' calls ------------------------------------------------------- */

typedef struct dw_cmp {
    const dw_scene *sc;
    dw_result *res;
    double apart; /* state difference / L at the last matched event */
} dw_cmp;

static void say(dw_result *res, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(res->why, sizeof res->why, fmt, ap);
    va_end(ap);
}

/* The identity of an event, independent of which body the simulator named first. */
static void identity(const cc_contact_event *e, int *lo, int *hi, int *seg)
{
    *seg = e->segment;
    *lo = e->b < 0 || e->a < e->b ? e->a : e->b;
    *hi = e->b < 0 ? -1 : (e->a < e->b ? e->b : e->a);
}

static int by_identity(const void *x, const void *y)
{
    const dw_event *a = *(const dw_event *const *)x, *b = *(const dw_event *const *)y;
    int la, ha, sa, lb, hb, sb;
    identity(&a->e, &la, &ha, &sa);
    identity(&b->e, &lb, &hb, &sb);
    if (la != lb)
        return la < lb ? -1 : 1;
    if (ha != hb)
        return ha < hb ? -1 : 1;
    return sa < sb ? -1 : sa > sb;
}

/* Does rounding decide anything in this call (the reference's doubts)? */
static int doubtful(const dw_sim *ref)
{
    const rw_doubt *d = &ref->r->doubt;
    return d->tie_gap <= DW_TIE || d->graze_gap <= DW_GRAZE || d->slow <= DW_SLOW || d->slack <= DW_SLACK ||
           d->chain || d->push;
}

/* The largest difference between two snapshots (the same ids in both): positions / L and
 * velocities / V. */
static double apart(const dw_scene *sc, const dw_event *a, const dw_event *b)
{
    double mp = 0.0, mv = 0.0;
    int i;
    if (a->n != b->n)
        return HUGE_VAL;
    for (i = 0; i < a->n; i++) {
        double p = diff(sc, a->pos[i].x, b->pos[i].x, 0) + diff(sc, a->pos[i].y, b->pos[i].y, 1);
        double v = fabs(a->vel[i].x - b->vel[i].x) + fabs(a->vel[i].y - b->vel[i].y);
        mp = p > mp ? p : mp;
        mv = v > mv ? v : mv;
    }
    return mp / sc->L > mv / sc->vmax ? mp / sc->L : mv / sc->vmax;
}

/* Compares the events of one call. Returns DW_END_DONE to go on, or how the scene ends. */
static dw_end compare_call(dw_cmp *c, const dw_sim *A, const dw_sim *B, const dw_sim *ref, const char *call)
{
    const dw_event *ra[DW_LOG_MAX], *rb[DW_LOG_MAX];
    int na = A->n_events < DW_LOG_MAX ? A->n_events : DW_LOG_MAX;
    int nb = B->n_events < DW_LOG_MAX ? B->n_events : DW_LOG_MAX;
    int i = 0, j = 0, k;
    while (i < na && j < nb) {
        /* a run: the events one simulator reported at one instant (a cluster), any order */
        int ia = i, jb = j, m;
        double t = B->log[j].e.t;
        while (i < na && A->log[i].e.t == A->log[ia].e.t)
            ra[i - ia] = &A->log[i], i++;
        while (j < nb && B->log[j].e.t == B->log[jb].e.t)
            rb[j - jb] = &B->log[j], j++;
        m = i - ia;
        if (m != j - jb) {
            if (c->apart > DW_APART || doubtful(ref))
                return DW_END_TIE;
            say(c->res, "%s: at t = %.17g %s reports %d contacts, %s %d", call, t, A->name, m, B->name, j - jb);
            return DW_END_FAILED;
        }
        qsort(ra, (size_t)m, sizeof ra[0], by_identity);
        qsort(rb, (size_t)m, sizeof rb[0], by_identity);
        for (k = 0; k < m; k++) {
            const cc_contact_event *ea = &ra[k]->e, *eb = &rb[k]->e;
            int la, ha, sa, lb, hb, sb;
            double flip = ea->a == eb->a ? 1.0 : -1.0, dt, dj, dn;
            identity(ea, &la, &ha, &sa);
            identity(eb, &lb, &hb, &sb);
            if (la != lb || ha != hb || sa != sb) {
                if (c->apart > DW_APART || doubtful(ref))
                    return DW_END_TIE;
                say(c->res, "%s: at t = %.17g %s reports contact (%d, %d, wall %d), %s (%d, %d, wall %d)", call, t,
                    A->name, ea->a, ea->b, ea->segment, B->name, eb->a, eb->b, eb->segment);
                return DW_END_FAILED;
            }
            dt = fabs(ea->t - eb->t) / (fabs(eb->t) + c->sc->T);
            dj = fabs(ea->impulse - eb->impulse) / (fabs(eb->impulse) + 1e-9 * c->sc->J);
            dn = fabs(ea->normal.x - flip * eb->normal.x) + fabs(ea->normal.y - flip * eb->normal.y);
            if (dt > DW_T_TOL + DW_GROW * c->apart || dj > DW_J_TOL + DW_GROW * c->apart ||
                dn > DW_J_TOL + DW_GROW * c->apart) {
                if (c->apart > DW_APART || doubtful(ref))
                    return DW_END_TIE;
                say(c->res, "%s: contact (%d, %d, wall %d), event %d of %d: t %.17g against %.17g, impulse %.17g "
                    "against %.17g, normals differ by %.3g; the states before were %.3g L apart", call, ea->a, ea->b,
                    ea->segment, jb + k, nb, ea->t, eb->t, ea->impulse, eb->impulse, dn, c->apart);
                return DW_END_FAILED;
            }
            if (c->apart < DW_FRESH && dt > c->res->worst_dt)
                c->res->worst_dt = dt;
            c->res->events_compared++;
        }
        c->apart = apart(c->sc, ra[m - 1], rb[m - 1]);
        if (c->apart > DW_APART) {
            say(c->res, "%s: after the contacts at t = %.17g the states are %.3g L apart (chaos)", call, t, c->apart);
            return DW_END_DIVERGED;
        }
    }
    if (na != nb && i == na && j == nb) {
        /* unreachable: both lists were consumed run by run */
    } else if (i < na || j < nb) {
        const dw_event *extra = i < na ? &A->log[i] : &B->log[j];
        if (A->n_events > DW_LOG_MAX || B->n_events > DW_LOG_MAX)
            return DW_END_DONE; /* the rest is beyond what is compared */
        if (c->apart > DW_APART || doubtful(ref))
            return DW_END_TIE;
        say(c->res, "%s: %s alone reports contact (%d, %d, wall %d) at t = %.17g", call,
            i < na ? A->name : B->name, extra->e.a, extra->e.b, extra->e.segment, extra->e.t);
        return DW_END_FAILED;
    }
    return DW_END_DONE;
}

static int by_pair(const void *x, const void *y)
{
    const cc_sensor_event *a = (const cc_sensor_event *)x, *b = (const cc_sensor_event *)y;
    if (a->sensor != b->sensor)
        return a->sensor < b->sensor ? -1 : 1;
    if (a->visitor != b->visitor)
        return a->visitor < b->visitor ? -1 : 1;
    return a->t < b->t ? -1 : a->t > b->t; /* a pair's events alternate: time orders them */
}

/* The sensor events of one call: pair by pair, the same begins and ends at the same times (the
 * order across pairs at one instant is the simulators' own). */
static dw_end compare_sensors(dw_cmp *c, dw_sim *A, dw_sim *B, const dw_sim *ref, const char *call)
{
    int k, n = A->n_sensed;
    if (A->n_sensed > DW_LOG_MAX || B->n_sensed > DW_LOG_MAX)
        return DW_END_DONE; /* beyond what is compared */
    if (A->n_sensed != B->n_sensed) {
        if (c->apart > DW_APART || doubtful(ref))
            return DW_END_TIE;
        say(c->res, "%s: %s reports %d sensor events, %s %d", call, A->name, A->n_sensed, B->name, B->n_sensed);
        return DW_END_FAILED;
    }
    qsort(A->sensed, (size_t)n, sizeof A->sensed[0], by_pair);
    qsort(B->sensed, (size_t)n, sizeof B->sensed[0], by_pair);
    for (k = 0; k < n; k++) {
        const cc_sensor_event *a = &A->sensed[k], *b = &B->sensed[k];
        double dt = fabs(a->t - b->t) / (fabs(b->t) + c->sc->T);
        if (a->sensor != b->sensor || a->visitor != b->visitor || a->begin != b->begin ||
            dt > DW_T_TOL + DW_GROW * c->apart) {
            if (c->apart > DW_APART || doubtful(ref))
                return DW_END_TIE;
            say(c->res, "%s: sensor event (%d, %d, begin %d) at t = %.17g in %s, (%d, %d, begin %d) at t = %.17g in %s",
                call, a->sensor, a->visitor, a->begin, a->t, A->name, b->sensor, b->visitor, b->begin, b->t, B->name);
            return DW_END_FAILED;
        }
        c->res->sensor_events_compared++;
    }
    return DW_END_DONE;
}

/* After a call: the same circles, at states apart by no more than rounding explains. */
static dw_end compare_states(dw_cmp *c, const dw_sim *A, const dw_sim *B, const dw_sim *ref, const char *call)
{
    cc_circle ca[DW_MAX_CIRCLES], cb[DW_MAX_CIRCLES];
    int ia[DW_MAX_CIRCLES], ib[DW_MAX_CIRCLES];
    int na = sim_get(A, ia, ca, DW_MAX_CIRCLES), nb = sim_get(B, ib, cb, DW_MAX_CIRCLES), k;
    double dp = 0.0, dv = 0.0;
    int worst = 0;
    if (na != nb || memcmp(ia, ib, sizeof ia[0] * (size_t)na) != 0) {
        say(c->res, "%s: %s holds %d circles, %s %d (or other ids)", call, A->name, na, B->name, nb);
        return DW_END_FAILED;
    }
    for (k = 0; k < na; k++) {
        double p = diff(c->sc, ca[k].pos.x, cb[k].pos.x, 0) + diff(c->sc, ca[k].pos.y, cb[k].pos.y, 1);
        double v = fabs(ca[k].vel.x - cb[k].vel.x) + fabs(ca[k].vel.y - cb[k].vel.y);
        if (ca[k].radius != cb[k].radius || !(ca[k].mass == cb[k].mass)) {
            say(c->res, "%s: circle %d changed radius or mass", call, ia[k]);
            return DW_END_FAILED;
        }
        if (p > dp)
            worst = k;
        dp = p > dp ? p : dp;
        dv = v > dv ? v : dv;
    }
    dp /= c->sc->L;
    dv /= c->sc->vmax;
    if (dp > DW_APART || dv > DW_APART) {
        say(c->res, "%s: states apart by %.3g L in position, %.3g V in velocity, with every contact matched (circle "
            "%d at (%.17g, %.17g) in %s, (%.17g, %.17g) in %s); before: %.3g L apart, doubt %d, %d events", call, dp,
            dv, ia[worst], ca[worst].pos.x, ca[worst].pos.y, A->name, cb[worst].pos.x, cb[worst].pos.y, B->name,
            c->apart, doubtful(ref), A->n_events);
        /* every contact matched, so the velocities can differ only by what the contacts made of
         * the states' difference before them, and positions by that plus free flight since */
        if (c->apart > DW_APART || A->n_events > DW_LOG_MAX || B->n_events > DW_LOG_MAX || ref->r->doubt.chain ||
            (dv <= DW_GROW * (c->apart + DW_FRESH) && dp <= c->apart + dv + DW_FRESH))
            return DW_END_DIVERGED;
        say(c->res, "%s: states apart by %.3g L in position, %.3g V in velocity, with every contact matched (circle "
            "%d at (%.17g, %.17g) in %s, (%.17g, %.17g) in %s)", call, dp, dv, ia[worst], ca[worst].pos.x,
            ca[worst].pos.y, A->name, cb[worst].pos.x, cb[worst].pos.y, B->name);
        return DW_END_FAILED;
    }
    if (dp > c->res->worst_dp)
        c->res->worst_dp = dp;
    c->apart = dp > dv ? dp : dv;
    return DW_END_DONE;
}

/* ---- the scene played ----------------------------------------------------------------------- */

/* The reference set to the world's state: the next call starts from the same numbers. */
static void resync(dw_sim *ref, const dw_sim *from)
{
    cc_circle c[DW_MAX_CIRCLES];
    int ids[DW_MAX_CIRCLES], n = sim_get(from, ids, c, DW_MAX_CIRCLES), k;
    for (k = 0; k < n; k++)
        ref->r->body[ids[k]].c = c[k];
    ref->r->now = cc_world_time(from->w);
}

enum { CALL_ADD, CALL_REMOVE, CALL_SET, CALL_PROPS, CALL_SEGMENT_PROPS, CALL_STEP, CALL_ADD_BATCH };
static const char *const call_name[] = {"add", "remove", "set", "props", "segment props", "step", "add batch"};

typedef struct dw_call {
    int kind, id;
    cc_circle c;
    int n;                     /* a batch add: its circles */
    cc_circle batch[DW_BATCH];
    cc_circle_props props;
    cc_segment_props seg_props;
    double dt;
} dw_call;

static int sim_call(dw_sim *m, const dw_call *k)
{
    int i;
    m->n_events = 0;
    m->n_sensed = 0;
    m->batch_failed = -77;
    for (i = 0; i < DW_BATCH; i++)
        m->batch_ids[i] = -77;
    if (m->w != NULL)
        switch (k->kind) {
        case CALL_ADD: return cc_world_add_circle(m->w, &k->c);
        case CALL_ADD_BATCH: return cc_world_add_circles(m->w, k->batch, k->n, m->batch_ids, &m->batch_failed);
        case CALL_REMOVE: return cc_world_remove_circle(m->w, k->id);
        case CALL_SET: return cc_world_set_circle(m->w, k->id, &k->c);
        case CALL_PROPS: return cc_world_set_circle_props(m->w, k->id, &k->props);
        case CALL_SEGMENT_PROPS: return cc_world_set_segment_props(m->w, k->id, &k->seg_props);
        default: return cc_world_step(m->w, k->dt);
        }
    switch (k->kind) {
    case CALL_ADD: return rw_add_circle(m->r, &k->c);
    case CALL_ADD_BATCH: return rw_add_circles(m->r, k->batch, k->n, m->batch_ids, &m->batch_failed);
    case CALL_REMOVE: return rw_remove_circle(m->r, k->id);
    case CALL_SET: return rw_set_circle(m->r, k->id, &k->c);
    case CALL_PROPS: return rw_set_circle_props(m->r, k->id, &k->props);
    case CALL_SEGMENT_PROPS: return rw_set_segment_props(m->r, k->id, &k->seg_props);
    default: return rw_step(m->r, k->dt);
    }
}

/* Random properties: restitution in [0.3, 1], one of three category bits, a mask that admits
 * everything or all but one bit, a sensor now and then. */
static cc_circle_props random_props(dw_scene *sc)
{
    cc_circle_props p;
    p.struct_size = sizeof p;
    p.restitution = rng_unit(&sc->rng) < 0.5 ? 1.0 : rng_range(&sc->rng, 0.3, 1.0);
    p.rolling_decel = sc->decel;
    p.category = 1u << rng_int(&sc->rng, 3);
    p.mask = rng_unit(&sc->rng) < 0.6 ? 0xFFFFFFFFu : ~(1u << rng_int(&sc->rng, 3));
    p.sensor = rng_unit(&sc->rng) < 0.1;
    return p;
}

/* Does c stay clear (the margin of overlaps()) of the n circles in f? */
static int clear_of(const dw_scene *sc, const cc_circle *c, const cc_circle *f, int n)
{
    int i;
    for (i = 0; i < n; i++) {
        double dx = diff(sc, f[i].pos.x, c->pos.x, 0), dy = diff(sc, f[i].pos.y, c->pos.y, 1);
        double R = f[i].radius + c->radius;
        if (dx * dx + dy * dy < R * R * 1.0201)
            return 0;
    }
    return 1;
}

/* A batch add: up to DW_BATCH circles (the first round: those still to place, as many as fit),
 * each placed as add places one and apart from the others' footprints (where each is, where
 * its push-apart takes it and the circle it lands on), so that the order of the adds decides
 * nothing the reference could not know. Now and then (after the first round) one of them is
 * invalid, or the batch finds the world full: both must refuse it alike, adding none. */
static int next_batch(dw_scene *sc, const dw_sim *ref, int step, int n_live, int max_circles, dw_call *k)
{
    cc_circle foot[3 * DW_BATCH];
    int want = step == 0 ? (sc->to_place < DW_BATCH ? sc->to_place : DW_BATCH) : 1 + rng_int(&sc->rng, 3), nf = 0;
    if ((step == 0 || !sc->may_fill) && want > max_circles - n_live)
        want = max_circles - n_live;
    if (want <= 0 && !sc->may_fill)
        return 0;
    if (step > 0 && n_live >= max_circles && rng_unit(&sc->rng) < 0.7)
        return 0; /* a full world: a refused batch now and then, not every round */
    k->kind = CALL_ADD_BATCH;
    k->n = 0;
    while (k->n < want) {
        cc_circle c, pushed[2];
        int tries;
        for (tries = 0; tries < 5; tries++)
            if (place(sc, ref, -1, step > 0 && rng_unit(&sc->rng) < 0.25, &c, pushed) && clear_of(sc, &c, foot, nf) &&
                clear_of(sc, &pushed[0], foot, nf) && clear_of(sc, &pushed[1], foot, nf))
                break;
        if (tries == 5)
            break;
        foot[nf++] = c, foot[nf++] = pushed[0], foot[nf++] = pushed[1];
        k->batch[k->n++] = c;
    }
    if (step == 0)
        sc->to_place -= want;
    if (step > 0 && k->n > 0 && rng_unit(&sc->rng) < 0.1)
        k->batch[rng_int(&sc->rng, k->n)].radius = 0.0; /* invalid: the batch is refused at its index */
    return k->n > 0 || step > 0;
}

/* The next call of the scene (a step ends each round of calls). Returns 0 when there is none
 * to make this time (nothing to remove, no place found). */
static int next_call(dw_scene *sc, const dw_sim *ref, int step, int last, int max_circles, dw_call *k)
{
    cc_circle live[DW_MAX_CIRCLES];
    int ids[DW_MAX_CIRCLES], n_live = sim_get(ref, ids, live, DW_MAX_CIRCLES);
    memset(k, 0, sizeof *k);
    k->id = -1;
    k->kind = last ? CALL_STEP : step == 0 ? CALL_ADD : rng_int(&sc->rng, sc->props ? 5 : 3);
    if (k->kind == CALL_ADD && sc->batch)
        return next_batch(sc, ref, step, n_live, max_circles, k);
    switch (k->kind) {
    case CALL_ADD:
        return n_live < max_circles && place(sc, ref, -1, step > 0 && rng_unit(&sc->rng) < 0.25, &k->c, NULL);
    case CALL_REMOVE:
    case CALL_SET:
    case CALL_PROPS:
        if (n_live == 0)
            return 0;
        k->id = ids[rng_int(&sc->rng, n_live)];
        if (k->kind == CALL_PROPS)
            k->props = random_props(sc);
        return k->kind != CALL_SET || place(sc, ref, k->id, rng_unit(&sc->rng) < 0.25, &k->c, NULL);
    case CALL_SEGMENT_PROPS:
        if (sc->n_seg == 0)
            return 0;
        k->id = rng_int(&sc->rng, sc->n_seg);
        k->seg_props.struct_size = sizeof k->seg_props;
        k->seg_props.restitution = rng_range(&sc->rng, 0.3, 1.0);
        k->seg_props.category = 1u << rng_int(&sc->rng, 3);
        k->seg_props.mask = rng_unit(&sc->rng) < 0.6 ? 0xFFFFFFFFu : ~(1u << rng_int(&sc->rng, 3));
        return 1;
    default:
        k->dt = sc->T * rng_log(&sc->rng, 1e-3, 0.5);
        return 1;
    }
}

void dw_run_scene(uint64_t seed, dw_pairing pairing, unsigned long max_events, dw_result *out)
{
    dw_scene sc;
    dw_sim *sims = (dw_sim *)calloc(3, sizeof *sims);
    dw_sim *A, *B, *ref;
    dw_cmp cmp;
    cc_world_def def;
    int n_sims, n0, k, step, small;
    memset(out, 0, sizeof *out);
    memset(&sc, 0, sizeof sc);
    sc.rng.s = seed * UINT64_C(0x2545F4914F6CDD1D) + 1u;
    sc.batch = (int)(seed & 1u); /* odd scenes add in batches (no draw: the even ones stay as they were) */
    sc.may_fill = pairing == DW_WORLD_VS_REFERENCE;
    /* the scene's shape */
    n0 = 2 + rng_int(&sc.rng, pairing == DW_SMALL_VS_GRID ? 20 : 63);
    sc.rmin = 1.0;
    sc.rmax = rng_log(&sc.rng, 1.0, 100.0);
    sc.vmax = rng_log(&sc.rng, 0.01, 100.0);
    {   /* a box that holds the circles at an area fraction of 5% to 40% (E[r^2] of log-uniform radii) */
        double r2 = sc.rmax > 1.0 + 1e-9 ? (sc.rmax * sc.rmax - 1.0) / (2.0 * log(sc.rmax)) : 1.0;
        sc.box = sqrt(n0 * 3.14159 * r2 / rng_range(&sc.rng, 0.05, 0.4)) * 0.5 + sc.rmax;
    }
    sc.L = 2.0 * sc.box;
    sc.T = sc.L / sc.vmax;
    sc.J = 10.0 * sc.rmax * sc.rmax * sc.vmax;
    cc_world_def_init(&def);
    small = pairing == DW_SMALL_VS_GRID || rng_unit(&sc.rng) < 0.3;
    def.max_circles = small ? 32 : 33 + rng_int(&sc.rng, DW_MAX_CIRCLES - 33);
    def.max_segments = 64;
    def.restitution = rng_unit(&sc.rng) < 0.5 ? 1.0 : rng_range(&sc.rng, 0.3, 1.0);
    def.rest_speed = rng_unit(&sc.rng) < 0.3 ? sc.vmax * 1e-3 : 0.0;
    sc.props = rng_unit(&sc.rng) < 0.5;
    /* a third of the scenes roll to rest: a circle at the largest speed stops after 0.05 to 2 of
     * the box's widths */
    sc.decel = rng_unit(&sc.rng) < 0.33 ? sc.vmax * sc.vmax / (2.0 * sc.L * rng_log(&sc.rng, 0.05, 2.0)) : 0.0;
    def.rolling_decel = sc.decel;
    /* a jam (see DW_END_JAMMED) costs little: the reference's cap counts impacts, each O(N^2);
     * a rolling scene's pushed pair jams to it (1.1 has no carried contacts), so its cap is lower */
    def.max_events = sc.decel > 0.0 ? 1000 : 3000;
    def.restitution_mix = sc.props ? rng_int(&sc.rng, 4) : CC_MIX_MIN;
    /* every other scene that sets no property runs in worlds that reserve nothing more than it
     * uses (def.uses; no draw: the scenes stay as they were) */
    if (!sc.props && (seed >> 1 & 1u))
        def.uses = sc.decel > 0.0 ? CC_USES_ROLLING : 0u;
    if (rng_unit(&sc.rng) < 0.25) { /* a periodic box: a channel along x (walls along y), or a torus */
        int channel = rng_unit(&sc.rng) < 0.5;
        double b;
        sc.box = sc.box > 3.2 * sc.rmax ? sc.box : 3.2 * sc.rmax; /* room for the images */
        b = sc.box;
        sc.L = 2.0 * b;
        sc.T = sc.L / sc.vmax;
        sc.period[0] = 2.0 * b;
        sc.period[1] = channel ? 0.0 : 2.0 * b;
        def.period.x = sc.period[0];
        def.period.y = sc.period[1];
        if (pairing == DW_SMALL_VS_GRID)
            def.cell_size = 2.2 * sc.rmax; /* a periodic world has a grid too: the same cells */
        if (channel) { /* sides reaching past the period's ends */
            sc.seg[0] = (cc_segment){{-2.0 * b, -b}, {4.0 * b, -b}};
            sc.seg[1] = (cc_segment){{4.0 * b, b}, {-2.0 * b, b}};
            sc.n_seg = 2;
        }
    } else if (rng_unit(&sc.rng) < 0.5) { /* a box of walls */
        double b = sc.box;
        sc.seg[0] = (cc_segment){{-b, -b}, {b, -b}};
        sc.seg[1] = (cc_segment){{b, -b}, {b, b}};
        sc.seg[2] = (cc_segment){{b, b}, {-b, b}};
        sc.seg[3] = (cc_segment){{-b, b}, {-b, -b}};
        sc.n_seg = 4;
    }
    /* walls inside: a few short segments and points, or (a maze, for the walls' tree) up to 56
     * segments of a tenth of the box */
    for (k = def.period.x > 0.0 ? 0 : rng_unit(&sc.rng) < 0.2 ? 20 + rng_int(&sc.rng, 37) : rng_int(&sc.rng, 5);
         k > 0; k--) {
        cc_segment s;
        double len = k > 4 ? 0.1 : 0.3;
        s.a.x = rng_range(&sc.rng, -sc.box, sc.box);
        s.a.y = rng_range(&sc.rng, -sc.box, sc.box);
        s.b = s.a;
        if (rng_unit(&sc.rng) < 0.7) {
            s.b.x += rng_range(&sc.rng, -len, len) * sc.box;
            s.b.y += rng_range(&sc.rng, -len, len) * sc.box;
        }
        sc.seg[sc.n_seg++] = s;
    }
    /* the simulators: A against B; the reference always runs, for its doubts */
    ref = &sims[1];
    A = &sims[0];
    B = ref;
    n_sims = 2;
    if (!sim_make(&sims[0], small ? "world (all pairs)" : "world (grid)", &def, 0) ||
        !sim_make(ref, "reference", &def, 1)) {
        say(out, "cannot make the simulators");
        out->end = DW_END_FAILED;
        goto done;
    }
    ref->r->time_scale = sc.T;
    if (pairing == DW_SMALL_VS_GRID) {
        cc_world_def g = def;
        g.max_circles = 33 + rng_int(&sc.rng, 200);
        /* cells wider than any circle: a wider one would make the gridded world wait for its next
         * step to push it apart ("Overlaps"), which a world without a grid never does */
        g.cell_size = 2.2 * sc.rmax;
        if (!sim_make(&sims[2], "world (grid)", &g, 0)) {
            say(out, "cannot make the gridded world");
            out->end = DW_END_FAILED;
            goto done;
        }
        B = &sims[2];
        n_sims = 3;
    }
    cmp.sc = &sc;
    cmp.res = out;
    cmp.apart = 0.0;
    /* walls, then the first circles (placed apart, a few onto another) */
    for (k = 0; k < sc.n_seg; k++) {
        int s;
        for (s = 0; s < n_sims; s++) {
            int r = sims[s].w != NULL ? cc_world_add_segment(sims[s].w, &sc.seg[k]) : rw_add_segment(sims[s].r, &sc.seg[k]);
            if (r != k) {
                say(out, "add_segment %d returned %d in %s", k, r, sims[s].name);
                out->end = DW_END_FAILED;
                goto done;
            }
        }
    }
    sc.to_place = n0;
    for (step = 0; out->end == DW_END_DONE && out->events_compared < max_events && step < 60; step++) {
        int calls = step == 0 ? (sc.batch ? (n0 + DW_BATCH - 1) / DW_BATCH : n0) : rng_int(&sc.rng, 4), q;
        for (q = 0; q <= calls && out->end == DW_END_DONE; q++) {
            dw_call call;
            int rc[3], s;
            char what[96];
            if (!next_call(&sc, ref, step, q == calls, def.max_circles, &call))
                continue;
            if (dw_trace && call.kind != CALL_STEP) {
                cc_circle live[DW_MAX_CIRCLES];
                int ids[DW_MAX_CIRCLES], n_live = sim_get(ref, ids, live, DW_MAX_CIRCLES);
                for (s = 0; s < n_live; s++)
                    printf("  live %d: ((%.17g, %.17g), (%.17g, %.17g), r %.17g, m %.17g)\n", ids[s], live[s].pos.x,
                           live[s].pos.y, live[s].vel.x, live[s].vel.y, live[s].radius, live[s].mass);
            }
            for (s = 0; s < n_sims; s++)
                rc[s] = sim_call(&sims[s], &call);
            out->calls++;
            if (dw_trace && call.kind == CALL_PROPS)
                printf("  props: e %.17g category %u mask %x sensor %d\n", call.props.restitution,
                       (unsigned)call.props.category, (unsigned)call.props.mask, call.props.sensor);
            if (dw_trace && call.kind == CALL_SEGMENT_PROPS)
                printf("  segment props: e %.17g category %u mask %x\n", call.seg_props.restitution,
                       (unsigned)call.seg_props.category, (unsigned)call.seg_props.mask);
            if (dw_trace && step == 0 && q == 0)
                for (s = 0; s < sc.n_seg; s++)
                    printf("  wall %d: (%.17g, %.17g) - (%.17g, %.17g)\n", s, sc.seg[s].a.x, sc.seg[s].a.y, sc.seg[s].b.x,
                           sc.seg[s].b.y);
            if (dw_trace)
                printf("call %s id %d c = ((%.17g, %.17g), (%.17g, %.17g), r %.17g, m %.17g) dt %.17g -> %d; events "
                       "%d/%d, sensor events %d/%d\n",
                       call_name[call.kind], call.id, call.c.pos.x, call.c.pos.y, call.c.vel.x, call.c.vel.y,
                       call.c.radius, call.c.mass, call.dt, rc[0], A->n_events, B->n_events, A->n_sensed, B->n_sensed);
            snprintf(what, sizeof what, "scene %llu, step %d, %s", (unsigned long long)seed, step, call_name[call.kind]);
            if (call.kind == CALL_STEP && rc[1] == CC_EVENT_LIMIT) {
                out->end = DW_END_JAMMED; /* the reference, whose cap counts impacts only */
                break;
            }
            for (s = 1; s < n_sims; s++)
                if (rc[s] != rc[0] && (ref->r->doubt.push || (sc.decel > 0.0 && rc[0] == CC_EVENT_LIMIT))) {
                    /* a pushing pair's impacts without end (a ball bouncing on a floor: 1.1 has no
                     * carried contacts), in the world and not in the reference, where rounding
                     * decided otherwise (docs/TESTING.md) */
                    out->end = DW_END_JAMMED;
                } else if (rc[s] != rc[0]) {
                    say(out, "%s: %s returned %d, %s %d", what, sims[0].name, rc[0], sims[s].name, rc[s]);
                    out->end = DW_END_FAILED;
                }
            if (call.kind == CALL_ADD_BATCH)
                out->batches++, out->batches_refused += rc[0] < 0;
            if (out->end == DW_END_DONE && call.kind == CALL_ADD_BATCH)
                for (s = 1; s < n_sims; s++) {
                    int i;
                    if (sims[s].batch_failed != sims[0].batch_failed)
                        say(out, "%s: %s's failed %d, %s's %d", what, sims[0].name, sims[0].batch_failed, sims[s].name,
                            sims[s].batch_failed);
                    for (i = 0; i < DW_BATCH; i++)
                        if (sims[s].batch_ids[i] != sims[0].batch_ids[i])
                            say(out, "%s: %s's id %d is %d, %s's %d", what, sims[0].name, i, sims[0].batch_ids[i],
                                sims[s].name, sims[s].batch_ids[i]);
                    if (sims[s].batch_failed != sims[0].batch_failed)
                        out->end = DW_END_FAILED;
                    for (i = 0; i < DW_BATCH; i++)
                        if (sims[s].batch_ids[i] != sims[0].batch_ids[i])
                            out->end = DW_END_FAILED;
                }
            if (out->end != DW_END_DONE)
                break;
            out->end = compare_call(&cmp, A, B, ref, what);
            if (out->end == DW_END_DONE)
                out->end = compare_sensors(&cmp, A, B, ref, what);
            if (dw_trace && out->end != DW_END_DONE) {
                int e, z;
                for (z = 0; z < 2; z++) {
                    const dw_sim *m = z == 0 ? A : B;
                    for (e = 0; e < m->n_sensed && e < DW_LOG_MAX; e++)
                        printf("  %s sensor event %d: (%d, %d, begin %d) t %.17g\n", m->name, e, m->sensed[e].sensor,
                               m->sensed[e].visitor, m->sensed[e].begin, m->sensed[e].t);
                    for (e = 0; e < m->n_events && e < DW_LOG_MAX; e++)
                        printf("  %s event %d: (%d, %d, wall %d) t %.17g impulse %.17g n (%.17g, %.17g)\n", m->name, e,
                               m->log[e].e.a, m->log[e].e.b, m->log[e].e.segment, m->log[e].e.t, m->log[e].e.impulse,
                               m->log[e].e.normal.x, m->log[e].e.normal.y);
                }
            }
            if (out->end == DW_END_DONE)
                out->end = compare_states(&cmp, A, B, ref, what);
            if (dw_trace && out->end != DW_END_DONE) {
                cc_circle ca[DW_MAX_CIRCLES], cb[DW_MAX_CIRCLES];
                int ia[DW_MAX_CIRCLES], na = sim_get(A, ia, ca, DW_MAX_CIRCLES), nb = sim_get(B, NULL, cb, DW_MAX_CIRCLES);
                for (s = 0; s < na && s < nb; s++)
                    if (memcmp(&ca[s], &cb[s], sizeof ca[s]) != 0)
                        printf("  after: circle %d at (%.17g, %.17g) v (%.17g, %.17g) in %s, (%.17g, %.17g) v (%.17g, "
                               "%.17g) in %s\n", ia[s], ca[s].pos.x, ca[s].pos.y, ca[s].vel.x, ca[s].vel.y, A->name,
                               cb[s].pos.x, cb[s].pos.y, cb[s].vel.x, cb[s].vel.y, B->name);
            }
            if (call.kind == CALL_STEP)
                out->steps_compared++;
            resync(ref, A);
        }
    }
done:
    for (k = 0; k < 3; k++)
        sim_free(&sims[k]);
    free(sims);
}
