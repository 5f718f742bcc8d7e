/* EXACT mode: event-driven stepping. The queue holds each moving body once, keyed by its next
 * event (its predicted hit or its cell crossing, whichever comes first); events are taken in
 * (time, storage index) order up to the end of the step. A hit on a circle whose count changed since the
 * prediction is stale: the body predicts again from now. Only the bodies an event involves are
 * advanced (lazily) and predicted again. */
#include "world_internal.h"

/* The common case of an impact of two movable circles with nothing else touching either, made
 * cheap: the pair impulse, then the two predictions, whose neighbour scans also tell whether
 * the gathering (simultaneous.c) would have found anything else touching them now, with twice
 * its reach; walls are looked at first. If anything might touch, or the impulse did not change
 * both velocities, what the impulse changed is put back (no prediction has been stored yet) and
 * 0 is returned: the caller takes the general path, which then finds exactly what it found
 * before. Otherwise the world is bit for bit where the general path would have left it: its
 * gathering finds nothing, so it resolves the pair with resolve.c and predicts both bodies
 * (predictions of distinct bodies commute, and the queue orders by time and index, not by
 * insertion). The callback sees the world as it did there: velocities before the impulse, the
 * pair tests of the predictions not yet counted. Returns 1 when done. */
static int cc__impact_pair(cc_world *w, const cc__touch *tc)
{
    cc__body *B = CC__ARR(w, cc__body, off_body);
    const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
    int a = tc->a, b = tc->b;
    double reach_a, reach_b, impulse, va[2], vb[2];
    uint32_t count_a, count_b;
    uint64_t tested;
    cc_world_stats stats;
    cc_contact k;
    if (b < 0 || w->clu_bodies < 2 || w->dirty || w->n_touched != 0 || isinf(C[a].m) || isinf(C[b].m) ||
        (w->features & CC__F_ROLL)) /* (what it puts back would have to include the rolling state) */
        return 0;
    if (cc__cluster_pair_reach(w, a, b, &reach_a, &reach_b))
        return 0;
    va[0] = B[a].vx, va[1] = B[a].vy, vb[0] = B[b].vx, vb[1] = B[b].vy;
    count_a = B[a].count, count_b = B[b].count;
    stats = w->stats;
    if (cc__world_resolve_pair_held(w, tc, &k, &impulse) != 1 || w->n_touched != 2 ||
        cc__predict_pair_alone(w, a, b, reach_a, reach_b)) {
        while (cc__world_take_touched(w) >= 0)
            ;
        B[a].vx = va[0], B[a].vy = va[1], B[b].vx = vb[0], B[b].vy = vb[1];
        B[a].count = count_a, B[b].count = count_b;
        w->stats = stats;
        return 0;
    }
    while (cc__world_take_touched(w) >= 0)
        ;
    if (w->on_contact == NULL) {
        cc__world_report(w, a, b, -1, &k, impulse); /* counts it */
        return 1;
    }
    tested = w->stats.pairs_tested;
    w->stats.pairs_tested = stats.pairs_tested;
    {
        double na[2], nb[2];
        na[0] = B[a].vx, na[1] = B[a].vy, nb[0] = B[b].vx, nb[1] = B[b].vy;
        B[a].vx = va[0], B[a].vy = va[1], B[b].vx = vb[0], B[b].vy = vb[1];
        cc__world_report(w, a, b, -1, &k, impulse);
        B[a].vx = na[0], B[a].vy = na[1], B[b].vx = nb[0], B[b].vy = nb[1];
    }
    w->stats.pairs_tested = tested;
    return 1;
}

/* Resolves the impact due now (with everything touching it: simultaneous.c), then predicts
 * again every body whose trajectory changed, and body tc->a in any case (its event is spent). */
static void cc__impact(cc_world *w, const cc__touch *tc)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    int k, a_done = 0;
    if (cc__impact_pair(w, tc))
        return;
    (void)cc__world_resolve(w, tc, 1);
    while ((k = cc__world_take_touched(w)) >= 0) {
        a_done |= k == tc->a;
        cc__predict(w, k);
        /* a body brought to rest predicts nothing, so whatever moves towards it must look again
         * (a body following it along a chain would otherwise pass through it) */
        if (B[k].vx == 0.0 && B[k].vy == 0.0)
            cc__predict_neighbours(w, k);
    }
    if (!a_done)
        cc__predict(w, tc->a);
}

int cc__step_exact(cc_world *w, double t_end)
{
    cc__body *B = CC__ARR(w, cc__body, off_body);
    const cc__event *EV = CC__CARR(w, cc__event, off_ev);
    uint64_t done = 0;
    if (w->dirty)
        cc__rebuild(w);
    for (;;) {
        int i, j;
        double t;
        const cc__event *e;
        cc__touch tc;
        if (cc__sort_due(w))
            cc__sort_bodies(w);
        i = cc__queue_top(w, &t);
        if (i < 0 || t > t_end)
            break;
        if (done == w->max_events)
            return CC_EVENT_LIMIT; /* w->now is the time of the last event processed */
        done++;
        w->stats.events++;
        cc__prefetch_ahead(w);
        e = &EV[i];
        if (t > w->now)
            w->now = t;
        cc__advance_body(w, &B[i], w->now);
        if (e->t_cross < e->t) {
            int dir = e->dir;
            if (dir == CC__DIR_AGAIN) { /* a large body of a periodic world: anew, within the period */
                cc__wrap_body(w, i);
                cc__predict(w, i);
                continue;
            }
            if (dir == CC__DIR_STOP) { /* a rolling body at rest: it predicts nothing from here on */
                cc__roll_stop(w, i);
                cc__predict(w, i);
                /* the hits it had found after its stop were dropped with its event (a body at
                 * rest holds none): the movers near it look again, as for a body set at rest */
                cc__predict_neighbours(w, i);
                continue;
            }
            w->stats.cell_crossings++;
            cc__grid_move(w, i, dir);
            cc__predict_crossed(w, i, dir);
        } else if (e->kind != CC__EV_SEGMENT) { /* a circle, or a sensor pair's begin or end */
            j = e->partner;
            if (!(CC__CARR(w, cc__cold, off_cold)[j].flags & CC__ALIVE) || B[j].count != e->pcount) {
                w->stats.stale_events++;
                cc__predict(w, i);
                continue;
            }
            cc__advance_body(w, &B[j], w->now);
            if (e->kind != CC__EV_CIRCLE) { /* no trajectory changes: the body looks ahead again */
                if (!cc__sensor_event(w, i, j, e->kind))
                    w->stats.stale_events++; /* the other body of the pair reported it first */
                cc__predict(w, i);
                continue;
            }
            tc.a = i;
            tc.b = j;
            tc.segment = -1;
            cc__impact(w, &tc);
        } else {
            tc.a = i;
            tc.b = -1;
            tc.segment = e->partner;
            cc__impact(w, &tc);
        }
    }
    w->now = t_end;
    return CC_OK;
}
