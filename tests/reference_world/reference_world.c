/* The reference world (see reference_world.h): EXACT's semantics, plainly. Each rule below
 * names the paragraph of the header (include/circlecollide.h, "The world") that it follows. */
#include "reference_world.h"

#include "world/cluster.h"
#include "world/world_internal.h" /* the world's rolling solver (roll.c), until the pair API has one */

#include <math.h>
#include <string.h>

/* The world's own constants, restated (world_internal.h, simultaneous.c). */
#define RW_APPROACH_ROUNDING 0x1p-40 /* "An approach slower than 2^-40 times the summed speeds" */
#define RW_REST_FRACTION 0x1p-20     /* "or slower than rest_speed * 2^-20" */
#define RW_CLU_TOL 0x1p-40           /* "Simultaneous": gap below 2^-40 of the numbers involved */
#define RW_CLU_BODIES 24             /* "Up to 24 circles and 48 contacts per cluster" */
#define RW_CLU_CONTACTS 48

static cc_vec2 v2(double x, double y)
{
    cc_vec2 v;
    v.x = x;
    v.y = y;
    return v;
}

/* "Periodic boxes": position b moved to its image nearest position a (a difference of less
 * than a period either way: positions are kept within the period). */
static cc_vec2 near_image(const rw_world *w, cc_vec2 a, cc_vec2 b)
{
    int k;
    for (k = 0; k < 2; k++) {
        double P = w->period[k], *x = k ? &b.y : &b.x, d = *x - (k ? a.y : a.x);
        if (P > 0.0 && d > 0.5 * P)
            *x -= P;
        else if (P > 0.0 && d < -0.5 * P)
            *x += P;
    }
    return b;
}

/* A coordinate within [0, period), as the world keeps them (fmod is exact). */
static double wrap(double x, double P)
{
    double r = fmod(x, P);
    if (r < 0.0)
        r += P;
    return r >= P ? 0.0 : r;
}

/* "Periodic boxes": every position within its period. */
static void wrap_all(rw_world *w)
{
    int i;
    for (i = 0; i < w->id_end; i++)
        if (w->body[i].alive) {
            if (w->period[0] > 0.0)
                w->body[i].c.pos.x = wrap(w->body[i].c.pos.x, w->period[0]);
            if (w->period[1] > 0.0)
                w->body[i].c.pos.y = wrap(w->body[i].c.pos.y, w->period[1]);
        }
}

static double inf_norm(cc_vec2 v) { return fabs(v.x) > fabs(v.y) ? fabs(v.x) : fabs(v.y); }
static double l1(cc_vec2 v) { return fabs(v.x) + fabs(v.y); }
static double dot(cc_vec2 a, cc_vec2 b) { return a.x * b.x + a.y * b.y; }
static cc_vec2 sub(cc_vec2 a, cc_vec2 b) { return v2(a.x - b.x, a.y - b.y); }
static int at_rest(const cc_circle *c) { return c->vel.x == 0.0 && c->vel.y == 0.0; }

/* "Periodic boxes": at least twice the diameter plus a cell along each periodic axis. */
static int fits_period(const rw_world *w, const cc_circle *c)
{
    double d = 2.0 * c->radius, cell = 1.0625 * d > w->cell_hint ? 1.0625 * d : w->cell_hint;
    int k;
    for (k = 0; k < 2; k++)
        if (w->period[k] > 0.0 && !(2.0 * d + cell <= w->period[k]))
            return 0;
    return 1;
}

static int circle_ok(const cc_circle *c)
{
    return c != NULL && isfinite(c->pos.x) && isfinite(c->pos.y) && isfinite(c->vel.x) && isfinite(c->vel.y) &&
           isfinite(c->radius) && c->radius > 0.0 && c->mass > 0.0 && !isnan(c->mass);
}

static int segment_ok(const cc_segment *s)
{
    return s != NULL && isfinite(s->a.x) && isfinite(s->a.y) && isfinite(s->b.x) && isfinite(s->b.y);
}

/* "Tolerance": a collision approaches faster than rounding and faster than a resting contact. */
static double approach_threshold(const rw_world *w, double speeds)
{
    double a = RW_APPROACH_ROUNDING * speeds, b = w->rest_speed * RW_REST_FRACTION;
    return a > b ? a : b;
}

static int approaching(const rw_world *w, double vn, double speeds)
{
    return vn > RW_APPROACH_ROUNDING * speeds && vn > w->rest_speed * RW_REST_FRACTION;
}

/* Unit vector from a to b, (1, 0) for coincident centres (the world's rule). */
static cc_vec2 centre_normal(cc_vec2 a, cc_vec2 b)
{
    double dx = b.x - a.x, dy = b.y - a.y, d = sqrt(dx * dx + dy * dy);
    return d > 0.0 ? v2(dx / d, dy / d) : v2(1.0, 0.0);
}

/* A circle's contact with a wall now: normal from the centre to the closest point, or the
 * wall's own normal when the centre lies on it. */
static cc_contact wall_contact(const cc_circle *c, const cc_segment *s)
{
    cc_contact k;
    cc_vec2 q = cc_closest_point_on_segment(c->pos, s), d = sub(q, c->pos);
    double dist = sqrt(d.x * d.x + d.y * d.y);
    k.t = 0.0;
    if (dist > 0.0) {
        k.normal = v2(d.x / dist, d.y / dist);
    } else {
        cc_vec2 n = v2(s->a.y - s->b.y, s->b.x - s->a.x);
        double l = sqrt(n.x * n.x + n.y * n.y);
        k.normal = l > 0.0 ? v2(n.x / l, n.y / l) : v2(1.0, 0.0);
    }
    k.depth = c->radius - dist;
    k.point = q;
    return k;
}

static void report(rw_world *w, int a, int b, int seg, cc_vec2 point, cc_vec2 normal, double impulse)
{
    cc_contact_event e;
    e.a = a;
    e.b = b;
    e.segment = seg;
    e.t = w->now;
    e.point = point;
    e.normal = normal;
    e.impulse = impulse;
    w->events++;
    if (w->on_event != NULL)
        w->on_event(&e, w->user);
}

/* A public call begins: nothing is in doubt yet. */
static void new_call(rw_world *w)
{
    w->doubt.tie_gap = w->doubt.graze_gap = w->doubt.slow = w->doubt.slack = HUGE_VAL;
    w->doubt.chain = 0;
    w->doubt.push = 0;
}

/* "Collapse": approaches slower than rest_speed get restitution 0. */
static double mix(int rule, double a, double b)
{
    switch (rule) {
    case CC_MIX_MAX: return a > b ? a : b;
    case CC_MIX_PRODUCT: return a * b;
    case CC_MIX_MEAN: return 0.5 * (a + b);
    default: return a < b ? a : b;
    }
}

/* "Restitution": the mix of the two sides' (b < 0: wall seg). */
static double contact_restitution(const rw_world *w, int a, int b, int seg)
{
    return mix(w->mix, w->body[a].props.restitution,
               b >= 0 ? w->body[b].props.restitution : w->seg_props[seg].restitution);
}

static double restitution_for(const rw_world *w, double approach, int a, int b, int seg)
{
    return approach < w->rest_speed ? 0.0 : contact_restitution(w, a, b, seg);
}

/* "Rolling to rest": circle id's coefficient from its velocity and deceleration now (an
 * immovable circle never decelerates). */
static void reroll(rw_world *w, int id)
{
    const cc_circle *c = &w->body[id].c;
    double d = w->body[id].props.rolling_decel, s = sqrt(c->vel.x * c->vel.x + c->vel.y * c->vel.y);
    w->body[id].roll = isinf(c->mass) || !(d > 0.0) || s == 0.0 ? 0.0 : d / (2.0 * s);
}

/* "Filters" and "Sensors": pairs that interact (impulses, push-apart, clusters). */
static int admits(const cc_circle_props *a, uint32_t b_category, uint32_t b_mask)
{
    return (a->category & b_mask) != 0 && (b_category & a->mask) != 0;
}

static int interact(const rw_world *w, int a, int b)
{
    const cc_circle_props *pa = &w->body[a].props, *pb = &w->body[b].props;
    return admits(pa, pb->category, pb->mask) && !pa->sensor && !pb->sensor;
}

static int wall_interacts(const rw_world *w, int a, int s)
{
    return admits(&w->body[a].props, w->seg_props[s].category, w->seg_props[s].mask) && !w->body[a].props.sensor;
}

/* Sensor s senses circle v. */
static int senses(const rw_world *w, int s, int v)
{
    const cc_circle_props *ps = &w->body[s].props, *pv = &w->body[v].props;
    return s != v && w->body[s].alive && w->body[v].alive && ps->sensor && !pv->sensor &&
           admits(ps, pv->category, pv->mask);
}

static void sensor_report(rw_world *w, int s, int v, int begin)
{
    cc_sensor_event e;
    w->inside[s][v] = (unsigned char)begin;
    e.sensor = s;
    e.visitor = v;
    e.begin = begin;
    e.t = w->now;
    if (w->on_sensor != NULL)
        w->on_sensor(&e, w->user);
}

/* Every pair's membership brought up to what the positions say now. */
static void sensors_sync(rw_world *w)
{
    int s, v;
    for (s = 0; s < w->id_end; s++)
        for (v = 0; v < w->id_end; v++) {
            int in = 0;
            if (senses(w, s, v)) {
                cc_vec2 pv = near_image(w, w->body[s].c.pos, w->body[v].c.pos);
                cc_vec2 d = v2(pv.x - w->body[s].c.pos.x, pv.y - w->body[s].c.pos.y);
                double R = w->body[s].c.radius + w->body[v].c.radius, gap = sqrt(d.x * d.x + d.y * d.y) - R;
                in = d.x * d.x + d.y * d.y < R * R;
                if (fabs(gap) <= 1e-9 * R) /* touching: overlapping or not is rounding's */
                    w->doubt.graze_gap = 0.0;
            }
            if (in != w->inside[s][v])
                sensor_report(w, s, v, in);
        }
}

static double speed_change(cc_vec2 a, cc_vec2 b)
{
    cc_vec2 d = sub(a, b);
    return sqrt(d.x * d.x + d.y * d.y);
}

/* A contact whose normal speed is this close to 0 relative to the speeds: whether it takes an
 * impulse is rounding's. */
static void note_slack(rw_world *w, double vn, double speeds)
{
    if (speeds > 0.0 && fabs(vn) / speeds < w->doubt.slack)
        w->doubt.slack = fabs(vn) / speeds;
}

/* One contact by itself, with the public pair functions (b < 0: wall seg). */
static int resolve_pair(rw_world *w, int a, int b, int seg)
{
    cc_circle *ca = &w->body[a].c;
    cc_circle na = *ca;
    cc_contact k;
    if (b >= 0) {
        cc_circle image = w->body[b].c, *cb = &image, nb;
        cc_vec2 d;
        image.pos = near_image(w, ca->pos, image.pos);
        nb = image;
        d = sub(cb->pos, ca->pos);
        k.t = 0.0;
        k.normal = centre_normal(ca->pos, cb->pos);
        k.depth = ca->radius + cb->radius - sqrt(d.x * d.x + d.y * d.y);
        k.point = v2(ca->pos.x + k.normal.x * (ca->radius - 0.5 * k.depth),
                     ca->pos.y + k.normal.y * (ca->radius - 0.5 * k.depth));
        note_slack(w, dot(sub(ca->vel, cb->vel), k.normal), l1(ca->vel) + l1(cb->vel));
        if (cc_respond(&na, &nb, &k, restitution_for(w, -dot(sub(cb->vel, ca->vel), k.normal), a, b, -1)) != CC_HIT)
            return 0;
        report(w, a, b, -1, k.point, k.normal,
               isinf(ca->mass) ? cb->mass * speed_change(nb.vel, cb->vel) : ca->mass * speed_change(na.vel, ca->vel));
        ca->vel = na.vel;
        w->body[b].c.vel = nb.vel;
        reroll(w, a);
        reroll(w, b);
        return 1;
    }
    k = wall_contact(ca, &w->seg[seg]);
    note_slack(w, dot(ca->vel, k.normal), l1(ca->vel));
    if (isinf(ca->mass) || cc_respond_segment(&na, &k, restitution_for(w, dot(ca->vel, k.normal), a, -1, seg)) != CC_HIT)
        return 0;
    report(w, a, -1, seg, k.point, k.normal, ca->mass * speed_change(na.vel, ca->vel));
    ca->vel = na.vel;
    reroll(w, a);
    return 1;
}

/* ---- "Simultaneous": the cluster of an impact, gathered plainly ---------------------------- */

typedef struct rw_clu {
    int nb, nc;
    int id[RW_CLU_BODIES];
    cc__cluster_body body[RW_CLU_BODIES];
    cc__cluster_contact contact[RW_CLU_CONTACTS];
    int seg[RW_CLU_CONTACTS];
} rw_clu;

static int clu_body(const rw_world *w, rw_clu *c, int k)
{
    int i;
    for (i = 0; i < c->nb; i++)
        if (c->id[i] == k)
            return i;
    if (c->nb == RW_CLU_BODIES || c->nb == w->max_circles)
        return -1;
    c->id[c->nb] = k;
    c->body[c->nb].vel = w->body[k].c.vel;
    c->body[c->nb].inv_mass = isinf(w->body[k].c.mass) ? 0.0 : 1.0 / w->body[k].c.mass;
    return c->nb++;
}

static void clu_contact(const rw_world *w, rw_clu *c, int a, int b, int seg, cc_vec2 n)
{
    int i, cap = 2 * (w->max_circles < RW_CLU_BODIES ? w->max_circles : RW_CLU_BODIES) + 8;
    for (i = 0; i < c->nc; i++) {
        const cc__cluster_contact *q = &c->contact[i];
        if (c->seg[i] == seg && ((q->a == a && q->b == b) || (seg < 0 && q->a == b && q->b == a)))
            return;
    }
    if (c->nc == (cap < RW_CLU_CONTACTS ? cap : RW_CLU_CONTACTS))
        return;
    c->contact[c->nc].a = a;
    c->contact[c->nc].b = b;
    c->contact[c->nc].normal = n;
    c->contact[c->nc].impulse = 0.0;
    c->seg[c->nc++] = seg;
}

/* Body k touches a partner of radius r at p moving at v when their gap is within this. */
static double clu_tol(const rw_world *w, const cc_circle *k, double r, cc_vec2 p, cc_vec2 v)
{
    return RW_CLU_TOL *
           (inf_norm(k->pos) + inf_norm(p) + k->radius + r + (inf_norm(k->vel) + inf_norm(v)) * fabs(w->now));
}

static void clu_gather(const rw_world *w, rw_clu *c)
{
    int from, j, s;
    for (from = 0; from < c->nb; from++) {
        const cc_circle *k = &w->body[c->id[from]].c;
        if (isinf(k->mass))
            continue; /* immovable circles take impulses but pass none on */
        for (j = 0; j < w->id_end; j++) {
            const cc_circle *q = &w->body[j].c;
            cc_vec2 d;
            int i;
            if (!w->body[j].alive || j == c->id[from] || (isinf(k->mass) && isinf(q->mass)) ||
                !interact(w, c->id[from], j))
                continue;
            d = sub(near_image(w, k->pos, q->pos), k->pos);
            if (sqrt(d.x * d.x + d.y * d.y) - (k->radius + q->radius) > clu_tol(w, k, q->radius, q->pos, q->vel))
                continue;
            if ((i = clu_body(w, c, j)) >= 0)
                clu_contact(w, c, from, i, -1, centre_normal(k->pos, near_image(w, k->pos, q->pos)));
        }
        for (s = 0; s < w->n_segments; s++) {
            cc_contact kk = wall_contact(k, &w->seg[s]);
            if (!wall_interacts(w, c->id[from], s))
                continue;
            if (-kk.depth <= clu_tol(w, k, 0.0, kk.point, v2(0.0, 0.0)))
                clu_contact(w, c, from, -1, s, kk.normal);
        }
    }
}

/* "Restitution": a cluster takes the smallest of its contacts'. */
static double clu_restitution(const rw_world *w, const rw_clu *c)
{
    double e = 1.0;
    int i;
    for (i = 0; i < c->nc; i++) {
        const cc__cluster_contact *k = &c->contact[i];
        double ek = contact_restitution(w, c->id[k->a], k->b >= 0 ? c->id[k->b] : -1, c->seg[i]);
        e = ek < e ? ek : e;
    }
    return e;
}

static int still_approaching(const rw_world *w, int a, int b, int seg)
{
    const cc_circle *ca = &w->body[a].c;
    if (b >= 0) {
        const cc_circle *cb = &w->body[b].c;
        return approaching(w, dot(sub(ca->vel, cb->vel), centre_normal(ca->pos, near_image(w, ca->pos, cb->pos))),
                           l1(ca->vel) + l1(cb->vel));
    }
    return approaching(w, dot(ca->vel, wall_contact(ca, &w->seg[seg]).normal), l1(ca->vel));
}

/* The impact (a, b or wall seg) due now, with everything touching it. */
static int resolve_cluster(rw_world *w, int a, int b, int seg)
{
    static unsigned char scratch[4 * RW_CLU_CONTACTS * RW_CLU_CONTACTS + 64 * RW_CLU_CONTACTS + 4096];
    rw_clu c;
    int i, ia, ib, hits = 0;
    c.nb = c.nc = 0;
    ia = clu_body(w, &c, a);
    if (b < 0)
        clu_contact(w, &c, ia, -1, seg, wall_contact(&w->body[a].c, &w->seg[seg]).normal);
    else if ((ib = clu_body(w, &c, b)) >= 0)
        clu_contact(w, &c, ia, ib, -1, centre_normal(w->body[a].c.pos, near_image(w, w->body[a].c.pos, w->body[b].c.pos)));
    clu_gather(w, &c);
    for (i = 0; i < c.nc; i++) { /* how close each contact is to neither approaching nor parting */
        const cc__cluster_contact *k = &c.contact[i];
        cc_vec2 va = c.body[k->a].vel, vb = k->b >= 0 ? c.body[k->b].vel : v2(0.0, 0.0);
        double speeds = l1(va) + l1(vb), vn = fabs(dot(sub(va, vb), k->normal));
        if (speeds > 0.0 && vn / speeds < w->doubt.slack)
            w->doubt.slack = vn / speeds;
    }
    if (c.nc <= 1)
        return resolve_pair(w, a, b, seg); /* nothing else touches: a pair impact */
    if (cc__cluster_scratch_size(c.nb, c.nc) > sizeof scratch ||
        cc__cluster_resolve(c.body, c.nb, c.contact, c.nc, clu_restitution(w, &c), w->rest_speed, scratch,
                            sizeof scratch, NULL) != CC_OK)
        return -1000; /* cannot happen for a valid cluster: the comparison will show it */
    for (i = 0; i < c.nb; i++) {
        w->body[c.id[i]].c.vel = c.body[i].vel;
        reroll(w, c.id[i]);
    }
    for (i = 0; i < c.nc; i++) {
        const cc__cluster_contact *k = &c.contact[i];
        const cc_circle *ka = &w->body[c.id[k->a]].c;
        cc_vec2 point;
        if (!(k->impulse > 0.0))
            continue;
        if (k->b >= 0) {
            const cc_circle *kb = &w->body[c.id[k->b]].c;
            cc_vec2 d = sub(near_image(w, ka->pos, kb->pos), ka->pos);
            double depth = ka->radius + kb->radius - sqrt(d.x * d.x + d.y * d.y);
            point = v2(ka->pos.x + k->normal.x * (ka->radius - 0.5 * depth),
                       ka->pos.y + k->normal.y * (ka->radius - 0.5 * depth));
        } else {
            point = wall_contact(ka, &w->seg[c.seg[i]]).point;
        }
        report(w, c.id[k->a], k->b >= 0 ? c.id[k->b] : -1, c.seg[i], point, k->normal, k->impulse);
        hits++;
    }
    /* an impact the cluster model left approaching by the pair's own measure: the pair impulse */
    if (still_approaching(w, a, b, seg))
        hits += resolve_pair(w, a, b, seg);
    return hits;
}

/* "Overlaps": resolved with the pair's impulse by itself while the world is being rebuilt (the
 * first step, after a wall), with its cluster otherwise. */
static void resolve(rw_world *w, int a, int b, int seg)
{
    if (w->dirty)
        (void)resolve_pair(w, a, b, seg);
    else
        (void)resolve_cluster(w, a, b, seg);
}

/* Pushes a out of b (or wall seg) when they overlap, then resolves the contact. */
static void unoverlap(rw_world *w, int a, int b, int seg)
{
    cc_circle *ca = &w->body[a].c;
    if (b >= 0 ? !interact(w, a, b) : !wall_interacts(w, a, seg))
        return; /* they pass through each other */
    if (b >= 0) {
        cc_circle *cb = &w->body[b].c, image = *cb;
        cc_vec2 shift;
        if (isinf(ca->mass) && isinf(cb->mass))
            return;
        image.pos = near_image(w, ca->pos, cb->pos);
        shift = sub(image.pos, cb->pos);
        if (cc_detect_static(ca, &image, NULL) != CC_OVERLAP || cc_separate(ca, &image) != CC_OVERLAP)
            return;
        cb->pos = sub(image.pos, shift); /* the image's shift taken off again */
    } else {
        cc_contact k;
        if (isinf(ca->mass))
            return;
        k = wall_contact(ca, &w->seg[seg]);
        if (!(k.depth > 0.0))
            return;
        ca->pos.x -= k.normal.x * k.depth;
        ca->pos.y -= k.normal.y * k.depth;
    }
    resolve(w, a, b, seg);
}

/* A circle added or set on top of others: pushed out of each, then out of the walls. A push
 * that leaves either circle overlapping a third makes the outcome depend on the order of the
 * pushes, which is the world's to choose: a doubt. */
/* Whether circles i and k overlap now (through the nearest image). */
static int overlap_now(const rw_world *w, int i, int k)
{
    cc_circle image = w->body[k].c;
    image.pos = near_image(w, w->body[i].c.pos, image.pos);
    return cc_detect_static(&w->body[i].c, &image, NULL) == CC_OVERLAP;
}

/* How many interacting circles (circle `but` aside) and walls circle i overlaps. */
static int overlaps_except(const rw_world *w, int i, int but)
{
    int k, n = 0;
    for (k = 0; k < w->id_end; k++)
        n += k != i && k != but && w->body[k].alive && interact(w, i, k) && overlap_now(w, i, k);
    for (k = 0; k < w->n_segments; k++)
        n += wall_interacts(w, i, k) && !isinf(w->body[i].c.mass) && wall_contact(&w->body[i].c, &w->seg[k]).depth > 0.0;
    return n;
}

static int overlaps_count(const rw_world *w, int i) { return overlaps_except(w, i, -1); }

/* Pushes i out of circle j (or wall seg when j < 0) and resolves the contact; a push that leaves
 * either overlapping a third makes the outcome depend on the order of the pushes, which is the
 * world's to choose: a doubt. */
static void push(rw_world *w, int i, int j, int seg)
{
    cc_vec2 before = w->body[i].c.pos;
    unoverlap(w, i, j, seg);
    if (w->body[i].c.pos.x != before.x || w->body[i].c.pos.y != before.y)
        if (overlaps_except(w, i, j) > 0 || (j >= 0 && overlaps_except(w, j, i) > 0))
            w->doubt.chain = 1;
}

static void settle(rw_world *w, int id)
{
    int j, s;
    if (overlaps_count(w, id) > 1) /* two overlaps to begin with: their order decides too */
        w->doubt.chain = 1;
    for (j = 0; j < w->id_end; j++)
        if (j != id && w->body[j].alive)
            push(w, id, j, -1);
    for (s = 0; s < w->n_segments; s++)
        push(w, id, -1, s);
    sensors_sync(w);
}

/* "Cells": 1.0625 times the largest diameter of a movable circle (sensors excepted), or of any
 * circle when none is movable, or def.cell_size when larger; made at each rebuild. */
static void cell_size(rw_world *w)
{
    double dmax = 0.0, any = 0.0;
    int i;
    for (i = 0; i < w->id_end; i++) {
        const cc_circle *c = &w->body[i].c;
        if (!w->body[i].alive)
            continue;
        if (!isinf(c->mass) && !w->body[i].props.sensor && 2.0 * c->radius > dmax)
            dmax = 2.0 * c->radius;
        if (2.0 * c->radius > any)
            any = 2.0 * c->radius;
    }
    if (dmax == 0.0)
        dmax = any > 0.0 ? any : 1.0;
    w->cs = dmax * 1.0625 > w->cell_hint ? dmax * 1.0625 : w->cell_hint;
}

/* "Overlaps": a circle wider than the cells makes everything wait for the next step's rebuild. */
static void defer_if_wide(rw_world *w, const cc_circle *c)
{
    if (!w->dirty && w->use_grid && 2.0 * c->radius * 1.0625 > w->cs)
        w->dirty = 1;
}

int rw_init(rw_world *w, const cc_world_def *def, rw_event_fn on_event, rw_sensor_fn on_sensor, void *user)
{
    if (w == NULL || def == NULL || def->mode != CC_MODE_EXACT || def->max_circles < 0 ||
        def->max_circles > RW_MAX_CIRCLES || def->max_segments < 0 || def->max_segments > RW_MAX_SEGMENTS ||
        !(def->restitution >= 0.0 && def->restitution <= 1.0) || !(def->rest_speed >= 0.0) ||
        (def->rolling_decel > 0.0 && !(def->uses & CC_USES_ROLLING))) /* the header's uses rule */
        return CC_ERR_INVALID;
    memset(w, 0, sizeof *w);
    w->restitution = def->restitution;
    w->rest_speed = def->rest_speed;
    w->max_events = def->max_events;
    if (w->max_events == 0) /* a 1.2 def's automatic cap (the header's "Collapse") */
        w->max_events = def->max_circles > 312 ? 32u * (uint64_t)def->max_circles : 10000u;
    w->max_circles = def->max_circles;
    w->max_segments = def->max_segments;
    w->dirty = 1; /* "Before the first step ... this happens for all circles at the next step" */
    w->on_event = on_event;
    w->on_sensor = on_sensor;
    w->user = user;
    w->mix = def->restitution_mix;
    w->use_grid = def->max_circles > 32 || def->period.x > 0.0 || def->period.y > 0.0;
    w->period[0] = def->period.x;
    w->period[1] = def->period.y;
    w->cell_hint = def->cell_size;
    w->rolling_decel = def->rolling_decel;
    return CC_OK;
}

static int add_one(rw_world *w, const cc_circle *c)
{
    int id;
    if (w->busy || !circle_ok(c) || !fits_period(w, c))
        return CC_ERR_INVALID;
    if (w->id_end - w->free_top >= w->max_circles)
        return CC_ERR_FULL;
    id = w->free_top > 0 ? w->free_ids[--w->free_top] : w->id_end++; /* "Ids": last removed first */
    w->body[id].c = *c;
    w->body[id].alive = 1;
    w->body[id].props.struct_size = sizeof w->body[id].props;
    w->body[id].props.restitution = w->restitution;
    w->body[id].props.rolling_decel = w->rolling_decel;
    w->body[id].props.category = 1u;
    w->body[id].props.mask = 0xFFFFFFFFu;
    w->body[id].props.sensor = 0;
    reroll(w, id);
    defer_if_wide(w, c);
    wrap_all(w);
    w->busy = 1;
    if (!w->dirty)
        settle(w, id);
    else /* the push-apart waits for the next step, the sensors' begins and ends do not */
        sensors_sync(w);
    w->busy = 0;
    return id;
}

int rw_add_circle(rw_world *w, const cc_circle *c)
{
    new_call(w);
    return add_one(w, c);
}

/* "Batches": every circle checked before any is added (the first one add would refuse decides,
 * its index to *failed), then one add per circle in order, as one call (its doubts summed). */
int rw_add_circles(rw_world *w, const cc_circle *c, int n, int *ids_out, int *failed)
{
    int i;
    new_call(w);
    if (w->busy || n < 0 || (c == NULL && n > 0)) {
        if (failed != NULL)
            *failed = -1;
        return CC_ERR_INVALID;
    }
    for (i = 0; i < n; i++) {
        int r = !circle_ok(&c[i]) || !fits_period(w, &c[i]) ? CC_ERR_INVALID
                : w->id_end - w->free_top + i >= w->max_circles ? CC_ERR_FULL
                                                                : CC_OK;
        if (r != CC_OK) {
            if (failed != NULL)
                *failed = i;
            return r;
        }
    }
    for (i = 0; i < n; i++) {
        int id = add_one(w, &c[i]);
        if (ids_out != NULL)
            ids_out[i] = id;
    }
    return n;
}

int rw_remove_circle(rw_world *w, int id)
{
    new_call(w);
    if (w->busy)
        return CC_ERR_INVALID;
    if (id < 0 || id >= w->id_end || !w->body[id].alive)
        return CC_ERR_NOT_FOUND;
    w->body[id].alive = 0;
    w->free_ids[w->free_top++] = id;
    {   /* "a circle removed gets none: its overlaps are forgotten" */
        int j;
        for (j = 0; j < RW_MAX_CIRCLES; j++)
            w->inside[id][j] = w->inside[j][id] = 0;
    }
    return CC_OK;
}

int rw_set_circle(rw_world *w, int id, const cc_circle *c)
{
    new_call(w);
    if (w->busy || !circle_ok(c) || !fits_period(w, c))
        return CC_ERR_INVALID;
    if (id < 0 || id >= w->id_end || !w->body[id].alive)
        return CC_ERR_NOT_FOUND;
    w->body[id].c = *c;
    reroll(w, id);
    defer_if_wide(w, c);
    wrap_all(w);
    w->busy = 1;
    if (!w->dirty)
        settle(w, id);
    else /* the push-apart waits for the next step, the sensors' begins and ends do not */
        sensors_sync(w);
    w->busy = 0;
    return CC_OK;
}

int rw_add_segment(rw_world *w, const cc_segment *s)
{
    if (w->busy || !segment_ok(s))
        return CC_ERR_INVALID;
    if (w->n_segments >= w->max_segments)
        return CC_ERR_FULL;
    w->seg[w->n_segments] = *s;
    w->seg_props[w->n_segments].struct_size = sizeof w->seg_props[0];
    w->seg_props[w->n_segments].restitution = w->restitution;
    w->seg_props[w->n_segments].category = 1u;
    w->seg_props[w->n_segments].mask = 0xFFFFFFFFu;
    w->dirty = 1; /* "after a wall ... was added, this happens for all circles at the next step" */
    return w->n_segments++;
}

int rw_get_circles(const rw_world *w, int *ids, cc_circle *out, int capacity)
{
    int i, k = 0;
    if (capacity < 0)
        return CC_ERR_INVALID;
    for (i = 0; i < w->id_end; i++) {
        if (!w->body[i].alive)
            continue;
        if (k < capacity) {
            if (ids != NULL)
                ids[k] = i;
            if (out != NULL)
                out[k] = w->body[i].c;
        }
        k++;
    }
    return k;
}

int rw_set_circle_props(rw_world *w, int id, const cc_circle_props *p)
{
    cc_circle_props *q;
    int j, n_sensors = 0;
    new_call(w);
    if (w->busy || p == NULL || !(p->restitution >= 0.0 && p->restitution <= 1.0) ||
        !(p->rolling_decel >= 0.0 && isfinite(p->rolling_decel)))
        return CC_ERR_INVALID;
    if (id < 0 || id >= w->id_end || !w->body[id].alive)
        return CC_ERR_NOT_FOUND;
    q = &w->body[id].props;
    for (j = 0; j < w->id_end; j++)
        n_sensors += w->body[j].alive && w->body[j].props.sensor;
    if (p->sensor && !q->sensor && n_sensors == CC_MAX_SENSORS)
        return CC_ERR_FULL;
    w->busy = 1;
    if (!p->sensor != !q->sensor) /* a sensor that stops, a visitor that becomes one: ends */
        for (j = 0; j < w->id_end; j++) {
            if (w->inside[id][j])
                sensor_report(w, id, j, 0);
            if (w->inside[j][id])
                sensor_report(w, j, id, 0);
        }
    q->restitution = p->restitution;
    q->rolling_decel = p->rolling_decel;
    reroll(w, id);
    q->category = p->category;
    q->mask = p->mask;
    q->sensor = p->sensor != 0;
    if (!w->dirty) /* as set: overlaps that now interact are pushed apart, sensors brought up */
        settle(w, id);
    else /* "at once, from inside that call", even while the push-apart waits */
        sensors_sync(w);
    w->busy = 0;
    return CC_OK;
}

int rw_set_segment_props(rw_world *w, int id, const cc_segment_props *p)
{
    new_call(w);
    if (w->busy || p == NULL || !(p->restitution >= 0.0 && p->restitution <= 1.0))
        return CC_ERR_INVALID;
    if (id < 0 || id >= w->n_segments)
        return CC_ERR_NOT_FOUND;
    w->seg_props[id] = *p;
    w->dirty = 1; /* as the world: everything looked at again at the next step */
    return CC_OK;
}

/* ---- stepping ---------------------------------------------------------------------------- */

typedef struct rw_cand {
    double t; /* absolute */
    int a, b, seg;
    int sensor; /* a sensor pair's begin or end: a is the sensor, b the visitor */
} rw_cand;

static void advance_all(rw_world *w, double t)
{
    int i;
    for (i = 0; i < w->id_end; i++)
        if (w->body[i].alive && t != w->now) {
            cc_circle *c = &w->body[i].c;
            double k = w->body[i].roll, tau = t - w->now, ts = k > 0.0 ? 0.5 / k : HUGE_VAL;
            if (k == 0.0) {
                c->pos.x += c->vel.x * tau;
                c->pos.y += c->vel.y * tau;
            } else if (tau >= ts) { /* "Rolling to rest": p + v ts / 2, at rest */
                c->pos.x += c->vel.x * (0.5 * ts);
                c->pos.y += c->vel.y * (0.5 * ts);
                c->vel.x = c->vel.y = 0.0;
                w->body[i].roll = 0.0;
            } else { /* p + v tau (1 - k tau), velocity v (1 - 2 k tau) */
                double g = tau * (1.0 - k * tau), gd = 1.0 - 2.0 * k * tau;
                c->pos.x += c->vel.x * g;
                c->pos.y += c->vel.y * g;
                c->vel.x *= gd;
                c->vel.y *= gd;
                w->body[i].roll = k / gd;
            }
        }
    w->now = t;
    wrap_all(w);
}

/* Offers a candidate event; keeps the earliest and the next distinct time behind it. */
static void offer(rw_cand *best, double *second, double t, int a, int b, int seg, int sensor)
{
    if (t < best->t) {
        *second = best->t;
        best->t = t;
        best->a = a;
        best->b = b;
        best->seg = seg;
        best->sensor = sensor;
    } else if (t < *second) {
        *second = t;
    }
}

/* "Sensors": when sensor s and visitor v next begin or stop overlapping, from now (absolute;
 * +INF for never). Within 2^-40 of the numbers involved, the boundary is rounding's and the
 * membership decides, as in the world. */
static double sensor_next(const rw_world *w, int s, int v, cc_vec2 shift)
{
    const cc_circle *a = &w->body[s].c, *b = &w->body[v].c;
    cc_vec2 bp = v2(b->pos.x + shift.x, b->pos.y + shift.y), dp = sub(bp, a->pos), dv = sub(b->vel, a->vel);
    double R = a->radius + b->radius, d = sqrt(dot(dp, dp)), vv = dot(dv, dv), bb = dot(dp, dv);
    double tol = 0x1p-40 * (l1(a->pos) + l1(bp) + R + (l1(a->vel) + l1(b->vel)) * fabs(w->now));
    cc_vec2 nearest = near_image(w, a->pos, bp);
    if (w->inside[s][v] && (nearest.x != bp.x || nearest.y != bp.y))
        return HUGE_VAL; /* inside through its nearest image: this one ends nothing */
    if (w->body[s].roll > 0.0 || w->body[v].roll > 0.0) { /* "Rolling to rest" */
        double t, nx, ny;
        int inside = w->inside[s][v];
        if (inside ? d - R > tol : d - R < -tol)
            return w->now;
        if (!inside && d < R)
            return bb < 0.0 ? w->now : HUGE_VAL;
        if (cc__roll_sweep(dp.x, dp.y, a->vel.x, a->vel.y, w->body[s].roll, b->vel.x, b->vel.y, w->body[v].roll, R,
                           HUGE_VAL, inside ? 1 : -1, 0.0, &t, &nx, &ny) != CC_HIT)
            return HUGE_VAL;
        return w->now + t;
    }
    if (w->inside[s][v]) {
        double h, q, disc, c, t;
        if (d - R > tol)
            return w->now;
        if (vv == 0.0)
            return HUGE_VAL;
        h = fabs(dp.x * dv.y - dp.y * dv.x);
        q = sqrt(vv) * R;
        if (!(q > h))
            return w->now;
        disc = (q - h) * (q + h);
        c = (d - R) * (d + R);
        t = bb <= 0.0 ? (-bb + sqrt(disc)) / vv : -c / (bb + sqrt(disc));
        return t > 0.0 ? w->now + t : w->now;
    } else {
        cc_contact k;
        if (d - R < -tol)
            return w->now;
        cc_circle bi = *b;
        bi.pos = bp;
        switch (cc_sweep(a, &bi, HUGE_VAL, &k)) {
        case CC_HIT: return w->now + k.t;
        case CC_OVERLAP: return bb < 0.0 ? w->now : HUGE_VAL;
        default: return HUGE_VAL;
        }
    }
}

/* "Rolling to rest": a wall against a circle that may decelerate. */
static int wall_sweep(const rw_world *w, int i, const cc_circle *c, const cc_segment *g, double h, cc_contact *k)
{
    return w->body[i].roll > 0.0 ? cc__roll_sweep_segment(c, w->body[i].roll, g, h, k) : cc_sweep_segment(c, g, h, k);
}

/* "Rolling to rest": pair i, j (the image cj of j) of which one rolls; hits and misses within
 * 1e-6 of the radius sum are rounding's (a ball stopping just short of another is such a graze). */
static void roll_pair(rw_world *w, int i, int j, const cc_circle *cj, double h, rw_cand *best, double *second)
{
    const cc_circle *ci = &w->body[i].c;
    double ki = w->body[i].roll, kj = w->body[j].roll, R = ci->radius + cj->radius, t, nx, ny, gi, gdi, gj, gdj;
    double vn, speeds, tt, a, b;
    cc_vec2 dp = sub(cj->pos, ci->pos);
    double vmin = 2.0 * approach_threshold(w, l1(ci->vel) + l1(cj->vel));
    int r, ri, ro;
    double len = sqrt(dp.x * dp.x + dp.y * dp.y);
    if (len > 0.0 && fabs(len - R) <= 1e-6 * R &&
        fabs((cj->vel.x - ci->vel.x) * dp.x + (cj->vel.y - ci->vel.y) * dp.y) <= 1e-6 * len * (l1(ci->vel) + l1(cj->vel)))
        w->doubt.push = 1;
    ro = cc__roll_sweep(dp.x, dp.y, ci->vel.x, ci->vel.y, ki, cj->vel.x, cj->vel.y, kj, R * (1.0 + 1e-6), h, -1, vmin,
                        &tt, &a, &b);
    if (ro == CC_MISS && len > R * (1.0 + 1e-6))
        return; /* apart, and never within R (1 + 1e-6): the smaller distances are not reached either */
    r = cc__roll_sweep(dp.x, dp.y, ci->vel.x, ci->vel.y, ki, cj->vel.x, cj->vel.y, kj, R, h, -1, vmin, &t, &nx, &ny);
    ri = cc__roll_sweep(dp.x, dp.y, ci->vel.x, ci->vel.y, ki, cj->vel.x, cj->vel.y, kj, R * (1.0 - 1e-6), h, -1, vmin,
                        &tt, &a, &b);
    if (ri != ro)
        w->doubt.graze_gap = 0.0;
    if (r == CC_MISS)
        return;
    cc__roll_motion(ki, t, &gi, &gdi);
    cc__roll_motion(kj, t, &gj, &gdj);
    vn = -((cj->vel.x * gdj - ci->vel.x * gdi) * nx + (cj->vel.y * gdj - ci->vel.y * gdi) * ny);
    speeds = l1(ci->vel) * gdi + l1(cj->vel) * gdj;
    if (vn > 0.0 && fabs(vn / approach_threshold(w, speeds) - 1.0) < w->doubt.slow)
        w->doubt.slow = fabs(vn / approach_threshold(w, speeds) - 1.0);
    if (approaching(w, vn, speeds))
        offer(best, second, w->now + t, i, j, -1, 0);
}

/* Every pair swept from now: the earliest event up to t_end, with its doubts. */
static rw_cand next_event(rw_world *w, double t_end)
{
    rw_cand best;
    double second = HUGE_VAL, h = t_end - w->now;
    int i, j, s, img;
    best.t = HUGE_VAL;
    best.a = best.b = best.seg = -1;
    best.sensor = 0;
    for (i = 0; i < w->id_end; i++) {
        const cc_circle *ci = &w->body[i].c;
        if (!w->body[i].alive)
            continue;
        for (j = i + 1; j < w->id_end; j++)
            for (img = 0; img < 9; img++) {
            /* "Periodic boxes": every image of j within a period either way (the search's horizon
             * keeps every body within a quarter period of where it is) */
            int ix = img % 3 - 1, iy = img / 3 - 1;
            cc_circle image;
            const cc_circle *cj = &image;
            cc_contact k;
            cc_vec2 dp, dv;
            double vv, vn, speeds;
            int r;
            if ((ix != 0 && !(w->period[0] > 0.0)) || (iy != 0 && !(w->period[1] > 0.0)))
                continue;
            image = w->body[j].c;
            image.pos.x += ix * w->period[0];
            image.pos.y += iy * w->period[1];
            if (!w->body[j].alive || (at_rest(ci) && at_rest(cj)))
                continue;
            if (senses(w, i, j) || senses(w, j, i)) {
                int sn = senses(w, i, j) ? i : j;
                cc_vec2 sh = v2(ix * w->period[0], iy * w->period[1]);
                double ts = sensor_next(w, sn, sn == i ? j : i, sn == i ? sh : v2(-sh.x, -sh.y));
                if (ts <= t_end)
                    offer(&best, &second, ts, sn, sn == i ? j : i, -1, 1);
            }
            if ((isinf(ci->mass) && isinf(cj->mass)) || !interact(w, i, j))
                continue;
            if (w->body[i].roll > 0.0 || w->body[j].roll > 0.0) {
                roll_pair(w, i, j, cj, h, &best, &second);
                continue;
            }
            dp = sub(cj->pos, ci->pos);
            dv = sub(cj->vel, ci->vel);
            vv = dot(dv, dv);
            /* how close the pair passes, relative to the radius sum: near 0, hit and miss are
             * decided by rounding */
            if (dot(dp, dv) < 0.0 && vv > 0.0) {
                double tca = -dot(dp, dv) / vv, R = ci->radius + cj->radius;
                double miss = fabs(fabs(dp.x * dv.y - dp.y * dv.x) / sqrt(vv) - R) / R;
                if (tca <= h && miss < w->doubt.graze_gap)
                    w->doubt.graze_gap = miss;
            }
            if (!(dot(dp, dv) < 0.0) && dot(dp, dp) > 4.0 * (ci->radius + cj->radius) * (ci->radius + cj->radius))
                continue; /* far apart and not closing: cc_sweep would say so, at more cost */
            r = cc_sweep(ci, cj, h, &k);
            if (r != CC_HIT && r != CC_OVERLAP)
                continue;
            vn = -dot(dv, k.normal);
            speeds = l1(ci->vel) + l1(cj->vel);
            if (vn > 0.0 && fabs(vn / approach_threshold(w, speeds) - 1.0) < w->doubt.slow)
                w->doubt.slow = fabs(vn / approach_threshold(w, speeds) - 1.0);
            if (approaching(w, vn, speeds))
                offer(&best, &second, w->now + k.t, i, j, -1, 0);
        }
        if (isinf(ci->mass) || at_rest(ci))
            continue; /* "Immovable": kinematic circles pass through walls */
        for (s = 0; s < w->n_segments; s++) {
            const cc_segment *g = &w->seg[s];
            cc_contact k;
            double vn, thr, ex = ci->pos.x + ci->vel.x * h, ey = ci->pos.y + ci->vel.y * h, m = 2.0 * ci->radius;
            int r;
            /* the path's box, grown by twice the radius, misses the wall's: cc_sweep_segment would
             * say so, at more cost */
            if (!wall_interacts(w, i, s))
                continue;
            if (fmax(g->a.x, g->b.x) < fmin(ci->pos.x, ex) - m || fmin(g->a.x, g->b.x) > fmax(ci->pos.x, ex) + m ||
                fmax(g->a.y, g->b.y) < fmin(ci->pos.y, ey) - m || fmin(g->a.y, g->b.y) > fmax(ci->pos.y, ey) + m)
                continue;
            r = wall_sweep(w, i, ci, g, h, &k);
            {   /* the wall passed within 1e-6 of the radius: hit or miss is rounding's */
                cc_circle in = *ci, out = *ci;
                cc_contact kk;
                int ri, ro;
                in.radius *= 1.0 - 1e-6;
                out.radius *= 1.0 + 1e-6;
                ri = wall_sweep(w, i, &in, g, h, &kk);
                ro = wall_sweep(w, i, &out, g, h, &kk);
                if ((ri == CC_HIT && ro == CC_MISS) || (ri == CC_MISS && ro == CC_HIT))
                    w->doubt.graze_gap = 0.0;
            }
            if (r != CC_HIT && r != CC_OVERLAP)
                continue;
            {   /* the velocity at contact: a rolling circle slows */
                double gg, gd;
                cc__roll_motion(w->body[i].roll, k.t, &gg, &gd);
                vn = gd * dot(ci->vel, k.normal);
                if (!(vn > 0.0 && approaching(w, vn, gd * l1(ci->vel)))) {
                    if (vn > 0.0 && fabs(vn / approach_threshold(w, gd * l1(ci->vel)) - 1.0) < w->doubt.slow)
                        w->doubt.slow = fabs(vn / approach_threshold(w, gd * l1(ci->vel)) - 1.0);
                    continue;
                }
                offer(&best, &second, w->now + k.t, i, -1, s, 0);
                continue;
            }
            vn = dot(ci->vel, k.normal);
            thr = approach_threshold(w, l1(ci->vel));
            if (vn > 0.0 && fabs(vn / thr - 1.0) < w->doubt.slow)
                w->doubt.slow = fabs(vn / thr - 1.0);
            if (approaching(w, vn, l1(ci->vel)))
                offer(&best, &second, w->now + k.t, i, -1, s, 0);
        }
    }
    if (second < HUGE_VAL && (second - best.t) / (fabs(best.t) + w->time_scale) < w->doubt.tie_gap)
        w->doubt.tie_gap = (second - best.t) / (fabs(best.t) + w->time_scale);
    return best;
}

/* "Periodic boxes": how far ahead to search, so that no body travels a quarter period (then the
 * images one period either way are all that can be met). */
static double horizon(const rw_world *w, double t_end)
{
    double t = t_end;
    int i, k;
    for (i = 0; i < w->id_end; i++)
        for (k = 0; k < 2; k++) {
            double v = fabs(k ? w->body[i].c.vel.y : w->body[i].c.vel.x);
            if (w->body[i].alive && w->period[k] > 0.0 && v > 0.0 && w->now + 0.25 * w->period[k] / v < t)
                t = w->now + 0.25 * w->period[k] / v;
        }
    return t;
}

int rw_step(rw_world *w, double dt)
{
    double t_end;
    uint64_t done;
    int i, j, s;
    new_call(w);
    if (w->busy || !(dt >= 0.0) || !isfinite(dt) || !isfinite(w->now + dt))
        return CC_ERR_INVALID;
    t_end = w->now + dt;
    w->busy = 1;
    if (w->dirty) { /* one pass over every overlap, each pair by itself */
        cell_size(w);
        for (i = 0; i < w->id_end; i++) { /* a circle in two overlaps: the order of the pushes decides */
            if (!w->body[i].alive)
                continue;
            if (overlaps_count(w, i) > 1)
                w->doubt.chain = 1;
            for (j = i + 1; j < w->id_end; j++) /* touching pairs: overlapping or not is rounding's */
                if (w->body[j].alive && interact(w, i, j)) {
                    cc_vec2 d = sub(w->body[j].c.pos, w->body[i].c.pos);
                    double R = w->body[i].c.radius + w->body[j].c.radius;
                    if (fabs(sqrt(dot(d, d)) - R) <= 1e-9 * R)
                        w->doubt.graze_gap = 0.0;
                }
        }
        for (i = 0; i < w->id_end; i++) {
            if (!w->body[i].alive)
                continue;
            for (j = i + 1; j < w->id_end; j++)
                if (w->body[j].alive)
                    push(w, i, j, -1);
            for (s = 0; s < w->n_segments; s++)
                push(w, i, -1, s);
        }
        sensors_sync(w);
        w->dirty = 0;
    }
    for (done = 0;; done++) {
        double t_lim = horizon(w, t_end);
        rw_cand e = next_event(w, t_lim);
        if (!(e.t <= t_lim)) {
            if (t_lim >= t_end)
                break;
            advance_all(w, t_lim); /* nothing within a quarter period: on, and look again */
            done--;
            continue;
        }
        if (done == w->max_events) { /* "Collapse": the step stops at the cap */
            w->busy = 0;
            return CC_EVENT_LIMIT;
        }
        advance_all(w, e.t > w->now ? e.t : w->now);
        if (e.sensor)
            sensor_report(w, e.a, e.b, !w->inside[e.a][e.b]);
        else
            (void)resolve_cluster(w, e.a, e.b, e.seg);
    }
    advance_all(w, t_end);
    w->busy = 0;
    return CC_OK;
}
