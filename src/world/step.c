/* Stepping's entry: cc_world_step's validation (including the range a step may carry a circle
 * to), the dispatch to the mode's stepper (exact.c, swept.c, discrete.c), and the counters the
 * steps keep (cc_world_get_stats). */
#include "world_internal.h"

#include <math.h>
#include <string.h>

static int cc__world_ok(const cc_world *w) { return w != NULL && w->magic == CC__WORLD_MAGIC; }

/* Whether a step to now + dt may be made, checked in one pass over the circles before anything
 * changes (cc_world_step in the header): every straight path stays within 2^1017 (about 1.4e306)
 * of the origin along each axis, beyond which positions, cell crossings and impacts would
 * overflow to Inf (world fuzzer D1; rolling paths are shorter than straight ones); and in SWEPT,
 * a periodic world's circles travel less than half a period along a periodic axis (along their
 * rolling paths when they roll), since each pair is swept through its images nearest now only
 * (D8: a query then missed the circle). */
static int cc__step_allowed(const cc_world *w, double dt)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
    const double lim = 0x1p1017, t_end = w->now + dt;
    const int half = w->mode == CC_MODE_SWEPT && (w->features & CC__F_PERIODIC);
    int j;
    for (j = 0; j < w->id_end; j++) {
        double tau = t_end - B[j].t, vx = B[j].vx, vy = B[j].vy, g = dt, gd, x, y, k;
        int in = fabs(B[j].px) + fabs(vx) * tau < lim && fabs(B[j].py) + fabs(vy) * tau < lim;
        /* the hot line first: the cold one (is it alive?) only when there is more to look at */
        if ((in && !half) || !(C[j].flags & CC__ALIVE))
            continue;
        if (!in)
            return 0;
        if (w->features & CC__F_ROLL) { /* its velocity now, and its slowing path from now */
            cc__roll_state(w, j, w->now, &x, &y, &vx, &vy, &k);
            cc__roll_motion(k, dt, &g, &gd);
        }
        if ((w->period[0] > 0.0 && !(fabs(vx) * g < 0.5 * w->period[0])) ||
            (w->period[1] > 0.0 && !(fabs(vy) * g < 0.5 * w->period[1])))
            return 0;
    }
    return 1;
}

CC_API int cc_world_step(cc_world *w, double dt)
{
    int r;
    if (!cc__world_ok(w) || w->busy || !(dt >= 0.0) || !isfinite(dt) || !isfinite(w->now + dt) ||
        !cc__step_allowed(w, dt))
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
