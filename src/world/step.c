/* Stepping's entry: cc_world_step's validation (including the range a step may carry a circle
 * to), the dispatch to the mode's stepper (exact.c, swept.c, discrete.c), and the counters the
 * steps keep (cc_world_get_stats). */
#include "world_internal.h"

#include <math.h>
#include <string.h>

static int cc__world_ok(const cc_world *w) { return w != NULL && w->magic == CC__WORLD_MAGIC; }

/* Whether every circle's straight path to t_end stays within 2^1017 (about 1.4e306) of the
 * origin along each axis: the bound a step may carry a circle to (cc_world_step in the header),
 * beyond which its arithmetic (positions, cell crossings, impacts) would overflow to Inf
 * (world fuzzer D1). Rolling paths are shorter than straight ones. */
static int cc__step_in_range(const cc_world *w, double t_end)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
    const double lim = 0x1p1017;
    int j;
    for (j = 0; j < w->id_end; j++) {
        double tau = t_end - B[j].t;
        /* the hot line first: the cold one (is it alive?) only for a path out of range */
        if (!(fabs(B[j].px) + fabs(B[j].vx) * tau < lim && fabs(B[j].py) + fabs(B[j].vy) * tau < lim) &&
            (C[j].flags & CC__ALIVE))
            return 0;
    }
    return 1;
}

CC_API int cc_world_step(cc_world *w, double dt)
{
    int r;
    if (!cc__world_ok(w) || w->busy || !(dt >= 0.0) || !isfinite(dt) || !isfinite(w->now + dt) ||
        !cc__step_in_range(w, w->now + dt))
        return CC_ERR_INVALID;
    w->busy = 1;
    if (w->mode == CC_MODE_EXACT)
        r = cc__step_exact(w, w->now + dt);
    else if (w->mode == CC_MODE_SWEPT)
        r = cc__step_swept(w, dt);
    else
        r = cc__step_discrete(w, dt);
    w->busy = 0;
    return r;
}

CC_API int cc_world_get_stats(const cc_world *w, cc_world_stats *out)
{
    static const size_t ends[] = {
        CC__END(cc_world_stats, struct_size), CC__END(cc_world_stats, collisions),
        CC__END(cc_world_stats, events), CC__END(cc_world_stats, stale_events),
        CC__END(cc_world_stats, pairs_tested), CC__END(cc_world_stats, cell_crossings),
        CC__END(cc_world_stats, max_overlap), CC__END(cc_world_stats, virial),
        CC__END(cc_world_stats, wall_impulse)};
    const size_t from = sizeof out->struct_size; /* the caller's struct_size is kept */
    size_t n;
    if (!cc__world_ok(w) || out == NULL)
        return CC_ERR_INVALID;
    if (out->struct_size < CC__END(cc_world_stats, collisions))
        return CC_ERR_VERSION;
    /* whole fields only: a struct_size that ends inside a field leaves that field untouched */
    n = cc__whole_fields(out->struct_size, ends, (int)(sizeof ends / sizeof ends[0]));
    memcpy((unsigned char *)out + from, (const unsigned char *)&w->stats + from, n - from);
    return CC_OK;
}
