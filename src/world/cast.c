/* Casts (issue 14): the first circle or wall a circle (or a ray) moving from p to p + d touches,
 * with the world held still at its current time. The path is walked in pieces about a cell long
 * (longer for a wide cast), each piece's cells searched through the grid (region.h), and the walk
 * stops once a hit lies before the end of the piece searched: a circle hit at t lies within the
 * cast radius plus its own of the path's point at t, so it is found with the piece holding t. */
#include "filter.h"
#include "region.h"
#include "walls.h"

#include "precision_double.h"
#include "helpers.inc"
#include "solver.inc"
#include "precision_end.h"

typedef struct cc__cast {
    const cc_world *w;
    cc_vec2 p, d;
    double r;
    uint32_t mask;
    int ignore; /* the storage index of the circle the filter leaves out, or -1 */
    /* the best so far: (t, touch, wall, id) smallest first */
    double t;
    int touch, wall, id;
    cc_vec2 point, normal;
} cc__cast;

/* Whether (t, touch, wall, id) comes before the best so far. */
static int cc__earlier(const cc__cast *c, double t, int touch, int wall, int id)
{
    if (t != c->t)
        return t < c->t;
    if (touch != c->touch)
        return touch < c->touch; /* an overlap before a touch at t = 0 */
    if (wall != c->wall)
        return wall < c->wall; /* circles before walls */
    return id < c->id;
}

static void cc__offer(cc__cast *c, double t, int touch, int wall, int id, cc_vec2 n)
{
    if (!cc__earlier(c, t, touch, wall, id))
        return;
    c->t = t;
    c->touch = touch;
    c->wall = wall;
    c->id = id;
    c->normal = n;
    c->point = cc__advance(cc__advance(c->p, c->d, t), n, c->r);
}

static void cc__cast_visit(void *ctx, int j, double sx, double sy)
{
    cc__cast *c = (cc__cast *)ctx;
    const cc_world *w = c->w;
    const cc__body *b = &CC__CARR(w, cc__body, off_body)[j];
    cc_vec2 q, dp, n;
    double t, R = c->r + b->r;
    int eL, r, id;
    if (j == c->ignore || !cc__category_meets(w, j, c->mask) ||
        ((w->features & CC__F_SENSOR) && CC__CARR(w, cc__props, off_props)[j].sensor >= 0))
        return;
    cc__body_pos(w, j, w->now, &q.x, &q.y);
    q.x += sx; /* periodic: the image the path meets here */
    q.y += sy;
    /* relative frame, as cc_sweep: the circle at q - p, the cast moving at d against it */
    dp = cc__diff(c->p, q, &eL);
    r = cc__sweep_rel(dp, cc__v(-c->d.x, -c->d.y), eL ? R * 0.5 : R, eL, 0, 1.0, &t, &n);
    if (r != CC_HIT && r != CC_OVERLAP)
        return;
    id = cc__idx2id(w, j);
    cc__offer(c, r == CC_OVERLAP ? 0.0 : t, r == CC_HIT, 0, id, n);
}

/* A ray (radius 0) against wall s: where it crosses it. Relative to p, so that a cast far from
 * the origin costs no accuracy. */
static int cc__ray_wall(const cc__cast *c, const cc_segment *s, double *t_out, cc_vec2 *n_out)
{
    cc_vec2 a = cc__sub(s->a, c->p), b = cc__sub(s->b, c->p), u = cc__sub(b, a), d = c->d;
    double den = cc__cross(d, u), t, v;
    if (d.x == 0.0 && d.y == 0.0)
        return CC_MISS; /* a ray that does not move touches nothing it is not already on */
    if (den == 0.0) {
        /* parallel (or a point): only a wall on the ray's own line is met, at its nearer end */
        double ta, tb, dd = cc__dot(d, d);
        if (cc__cross(d, a) != 0.0)
            return CC_MISS;
        ta = cc__dot(a, d) / dd;
        tb = cc__dot(b, d) / dd;
        t = ta < tb ? ta : tb;
        if ((ta < 0.0) != (tb < 0.0) || ta == 0.0 || tb == 0.0)
            t = 0.0; /* it starts on the wall */
        if (!(t >= 0.0 && t <= 1.0))
            return CC_MISS;
        *t_out = t;
        *n_out = cc__unit(d);
        return CC_HIT;
    }
    t = cc__cross(a, u) / den;
    v = cc__cross(a, d) / den; /* where along the wall: 0 at its end a, 1 at b */
    if (!(t >= 0.0 && t <= 1.0 && v >= 0.0 && v <= 1.0))
        return CC_MISS;
    *t_out = t;
    *n_out = cc__unit(cc__v(-u.y, u.x));
    if (cc__dot(*n_out, d) < 0.0)
        *n_out = cc__v(-n_out->x, -n_out->y); /* towards the wall, from the ray's side */
    return CC_HIT;
}

static void cc__cast_walls(cc__cast *c)
{
    const cc_world *w = c->w;
    const cc_segment *seg = CC__CARR(w, cc_segment, off_seg);
    const cc__segment_props *sp = CC__CARR(w, cc__segment_props, off_segprops);
    cc_vec2 e = cc__advance(c->p, c->d, 1.0);
    double g = c->r + 0x1p-30 * (fabs(c->p.x) + fabs(c->p.y) + fabs(e.x) + fabs(e.y) + c->r);
    cc__wall_walk walk;
    int s;
    cc__walls_begin(w, &walk, (c->p.x < e.x ? c->p.x : e.x) - g, (c->p.y < e.y ? c->p.y : e.y) - g,
                    (c->p.x < e.x ? e.x : c->p.x) + g, (c->p.y < e.y ? e.y : c->p.y) + g);
    while ((s = cc__walls_next(w, &walk)) >= 0) {
        cc_vec2 n;
        double t;
        int r;
        if (!((w->features & CC__F_FILTER) ? sp[s].category & c->mask : c->mask & 1u))
            continue; /* (no filter set: every wall has category 1, and a world may have no props) */
        if (c->r > 0.0) {
            cc_circle k;
            cc_contact hit;
            k.pos = c->p;
            k.vel = c->d;
            k.radius = c->r;
            k.mass = 1.0;
            r = cc_sweep_segment(&k, &seg[s], 1.0, &hit);
            t = hit.t;
            n = hit.normal;
        } else {
            r = cc__ray_wall(c, &seg[s], &t, &n);
        }
        if (r == CC_HIT || r == CC_OVERLAP)
            cc__offer(c, r == CC_OVERLAP ? 0.0 : t, r == CC_HIT, 1, s, n);
    }
}

/* How many images of each circle a periodic cast may look at: the path, widened by the radius,
 * may cross about this many period cells (2^13 periods along its length, or a radius of some 60
 * periods across). Beyond it a cast looks at each circle's nearest image to the middle of its
 * path, once (the header's "Periodic boxes"), so that its cost stays bounded. */
#define CC__CAST_IMAGES 16384.0

/* The pieces the path is walked in: a cell long (or the cast's radius, when wider) through a
 * current grid, at most one per circle (a longer path is walked in pieces half a period long, as
 * without a grid: cc__visit_region gives every circle's images in each); one piece for an open
 * world without a grid (every circle once: no images to find); 0 for a periodic cast that would
 * look at more than CC__CAST_IMAGES images of each circle, counted on pieces half a period (or
 * the radius) long whatever the mode or state, so that which casts see every image is one rule. */
static long cc__cast_pieces(const cc_world *w, cc_vec2 d, double radius, double len)
{
    double piece, n, looks = 1.0, pmin = HUGE_VAL;
    int k;
    if (w->features & CC__F_PERIODIC) {
        for (k = 0; k < 2; k++)
            if (w->period[k] > 0.0 && w->period[k] < pmin)
                pmin = w->period[k];
        piece = 0.5 * pmin > radius ? 0.5 * pmin : radius;
        n = len / piece < 1.0 ? 1.0 : ceil(len / piece);
        /* a circle fits its period three times over (cc__fits_period): its radius is below pmin / 4 */
        for (k = 0; k < 2; k++)
            if (w->period[k] > 0.0)
                looks *= (fabs(k == 0 ? d.x : d.y) / n + 2.0 * (radius + 0.25 * pmin)) / w->period[k] + 2.0;
        if (!(n * looks <= CC__CAST_IMAGES))
            return 0;
    } else {
        n = 1.0;
    }
    if (cc__grid_current(w)) {
        piece = w->cs > radius ? w->cs : radius;
        if (len / piece < (double)w->id_end)
            return len / piece < 1.0 ? 1 : (long)ceil(len / piece);
    }
    return (long)n;
}

/* Each circle's nearest image to the middle of the path, once. */
static void cc__cast_nearest(cc__cast *c)
{
    const cc_world *w = c->w;
    const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
    cc_vec2 m = cc__advance(c->p, c->d, 0.5);
    int j;
    for (j = 0; j < w->id_end; j++)
        if (C[j].flags & CC__ALIVE)
            cc__visit_nearest(w, j, m.x, m.y, cc__cast_visit, c);
}

CC_API int cc_world_cast_circle(const cc_world *w, cc_vec2 p, double radius, cc_vec2 d, uint32_t mask,
                                cc_cast_hit *out)
{
    cc_query_filter f = cc__filter_of_mask(mask);
    return cc_world_cast_circle_filtered(w, p, radius, d, &f, out);
}

CC_API int cc_world_cast_circle_filtered(const cc_world *w, cc_vec2 p, double radius, cc_vec2 d,
                                         const cc_query_filter *filter, cc_cast_hit *out)
{
    cc__cast c;
    double len;
    long k, pieces;
    if (w == NULL || w->magic != CC__WORLD_MAGIC || out == NULL || !cc__vec_ok(p) || !cc__vec_ok(d) ||
        !(radius >= 0.0) || !isfinite(radius))
        return CC_ERR_INVALID;
    memset(&c, 0, sizeof c);
    if (cc__filter_read(w, filter, &c.mask, &c.ignore) != CC_OK)
        return CC_ERR_VERSION;
    c.w = w;
    c.p = p;
    c.d = d;
    c.r = radius;
    c.t = HUGE_VAL;
    c.touch = c.wall = 1;
    c.id = INT32_MAX;
    cc__cast_walls(&c);
    len = cc__length(d);
    pieces = cc__cast_pieces(w, d, radius, len);
    if (pieces == 0) { /* beyond the images it looks at: each circle's nearest to the path's middle */
        cc__cast_nearest(&c);
    }
    for (k = 0; k < pieces; k++) {
        double t0 = (double)k / (double)pieces, t1 = (double)(k + 1) / (double)pieces;
        cc_vec2 a = cc__advance(p, d, t0), b = cc__advance(p, d, t1);
        /* the piece's box grown by the radius, and by far more than the rounding of a and b
         * (2^-40 of them: thousands of ulps, and few enough that a periodic box holds no more
         * images than its width gives it) */
        double g = radius + 0x1p-40 * (fabs(a.x) + fabs(a.y) + fabs(b.x) + fabs(b.y) + radius);
        cc__visit_region(w, (a.x < b.x ? a.x : b.x) - g, (a.y < b.y ? a.y : b.y) - g, (a.x < b.x ? b.x : a.x) + g,
                         (a.y < b.y ? b.y : a.y) + g, 1, cc__cast_visit, &c);
        if (c.t < t1)
            break; /* every circle touched before t1 has been looked at */
    }
    if (c.t > 1.0)
        return CC_MISS;
    out->circle = c.wall ? -1 : c.id;
    out->segment = c.wall ? c.id : -1;
    out->t = c.t;
    out->point = c.point;
    out->normal = c.normal;
    return c.touch ? CC_HIT : CC_OVERLAP;
}
