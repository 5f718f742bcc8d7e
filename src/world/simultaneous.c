/* EXACT mode's simultaneous impacts: an impact due now is resolved together with every body
 * that touches the impacting bodies at this instant (transitively, through movable bodies) and
 * every wall those touch: one cluster, resolved by the model of cluster.c (generalized
 * reflections; docs/SIMULTANEOUS.md). Impacts predicted for the same instant are touching now,
 * so they join the same cluster. An impact that touches nothing else stays a pair impact
 * (resolve.c), bit for bit as before. */
#include "world_internal.h"
#include "walls.h"
#include "world/cluster.h"

/* Capacities: a cluster holds up to CC__CLU_BODIES bodies (the 15-ball rack and its cue ball
 * take 16) and CC__CLU_CONTACTS contacts (the rack: 31); the solver's scratch grows as
 * 4 * contacts^2 bytes. Touching bodies beyond them are left out of the cluster: their
 * contacts, if approaching, are impacts due now and resolved right after. */
#define CC__CLU_BODIES 24
#define CC__CLU_CONTACTS 48

/* Two bodies touch when their gap is at most 2^-40 of the size of the numbers that made it:
 * their coordinates and radii, and the distance they travel in the rounding of the world time
 * (predicted times of impacts carry a few ulps of |now|). See docs/SIMULTANEOUS.md. */
#define CC__CLU_TOL 0x1p-40

typedef struct cc__clu {
    cc_world *w;
    int nb, nc;
    int *id;                      /* storage indices of the bodies */
    cc__cluster_body *body;       /* their velocities and inverse masses */
    cc__cluster_contact *contact; /* a, b index into id[]; b = -1 for a wall */
    int *seg;                     /* a wall contact's segment, else -1 */
    void *scratch;
    size_t scratch_bytes;
    int from;      /* the body whose touching neighbours are being visited (position in id[]) */
    double fx, fy; /* its position now */
} cc__clu;

static size_t cc__al16(size_t n) { return (n + 15u) & ~(size_t)15u; }

static cc_vec2 cc__v(double x, double y)
{
    cc_vec2 v;
    v.x = x;
    v.y = y;
    return v;
}

static double cc__inf_norm(double x, double y) { return fabs(x) > fabs(y) ? fabs(x) : fabs(y); }

/* Unit vector from a to b at world time now; (1, 0) for coincident centres, like cc_sweep. */
static cc_vec2 cc__centre_normal(const cc_world *w, const cc__body *a, const cc__body *b, double now)
{
    double dx = cc__near_d(w, cc__bx(w, b, now) - cc__bx(w, a, now), 0), dy = cc__near_d(w, cc__by(w, b, now) - cc__by(w, a, now), 1);
    double d = sqrt(dx * dx + dy * dy);
    return d > 0.0 ? cc__v(dx / d, dy / d) : cc__v(1.0, 0.0);
}

/* Contact of body k with wall s at world time now (resolve.c's rule for the normal). */
static cc_contact cc__wall_now(const cc_world *w, int k, int s)
{
    const cc__body *b = &CC__CARR(w, cc__body, off_body)[k];
    cc_circle c;
    c.pos = cc__v(cc__bx(w, b, w->now), cc__by(w, b, w->now));
    c.vel = cc__v(b->vx, b->vy);
    c.radius = b->r;
    c.mass = 1.0;
    return cc__world_wall_contact(&c, &CC__CARR(w, cc_segment, off_seg)[s]);
}

size_t cc__cluster_block(int max_circles, int mode, int *bodies, int *contacts)
{
    int nb, nc;
    if (mode != CC_MODE_EXACT || max_circles < 1) {
        *bodies = *contacts = 0;
        return 0;
    }
    nb = max_circles < CC__CLU_BODIES ? max_circles : CC__CLU_BODIES;
    nc = 2 * nb + 8 < CC__CLU_CONTACTS ? 2 * nb + 8 : CC__CLU_CONTACTS; /* walls: a corner is 2 */
    *bodies = nb;
    *contacts = nc;
    return cc__al16((size_t)nb * sizeof(int)) + cc__al16((size_t)nb * sizeof(cc__cluster_body)) +
           cc__al16((size_t)nc * sizeof(cc__cluster_contact)) + cc__al16((size_t)nc * sizeof(int)) +
           cc__cluster_scratch_size(nb, nc);
}

static void cc__clu_carve(cc_world *w, cc__clu *c)
{
    unsigned char *p = (unsigned char *)w + w->off_clu;
    size_t nb = (size_t)w->clu_bodies, nc = (size_t)w->clu_contacts;
    c->id = (int *)(void *)p;
    p += cc__al16(nb * sizeof(int));
    c->body = (cc__cluster_body *)(void *)p;
    p += cc__al16(nb * sizeof(cc__cluster_body));
    c->contact = (cc__cluster_contact *)(void *)p;
    p += cc__al16(nc * sizeof(cc__cluster_contact));
    c->seg = (int *)(void *)p;
    p += cc__al16(nc * sizeof(int));
    c->scratch = p;
    c->scratch_bytes = cc__cluster_scratch_size(w->clu_bodies, w->clu_contacts);
    c->nb = c->nc = 0;
    c->w = w;
}

/* Position of body k in the cluster (adding it when new and there is room), or -1. */
static int cc__clu_body(cc__clu *c, int k)
{
    const cc__body *B = CC__CARR(c->w, cc__body, off_body);
    double m = CC__CARR(c->w, cc__cold, off_cold)[k].m;
    int i;
    for (i = 0; i < c->nb; i++)
        if (c->id[i] == k)
            return i;
    if (c->nb == c->w->clu_bodies)
        return -1;
    if (c->w->features & CC__F_ROLL)
        cc__advance_body(c->w, &CC__ARR(c->w, cc__body, off_body)[k], c->w->now); /* its velocity now, slowed as it rolled */
    c->id[c->nb] = k;
    c->body[c->nb].vel = cc__v(B[k].vx, B[k].vy);
    c->body[c->nb].inv_mass = isinf(m) ? 0.0 : 1.0 / m;
    return c->nb++;
}

/* The model's arithmetic is homogeneous in the masses: inverse masses all multiplied by 2^s
 * give the same velocities and impulses divided by 2^s, bit for bit while nothing under- or
 * overflows. With a finite mass beyond 2^500 (or all below 2^-500) something would: a body of
 * mass 1e308 against an immovable one or a wall has an impulse (1 + e) v_n / (1 / m) beyond
 * DBL_MAX, then Inf * (1 / m) for its velocity (the world fuzzer's D17), and 1 / m itself is
 * subnormal. Such a cluster is solved with its heaviest finite mass as the unit (2^s of the
 * returned s); every other cluster as it is (s = 0, the bits of 1.0). A body whose scaled
 * inverse mass overflows (masses more than 2^1024 apart) makes the model refuse the cluster,
 * which the caller then resolves pairwise with the pair functions' mass shares. */
static int cc__clu_scale(cc__clu *c)
{
    const cc__cold *C = CC__CARR(c->w, cc__cold, off_cold);
    double mmax = 0.0;
    int i, s;
    for (i = 0; i < c->nb; i++) {
        double m = C[c->id[i]].m;
        if (!isinf(m) && m > mmax)
            mmax = m;
    }
    if (!(mmax > 0x1p500 || mmax < 0x1p-500) || mmax == 0.0) /* (0: no finite mass) */
        return 0;
    (void)frexp(mmax, &s); /* mmax in [2^(s-1), 2^s): frexp, not ilogb, which the embedded */
    s -= 1;                /* and WebAssembly builds do not link (scripts/test.d/40-embedded.sh) */
    for (i = 0; i < c->nb; i++) {
        double m = C[c->id[i]].m;
        c->body[i].inv_mass = isinf(m) ? 0.0 : 1.0 / ldexp(m, -s);
    }
    return s;
}

/* Lists contact a-b (b = -1: wall seg) unless it is listed already (a seed, or found from the
 * other body) or the cluster is full. */
static void cc__clu_contact(cc__clu *c, int a, int b, int seg, cc_vec2 n)
{
    cc__cluster_contact *k;
    int i;
    for (i = 0; i < c->nc; i++) {
        const cc__cluster_contact *q = &c->contact[i];
        if (c->seg[i] == seg && ((q->a == a && q->b == b) || (seg < 0 && q->a == b && q->b == a)))
            return;
    }
    if (c->nc == c->w->clu_contacts)
        return;
    k = &c->contact[c->nc];
    k->a = a;
    k->b = b;
    k->normal = n;
    k->impulse = 0.0;
    c->seg[c->nc++] = seg;
}

/* The touching tolerance of body k at (x, y) now and a partner of radius r at (px, py) moving
 * at (vx, vy); a wall is a partner of radius 0 at rest at k's closest point. */
static double cc__clu_tol(const cc_world *w, int k, double x, double y, double r, double px,
                          double py, double vx, double vy)
{
    const cc__body *b = &CC__CARR(w, cc__body, off_body)[k];
    double speeds = cc__inf_norm(b->vx, b->vy) + cc__inf_norm(vx, vy);
    return CC__CLU_TOL *
           (cc__inf_norm(x, y) + cc__inf_norm(px, py) + b->r + r + speeds * fabs(w->now));
}

/* near.c's visitor: circle j or wall s is within the loose tolerance of the body expanded. */
static void cc__clu_visit(void *ctx, int j, int s)
{
    cc__clu *c = (cc__clu *)ctx;
    cc_world *w = c->w;
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
    int k = c->id[c->from], i;
    if (j >= 0) {
        double jx = cc__bx(w, &B[j], w->now), jy = cc__by(w, &B[j], w->now);
        double dx = cc__near_d(w, jx - c->fx, 0), dy = cc__near_d(w, jy - c->fy, 1);
        double gap = sqrt(dx * dx + dy * dy) - (B[k].r + B[j].r);
        if (isinf(C[k].m) && isinf(C[j].m))
            return; /* immovable circles pass through each other */
        if (gap > cc__clu_tol(w, k, c->fx, c->fy, B[j].r, jx, jy, B[j].vx, B[j].vy))
            return;
        i = cc__clu_body(c, j);
        if (i >= 0)
            cc__clu_contact(c, c->from, i, -1, cc__centre_normal(w, &B[k], &B[j], w->now));
    } else {
        cc_contact kk = cc__wall_now(w, k, s);
        if (-kk.depth <= cc__clu_tol(w, k, c->fx, c->fy, 0.0, kk.point.x, kk.point.y, 0.0, 0.0))
            cc__clu_contact(c, c->from, -1, s, kk.normal);
    }
}

/* Grows the cluster breadth first through the bodies touching now. Immovable ones stop the
 * spread: they take impulses but pass none on (and pass through walls). */
static void cc__clu_gather(cc__clu *c)
{
    cc_world *w = c->w;
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
    for (c->from = 0; c->from < c->nb; c->from++) {
        int k = c->id[c->from], q;
        double vmax = 0.0, rmax = w->cs, loose;
        if (isinf(C[k].m))
            continue;
        c->fx = cc__bx(w, &B[k], w->now);
        c->fy = cc__by(w, &B[k], w->now);
        /* near.c takes one tolerance: a bound on every pair tolerance of this body (neighbours
         * lie within a cell or two and are rarely faster than the cluster's fastest body) */
        for (q = 0; q < c->nb; q++) {
            double v = cc__inf_norm(c->body[q].vel.x, c->body[q].vel.y);
            vmax = v > vmax ? v : vmax;
            rmax = B[c->id[q]].r > rmax ? B[c->id[q]].r : rmax;
        }
        loose = 4.0 * CC__CLU_TOL *
                (2.0 * cc__inf_norm(c->fx, c->fy) + 4.0 * rmax + 2.0 * vmax * fabs(w->now));
        (void)cc__world_touching(w, k, loose, cc__clu_visit, c);
    }
}

/* For exact.c's plain pair impact of movable circles a and b: twice the reach cc__clu_gather
 * gives near.c for each of them before anything joins the cluster (the same terms, velocities
 * before the impact), so that a circle near.c would visit is surely within it; and whether
 * near.c could visit a wall for either (its box test, with that larger reach): 1 when maybe. */
int cc__cluster_pair_reach(const cc_world *w, int a, int b, double *reach_a, double *reach_b)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const cc_segment *seg = CC__CARR(w, cc_segment, off_seg);
    double va = cc__inf_norm(B[a].vx, B[a].vy), vb = cc__inf_norm(B[b].vx, B[b].vy);
    double vmax = va > vb ? va : vb, rmax = w->cs, common;
    double ax = cc__bx(w, &B[a], w->now), ay = cc__by(w, &B[a], w->now), bx = cc__bx(w, &B[b], w->now),
           by = cc__by(w, &B[b], w->now), ga, gb, g, x0, x1, y0, y1;
    bx = ax + cc__near_d(w, bx - ax, 0); /* periodic: the image of b next to a */
    by = ay + cc__near_d(w, by - ay, 1);
    cc__wall_walk walk;
    int s;
    rmax = B[a].r > rmax ? B[a].r : rmax;
    rmax = B[b].r > rmax ? B[b].r : rmax;
    common = 4.0 * rmax + 2.0 * vmax * fabs(w->now);
    *reach_a = 8.0 * CC__CLU_TOL * (2.0 * cc__inf_norm(ax, ay) + common);
    *reach_b = 8.0 * CC__CLU_TOL * (2.0 * cc__inf_norm(bx, by) + common);
    ga = B[a].r + *reach_a;
    gb = B[b].r + *reach_b;
    g = ga > gb ? ga : gb;
    /* one box around both bodies, grown by the larger reach: contains both of near.c's */
    x0 = (ax < bx ? ax : bx) - g;
    x1 = (ax < bx ? bx : ax) + g;
    y0 = (ay < by ? ay : by) - g;
    y1 = (ay < by ? by : ay) + g;
    cc__walls_begin(w, &walk, x0, y0, x1, y1);
    while ((s = cc__walls_next(w, &walk)) >= 0) {
        const cc_segment *q = &seg[s];
        if ((q->a.x < x0 && q->b.x < x0) || (q->a.x > x1 && q->b.x > x1) || (q->a.y < y0 && q->b.y < y0) ||
            (q->a.y > y1 && q->b.y > y1))
            continue;
        return 1;
    }
    return 0;
}

/* The cluster's restitution: the smallest of its contacts' (each the mix of its two sides'), so
 * that a cluster of one material behaves as before and kinetic energy never grows (the model
 * takes one coefficient; docs/SIMULTANEOUS.md). */
static double cc__clu_restitution(const cc__clu *c)
{
    double e = c->w->restitution;
    int i;
    if (!(c->w->features & CC__F_RESTITUTION))
        return e;
    for (i = 0; i < c->nc; i++) {
        const cc__cluster_contact *k = &c->contact[i];
        double ek = cc__contact_restitution(c->w, c->id[k->a], k->b >= 0 ? c->id[k->b] : -1, c->seg[i]);
        e = i == 0 || ek < e ? ek : e;
    }
    return e;
}

/* The world's own test of an impact: does touch t still approach? */
static int cc__still_approaching(const cc_world *w, const cc__touch *t)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const cc__body *ba = &B[t->a];
    double vn, speeds = fabs(ba->vx) + fabs(ba->vy);
    cc_vec2 n;
    if (t->b >= 0) {
        const cc__body *bb = &B[t->b];
        n = cc__centre_normal(w, ba, bb, w->now);
        vn = (ba->vx - bb->vx) * n.x + (ba->vy - bb->vy) * n.y;
        speeds += fabs(bb->vx) + fabs(bb->vy);
    } else {
        n = cc__wall_now(w, t->a, t->segment).normal;
        vn = ba->vx * n.x + ba->vy * n.y;
    }
    return cc__approaching(w, vn, speeds);
}

int cc__world_resolve_cluster(cc_world *w, const cc__touch *touch, int n)
{
    cc__body *B = CC__ARR(w, cc__body, off_body);
    cc__clu c;
    cc__cluster_report rep;
    int i, hits = 0, scale;
    cc__clu_carve(w, &c);
    /* the impacts themselves first, whatever their gap */
    for (i = 0; i < n; i++) {
        int a = cc__clu_body(&c, touch[i].a), b;
        if (a < 0)
            continue;
        if (touch[i].b < 0) {
            cc_vec2 nw = cc__wall_now(w, touch[i].a, touch[i].segment).normal;
            cc__clu_contact(&c, a, -1, touch[i].segment, nw);
        } else if ((b = cc__clu_body(&c, touch[i].b)) >= 0) {
            cc__clu_contact(&c, a, b, -1, cc__centre_normal(c.w, &B[touch[i].a], &B[touch[i].b], w->now));
        }
    }
    cc__clu_gather(&c);
    if (c.nc <= 1 && n == 1)
        return cc__world_resolve_pairwise(w, touch, n); /* nothing else touches: a pair impact */
    scale = cc__clu_scale(&c);
    if (cc__cluster_resolve(c.body, c.nb, c.contact, c.nc, cc__clu_restitution(&c), w->rest_speed, c.scratch,
                            c.scratch_bytes, &rep) != CC_OK)
        return cc__world_resolve_pairwise(w, touch, n); /* an inverse mass not finite: masses 2^1024 apart */
    /* new velocities from this instant on: each changed body is carried to now first */
    for (i = 0; i < c.nb; i++) {
        cc__body *b = &B[c.id[i]];
        if (c.body[i].vel.x == b->vx && c.body[i].vel.y == b->vy)
            continue;
        cc__advance_body(w, b, w->now);
        b->vx = c.body[i].vel.x;
        b->vy = c.body[i].vel.y;
        cc__world_mark(w, c.id[i]);
    }
    /* one report per contact that took an impulse, after every velocity is set */
    for (i = 0; i < c.nc; i++) {
        const cc__cluster_contact *k = &c.contact[i];
        const cc__body *ba = &B[c.id[k->a]];
        cc_contact ev;
        if (k->b >= 0) {
            const cc__body *bb = &B[c.id[k->b]];
            double ax = cc__bx(w, ba, w->now), ay = cc__by(w, ba, w->now);
            double dx = cc__near_d(w, cc__bx(w, bb, w->now) - ax, 0), dy = cc__near_d(w, cc__by(w, bb, w->now) - ay, 1);
            ev.depth = ba->r + bb->r - sqrt(dx * dx + dy * dy);
            ev.point = cc__v(ax + k->normal.x * (ba->r - 0.5 * ev.depth),
                             ay + k->normal.y * (ba->r - 0.5 * ev.depth));
        } else {
            ev = cc__wall_now(w, c.id[k->a], c.seg[i]);
        }
        cc__world_overlap_seen(w, ev.depth);
        if (!(k->impulse > 0.0))
            continue;
        ev.t = 0.0;
        ev.normal = k->normal;
        /* the impulse in the masses' own unit: beyond DBL_MAX it is +INFINITY (the header's rule) */
        cc__world_report(w, c.id[k->a], k->b >= 0 ? c.id[k->b] : -1, c.seg[i], &ev, ldexp(k->impulse, scale));
        hits++;
    }
    /* The event loop moves on because the impacts it hands in get resolved. The model calls a
     * contact approaching relative to the cluster's fastest body, the world relative to the
     * pair's own speeds: an impact the world still sees approaching gets the pair impulse. */
    for (i = 0; i < n; i++) {
        if (!cc__still_approaching(w, &touch[i]))
            continue;
        cc__advance_body(w, &B[touch[i].a], w->now);
        if (touch[i].b >= 0)
            cc__advance_body(w, &B[touch[i].b], w->now);
        hits += cc__world_resolve_pairwise(w, &touch[i], 1);
    }
    return hits;
}
