/* The state hash (issue 14): 64 bits over everything that decides what the world does next, in a
 * fixed order (ids ascending, then walls, then the settings), each double by its bits, so that two
 * worlds in the same state hash alike wherever their memory lives, and a state one bit apart
 * hashes otherwise. The mixing is a multiply-xorshift over 64-bit words (the finaliser of
 * SplitMix64 after each word), written here. */
#include "world_internal.h"

#include <string.h>

static uint64_t cc__mix(uint64_t h, uint64_t v)
{
    h ^= v + UINT64_C(0x9E3779B97F4A7C15) + (h << 6) + (h >> 2);
    h ^= h >> 30;
    h *= UINT64_C(0xBF58476D1CE4E5B9);
    h ^= h >> 27;
    h *= UINT64_C(0x94D049BB133111EB);
    h ^= h >> 31;
    return h;
}

static uint64_t cc__mix_double(uint64_t h, double x)
{
    uint64_t v;
    memcpy(&v, &x, sizeof v);
    return cc__mix(h, v);
}

static uint64_t cc__mix_vec(uint64_t h, cc_vec2 p) { return cc__mix_double(cc__mix_double(h, p.x), p.y); }

CC_API uint64_t cc_world_hash(const cc_world *w)
{
    const cc__cold *C;
    const cc__props *P;
    cc__props dflt;
    const cc_segment *seg;
    const cc__segment_props *sp;
    const int32_t *id2idx;
    uint64_t h = UINT64_C(0x63636861736831); /* "cchash1" */
    int id, s;
    if (w == NULL || w->magic != CC__WORLD_MAGIC)
        return 0;
    C = CC__CARR(w, cc__cold, off_cold);
    P = cc__props_reserved(w) ? CC__CARR(w, cc__props, off_props) : NULL;
    cc__props_default(w, &dflt); /* what every body of a world without props has */
    seg = CC__CARR(w, cc_segment, off_seg);
    sp = cc__props_reserved(w) ? CC__CARR(w, cc__segment_props, off_segprops) : NULL;
    id2idx = CC__CARR(w, int32_t, off_id2idx);
    h = cc__mix_double(h, w->now);
    for (id = 0; id < w->id_end; id++) {
        int k = id2idx[id];
        cc_circle c;
        const cc__props *p = P != NULL ? &P[k] : &dflt;
        if (!(C[k].flags & CC__ALIVE))
            continue;
        (void)cc_world_get_circle(w, id, &c); /* the state the API shows */
        h = cc__mix(h, (uint64_t)id);
        h = cc__mix_vec(cc__mix_vec(h, c.pos), c.vel);
        h = cc__mix_double(cc__mix_double(h, c.radius), c.mass);
        h = cc__mix_double(cc__mix_double(h, p->restitution), p->decel);
        h = cc__mix(h, (uint64_t)p->category << 32 | p->mask);
        h = cc__mix(h, p->sensor >= 0 ? (uint64_t)p->sensor + 1u : 0u);
        h = cc__mix(h, p->inside);
    }
    h = cc__mix(h, (uint64_t)w->n_segments);
    for (s = 0; s < w->n_segments; s++) {
        h = cc__mix_vec(cc__mix_vec(h, seg[s].a), seg[s].b);
        if (sp != NULL) {
            h = cc__mix_double(h, sp[s].restitution);
            h = cc__mix(h, (uint64_t)sp[s].category << 32 | sp[s].mask);
        } else { /* a wall's defaults */
            h = cc__mix_double(h, w->restitution);
            h = cc__mix(h, (uint64_t)1u << 32 | 0xFFFFFFFFu);
        }
    }
    /* the settings that decide what happens next (not the callbacks or the user pointer) */
    h = cc__mix(h, (uint64_t)w->mode << 32 | (uint32_t)w->mix);
    h = cc__mix(h, (uint64_t)(uint32_t)w->max_circles << 32 | (uint32_t)w->max_segments);
    h = cc__mix_double(cc__mix_double(h, w->restitution), w->rest_speed);
    h = cc__mix_double(cc__mix_double(h, w->cell_hint), w->rolling_decel);
    h = cc__mix(h, w->max_events);
    h = cc__mix_double(cc__mix_double(h, w->period[0]), w->period[1]);
    return h;
}
