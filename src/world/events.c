/* The event queue: an indexed binary min-heap holding each body that has a predicted event
 * (one per body, so its size is bounded by max_circles), keyed by (event time, body id). The id
 * breaks ties, never an address: the order of simultaneous events is deterministic. hpos[id]
 * is the body's index in the heap, -1 when it is not queued. */
#include "world_internal.h"

static int cc__before(const cc__event *ev, int32_t a, int32_t b)
{
    return ev[a].t < ev[b].t || (ev[a].t == ev[b].t && a < b);
}

static void cc__sift_up(int32_t *heap, int32_t *hpos, const cc__event *ev, int k)
{
    int32_t id = heap[k];
    while (k > 0) {
        int p = (k - 1) >> 1;
        if (!cc__before(ev, id, heap[p]))
            break;
        heap[k] = heap[p];
        hpos[heap[k]] = k;
        k = p;
    }
    heap[k] = id;
    hpos[id] = k;
}

static void cc__sift_down(int32_t *heap, int32_t *hpos, const cc__event *ev, int n, int k)
{
    int32_t id = heap[k];
    for (;;) {
        int c = 2 * k + 1;
        if (c >= n)
            break;
        if (c + 1 < n && cc__before(ev, heap[c + 1], heap[c]))
            c++;
        if (!cc__before(ev, heap[c], id))
            break;
        heap[k] = heap[c];
        hpos[heap[k]] = k;
        k = c;
    }
    heap[k] = id;
    hpos[id] = k;
}

void cc__heap_update(cc_world *w, int id)
{
    int32_t *heap = CC__ARR(w, int32_t, off_heap), *hpos = CC__ARR(w, int32_t, off_hpos);
    const cc__event *ev = CC__CARR(w, cc__event, off_ev);
    int k = hpos[id];
    if (k < 0) {
        k = w->heap_n++;
        heap[k] = id;
        hpos[id] = k;
        cc__sift_up(heap, hpos, ev, k);
        return;
    }
    if (k > 0 && cc__before(ev, id, heap[(k - 1) >> 1]))
        cc__sift_up(heap, hpos, ev, k);
    else
        cc__sift_down(heap, hpos, ev, w->heap_n, k);
}

void cc__heap_remove(cc_world *w, int id)
{
    int32_t *heap = CC__ARR(w, int32_t, off_heap), *hpos = CC__ARR(w, int32_t, off_hpos);
    const cc__event *ev = CC__CARR(w, cc__event, off_ev);
    int k = hpos[id], last;
    if (k < 0)
        return;
    hpos[id] = -1;
    last = --w->heap_n;
    if (k == last)
        return;
    heap[k] = heap[last];
    hpos[heap[k]] = k;
    if (k > 0 && cc__before(ev, heap[k], heap[(k - 1) >> 1]))
        cc__sift_up(heap, hpos, ev, k);
    else
        cc__sift_down(heap, hpos, ev, w->heap_n, k);
}

int cc__heap_top(const cc_world *w) { return w->heap_n > 0 ? CC__CARR(w, int32_t, off_heap)[0] : -1; }
