/* EXACT mode's simultaneous impacts: an impact due now is resolved together with every body
 * that touches the impacting bodies at this instant (transitively, through movable bodies) and
 * every wall those touch: one cluster, resolved by the model of cluster.c (generalized
 * reflections; docs/SIMULTANEOUS.md). Impacts predicted for the same instant are touching now,
 * so they join the same cluster. An impact that touches nothing else stays a pair impact
 * (resolve.c), bit for bit as before. */
#include "world_internal.h"
#include "world/cluster.h"

static cc_vec2 cc__v(double x, double y)
{
    cc_vec2 v;
    v.x = x;
    v.y = y;
    return v;
}

/* unit vector from a to b at world time now; (1, 0) for coincident centres, like cc_sweep */
static cc_vec2 cc__centre_normal(const cc__body *a, const cc__body *b, double now)
{
    double dx = cc__bx(b, now) - cc__bx(a, now), dy = cc__by(b, now) - cc__by(a, now);
    double d = sqrt(dx * dx + dy * dy);
    return d > 0.0 ? cc__v(dx / d, dy / d) : cc__v(1.0, 0.0);
}

/* Capacities: a cluster holds up to CC__CLU_BODIES bodies (the 15-ball rack and its cue ball
 * take 16) and CC__CLU_CONTACTS contacts (the rack: 31); the solver's scratch grows as
 * 16 * contacts^2 bytes. Touching bodies beyond them are left out of the cluster: their
 * contacts, if approaching, are impacts due now and resolved right after. */
#define CC__CLU_BODIES 24
#define CC__CLU_CONTACTS 48

/* Two bodies touch when their gap is at most 2^-40 of the size of the numbers that made it:
 * their coordinates and radii, and the distance they travel in the rounding of the world time
 * (predicted times of impacts carry a few ulps of |now|). See docs/SIMULTANEOUS.md. */
#define CC__CLU_TOL 0x1p-40

typedef struct cc__clu {
    int nb, nc, full;
    int *id;                      /* storage indices of the bodies */
    cc__cluster_body *body;       /* their velocities and inverse masses */
    cc__cluster_contact *contact; /* a, b index into id[]; b = -1 for a wall */
    int *seg;                     /* a wall contact's segment, else -1 */
    void *scratch;
    size_t scratch_bytes;
    cc_world *w;
    int from; /* the body whose touching neighbours are being visited (position in id[]) */
    double fx, fy; /* its position now */
} cc__clu;

static size_t cc__al16(size_t n) { return (n + 15u) & ~(size_t)15u; }

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
    c->nb = c->nc = c->full = 0;
    c->w = w;
}

static double cc__inf_norm(double x, double y) { return fabs(x) > fabs(y) ? fabs(x) : fabs(y); }

/* Position of body k in the cluster (adding it when new and there is room), or -1. */
static int cc__clu_body(cc__clu *c, int k)
{
    const cc__body *B = CC__CARR(c->w, cc__body, off_body);
    double m = CC__CARR(c->w, cc__cold, off_cold)[k].m;
    int i;
    for (i = 0; i < c->nb; i++)
        if (c->id[i] == k)
            return i;
    if (c->nb == c->w->clu_bodies) {
        c->full = 1;
        return -1;
    }
    c->id[c->nb] = k;
    c->body[c->nb].vel.x = B[k].vx;
    c->body[c->nb].vel.y = B[k].vy;
    c->body[c->nb].inv_mass = isinf(m) ? 0.0 : 1.0 / m;
    return c->nb++;
}

static void cc__clu_contact(cc__clu *c, int a, int b, int seg, cc_vec2 n)
{
    cc__cluster_contact *k;
    int i;
    for (i = 0; i < c->nc; i++) /* listed already (a seed, or found from the other side) */
        if (c->seg[i] == seg &&
            ((c->contact[i].a == a && c->contact[i].b == b) || (seg < 0 && c->contact[i].a == b && c->contact[i].b == a)))
            return;
    if (c->nc == c->w->clu_contacts) {
        c->full = 1;
        return;
    }
    k = &c->contact[c->nc];
    k->a = a;
    k->b = b;
    k->normal = n;
    k->impulse = 0.0;
    c->seg[c->nc++] = seg;
}

/* The touching tolerance for body k (at (x, y) now) and a partner of radius r at (px, py)
 * moving at speed (vx, vy); a wall is a partner of radius 0 at rest near k. */
static double cc__clu_tol(const cc_world *w, int k, double x, double y, double r, double px, double py,
                          double vx, double vy)
{
    const cc__body *b = &CC__CARR(w, cc__body, off_body)[k];
    return CC__CLU_TOL * (cc__inf_norm(x, y) + cc__inf_norm(px, py) + b->r + r +
                          (cc__inf_norm(b->vx, b->vy) + cc__inf_norm(vx, vy)) * fabs(w->now));
}

/* near.c's visitor: circle j or wall s touches the body being expanded. */
static void cc__clu_visit(void *ctx, int j, int s)
{
    cc__clu *c = (cc__clu *)ctx;
    cc_world *w = c->w;
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    int k = c->id[c->from], i;
    if (j >= 0) {
        double jx = cc__bx(&B[j], w->now), jy = cc__by(&B[j], w->now);
        double dx = jx - c->fx, dy = jy - c->fy, d = sqrt(dx * dx + dy * dy);
        const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
        if (isinf(C[k].m) && isinf(C[j].m))
            return; /* immovable circles pass through each other */
        if (d - (B[k].r + B[j].r) > cc__clu_tol(w, k, c->fx, c->fy, B[j].r, jx, jy, B[j].vx, B[j].vy))
            return;
        i = cc__clu_body(c, j);
        if (i < 0)
            return;
        cc__clu_contact(c, c->from, i, -1, d > 0.0 ? cc__v(dx / d, dy / d) : cc__v(1.0, 0.0));
    } else {
        cc_circle ci;
        cc_contact kk;
        const cc_segment *g = &CC__CARR(w, cc_segment, off_seg)[s];
        if (isinf(CC__CARR(w, cc__cold, off_cold)[k].m))
            return; /* an immovable circle passes through walls */
        ci.pos = cc__v(c->fx, c->fy);
        ci.vel = cc__v(B[k].vx, B[k].vy);
        ci.radius = B[k].r;
        ci.mass = 1.0;
        kk = cc__world_wall_contact(&ci, g);
        if (-kk.depth > cc__clu_tol(w, k, c->fx, c->fy, 0.0, kk.point.x, kk.point.y, 0.0, 0.0))
            return;
        cc__clu_contact(c, c->from, -1, s, kk.normal);
    }
}

int cc__world_resolve_cluster(cc_world *w, const cc__touch *touch, int n)
{
    cc__body *B = CC__ARR(w, cc__body, off_body);
    const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
    cc__clu c;
    cc__cluster_report rep;
    double loose;
    int i, hits = 0;
    cc__clu_carve(w, &c);
    /* the impacts themselves first, whatever their gap */
    for (i = 0; i < n; i++) {
        int a = cc__clu_body(&c, touch[i].a);
        if (touch[i].b >= 0) {
            int b = cc__clu_body(&c, touch[i].b);
            if (a >= 0 && b >= 0)
                cc__clu_contact(&c, a, b, -1, cc__centre_normal(&B[touch[i].a], &B[touch[i].b], w->now));
        } else if (a >= 0) {
            cc_circle ci;
            ci.pos = cc__v(cc__bx(&B[touch[i].a], w->now), cc__by(&B[touch[i].a], w->now));
            ci.vel = cc__v(B[touch[i].a].vx, B[touch[i].a].vy);
            ci.radius = B[touch[i].a].r;
            ci.mass = 1.0;
            cc__clu_contact(&c, a, -1, touch[i].segment,
                            cc__world_wall_contact(&ci, &CC__CARR(w, cc_segment, off_seg)[touch[i].segment]).normal);
        }
    }
    /* breadth first through the bodies touching now; immovable ones stop the spread (they take
     * impulses but pass none on) */
    for (c.from = 0; c.from < c.nb; c.from++) {
        int k = c.id[c.from];
        if (isinf(C[k].m))
            continue;
        c.fx = cc__bx(&B[k], w->now);
        c.fy = cc__by(&B[k], w->now);
        /* a bound on every pair tolerance of this body: neighbours lie within a cell or two and
         * move no faster than the fastest body of the cluster so far */
        {
            double vmax = 0.0, rmax = 0.0;
            int q;
            for (q = 0; q < c.nb; q++) {
                double v = cc__inf_norm(c.body[q].vel.x, c.body[q].vel.y);
                vmax = v > vmax ? v : vmax;
                rmax = B[c.id[q]].r > rmax ? B[c.id[q]].r : rmax;
            }
            loose = 4.0 * CC__CLU_TOL *
                    (2.0 * cc__inf_norm(c.fx, c.fy) + 4.0 * (w->cs > rmax ? w->cs : rmax) + 2.0 * vmax * fabs(w->now));
        }
        (void)cc__world_touching(w, k, loose, cc__clu_visit, &c);
    }
    if (c.nc <= 1 && n == 1)
        return cc__world_resolve_pairwise(w, touch, n); /* nothing else touches: a pair impact */
    if (cc__cluster_resolve(c.body, c.nb, c.contact, c.nc, w->restitution, w->rest_speed, c.scratch,
                            c.scratch_bytes, &rep) != CC_OK)
        return cc__world_resolve_pairwise(w, touch, n); /* cannot happen: valid by construction */
    /* new velocities from this instant on: each changed body is carried to now first */
    for (i = 0; i < c.nb; i++) {
        cc__body *b = &B[c.id[i]];
        if (c.body[i].vel.x == b->vx && c.body[i].vel.y == b->vy)
            continue;
        cc__advance_body(b, w->now);
        b->vx = c.body[i].vel.x;
        b->vy = c.body[i].vel.y;
        cc__world_mark(w, c.id[i]);
    }
    /* one report per contact that took an impulse, after every velocity is set */
    for (i = 0; i < c.nc; i++) {
        const cc__cluster_contact *k = &c.contact[i];
        const cc__body *ba = &B[c.id[k->a]];
        cc_contact ev;
        double depth;
        if (k->b >= 0) {
            const cc__body *bb = &B[c.id[k->b]];
            double dx = cc__bx(bb, w->now) - cc__bx(ba, w->now), dy = cc__by(bb, w->now) - cc__by(ba, w->now);
            depth = ba->r + bb->r - sqrt(dx * dx + dy * dy);
            ev.point = cc__v(cc__bx(ba, w->now) + k->normal.x * (ba->r - 0.5 * depth),
                             cc__by(ba, w->now) + k->normal.y * (ba->r - 0.5 * depth));
        } else {
            cc_circle ci;
            ci.pos = cc__v(cc__bx(ba, w->now), cc__by(ba, w->now));
            ci.vel = cc__v(ba->vx, ba->vy);
            ci.radius = ba->r;
            ci.mass = 1.0;
            ev = cc__world_wall_contact(&ci, &CC__CARR(w, cc_segment, off_seg)[c.seg[i]]);
            depth = ev.depth;
        }
        cc__world_overlap_seen(w, depth);
        if (!(k->impulse > 0.0))
            continue;
        ev.t = 0.0;
        ev.normal = k->normal;
        ev.depth = depth;
        cc__world_report(w, c.id[k->a], k->b >= 0 ? c.id[k->b] : -1, c.seg[i], &ev, k->impulse);
        hits++;
    }
    /* The event loop progresses because the impacts it hands in get resolved. The model calls a
     * contact approaching relative to the cluster's fastest body, the world relative to the
     * pair's own speeds: an impact the world still sees approaching gets the pair impulse. */
    for (i = 0; i < n; i++) {
        const cc__body *ba = &B[touch[i].a];
        double vn, speeds = fabs(ba->vx) + fabs(ba->vy);
        cc_vec2 nn;
        if (touch[i].b >= 0) {
            const cc__body *bb = &B[touch[i].b];
            nn = cc__centre_normal(ba, bb, w->now);
            vn = (ba->vx - bb->vx) * nn.x + (ba->vy - bb->vy) * nn.y;
            speeds += fabs(bb->vx) + fabs(bb->vy);
        } else {
            cc_circle ci;
            ci.pos = cc__v(cc__bx(ba, w->now), cc__by(ba, w->now));
            ci.vel = cc__v(ba->vx, ba->vy);
            ci.radius = ba->r;
            ci.mass = 1.0;
            nn = cc__world_wall_contact(&ci, &CC__CARR(w, cc_segment, off_seg)[touch[i].segment]).normal;
            vn = ba->vx * nn.x + ba->vy * nn.y;
        }
        if (cc__approaching(w, vn, speeds)) {
            cc__advance_body(&B[touch[i].a], w->now);
            if (touch[i].b >= 0)
                cc__advance_body(&B[touch[i].b], w->now);
            hits += cc__world_resolve_pairwise(w, &touch[i], 1);
        }
    }
    return hits;
}
