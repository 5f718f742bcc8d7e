/* The header's promises about casts, queries, the hash and sensor events, kept in every mode and
 * state: EXACT, SWEPT and DISCRETE; before the first step and after one; after add, set, remove,
 * add_segment and set_circle_props; and from inside the callbacks. Two worked cases first (a
 * periodic cast across the edge, a sensor's begin and end from inside add and set), then a
 * property test over random worlds and call sequences that checks every cast and query against a
 * brute force over the public pair functions (every image of every circle), the hash against
 * reads and copies, and the sensor events against the overlaps the positions show. */
#include "unity.h"

#include "test_world_util.h"

#include <stdio.h>

void setUp(void) {}
void tearDown(void) {}

static const char *mode_name[3] = {"EXACT", "SWEPT", "DISCRETE"};

static cc_world *make(tw_mem *m, int mode, double px, double py, int max_circles, int max_segments,
                      cc_sensor_fn on_sensor, cc_contact_fn on_contact, void *user)
{
    cc_world_def d;
    d = tw_def(mode, max_circles, max_segments);
    d.period.x = px;
    d.period.y = py;
    d.on_sensor = on_sensor;
    d.on_contact = on_contact;
    d.user = user;
    d.max_events = 2000; /* a circle squeezed between a wall and an immovable one jams a step */
    return tw_make(m, &d, 0);
}

/* ---- Worked cases --------------------------------------------------------------------------- */

/* Period 10 along x, one circle of radius 0.5 at (5, 5) (also in a 10 x 10 box: at (1.5, 5)).
 * A ray from x = 7 moving +9: the image at 15 is entered at x = 14.5, t = 7.5 / 9; a circle of
 * radius 0.25 at x = 14.25, t = 7.25 / 9. From x = 17 by +30 (outside the period, a path of
 * three periods against one circle): the image at 25, entered at 24.5, t = 7.5 / 30. In every
 * mode, before the first step and after one. */
static void test_periodic_casts_see_every_image(void)
{
    int mode, stepped, box;
    for (box = 0; box < 2; box++)
        for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++)
            for (stepped = 0; stepped < 2; stepped++) {
                tw_mem m;
                cc_world *w = make(&m, mode, 10.0, box ? 10.0 : 0.0, 8, 0, NULL, NULL, NULL);
                double cx = box ? 1.5 : 5.0, e = cx - 5.0; /* (box: every image 3.5 nearer) */
                cc_circle c = tw_circle(cx, 5, 0, 0, 0.5, 1);
                cc_cast_hit h;
                char what[96];
                TEST_ASSERT_NOT_NULL(w);
                TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &c));
                if (stepped)
                    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.01));
                sprintf(what, "%s, %s, %s", box ? "box" : "channel", mode_name[mode], stepped ? "stepped" : "before the first step");
                TEST_ASSERT_EQUAL_INT_MESSAGE(CC_HIT, cc_world_cast_circle(w, tw_vec2(7, 5), 0.0, tw_vec2(9, 0), 0xFFFFFFFFu, &h), what);
                TEST_ASSERT_EQUAL_INT_MESSAGE(0, h.circle, what);
                TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-12, (7.5 + e) / 9.0, h.t, what);
                TEST_ASSERT_EQUAL_INT_MESSAGE(CC_HIT, cc_world_cast_circle(w, tw_vec2(7, 5), 0.25, tw_vec2(9, 0), 0xFFFFFFFFu, &h), what);
                TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-12, (7.25 + e) / 9.0, h.t, what);
                TEST_ASSERT_EQUAL_INT_MESSAGE(CC_HIT, cc_world_cast_circle(w, tw_vec2(17, 5), 0.0, tw_vec2(30, 0), 0xFFFFFFFFu, &h), what);
                TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-12, (7.5 + e) / 30.0, h.t, what);
                TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-12, 24.5 + e, h.point.x, what); /* the image's own coordinates */
                /* towards -x from x = 3 by -9: the image at -5 (its surface at -4.5): t = 7.5 / 9 */
                TEST_ASSERT_EQUAL_INT_MESSAGE(CC_HIT, cc_world_cast_circle(w, tw_vec2(3 + 2 * e, 5), 0.0, tw_vec2(-9, 0), 0xFFFFFFFFu, &h), what);
                TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-12, (7.5 + e) / 9.0, h.t, what);
                tw_free(&m);
            }
}

typedef struct sensed {
    int n, begins, ends, sensor, visitor, last_begin;
} sensed;

static void count_sensor(const cc_sensor_event *e, void *user)
{
    sensed *s = (sensed *)user;
    s->n++;
    s->begins += e->begin != 0;
    s->ends += e->begin == 0;
    s->sensor = e->sensor;
    s->visitor = e->visitor;
    s->last_begin = e->begin;
}

/* A sensor of radius 1 at (5, 5). A circle of radius 0.5 added at (5.5, 5) overlaps it: begin,
 * from inside the add; set to (9, 9): end, from inside the set; set back: begin; made a sensor
 * through its properties: end (sensors do not sense sensors). In every mode, before the first
 * step, after one, and after a wall was added (which makes EXACT rebuild at its next step). */
static void test_sensor_events_at_once(void)
{
    int mode, state;
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++)
        for (state = 0; state < 3; state++) {
            tw_mem m;
            sensed s;
            cc_world *w;
            cc_circle sensor = tw_circle(5, 5, 0, 0, 1.0, INFINITY), v = tw_circle(5.5, 5, 0, 0, 0.5, 1);
            cc_circle_props p;
            int vid;
            char what[96];
            memset(&s, 0, sizeof s);
            w = make(&m, mode, 0.0, 0.0, 8, 4, count_sensor, NULL, &s);
            TEST_ASSERT_NOT_NULL(w);
            TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &sensor));
            p.struct_size = sizeof p;
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle_props(w, 0, &p));
            p.sensor = 1;
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, 0, &p));
            if (state >= 1)
                TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.01));
            if (state == 2) {
                cc_segment wall = tw_segment(0, 0, 10, 0);
                TEST_ASSERT_EQUAL_INT(0, cc_world_add_segment(w, &wall));
            }
            sprintf(what, "%s, %s", mode_name[mode], state == 0 ? "before the first step" : state == 1 ? "stepped" : "after add_segment");
            vid = cc_world_add_circle(w, &v);
            TEST_ASSERT_EQUAL_INT_MESSAGE(1, s.n, what);
            TEST_ASSERT_EQUAL_INT_MESSAGE(1, s.last_begin, what);
            TEST_ASSERT_EQUAL_INT_MESSAGE(0, s.sensor, what);
            TEST_ASSERT_EQUAL_INT_MESSAGE(vid, s.visitor, what);
            v.pos = tw_vec2(9, 9);
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle(w, vid, &v));
            TEST_ASSERT_EQUAL_INT_MESSAGE(2, s.n, what);
            TEST_ASSERT_EQUAL_INT_MESSAGE(0, s.last_begin, what);
            v.pos = tw_vec2(5, 5.75);
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle(w, vid, &v));
            TEST_ASSERT_EQUAL_INT_MESSAGE(3, s.n, what);
            TEST_ASSERT_EQUAL_INT_MESSAGE(1, s.last_begin, what);
            p.struct_size = sizeof p;
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle_props(w, vid, &p));
            p.sensor = 1;
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, vid, &p));
            TEST_ASSERT_EQUAL_INT_MESSAGE(4, s.n, what);
            TEST_ASSERT_EQUAL_INT_MESSAGE(0, s.last_begin, what);
            p.sensor = 0; /* a visitor again, where it overlaps the sensor: begin at once */
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_set_circle_props(w, vid, &p));
            TEST_ASSERT_EQUAL_INT_MESSAGE(5, s.n, what);
            TEST_ASSERT_EQUAL_INT_MESSAGE(1, s.last_begin, what);
            TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.01)); /* nothing changed: nothing more */
            TEST_ASSERT_EQUAL_INT_MESSAGE(5, s.n, what);
            tw_free(&m);
        }
}

/* ---- The property test ---------------------------------------------------------------------- */

#define PT_MAX 40
#define PT_SEG 6

typedef struct pt {
    cc_world *w;
    int mode;
    double P[2];
    uint64_t rng;
    int n_seg;
    cc_segment seg[PT_SEG];
    unsigned char inside[PT_MAX][PT_MAX]; /* [sensor][visitor], as the events said */
    int in_callback, failures, checks, failed_casts, failed_queries, failed_sensors;
    int stepping, settles_now; /* the call is a step; EXACT has stepped since its last wall */
    int removing;              /* the call is a remove: it fires nothing */
    double call_t0;            /* the world time when the call began */
    long contacts_in_call;
    long casts, queries, events, callback_checks, sensor_events, contact_events;
    char call[64];
} pt;

static void fail(pt *t, const char *what)
{
    t->failed_casts += strstr(what, "cast") != NULL;
    t->failed_queries += strstr(what, "query") != NULL;
    t->failed_sensors += strstr(what, "sensor") != NULL;
    if (t->failures++ < 10)
        printf("  %s mode, period (%g, %g), after %s%s: %s\n", mode_name[t->mode], t->P[0], t->P[1], t->call,
               t->in_callback ? " (from a callback)" : "", what);
}

/* The live circles with their properties, as the public getters give them. */
typedef struct pt_state {
    int n, ids[PT_MAX];
    cc_circle c[PT_MAX];
    cc_circle_props p[PT_MAX];
} pt_state;

static void read_state(const cc_world *w, pt_state *s)
{
    int k;
    s->n = cc_world_get_circles(w, s->ids, s->c, PT_MAX);
    for (k = 0; k < s->n; k++) {
        s->p[k].struct_size = sizeof s->p[k];
        (void)cc_world_get_circle_props(w, s->ids[k], &s->p[k]);
    }
}

/* The first image index n along axis k whose centre q + n P can lie within R of [lo, hi]. */
static void images(double P, double q, double lo, double hi, double R, int *n0, int *n1)
{
    if (P <= 0.0) {
        *n0 = *n1 = 0;
        return;
    }
    *n0 = (int)floor((lo - R - q) / P) - 1;
    *n1 = (int)ceil((hi + R - q) / P) + 1;
}

/* The brute force's best: (t, touch, wall, id), smallest first, as the header orders them. */
typedef struct bf_hit {
    double t;
    int touch, wall, id, found;
    double second; /* the next candidate's t (another id): within tolerance, the order is rounding's */
} bf_hit;

static void bf_offer(bf_hit *b, double t, int touch, int wall, int id)
{
    int better = !b->found || t < b->t || (t == b->t && (touch < b->touch || (touch == b->touch && (wall < b->wall || (wall == b->wall && id < b->id)))));
    if (b->found && (wall != b->wall || id != b->id)) {
        double other = better ? b->t : t;
        if (fabs(other - (better ? t : b->t)) < fabs(b->second - (better ? t : b->t)))
            b->second = other;
    }
    if (better) {
        b->t = t, b->touch = touch, b->wall = wall, b->id = id, b->found = 1;
    }
}

/* A ray from p along d against wall s, plainly: where p + t d crosses it, t in [0, 1]. */
static int ray_wall(cc_vec2 p, cc_vec2 d, const cc_segment *s, double *t)
{
    double ux = s->b.x - s->a.x, uy = s->b.y - s->a.y, ax = s->a.x - p.x, ay = s->a.y - p.y;
    double den = d.x * uy - d.y * ux, tt, v;
    if (den == 0.0)
        return 0; /* parallel: the random scenes do not cast along a wall's line */
    tt = (ax * uy - ay * ux) / den;
    v = (ax * d.y - ay * d.x) / den;
    if (!(tt >= 0.0 && tt <= 1.0 && v >= 0.0 && v <= 1.0))
        return 0;
    *t = tt;
    return 1;
}

/* The brute force of a cast: every image of every live non-sensor circle the filter admits, by
 * cc_sweep (a ray as a circle of half the other's radius against one of the other half: only
 * the sum counts), every wall by cc_sweep_segment (a ray: its crossing). */
static bf_hit bf_cast(const pt *t, const pt_state *s, cc_vec2 p, double r, cc_vec2 d, uint32_t mask, int ignore)
{
    bf_hit b;
    int k, a, c, w;
    memset(&b, 0, sizeof b);
    b.second = HUGE_VAL;
    for (k = 0; k < s->n; k++) {
        int ia0, ia1, ib0, ib1;
        double rb = s->c[k].radius, lo[2], hi[2];
        if (s->ids[k] == ignore || s->p[k].sensor || !(s->p[k].category & mask))
            continue;
        lo[0] = p.x < p.x + d.x ? p.x : p.x + d.x, hi[0] = p.x < p.x + d.x ? p.x + d.x : p.x;
        lo[1] = p.y < p.y + d.y ? p.y : p.y + d.y, hi[1] = p.y < p.y + d.y ? p.y + d.y : p.y;
        images(t->P[0], s->c[k].pos.x, lo[0], hi[0], r + rb, &ia0, &ia1);
        images(t->P[1], s->c[k].pos.y, lo[1], hi[1], r + rb, &ib0, &ib1);
        for (a = ia0; a <= ia1; a++)
            for (c = ib0; c <= ib1; c++) {
                cc_circle me = tw_circle(p.x, p.y, d.x, d.y, r + 0.5 * rb, 1);
                cc_circle im = tw_circle(s->c[k].pos.x + a * t->P[0], s->c[k].pos.y + c * t->P[1], 0, 0, 0.5 * rb, 1);
                cc_contact h;
                int res = cc_sweep(&me, &im, 1.0, &h);
                if (res == CC_HIT)
                    bf_offer(&b, h.t, 1, 0, s->ids[k]);
                else if (res == CC_OVERLAP)
                    bf_offer(&b, 0.0, 0, 0, s->ids[k]);
            }
    }
    for (w = 0; w < t->n_seg; w++) {
        cc_segment_props sp;
        sp.struct_size = sizeof sp;
        (void)cc_world_get_segment_props(t->w, w, &sp);
        if (!(sp.category & mask))
            continue;
        if (r > 0.0) {
            cc_circle me = tw_circle(p.x, p.y, d.x, d.y, r, 1);
            cc_contact h;
            int res = cc_sweep_segment(&me, &t->seg[w], 1.0, &h);
            if (res == CC_HIT)
                bf_offer(&b, h.t, 1, 1, w);
            else if (res == CC_OVERLAP)
                bf_offer(&b, 0.0, 0, 1, w);
        } else {
            double tt;
            if (ray_wall(p, d, &t->seg[w], &tt))
                bf_offer(&b, tt, 1, 1, w);
        }
    }
    return b;
}

static double near_d(double d, double P) { return P > 0.0 ? d - P * floor(d / P + 0.5) : d; }

/* The tolerance within which a contact time or a boundary is rounding's: of the numbers that
 * make it (the path's coordinates and the periods), far above a few ulps. */
static double scale_of(const pt *t, cc_vec2 p, cc_vec2 d, double r)
{
    return fabs(p.x) + fabs(p.y) + fabs(d.x) + fabs(d.y) + r + t->P[0] + t->P[1] + 20.0;
}

static double rnd(pt *t, double lo, double hi) { return lo + (hi - lo) * tw_rand(&t->rng); }

/* One random cast (ray or circle; mask; filter) against the brute force. */
static void check_cast(pt *t, const pt_state *s)
{
    cc_vec2 p, d;
    double r = tw_rand(&t->rng) < 0.4 ? 0.0 : rnd(t, 0.05, 1.5), len = tw_rand(&t->rng) < 0.7 ? rnd(t, 0.5, 12) : rnd(t, 12, 80);
    double ang = rnd(t, 0, 6.283185307179586), tol;
    uint32_t mask = tw_rand(&t->rng) < 0.7 ? 0xFFFFFFFFu : (uint32_t)(1u + (t->rng >> 40) % 3u);
    int ignore = tw_rand(&t->rng) < 0.3 && s->n > 0 ? s->ids[(int)(tw_rand(&t->rng) * s->n)] : -1, res, want;
    cc_cast_hit h;
    cc_query_filter f = CC_QUERY_FILTER_DEFAULT;
    bf_hit b;
    /* from inside the box, near an edge, or periods out */
    p.x = tw_rand(&t->rng) < 0.5 ? rnd(t, -1, 11) : rnd(t, -45, 55);
    p.y = tw_rand(&t->rng) < 0.5 ? rnd(t, -1, 11) : rnd(t, -45, 55);
    if (tw_rand(&t->rng) < 0.25)
        ang = floor(ang / 1.5707963267948966 + 0.5) * 1.5707963267948966; /* along an axis */
    d.x = len * cos(ang), d.y = len * sin(ang);
    if (fabs(d.x) < 1e-12 * len)
        d.x = 0.0;
    if (fabs(d.y) < 1e-12 * len)
        d.y = 0.0;
    f.mask = mask;
    f.ignore = ignore;
    res = ignore < 0 && tw_rand(&t->rng) < 0.5 ? cc_world_cast_circle(t->w, p, r, d, mask, &h)
                                               : cc_world_cast_circle_filtered(t->w, p, r, d, &f, &h);
    b = bf_cast(t, s, p, r, d, mask, ignore);
    want = !b.found ? CC_MISS : b.touch ? CC_HIT : CC_OVERLAP;
    t->casts++;
    tol = 1e-9 * scale_of(t, p, d, r) / (len + 1e-300);
    if (!b.found || b.t > 1.0 - tol || (b.t < tol && want == CC_HIT)) {
        /* a graze at the path's end or its start: hit or miss, touch or overlap are rounding's */
        if (res != CC_MISS && res != CC_HIT && res != CC_OVERLAP)
            fail(t, "a cast gave an error");
        if (b.found || res == CC_MISS)
            return;
    }
    if (res != want) {
        char msg[256];
        sprintf(msg, "cast from (%.17g, %.17g) radius %g by (%.17g, %.17g): %d, brute force %d (t %.17g, %s %d)", p.x, p.y, r, d.x,
                d.y, res, want, b.t, b.wall ? "wall" : "circle", b.id);
        fail(t, msg);
        return;
    }
    if (res == CC_MISS)
        return;
    if (fabs(h.t - b.t) > tol) {
        char msg[256];
        sprintf(msg, "cast from (%.17g, %.17g) radius %g by (%.17g, %.17g): t %.17g, brute force %.17g", p.x, p.y, r, d.x, d.y, h.t, b.t);
        fail(t, msg);
        return;
    }
    if (fabs(b.second - b.t) > tol && ((b.wall ? h.segment : h.circle) != b.id || (b.wall ? h.circle : h.segment) != -1)) {
        char msg[256];
        sprintf(msg, "cast from (%.17g, %.17g) by (%.17g, %.17g): hit circle %d wall %d, brute force %s %d", p.x, p.y, d.x, d.y,
                h.circle, h.segment, b.wall ? "wall" : "circle", b.id);
        fail(t, msg);
    }
}

/* One random query (disc or box, centred anywhere) against the brute force: each circle's image
 * nearest the query's centre; a box as wide as a period holds every coordinate along it. A circle
 * within rounding of the boundary may be in or out. */
static void check_query(pt *t, const pt_state *s)
{
    int box = tw_rand(&t->rng) < 0.5, ids[PT_MAX], n, k, want[PT_MAX], nw = 0, nu = 0, i;
    double cx = tw_rand(&t->rng) < 0.5 ? rnd(t, -1, 11) : rnd(t, -95, 105), cy = tw_rand(&t->rng) < 0.5 ? rnd(t, -1, 11) : rnd(t, -95, 105);
    double r = rnd(t, 0, 3), hw = rnd(t, 0, 2.5), hh = rnd(t, 0, 2.5), tol;
    uint32_t mask = tw_rand(&t->rng) < 0.7 ? 0xFFFFFFFFu : (uint32_t)(1u + (t->rng >> 40) % 3u);
    int ignore = tw_rand(&t->rng) < 0.3 && s->n > 0 ? s->ids[(int)(tw_rand(&t->rng) * s->n)] : -1;
    int full[2] = {0, 0};
    cc_query_filter f = CC_QUERY_FILTER_DEFAULT;
    if (box && tw_rand(&t->rng) < 0.15) {
        hw = t->P[0] > 0.0 ? 0.5 * t->P[0] + 0.1 : 30.0; /* as wide as the period */
        full[0] = t->P[0] > 0.0;
    }
    f.mask = mask;
    f.ignore = ignore;
    if (box) {
        cc_vec2 lo = tw_vec2(cx - hw, cy - hh), hi = tw_vec2(cx + hw, cy + hh);
        n = ignore < 0 && tw_rand(&t->rng) < 0.5 ? cc_world_query_box(t->w, lo, hi, mask, ids, PT_MAX)
                                                 : cc_world_query_box_filtered(t->w, lo, hi, &f, ids, PT_MAX);
    } else {
        n = ignore < 0 && tw_rand(&t->rng) < 0.5 ? cc_world_query_circle(t->w, tw_vec2(cx, cy), r, mask, ids, PT_MAX)
                                                 : cc_world_query_circle_filtered(t->w, tw_vec2(cx, cy), r, &f, ids, PT_MAX);
    }
    t->queries++;
    /* wrapping the centre into the period rounds it by an ulp of its coordinate: the boundary's
     * tolerance is of that size, plus the distance's own rounding */
    tol = 1e-12 * (fabs(cx) + fabs(cy) + t->P[0] + t->P[1] + 10.0);
    for (k = 0; k < s->n; k++) {
        double dx, dy, g, rb = s->c[k].radius;
        if (s->ids[k] == ignore || !(s->p[k].category & mask))
            continue;
        dx = near_d(s->c[k].pos.x - cx, t->P[0]);
        dy = near_d(s->c[k].pos.y - cy, t->P[1]);
        if (box) {
            double ex = full[0] ? 0.0 : fabs(dx) > hw ? fabs(dx) - hw : 0.0, ey = fabs(dy) > hh ? fabs(dy) - hh : 0.0;
            g = sqrt(ex * ex + ey * ey) - rb;
            if (fabs(g) <= tol)
                nu++;
            else if (g < 0.0)
                want[nw++] = s->ids[k];
        } else {
            g = sqrt(dx * dx + dy * dy) - (r + rb);
            if (fabs(g) <= tol)
                nu++;
            else if (g < 0.0)
                want[nw++] = s->ids[k];
        }
    }
    if (n < nw || n > nw + nu) {
        char msg[160];
        sprintf(msg, "%s query at (%.17g, %.17g): %d circles, brute force %d (and %d at the boundary)", box ? "box" : "disc", cx, cy, n, nw, nu);
        fail(t, msg);
        return;
    }
    for (k = 1; k < n; k++)
        if (ids[k] <= ids[k - 1])
            fail(t, "a query's ids are not in increasing order");
    for (i = 0; i < nw; i++) {
        for (k = 0; k < n && ids[k] != want[i]; k++)
            ;
        if (k == n) {
            char msg[160];
            sprintf(msg, "%s query at (%.17g, %.17g) misses circle %d", box ? "box" : "disc", cx, cy, want[i]);
            fail(t, msg);
        }
    }
}

/* Sensor events against the positions: every pair the events call inside overlaps, every pair
 * that overlaps by more than rounding is inside (pairs the filters admit; sensors sense no sensor). */
static void check_sensors(pt *t, const pt_state *s)
{
    int a, b;
    for (a = 0; a < s->n; a++)
        for (b = 0; b < s->n; b++) {
            int si = s->ids[a], vi = s->ids[b], want;
            double dx, dy, R, g;
            if (!s->p[a].sensor || a == b)
                continue;
            want = !s->p[b].sensor && (s->p[a].category & s->p[b].mask) && (s->p[b].category & s->p[a].mask);
            dx = near_d(s->c[b].pos.x - s->c[a].pos.x, t->P[0]);
            dy = near_d(s->c[b].pos.y - s->c[a].pos.y, t->P[1]);
            R = s->c[a].radius + s->c[b].radius;
            g = sqrt(dx * dx + dy * dy) - R;
            if (want && fabs(g) <= 1e-9 * (R + 10.0))
                continue; /* at the boundary: rounding's */
            want = want && g < 0.0;
            if (t->inside[si][vi] != want) {
                char msg[160];
                sprintf(msg, "sensor %d, visitor %d: the events say %s, the positions %s (gap %.3g)", si, vi,
                        t->inside[si][vi] ? "inside" : "outside", want ? "inside" : "outside", g);
                fail(t, msg);
            }
        }
}

static void check_reads(pt *t, int casts, int queries)
{
    pt_state s;
    uint64_t h0 = cc_world_hash(t->w);
    int k;
    read_state(t->w, &s);
    for (k = 0; k < casts; k++)
        check_cast(t, &s);
    for (k = 0; k < queries; k++)
        check_query(t, &s);
    if (!t->in_callback) {
        check_sensors(t, &s);
        for (k = 0; k < s.n; k++) { /* the unwrapped position: the position plus whole periods */
            cc_vec2 u;
            int a;
            if (cc_world_get_unwrapped(t->w, s.ids[k], &u) != CC_OK)
                fail(t, "get_unwrapped of a live circle");
            for (a = 0; a < 2; a++) {
                double x = a ? s.c[k].pos.y : s.c[k].pos.x, ux = a ? u.y : u.x, n;
                if (t->P[a] == 0.0 ? ux != x : (n = (ux - x) / t->P[a], fabs(n - floor(n + 0.5)) > 1e-9))
                    fail(t, "an unwrapped position that is not the position plus whole periods");
            }
        }
        if (cc_world_hash(t->w) != h0)
            fail(t, "casts and queries changed the hash");
    }
    t->checks++;
}

static void pt_on_sensor(const cc_sensor_event *e, void *user)
{
    pt *t = (pt *)user;
    t->events++;
    t->sensor_events++;
    if (e->sensor < 0 || e->sensor >= PT_MAX || e->visitor < 0 || e->visitor >= PT_MAX) {
        fail(t, "a sensor event names no circle");
        return;
    }
    if (t->inside[e->sensor][e->visitor] == (e->begin != 0))
        fail(t, "a sensor pair's events do not alternate begin, end");
    t->inside[e->sensor][e->visitor] = e->begin != 0;
    if (t->removing)
        fail(t, "a sensor event from a remove (its overlaps are forgotten)");
    /* at once (add, set, props): at the world's time; from a step: within it (EXACT), at its end */
    if (!t->stepping ? e->t != t->call_t0 : !(e->t >= t->call_t0 && e->t <= cc_world_time(t->w)))
        fail(t, "a sensor event at a time outside its call");
    if (t->in_callback == 0 && (t->events & 3) == 0) { /* what a callback sees is the world now */
        t->in_callback = 1;
        check_reads(t, 1, 1);
        t->callback_checks++;
        t->in_callback = 0;
    }
}

static void pt_on_contact(const cc_contact_event *e, void *user)
{
    pt *t = (pt *)user;
    (void)e;
    t->contact_events++;
    t->contacts_in_call++;
    /* only a step, or in EXACT between steps an add, set or props that pushes apart at once */
    if ((!t->stepping && !t->settles_now) || t->removing)
        fail(t, "a contact event from a call that waits for the next step");
    if (t->in_callback == 0 && (++t->events & 7) == 0) {
        t->in_callback = 1;
        check_reads(t, 1, 1);
        t->callback_checks++;
        t->in_callback = 0;
    }
}

static cc_circle random_circle(pt *t)
{
    double r = rnd(t, 0.2, 0.9);
    double far = tw_rand(&t->rng) < 0.2 ? 30.0 * floor(rnd(t, -3, 3)) : 0.0; /* set periods out */
    return tw_circle(rnd(t, 0, 10) + (t->P[0] > 0.0 ? far : 0.0), rnd(t, 0, 10) + (t->P[1] > 0.0 ? far : 0.0), rnd(t, -2, 2),
                     rnd(t, -2, 2), r, tw_rand(&t->rng) < 0.1 ? INFINITY : rnd(t, 0.5, 2));
}

/* One random world played through a random call sequence, every promise checked after each call. */
static void play(pt *t, int mode, int periods, int max_circles)
{
    tw_mem m, m2;
    cc_world *twin;
    int calls, k, ids[PT_MAX], n;
    t->mode = mode;
    t->P[0] = periods & 1 ? 10.0 : 0.0;
    t->P[1] = periods & 2 ? 10.0 : 0.0;
    t->n_seg = 0;
    memset(t->inside, 0, sizeof t->inside);
    t->w = make(&m, mode, t->P[0], t->P[1], max_circles, PT_SEG, pt_on_sensor, pt_on_contact, t);
    /* a twin fed the same calls, without callbacks: the same state, the same hash */
    twin = make(&m2, mode, t->P[0], t->P[1], max_circles, PT_SEG, NULL, NULL, NULL);
    TEST_ASSERT_NOT_NULL(t->w);
    TEST_ASSERT_NOT_NULL(twin);
    t->settles_now = 0;
    strcpy(t->call, "init");
    check_reads(t, 2, 2);
    for (calls = 0; calls < 40; calls++) {
        double u = tw_rand(&t->rng);
        n = cc_world_get_circles(t->w, ids, NULL, PT_MAX);
        t->call_t0 = cc_world_time(t->w);
        t->stepping = 0;
        if (u < 0.3 || n == 0) {
            cc_circle c = random_circle(t);
            strcpy(t->call, "add");
            (void)cc_world_add_circle(t->w, &c);
            (void)cc_world_add_circle(twin, &c);
        } else if (u < 0.45) {
            cc_circle c = random_circle(t);
            int id = ids[(int)(tw_rand(&t->rng) * n)];
            strcpy(t->call, "set");
            (void)cc_world_set_circle(t->w, id, &c);
            (void)cc_world_set_circle(twin, id, &c);
        } else if (u < 0.52) {
            int id = ids[(int)(tw_rand(&t->rng) * n)];
            strcpy(t->call, "remove");
            (void)cc_world_remove_circle(twin, id);
            t->removing = 1;
            if (cc_world_remove_circle(t->w, id) == CC_OK)
                for (k = 0; k < PT_MAX; k++)
                    t->inside[id][k] = t->inside[k][id] = 0; /* forgotten, not reported */
            t->removing = 0;
        } else if (u < 0.57 && t->n_seg < PT_SEG) {
            /* walls inside the box, away from the periods' edges */
            cc_segment s = tw_segment(rnd(t, 2, 8), rnd(t, 2, 8), rnd(t, 2, 8), rnd(t, 2, 8));
            strcpy(t->call, "add_segment");
            (void)cc_world_add_segment(twin, &s);
            if (cc_world_add_segment(t->w, &s) >= 0)
                t->seg[t->n_seg++] = s;
            t->settles_now = 0; /* EXACT files everything again at its next step */
        } else if (u < 0.7) {
            cc_circle_props p;
            int id = ids[(int)(tw_rand(&t->rng) * n)];
            p.struct_size = sizeof p;
            (void)cc_world_get_circle_props(t->w, id, &p);
            p.sensor = tw_rand(&t->rng) < 0.35;
            p.category = tw_rand(&t->rng) < 0.7 ? 1u : 2u;
            p.mask = tw_rand(&t->rng) < 0.8 ? 0xFFFFFFFFu : 1u;
            strcpy(t->call, "set_circle_props");
            (void)cc_world_set_circle_props(t->w, id, &p);
            (void)cc_world_set_circle_props(twin, id, &p);
        } else {
            double dt = rnd(t, 0.0, 0.25);
            strcpy(t->call, "step");
            t->stepping = 1;
            (void)cc_world_step(t->w, dt);
            (void)cc_world_step(twin, dt);
            t->settles_now = mode == CC_MODE_EXACT;
        }
        t->stepping = 0;
        if (cc_world_hash(twin) != cc_world_hash(t->w))
            fail(t, "a twin fed the same calls hashes otherwise");
        check_reads(t, 4, 3);
        if ((calls & 7) == 7) { /* a copy answers as the original */
            unsigned char *copy = (unsigned char *)malloc(m.bytes + 16);
            unsigned char *al = copy + ((16u - ((size_t)copy & 15u)) & 15u);
            cc_world *w2 = (cc_world *)(void *)al, *w1 = t->w;
            cc_cast_hit h1, h2;
            int r1, r2;
            memcpy(al, m.mem, m.bytes);
            if (cc_world_hash(w2) != cc_world_hash(w1))
                fail(t, "a memcpy'd world hashes otherwise");
            r1 = cc_world_cast_circle(w1, tw_vec2(-3, 4), 0.3, tw_vec2(40, 7), 0xFFFFFFFFu, &h1);
            r2 = cc_world_cast_circle(w2, tw_vec2(-3, 4), 0.3, tw_vec2(40, 7), 0xFFFFFFFFu, &h2);
            if (r1 != r2 || (r1 != CC_MISS && (h1.t != h2.t || h1.circle != h2.circle || h1.segment != h2.segment)))
                fail(t, "a memcpy'd world casts otherwise");
            free(copy);
        }
    }
    tw_free(&m);
    tw_free(&m2);
}

/* Random worlds in every mode, open, periodic in x, in y and in both, all pairs and gridded. */
static void test_promises_in_every_mode_and_state(void)
{
    static pt t;
    int scene, mode;
    memset(&t, 0, sizeof t);
    t.rng = UINT64_C(0x32);
    for (scene = 0; scene < 200; scene++)
        for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++)
            play(&t, mode, scene % 4, scene % 3 == 0 ? 24 : PT_MAX);
    printf("promises: %d checks, %ld casts, %ld queries against the brute force (%ld from inside callbacks), "
           "%ld sensor and %ld contact events; %d failures (%d casts, %d queries, %d sensor pairs)\n", t.checks, t.casts, t.queries,
           t.callback_checks, t.sensor_events, t.contact_events, t.failures, t.failed_casts, t.failed_queries, t.failed_sensors);
    TEST_ASSERT_EQUAL_INT(0, t.failures);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_periodic_casts_see_every_image);
    RUN_TEST(test_sensor_events_at_once);
    RUN_TEST(test_promises_in_every_mode_and_state);
    return UNITY_END();
}
