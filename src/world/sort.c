/* Storage order: EXACT keeps circles in memory in the order of their grid cells along a Morton
 * (Z-order) curve, so that the circles a neighbour search visits sit close together in memory.
 * Ids never change: id2idx and the events' id (cc__idx2id) map the API's ids to storage indices. A sort permutes the
 * storage in place (no memory beyond the world's own: the queue's array, rebuilt afterwards,
 * holds the sort keys), then refiles every circle and predicts again. It runs at a step's start
 * after a rebuild and then whenever the queue has processed about 64 events per circle since
 * the last sort, so that its O(N log N) cost stays a small share. */
#include "world_internal.h"

typedef struct cc__sort_entry {
    uint64_t key;
    int32_t idx;
    int32_t done; /* scratch for the permutation */
} cc__sort_entry;

/* Interleaves the bits of x and y (each < 2^31): the Morton code of a cell. */
static uint64_t cc__spread(uint32_t v)
{
    uint64_t x = v;
    x = (x | (x << 16)) & UINT64_C(0x0000FFFF0000FFFF);
    x = (x | (x << 8)) & UINT64_C(0x00FF00FF00FF00FF);
    x = (x | (x << 4)) & UINT64_C(0x0F0F0F0F0F0F0F0F);
    x = (x | (x << 2)) & UINT64_C(0x3333333333333333);
    x = (x | (x << 1)) & UINT64_C(0x5555555555555555);
    return x;
}

static int cc__less(const cc__sort_entry *a, const cc__sort_entry *b)
{
    return a->key < b->key || (a->key == b->key && a->idx < b->idx);
}

/* Moves e[root] down its subtree within e[0, n) until both children come before it. */
static void cc__sift(cc__sort_entry *e, int root, int n)
{
    int child;
    cc__sort_entry t;
    for (; (child = 2 * root + 1) < n; root = child) {
        if (child + 1 < n && cc__less(&e[child], &e[child + 1]))
            child++;
        if (!cc__less(&e[root], &e[child]))
            break;
        t = e[root];
        e[root] = e[child];
        e[child] = t;
    }
}

/* Heapsort: in place, O(n log n) at worst, no recursion, and deterministic. */
static void cc__heapsort(cc__sort_entry *e, int n)
{
    int start, end;
    cc__sort_entry t;
    for (start = n / 2 - 1; start >= 0; start--)
        cc__sift(e, start, n);
    for (end = n - 1; end > 0; end--) {
        t = e[0];
        e[0] = e[end];
        e[end] = t;
        cc__sift(e, 0, end);
    }
}

void cc__sort_bodies(cc_world *w)
{
    cc__body *B = CC__ARR(w, cc__body, off_body);
    cc__cold *C = CC__ARR(w, cc__cold, off_cold);
    cc__event *EV = CC__ARR(w, cc__event, off_ev);
    cc__props *P = CC__ARR(w, cc__props, off_props);
    int32_t *W = CC__ARR(w, int32_t, off_wrap);
    int props = cc__props_reserved(w), wrap = w->off_wrap != 0;
    int32_t *id2idx = CC__ARR(w, int32_t, off_id2idx);
    int32_t *hpos = CC__ARR(w, int32_t, off_hpos);
    cc__sort_entry *e = CC__ARR(w, cc__sort_entry, off_heap); /* the queue is rebuilt below */
    int n = w->id_end, p;
    w->events_at_sort = w->stats.events;
    if (!w->use_grid)
        return;
    for (p = 0; p < n; p++) {
        e[p].idx = p;
        e[p].done = 0;
        if (!(C[p].flags & CC__ALIVE))
            e[p].key = UINT64_MAX; /* removed circles' storage goes last */
        else
            e[p].key = cc__spread((uint32_t)B[p].cx + 0x40000000u) << 1 | cc__spread((uint32_t)B[p].cy + 0x40000000u);
    }
    cc__heapsort(e, n);
    /* new position p takes what was at e[p].idx: follow each cycle with one temporary */
    for (p = 0; p < n; p++) {
        cc__body tb;
        cc__cold tc;
        cc__event te;
        cc__props tp;
        int32_t tw[2] = {0, 0};
        int q = p;
        if (e[p].done)
            continue;
        tb = B[p];
        tc = C[p];
        te = EV[p];
        if (props)
            tp = P[p];
        else
            memset(&tp, 0, sizeof tp); /* (never stored: only copied where a block holds it) */
        if (wrap) {
            tw[0] = W[2 * p];
            tw[1] = W[2 * p + 1];
        }
        for (;;) {
            int src = e[q].idx;
            e[q].done = 1;
            if (src == p) {
                B[q] = tb;
                C[q] = tc;
                EV[q] = te;
                if (props)
                    P[q] = tp;
                if (wrap) {
                    W[2 * q] = tw[0];
                    W[2 * q + 1] = tw[1];
                }
                break;
            }
            B[q] = B[src];
            C[q] = C[src];
            EV[q] = EV[src];
            if (props)
                P[q] = P[src];
            if (wrap) {
                W[2 * q] = W[2 * src];
                W[2 * q + 1] = W[2 * src + 1];
            }
            q = src;
        }
    }
    for (p = 0; p < n; p++)
        id2idx[EV[p].id] = p; /* (the event carried its circle's id along) */
    /* every index changed: grid lists, queue and the partners of events are rebuilt */
    cc__grid_clear(w);
    w->heap_n = 0;
    cc__queue_clear(w);
    for (p = 0; p < n; p++) {
        hpos[p * w->hpos_stride] = -1;
        if (C[p].flags & CC__ALIVE) {
            cc__advance_body(w, &B[p], w->now);
            cc__grid_insert(w, p);
        }
    }
    for (p = 0; p < n; p++)
        if (C[p].flags & CC__ALIVE)
            cc__predict(w, p);
}
