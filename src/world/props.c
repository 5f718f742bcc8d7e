/* Per-body properties (issue 13): the get/set API of circles' and walls' properties, the
 * filters that decide which pairs interact, and the restitution of a contact made from its two
 * sides'. A world whose bodies keep their defaults never reads any of this (w->features). */
#include "world_internal.h"
#include "codes.h"

#include <stddef.h>


static const size_t cc__circle_props_ends[] = {
    CC__END(cc_circle_props, struct_size), CC__END(cc_circle_props, restitution),
    CC__END(cc_circle_props, rolling_decel), CC__END(cc_circle_props, category), CC__END(cc_circle_props, mask),
    CC__END(cc_circle_props, sensor)};
static const size_t cc__segment_props_ends[] = {
    CC__END(cc_segment_props, struct_size), CC__END(cc_segment_props, restitution),
    CC__END(cc_segment_props, category), CC__END(cc_segment_props, mask)};
#define CC__COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

void cc__props_default(const cc_world *w, cc__props *p)
{
    memset(p, 0, sizeof *p); /* the rolling state starts at 0 */
    p->restitution = w->restitution;
    p->decel = w->rolling_decel;
    p->inside = 0;
    p->category = 1u;
    p->mask = 0xFFFFFFFFu;
    p->sensor = -1;
}

int cc__circles_interact(const cc_world *w, int i, int j)
{
    const cc__props *P = CC__CARR(w, cc__props, off_props);
    return cc__filter_pass(&P[i], &P[j]) && P[i].sensor < 0 && P[j].sensor < 0;
}

int cc__wall_interacts(const cc_world *w, int i, int s)
{
    const cc__props *p = &CC__CARR(w, cc__props, off_props)[i];
    const cc__segment_props *q = &CC__CARR(w, cc__segment_props, off_segprops)[s];
    return p->sensor < 0 && (p->category & q->mask) != 0 && (q->category & p->mask) != 0;
}

static double cc__mix(int mix, double a, double b)
{
    switch (mix) {
    case CC_MIX_MAX: return a > b ? a : b;
    case CC_MIX_PRODUCT: return a * b;
    case CC_MIX_MEAN: return 0.5 * (a + b);
    default: return a < b ? a : b;
    }
}

double cc__contact_restitution(const cc_world *w, int i, int j, int s)
{
    const cc__props *P = CC__CARR(w, cc__props, off_props);
    if (!(w->features & CC__F_RESTITUTION))
        return w->restitution; /* every side has def.restitution, which the rule mixes to itself */
    if (!cc__props_reserved(w)) /* (product mixing of defaults): every side has def.restitution */
        return cc__mix(w->mix, w->restitution, w->restitution);
    if (j >= 0)
        return cc__mix(w->mix, P[i].restitution, P[j].restitution);
    return cc__mix(w->mix, P[i].restitution, CC__CARR(w, cc__segment_props, off_segprops)[s].restitution);
}

/* ---- the API --------------------------------------------------------------------------------- */

static int cc__world_ok(const cc_world *w) { return w != NULL && w->magic == CC__WORLD_MAGIC; }

static int cc__live_index(const cc_world *w, int id)
{
    int k;
    if (id < 0 || id >= w->id_end)
        return -1;
    k = CC__CARR(w, int32_t, off_id2idx)[id];
    return (CC__CARR(w, cc__cold, off_cold)[k].flags & CC__ALIVE) ? k : -1;
}

/* Copies the whole fields of src that fit in `size` bytes after struct_size into dst. */
static void cc__copy_fields(void *dst, const void *src, size_t size, const size_t *ends, int count)
{
    size_t n = cc__whole_fields(size, ends, count), from = sizeof(size_t);
    if (n > from)
        memcpy((unsigned char *)dst + from, (const unsigned char *)src + from, n - from);
}

CC_API int cc_world_get_circle_props(const cc_world *w, int id, cc_circle_props *out)
{
    const cc__props *p;
    cc__props dflt;
    cc_circle_props q;
    int k;
    if (!cc__world_ok(w) || out == NULL)
        return CC_ERR_INVALID;
    if (out->struct_size < CC__END(cc_circle_props, restitution))
        return CC_ERR_VERSION;
    if ((k = cc__live_index(w, id)) < 0)
        return CC_ERR_NOT_FOUND;
    if (cc__props_reserved(w)) {
        p = &CC__CARR(w, cc__props, off_props)[k];
    } else {
        cc__props_default(w, &dflt); /* a world without props: every circle has its defaults */
        p = &dflt;
    }
    memset(&q, 0, sizeof q);
    q.restitution = p->restitution;
    q.rolling_decel = p->decel;
    q.category = p->category;
    q.mask = p->mask;
    q.sensor = p->sensor >= 0;
    cc__copy_fields(out, &q, out->struct_size, cc__circle_props_ends, CC__COUNT(cc__circle_props_ends));
    return CC_OK;
}

/* A free sensor slot, or -1. */
static int cc__free_slot(const cc_world *w)
{
    int s;
    for (s = 0; s < CC_MAX_SENSORS; s++)
        if (!(w->sensor_slots >> s & 1u))
            return s;
    return -1;
}

CC_API int cc_world_set_circle_props(cc_world *w, int id, const cc_circle_props *in)
{
    cc__props *p, dflt;
    cc_circle_props q;
    int k, was_sensor, slot = -1;
    if (!cc__world_ok(w) || in == NULL)
        return CC_ERR_INVALID;
    if (cc__busy(w))
        return cc__world_code(w, CC_ERR_BUSY);
    if (in->struct_size < CC__END(cc_circle_props, restitution))
        return CC_ERR_VERSION;
    if ((k = cc__live_index(w, id)) < 0)
        return CC_ERR_NOT_FOUND;
    if (cc__props_reserved(w)) {
        p = &CC__ARR(w, cc__props, off_props)[k];
    } else {
        cc__props_default(w, &dflt); /* its values; any other is refused below */
        p = &dflt;
    }
    /* the current values, overwritten by the fields the caller sent */
    q.struct_size = sizeof q;
    q.restitution = p->restitution;
    q.rolling_decel = p->decel;
    q.category = p->category;
    q.mask = p->mask;
    q.sensor = p->sensor >= 0;
    cc__copy_fields(&q, in, in->struct_size, cc__circle_props_ends, CC__COUNT(cc__circle_props_ends));
    if (!(q.restitution >= 0.0 && q.restitution <= 1.0) || !(q.rolling_decel >= 0.0 && isfinite(q.rolling_decel)))
        return CC_ERR_INVALID;
    was_sensor = p->sensor >= 0;
    if (q.restitution == p->restitution && q.rolling_decel == p->decel && q.category == p->category &&
        q.mask == p->mask && !q.sensor == !was_sensor)
        return CC_OK; /* nothing changes: nothing is done (the same bits as without the call) */
    /* what the world did not reserve (def.uses) is refused, nothing changed */
    if (((q.restitution != p->restitution || q.category != p->category || q.mask != p->mask) &&
         !(w->uses & CC_USES_PROPS)) ||
        (q.rolling_decel != p->decel && !(w->uses & (CC_USES_PROPS | CC_USES_ROLLING))) ||
        (!q.sensor != !was_sensor && !(w->uses & CC_USES_SENSORS)))
        return CC_ERR_INVALID;
    if (q.sensor && !was_sensor && (slot = cc__free_slot(w)) < 0)
        return CC_ERR_FULL;
    /* valid: from here on it changes, and callbacks may fire (ends of overlaps, push-aparts) */
    cc__world_own(w);
    cc__enter(w);
    if (was_sensor != !!q.sensor)
        cc__sensor_forget(w, k, 0); /* a sensor that stops, or a visitor that becomes one: ends */
    if (q.restitution != w->restitution)
        w->features |= CC__F_RESTITUTION;
    if (q.category != 1u || q.mask != 0xFFFFFFFFu)
        w->features |= CC__F_FILTER;
    if (q.rolling_decel > 0.0)
        w->features |= CC__F_ROLL;
    if (q.sensor)
        w->features |= CC__F_SENSOR;
    p->restitution = q.restitution;
    p->decel = q.rolling_decel;
    p->category = q.category;
    p->mask = q.mask;
    if (slot >= 0) {
        p->sensor = slot;
        w->sensor_slots |= (uint64_t)1 << slot;
        w->sensor_id[slot] = id;
    }
    cc__settle_props(w, k);
    cc__leave(w);
    return CC_OK;
}

/* A wall's defaults, for a world without props. */
static void cc__segment_default(const cc_world *w, cc__segment_props *p)
{
    p->restitution = w->restitution;
    p->category = 1u;
    p->mask = 0xFFFFFFFFu;
}

CC_API int cc_world_get_segment_props(const cc_world *w, int id, cc_segment_props *out)
{
    const cc__segment_props *p;
    cc__segment_props dflt;
    cc_segment_props q;
    if (!cc__world_ok(w) || out == NULL)
        return CC_ERR_INVALID;
    if (out->struct_size < CC__END(cc_segment_props, restitution))
        return CC_ERR_VERSION;
    if (id < 0 || id >= w->n_segments)
        return CC_ERR_NOT_FOUND;
    if (cc__props_reserved(w)) {
        p = &CC__CARR(w, cc__segment_props, off_segprops)[id];
    } else {
        cc__segment_default(w, &dflt);
        p = &dflt;
    }
    memset(&q, 0, sizeof q);
    q.restitution = p->restitution;
    q.category = p->category;
    q.mask = p->mask;
    cc__copy_fields(out, &q, out->struct_size, cc__segment_props_ends, CC__COUNT(cc__segment_props_ends));
    return CC_OK;
}

CC_API int cc_world_set_segment_props(cc_world *w, int id, const cc_segment_props *in)
{
    cc__segment_props *p, dflt;
    cc_segment_props q;
    if (!cc__world_ok(w) || in == NULL)
        return CC_ERR_INVALID;
    if (cc__busy(w))
        return cc__world_code(w, CC_ERR_BUSY);
    if (in->struct_size < CC__END(cc_segment_props, restitution))
        return CC_ERR_VERSION;
    if (id < 0 || id >= w->n_segments)
        return CC_ERR_NOT_FOUND;
    if (cc__props_reserved(w)) {
        p = &CC__ARR(w, cc__segment_props, off_segprops)[id];
    } else {
        cc__segment_default(w, &dflt);
        p = &dflt;
    }
    q.struct_size = sizeof q;
    q.restitution = p->restitution;
    q.category = p->category;
    q.mask = p->mask;
    cc__copy_fields(&q, in, in->struct_size, cc__segment_props_ends, CC__COUNT(cc__segment_props_ends));
    if (!(q.restitution >= 0.0 && q.restitution <= 1.0))
        return CC_ERR_INVALID;
    if (!(w->uses & CC_USES_PROPS)) /* the world did not reserve walls' properties: what it is */
        return q.restitution == p->restitution && q.category == p->category && q.mask == p->mask ? CC_OK
                                                                                                   : CC_ERR_INVALID;
    cc__world_own(w);
    if (q.restitution != w->restitution)
        w->features |= CC__F_RESTITUTION;
    if (q.category != 1u || q.mask != 0xFFFFFFFFu)
        w->features |= CC__F_FILTER;
    p->restitution = q.restitution;
    p->category = q.category;
    p->mask = q.mask;
    w->dirty = 1; /* which circles meet it may have changed: every prediction is made again */
    return CC_OK;
}
