/* EXACT mode: event-driven stepping. The queue holds each moving body once, keyed by its next
 * event (its predicted hit or its cell crossing, whichever comes first); events are taken in
 * (time, storage index) order up to the end of the step. A hit on a circle whose count changed since the
 * prediction is stale: the body predicts again from now. Only the bodies an event involves are
 * advanced (lazily) and predicted again. */
#include "world_internal.h"

/* Resolves the impact due now (with everything touching it: simultaneous.c), then predicts
 * again every body whose trajectory changed, and body tc->a in any case (its event is spent). */
static void cc__impact(cc_world *w, const cc__touch *tc)
{
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    int k, a_done = 0;
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
        i = cc__heap_top(w);
        t = cc__heap_top_key(w);
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
        cc__advance_body(&B[i], w->now);
        if (e->t_cross < e->t) {
            int dir = e->dir;
            cc__grid_move(w, i, dir);
            w->stats.cell_crossings++;
            cc__predict_crossed(w, i, dir);
        } else if (e->kind == CC__EV_CIRCLE) {
            j = e->partner;
            if (!(CC__CARR(w, cc__cold, off_cold)[j].flags & CC__ALIVE) || B[j].count != e->pcount) {
                w->stats.stale_events++;
                cc__predict(w, i);
                continue;
            }
            cc__advance_body(&B[j], w->now);
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
