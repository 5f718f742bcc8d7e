/* EXACT mode: event-driven stepping. The queue holds each moving body once, keyed by its next
 * event (its predicted hit or its cell crossing, whichever comes first); events are taken in
 * (time, storage index) order up to the end of the step. A hit on a circle whose count changed since the
 * prediction is stale: the body predicts again from now. Only the bodies an event involves are
 * advanced (lazily) and predicted again. */
#include "world_internal.h"

/* What cc__impact_pair changes before it knows that the impact is a plain pair impact. */
typedef struct cc__pair_undo {
    cc__body body[2];
    cc__event ev[2];
    int queued[2];
    double key[2];
    cc_world_stats stats;
} cc__pair_undo;

static void cc__pair_restore(cc_world *w, const cc__touch *tc, const cc__pair_undo *u)
{
    cc__body *B = CC__ARR(w, cc__body, off_body);
    cc__event *EV = CC__ARR(w, cc__event, off_ev);
    int q;
    while (cc__world_take_touched(w) >= 0)
        ;
    for (q = 0; q < 2; q++) {
        int k = q == 0 ? tc->a : tc->b;
        B[k] = u->body[q];
        EV[k] = u->ev[q];
        if (u->queued[q])
            cc__heap_update(w, k, u->key[q]);
        else
            cc__heap_remove(w, k);
    }
    w->stats = u->stats;
}

/* The common case of an impact of two movable circles with nothing else touching either, made
 * cheap: the pair impulse, then the two predictions, whose neighbour scans also tell whether
 * the gathering (simultaneous.c) would have found anything else touching them now, with a
 * larger reach than the gathering's; walls are looked at first. If anything might touch, or
 * the impact is not a plain exchange of velocities, everything is put back as it was and 0 is
 * returned: the caller takes the general path, which then finds exactly what it found before.
 * Otherwise the world is bit for bit where the general path would have left it (the gathering
 * finds nothing, so it resolves the pair with resolve.c and predicts both bodies; predictions
 * of distinct bodies commute, and the queue orders by time and index, not by insertion). The
 * contact is reported with the world as the callback saw it before: velocities before the
 * impulse, and the pair tests of the predictions not yet counted. Returns 1 when done. */
static int cc__impact_pair(cc_world *w, const cc__touch *tc)
{
    cc__body *B = CC__ARR(w, cc__body, off_body);
    const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
    const cc__heap_entry *heap = CC__CARR(w, cc__heap_entry, off_heap);
    const int32_t *hpos = CC__CARR(w, int32_t, off_hpos);
    int a = tc->a, b = tc->b, q;
    double reach_a, reach_b, impulse;
    cc_contact k;
    cc__pair_undo u;
    if (b < 0 || w->clu_bodies < 2 || w->dirty || w->n_touched != 0 || isinf(C[a].m) || isinf(C[b].m))
        return 0;
    if (cc__cluster_pair_reach(w, a, b, &reach_a, &reach_b))
        return 0;
    for (q = 0; q < 2; q++) {
        int id = q == 0 ? a : b;
        u.body[q] = B[id];
        u.ev[q] = CC__CARR(w, cc__event, off_ev)[id];
        u.queued[q] = hpos[id] >= 0;
        u.key[q] = hpos[id] >= 0 ? heap[hpos[id]].key : 0.0;
    }
    u.stats = w->stats;
    if (cc__world_resolve_pair_held(w, tc, &k, &impulse) != 1 || w->n_touched != 2 ||
        cc__predict_alone(w, b, a, reach_b) || cc__predict_alone(w, a, b, reach_a)) {
        cc__pair_restore(w, tc, &u);
        return 0;
    }
    while (cc__world_take_touched(w) >= 0)
        ;
    if (w->on_contact == NULL) {
        w->stats.collisions++;
    } else {
        double va[2], vb[2];
        uint64_t tested = w->stats.pairs_tested;
        va[0] = B[a].vx, va[1] = B[a].vy, vb[0] = B[b].vx, vb[1] = B[b].vy;
        B[a].vx = u.body[0].vx, B[a].vy = u.body[0].vy, B[b].vx = u.body[1].vx, B[b].vy = u.body[1].vy;
        w->stats.pairs_tested = u.stats.pairs_tested;
        cc__world_report(w, a, b, -1, &k, impulse);
        w->stats.pairs_tested = tested;
        B[a].vx = va[0], B[a].vy = va[1], B[b].vx = vb[0], B[b].vy = vb[1];
    }
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
