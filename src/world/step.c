/* Stepping's entry: cc_world_step's validation (including the range a step may carry a circle
 * to), the dispatch to the mode's stepper (exact.c, swept.c, discrete.c), and the counters the
 * steps keep (cc_world_get_stats). */
#include "world_internal.h"
#include "codes.h"

#include <math.h>
#include <string.h>

static int cc__world_ok(const cc_world *w) { return w != NULL && w->magic == CC__WORLD_MAGIC; }

/* Whether a step to now + dt may be made, decided before anything changes (cc_world_step in the
 * header): every straight path stays within 2^1017 (about 1.4e306) of the origin along each
 * axis, beyond which positions, cell crossings and impacts would overflow to Inf (world fuzzer
 * D1; rolling paths are shorter than straight ones); and in SWEPT, a periodic world's circles
 * travel less than half a period along a periodic axis (along their rolling paths when they
 * roll), since each pair is swept through its images nearest now only (D8: a query then missed
 * the circle).
 *
 * The rule is the pass below over every circle; most steps are decided without it, from the
 * world's bounds w->reach (R) and w->speed (V) (world_internal.h), in O(1), so that a world
 * at rest, or whose circles move a little in each step, pays nothing per circle for the check.
 * Why the quick test accepts only steps that the pass accepts:
 *  - R bounds, for every live circle and either axis, the pass's |p| + |v| (now - t) (lazy state
 *    (p, v) at its own time t) and V its |vx| + |vy| (>= its speed along either axis); so the
 *    pass's |p| + |v| (t_end - t) is at most R + V (t_end - now) in exact arithmetic. What writes
 *    a position or a velocity notes it: cc__put (add, set) notes both; every impulse and
 *    push-apart marks the body it changed (cc__world_mark), which notes its velocity, and its
 *    position when a push-apart moved it (CC__MOVED); an impulse changes only the velocity of a
 *    body carried to now, where its old path put it (R held that already). Carrying a body along
 *    its path (cc__advance_body, rolling, its stop) leaves |p| + |v| (now - t) as it was, or
 *    smaller (rolling only slows); a wrap to the other side of a period leaves a coordinate
 *    within the period (R starts at twice the largest period: cc__reach_floor); removal leaves
 *    R and V loose. After a step R grows by V (now' - now) with V as the step left it (V only
 *    grows inside a step, and a circle changed at time t in it is noted at t). Sorting permutes
 *    storage: nothing to do.
 *  - Rounding: each quantity is a max of the pass's own numbers, or a sum rounded up (the factor
 *    1 + 2^-50 after each step); carrying a body to another time rounds its position by a few
 *    ulps, relative to |p| + |v| tau, at most once per distinct world time, i.e. once per event
 *    or step. The pass runs again at least every 2^40 steps and events (reach_ticks), so these
 *    add up to less than 2^43 ulps, a relative 2^-10; the quick test wants R + V dt below
 *    1.5 * 2^1016, three quarters of 2^1017: far more room than that.
 *  - Half a period: the pass refuses when fl(|v| g) >= P / 2, with |v| <= V (a rolling body's
 *    velocity now is its lazy one times g' in [0, 1]) and its path's g <= dt; rounding is
 *    monotonic, so fl(V dt) < P / 2 implies fl(|v| g) < P / 2 for every circle: exact, no margin.
 * When the quick test fails the pass decides, exactly as before the bounds existed, and measures
 * R and V afresh (tight again: a circle that was fast or far and was then slowed, moved or
 * removed costs one pass). NaN anywhere makes a bound +Inf: the pass then decides every step. */
#define CC__REACH_QUICK 0x1.8p1016  /* 1.5 * 2^1016: the quick test's limit for R + V (t_end - now) */
#define CC__REACH_TICKS 0x10000000000ull /* 2^40 steps and events between passes at most */

static double cc__reach_floor(const cc_world *w)
{
    return 2.0 * (w->period[0] > w->period[1] ? w->period[0] : w->period[1]);
}

/* The O(1) test: 1 when the bounds show that the pass would accept (0: the pass decides). */
static int cc__step_quick(const cc_world *w, double dt, double elapsed)
{
    double s;
    if (w->reach_ticks >= CC__REACH_TICKS || !(w->reach + w->speed * elapsed < CC__REACH_QUICK))
        return 0;
    if (w->mode != CC_MODE_SWEPT || !(w->features & CC__F_PERIODIC))
        return 1;
    s = w->speed * dt;
    return (w->period[0] <= 0.0 || s < 0.5 * w->period[0]) && (w->period[1] <= 0.0 || s < 0.5 * w->period[1]);
}

/* The pass over every circle: the rule itself. When it accepts, w->reach and w->speed are
 * measured (exact maxima over the live circles) and reach_ticks starts again; when it refuses,
 * nothing changes. */
static int cc__step_allowed(cc_world *w, double dt)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
    const double lim = 0x1p1017, t_end = w->now + dt;
    const int half = w->mode == CC_MODE_SWEPT && (w->features & CC__F_PERIODIC);
    double reach = cc__reach_floor(w), speed = 0.0;
    int j;
    for (j = 0; j < w->id_end; j++) {
        double tau = t_end - B[j].t, vx = B[j].vx, vy = B[j].vy, g = dt, gd, x, y, k, ago;
        if (!(C[j].flags & CC__ALIVE))
            continue;
        if (!(fabs(B[j].px) + fabs(vx) * tau < lim && fabs(B[j].py) + fabs(vy) * tau < lim))
            return 0;
        ago = w->now > B[j].t ? w->now - B[j].t : 0.0; /* as cc__reach_note */
        reach = cc__reach_max(reach, fabs(B[j].px) + fabs(vx) * ago);
        reach = cc__reach_max(reach, fabs(B[j].py) + fabs(vy) * ago);
        speed = cc__reach_max(speed, fabs(vx) + fabs(vy));
        if (!half)
            continue;
        if (w->features & CC__F_ROLL) { /* its velocity now, and its slowing path from now */
            cc__roll_state(w, j, w->now, &x, &y, &vx, &vy, &k);
            cc__roll_motion(k, dt, &g, &gd);
        }
        if ((w->period[0] > 0.0 && !(fabs(vx) * g < 0.5 * w->period[0])) ||
            (w->period[1] > 0.0 && !(fabs(vy) * g < 0.5 * w->period[1])))
            return 0;
    }
    w->reach = reach;
    w->speed = speed;
    w->reach_ticks = 0;
    return 1;
}

CC_API int cc_world_step(cc_world *w, double dt)
{
    int r;
    double now;
    uint64_t events;
    if (!cc__world_ok(w) || !(dt >= 0.0) || !isfinite(dt))
        return CC_ERR_INVALID;
    if (cc__busy(w))
        return cc__world_code(w, CC_ERR_BUSY);
    if (!isfinite(w->now + dt))
        return cc__world_code(w, CC_ERR_RANGE);
    now = w->now;
    events = w->stats.events;
    /* a copy taken inside a callback: its bounds may be those of a step half done (the pass) */
    if (!(w->busy == 0 && cc__step_quick(w, dt, (now + dt) - now)) && !cc__step_allowed(w, dt))
        return cc__world_code(w, CC_ERR_RANGE);
    cc__world_own(w);
    cc__enter(w);
    if (w->mode == CC_MODE_EXACT)
        r = cc__step_exact(w, w->now + dt);
    else if (w->mode == CC_MODE_SWEPT)
        r = cc__step_swept(w, dt);
    else
        r = cc__step_discrete(w, dt);
    cc__leave(w);
    /* every circle's |p| + |v| (now - t) grew by at most V times the time that passed (V as the
     * step's impulses left it), rounded up (a world at rest keeps its bound as it is) */
    if (w->now > now && w->speed > 0.0)
        w->reach = (w->reach + w->speed * (w->now - now)) * (1.0 + 0x1p-50);
    w->reach_ticks += 1 + (w->stats.events - events);
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
