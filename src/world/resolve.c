/* Contact resolution: every impulse the world applies goes through cc__world_resolve, which
 * hands EXACT's impacts to the simultaneous-impact path (simultaneous.c: the impact with
 * everything touching it at that instant) and resolves the rest pairwise here, with the public
 * pair functions; every push-apart of an overlap goes through cc__world_unoverlap. */
#include "world_internal.h"

#include "precision_double.h"
#include "helpers.inc"
#include "precision_end.h"

static cc_circle cc__as_circle(const cc_world *w, int id)
{
    const cc__body *b = &CC__CARR(w, cc__body, off_body)[id];
    cc_circle c;
    c.pos.x = b->px;
    c.pos.y = b->py;
    c.vel.x = b->vx;
    c.vel.y = b->vy;
    c.radius = b->r;
    c.mass = CC__CARR(w, cc__cold, off_cold)[id].m;
    return c;
}

void cc__world_report(cc_world *w, int a, int b, int seg, const cc_contact *k, double impulse)
{
    cc_contact_event e;
    w->stats.collisions++;
    if (b >= 0) /* the distance between the centres at contact: the radii less the overlap */
        w->stats.virial += impulse * (CC__CARR(w, cc__body, off_body)[a].r + CC__CARR(w, cc__body, off_body)[b].r - k->depth);
    else
        w->stats.wall_impulse += impulse;
    if (w->on_contact == NULL)
        return;
    e.a = cc__idx2id(w, a); /* the caller's ids, not storage indices */
    e.b = b >= 0 ? cc__idx2id(w, b) : -1;
    e.segment = seg;
    e.t = w->now;
    e.point = k->point;
    e.normal = k->normal;
    e.impulse = impulse;
    w->on_contact(&e, w->user);
}

/* Restitution of contact a-b (b < 0: wall seg) for an approach speed: 0 below rest_speed (the
 * inelastic-collapse remedy), else the mix of the two sides' (props.c). */
static double cc__restitution_for(const cc_world *w, double approach, int a, int b, int seg)
{
    return approach < w->rest_speed ? 0.0 : cc__contact_restitution(w, a, b, seg);
}

void cc__world_overlap_seen(cc_world *w, double depth)
{
    if (depth > w->stats.max_overlap)
        w->stats.max_overlap = depth;
}

/* Wall contact of circle c with segment s: normal from the centre to the nearest point. */
cc_contact cc__world_wall_contact(const cc_circle *c, const cc_segment *s)
{
    cc_contact k;
    cc_vec2 q = cc_closest_point_on_segment(c->pos, s);
    cc_vec2 d = cc__sub(q, c->pos);
    double dist = cc__length(d);
    k.t = 0.0;
    if (dist > 0x1p-1000) /* (1 / dist finite, and d's parts normal enough for a unit vector) */
        k.normal = cc__scale(d, 1.0 / dist);
    else if (dist > 0.0) /* a centre a subnormal away from the wall: 1 / dist overflowed to */
        k.normal = cc__unit(d); /* inf, the push-out to (inf, NaN) (world fuzzer D25) */
    else
        k.normal = cc__unit(cc__v(s->a.y - s->b.y, s->b.x - s->a.x));
    k.depth = c->radius - dist;
    k.point = q;
    return k;
}

/* held != NULL (two circles only): the report is stored in *held and *held_impulse instead of
 * made, for a caller that makes it later (cc__world_resolve_pair_held). */
static int cc__resolve_one(cc_world *w, const cc__touch *tc, cc_contact *held, double *held_impulse)
{
    cc__body *B = CC__ARR(w, cc__body, off_body);
    cc__body *ba = &B[tc->a];
    cc_circle ca = cc__as_circle(w, tc->a);
    cc_contact k;
    double approach, impulse;
    if (tc->b >= 0) {
        cc__body *bb = &B[tc->b];
        cc_circle cb = cc__as_circle(w, tc->b);
        cc_vec2 d;
        cc__near_image(w, ca.pos, &cb.pos); /* periodic: the image it touches */
        d = cc__sub(cb.pos, ca.pos);
        double dist = cc__length(d);
        k.t = 0.0;
        k.normal = cc__unit(d);
        k.depth = ca.radius + cb.radius - dist;
        k.point = cc__advance(ca.pos, k.normal, ca.radius - 0.5 * k.depth);
        cc__world_overlap_seen(w, k.depth);
        approach = -cc__dot(cc__sub(cb.vel, ca.vel), k.normal);
        if (cc_respond(&ca, &cb, &k, cc__restitution_for(w, approach, tc->a, tc->b, -1)) != CC_HIT)
            return 0;
        impulse = isinf(ca.mass) ? cb.mass * cc__length(cc__sub(cb.vel, cc__v(bb->vx, bb->vy)))
                                 : ca.mass * cc__length(cc__sub(ca.vel, cc__v(ba->vx, ba->vy)));
        if (held != NULL) {
            *held = k;
            *held_impulse = impulse;
        } else {
            cc__world_report(w, tc->a, tc->b, -1, &k, impulse);
        }
        if (ca.vel.x != ba->vx || ca.vel.y != ba->vy) {
            ba->vx = ca.vel.x;
            ba->vy = ca.vel.y;
            cc__world_mark(w, tc->a);
        }
        if (cb.vel.x != bb->vx || cb.vel.y != bb->vy) {
            bb->vx = cb.vel.x;
            bb->vy = cb.vel.y;
            cc__world_mark(w, tc->b);
        }
        return 1;
    }
    k = cc__world_wall_contact(&ca, &CC__CARR(w, cc_segment, off_seg)[tc->segment]);
    cc__world_overlap_seen(w, k.depth);
    approach = cc__dot(ca.vel, k.normal);
    if (isinf(ca.mass) || cc_respond_segment(&ca, &k, cc__restitution_for(w, approach, tc->a, -1, tc->segment)) != CC_HIT)
        return 0;
    cc__world_report(w, tc->a, -1, tc->segment, &k, ca.mass * cc__length(cc__sub(ca.vel, cc__v(ba->vx, ba->vy))));
    ba->vx = ca.vel.x;
    ba->vy = ca.vel.y;
    cc__world_mark(w, tc->a);
    return 1;
}

void cc__world_touch(cc_world *w, int id)
{
    cc__cold *k = &CC__ARR(w, cc__cold, off_cold)[id];
    CC__ARR(w, cc__body, off_body)[id].count++;
    if (w->features & CC__F_ROLL)
        cc__roll_reset(w, id); /* a new velocity, the same deceleration */
    if (k->flags & CC__TOUCHED)
        return;
    k->flags |= CC__TOUCHED;
    CC__ARR(w, int32_t, off_touched)[w->n_touched++] = id;
}

int cc__world_take_touched(cc_world *w)
{
    int id;
    if (w->n_touched == 0)
        return -1;
    id = CC__ARR(w, int32_t, off_touched)[--w->n_touched];
    CC__ARR(w, cc__cold, off_cold)[id].flags &= ~CC__TOUCHED;
    return id;
}

/* Pairwise, in the order given: modes without clusters, and impacts that touch nothing else. */
int cc__world_resolve_pairwise(cc_world *w, const cc__touch *touch, int n)
{
    int i, hits = 0;
    for (i = 0; i < n; i++)
        hits += cc__resolve_one(w, &touch[i], NULL, NULL);
    return hits;
}

int cc__world_resolve_pair_held(cc_world *w, const cc__touch *tc, cc_contact *k, double *impulse)
{
    return tc->b >= 0 ? cc__resolve_one(w, tc, k, impulse) : 0;
}

/* EXACT resolves each impact with everything touching it at that instant (simultaneous.c);
 * SWEPT and DISCRETE, which do not keep positions current between impacts, pairwise; so does
 * the rebuild's pass over overlaps the caller made (w->dirty: without a current grid, finding
 * what touches would cost a look at every circle for each overlap). */
int cc__world_resolve(cc_world *w, const cc__touch *touch, int n)
{
    if (w->clu_bodies > 0 && !w->dirty)
        return cc__world_resolve_cluster(w, touch, n);
    return cc__world_resolve_pairwise(w, touch, n);
}

int cc__world_unoverlap(cc_world *w, int a, int b, int seg)
{
    cc__body *B = CC__ARR(w, cc__body, off_body);
    cc__cold *C = CC__ARR(w, cc__cold, off_cold);
    cc__body *ba = &B[a];
    cc_circle ca = cc__as_circle(w, a);
    cc__touch tc;
    tc.a = a;
    tc.b = b;
    tc.segment = seg;
    if ((w->features & (CC__F_FILTER | CC__F_SENSOR)) &&
        !(b >= 0 ? cc__circles_interact(w, a, b) : cc__wall_interacts(w, a, seg)))
        return 0; /* they pass through each other */
    if (b >= 0) {
        cc__body *bb = &B[b];
        cc_circle cb = cc__as_circle(w, b);
        cc_contact k;
        cc_vec2 image = cb.pos;
        if (isinf(ca.mass) && isinf(cb.mass))
            return 0;
        cc__near_image(w, ca.pos, &cb.pos); /* periodic: the image it overlaps */
        image = cc__sub(cb.pos, image);     /* the shift, taken off again below */
        if (cc_detect_static(&ca, &cb, &k) != CC_OVERLAP)
            return 0;
        cc__world_overlap_seen(w, k.depth);
        if (cc_separate(&ca, &cb) != CC_OVERLAP)
            return 0;
        cb.pos = cc__sub(cb.pos, image);
        if (ca.pos.x != ba->px || ca.pos.y != ba->py) {
            ba->px = ca.pos.x;
            ba->py = ca.pos.y;
            C[a].flags |= CC__MOVED;
            cc__world_mark(w, a);
        }
        if (cb.pos.x != bb->px || cb.pos.y != bb->py) {
            bb->px = cb.pos.x;
            bb->py = cb.pos.y;
            C[b].flags |= CC__MOVED;
            cc__world_mark(w, b);
        }
    } else {
        cc_contact k;
        if (isinf(ca.mass))
            return 0;
        k = cc__world_wall_contact(&ca, &CC__CARR(w, cc_segment, off_seg)[seg]);
        if (!(k.depth > 0.0))
            return 0;
        cc__world_overlap_seen(w, k.depth);
        ba->px -= k.normal.x * k.depth;
        ba->py -= k.normal.y * k.depth;
        C[a].flags |= CC__MOVED;
        cc__world_mark(w, a);
    }
    (void)cc__world_resolve(w, &tc, 1);
    return 1;
}
