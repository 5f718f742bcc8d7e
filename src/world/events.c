/* The event queue: an indexed 4-ary min-heap (half the depth of a binary one: fewer
 * unpredictable branches and scattered writes per update) holding each body that has a
 * predicted event (one per body, so its size is bounded by max_circles), keyed by (event time,
 * storage index). The index breaks ties, never an address: the order of simultaneous events is
 * deterministic. Entries carry their key, so sifting reads only the heap; hpos[id] is the
 * body's index in the heap, -1 when it is not queued. */
#include "world_internal.h"

static inline int cc__before(const cc__heap_entry *a, const cc__heap_entry *b)
{
    return a->key < b->key || (a->key == b->key && a->id < b->id);
}

/* The earliest of the four entries at c .. c + 3: two independent comparisons, then a third. */
static inline int cc__min4(const cc__heap_entry *heap, int c)
{
    int a = cc__before(&heap[c + 1], &heap[c]) ? c + 1 : c;
    int b = cc__before(&heap[c + 3], &heap[c + 2]) ? c + 3 : c + 2;
    return cc__before(&heap[b], &heap[a]) ? b : a;
}

static void cc__sift_up(cc__heap_entry *heap, int32_t *hpos, int st, int k, cc__heap_entry e)
{
    while (k > 0) {
        int p = (k - 1) >> 2;
        if (!cc__before(&e, &heap[p]))
            break;
        heap[k] = heap[p];
        hpos[heap[k].id * st] = k;
        k = p;
    }
    heap[k] = e;
    hpos[e.id * st] = k;
}

/* The children of the four entries at c .. c + 3 are the 16 entries from 4c + 1: asked for
 * before the four are compared, they arrive while the comparison runs. Only for a heap larger
 * than the caches, which then misses at every level; a small one would pay for nothing. */
#define CC__HEAP_PREFETCH_MIN 32768
static inline void cc__prefetch_children(const cc__heap_entry *heap, int c, int n)
{
#if defined(__GNUC__)
    int g = 4 * c + 1, k;
    if (n < CC__HEAP_PREFETCH_MIN)
        return;
    for (k = 0; k < 16 && g + k < n; k += 4) /* one line in four entries; none past the end */
        __builtin_prefetch(&heap[g + k]);
#else
    (void)heap, (void)c, (void)n;
#endif
}

static void cc__sift_down(cc__heap_entry *heap, int32_t *hpos, int st, int n, int k, cc__heap_entry e)
{
    for (;;) {
        int c = 4 * k + 1, m = c, q;
        cc__prefetch_children(heap, c, n);
        if (c + 4 <= n)
            m = cc__min4(heap, c);
        else if (c >= n)
            break;
        else
            for (q = c + 1; q < n; q++)
                m = cc__before(&heap[q], &heap[m]) ? q : m;
        if (!cc__before(&heap[m], &e))
            break;
        heap[k] = heap[m];
        hpos[heap[k].id * st] = k;
        k = m;
    }
    heap[k] = e;
    hpos[e.id * st] = k;
}

/* Puts entry e at index k, where it may be out of order in either direction. */
static void cc__place(cc_world *w, int k, cc__heap_entry e)
{
    cc__heap_entry *heap = CC__ARR(w, cc__heap_entry, off_heap);
    int32_t *hpos = CC__ARR(w, int32_t, off_hpos);
    if (k > 0 && cc__before(&e, &heap[(k - 1) >> 2]))
        cc__sift_up(heap, hpos, w->hpos_stride, k, e);
    else
        cc__sift_down(heap, hpos, w->hpos_stride, w->heap_n, k, e);
}

void cc__heap_update(cc_world *w, int id, double key)
{
    int32_t *hpos = CC__ARR(w, int32_t, off_hpos);
    cc__heap_entry e;
    int k = hpos[id * w->hpos_stride];
    e.key = key;
    e.id = id;
    e.pad_ = 0;
    if (k < 0) {
        k = w->heap_n++;
        cc__sift_up(CC__ARR(w, cc__heap_entry, off_heap), hpos, w->hpos_stride, k, e);
        return;
    }
    cc__place(w, k, e);
}

void cc__heap_remove(cc_world *w, int id)
{
    cc__heap_entry *heap = CC__ARR(w, cc__heap_entry, off_heap);
    int32_t *hpos = CC__ARR(w, int32_t, off_hpos);
    int k = hpos[id * w->hpos_stride], last;
    if (k < 0)
        return;
    hpos[id * w->hpos_stride] = -1;
    last = --w->heap_n;
    if (k == last)
        return;
    cc__place(w, k, heap[last]);
}

int cc__heap_top(const cc_world *w)
{
    return w->heap_n > 0 ? CC__CARR(w, cc__heap_entry, off_heap)[0].id : -1;
}

double cc__heap_top_key(const cc_world *w)
{
    return w->heap_n > 0 ? CC__CARR(w, cc__heap_entry, off_heap)[0].key : HUGE_VAL;
}

/* The next events are most likely those of the root's children in the queue: their states are
 * asked for now, and the neighbourhood (the three rows of slots) of the earliest, whose state
 * was asked for at the previous event already. Below a size where everything stays in the
 * caches this would cost without paying. */
#define CC__PREFETCH_MIN_BODIES 32768
void cc__prefetch_ahead(const cc_world *w)
{
#if defined(__GNUC__)
    const cc__heap_entry *heap = CC__CARR(w, cc__heap_entry, off_heap);
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const cc__event *EV = CC__CARR(w, cc__event, off_ev);
    const int32_t *slot = CC__CARR(w, int32_t, off_slot);
    int q, m = 1, end = w->heap_n < 5 ? w->heap_n : 5;
    if (w->n_circles < CC__PREFETCH_MIN_BODIES || w->heap_n < 2 || !w->use_grid) /* (bodies, not the heap: a
                                            calendar keeps the heap short; a periodic world's cells at its
                                            edges are prefetched unwrapped: another slot, harmless) */
        return;
    for (q = 1; q < end; q++) {
        __builtin_prefetch(&B[heap[q].id]);
        __builtin_prefetch(&EV[heap[q].id]);
        m = heap[q].key < heap[m].key ? q : m;
    }
    {
        const cc__body *b = &B[heap[m].id];
        int32_t y;
        for (y = b->cy - 1; y <= b->cy + 1; y++) {
            __builtin_prefetch(&slot[cc__grid_slot(w, b->cx - 1, y)]);
            __builtin_prefetch(&slot[cc__grid_slot(w, b->cx + 1, y)]);
        }
    }
#else
    (void)w;
#endif
}
