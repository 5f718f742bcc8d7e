/* EXACT's event queue for large worlds: an event calendar (G. Paul, J. Comput. Phys. 221:615,
 * 2007) in front of the 4-ary heap of events.c. Time is cut into blocks of width cal_w from
 * cal_base; the heap holds every event of the blocks up to the current one (cal_cur), and each
 * later block within the next cal_nb has a bucket: an unsorted doubly linked list of bodies,
 * O(1) to enter and to leave. Events beyond that window wait on an overflow list, looked at again
 * each time the window has moved on by cal_nb blocks. When the heap runs dry the next block's
 * bucket is poured into it, so that the heap stays a few dozen entries deep.
 *
 * The order of events is the heap's, (time, storage index), whatever the calendar's widths: a
 * body's block is a nondecreasing function of its time, every event in the heap is of an earlier
 * block than every event in a bucket, and ties share a block. The width is tuned from the rate
 * of events seen (cal_per_block events a block); before the first tuning, and in a world too small
 * for a calendar (cal_nb = 0), every event lives in the heap as before.
 *
 * hpos[3 id] says where body id is: >= 0 its heap position, -1 not queued, <= -2 in bucket -2 - hpos
 * (bucket cal_nb is the overflow list). In a calendar world a body's hpos and its bucket links
 * (next, prev) are one 12-byte node (hpos_stride 3; off_callink = off_hpos + 4), so that filing,
 * unfiling and pouring a body touch one line. */
#include "world_internal.h"

#define CC__CAL_PER_BLOCK 32.0 /* events a block, the aim of the tuning */
#define CC__CAL_WARM 2         /* events per queued body before the first tuning */

/* Worlds of fewer circles keep the heap alone: it stays in the caches, and they pay nothing. */
#define CC__CAL_MIN_CIRCLES 4096

int cc__calendar_buckets(int mode, int max_circles)
{
    int nb = 256;
    if (mode != CC_MODE_EXACT || max_circles < CC__CAL_MIN_CIRCLES)
        return 0;
    while (nb < max_circles / 4) /* a window of about 4 x 32 / 4 = 32 events per body (see tune) */
        nb <<= 1;
    return nb;
}

static int32_t *cc__cal_head(cc_world *w) { return CC__ARR(w, int32_t, off_calhead); }
static int32_t *cc__cal_link(cc_world *w) { return CC__ARR(w, int32_t, off_callink); } /* next, prev */

/* Body id into bucket b (cal_nb: overflow). */
static void cc__cal_link_in(cc_world *w, int id, int b)
{
    int32_t *head = cc__cal_head(w), *link = cc__cal_link(w), *hpos = CC__ARR(w, int32_t, off_hpos);
    int32_t f = head[b];
    link[3 * id] = f;
    link[3 * id + 1] = -1;
    if (f >= 0)
        link[3 * f + 1] = id;
    head[b] = id;
    hpos[3 * id] = -2 - b;
    w->cal_n++;
    if (b == w->cal_nb)
        w->cal_over++;
}

static void cc__cal_unlink(cc_world *w, int id)
{
    int32_t *head = cc__cal_head(w), *link = cc__cal_link(w), *hpos = CC__ARR(w, int32_t, off_hpos);
    int b = -2 - hpos[3 * id];
    int32_t nx = link[3 * id], pv = link[3 * id + 1];
    if (pv >= 0)
        link[3 * pv] = nx;
    else
        head[b] = nx;
    if (nx >= 0)
        link[3 * nx + 1] = pv;
    hpos[3 * id] = -1;
    w->cal_n--;
    if (b == w->cal_nb)
        w->cal_over--;
}

/* Where time t falls, in blocks from cal_base: its block is floor of this (kept unfloored: the
 * comparisons with whole block numbers below are the same, and no floor() call is made). */
static double cc__cal_block(const cc_world *w, double t)
{
    return (t - w->cal_base) * w->cal_inv_w;
}

/* Files body id (not queued) by its key: the heap when its block is due, else a bucket. */
static void cc__cal_file(cc_world *w, int id, double key)
{
    double blk = cc__cal_block(w, key);
    if (blk < (double)(w->cal_cur + 1)) {
        cc__heap_update(w, id, key);
        return;
    }
    if (blk < (double)(w->cal_cur + w->cal_nb))
        cc__cal_link_in(w, id, (int)((int64_t)blk & (int64_t)(w->cal_nb - 1)));
    else
        cc__cal_link_in(w, id, w->cal_nb); /* beyond the window (or a NaN key: never due early) */
}

/* The key of a body filed in the calendar: its event's time (what cc__finish queued it by). */
static double cc__cal_key(const cc_world *w, int id)
{
    const cc__event *e = &CC__CARR(w, cc__event, off_ev)[id];
    return e->t < e->t_cross ? e->t : e->t_cross;
}

/* Every queued body taken out and filed again under a width for `rate` events per unit time,
 * blocks counted from now. */
static void cc__cal_tune(cc_world *w, double rate)
{
    cc__heap_entry *heap = CC__ARR(w, cc__heap_entry, off_heap);
    int32_t *head = cc__cal_head(w), *link = cc__cal_link(w), *hpos = CC__ARR(w, int32_t, off_hpos);
    int32_t *stack = CC__ARR(w, int32_t, off_touched); /* spare here: no impact is being resolved */
    int n = 0, k, b;
    double width = CC__CAL_PER_BLOCK / rate;
    if (!(width > 0.0) || !(width < HUGE_VAL) || !(1.0 / width < HUGE_VAL) || w->n_touched != 0)
        return;
    for (k = 0; k < w->heap_n; k++)
        stack[n++] = heap[k].id;
    for (b = 0; b <= w->cal_nb; b++) {
        int32_t j;
        for (j = head[b]; j >= 0; j = link[3 * j])
            stack[n++] = j;
        head[b] = -1;
    }
    w->heap_n = 0;
    w->cal_n = w->cal_over = 0;
    for (k = 0; k < n; k++)
        hpos[3 * stack[k]] = -1;
    w->cal_w = width;
    w->cal_inv_w = 1.0 / width;
    w->cal_base = w->now;
    w->cal_cur = 0;
    w->cal_tuned = 1;
    for (k = 0; k < n; k++)
        cc__cal_file(w, stack[k], cc__cal_key(w, stack[k]));
    w->cal_e0 = w->stats.events;
    w->cal_t0 = w->now;
}

/* The events per unit time since the last mark, or 0 when unknown. */
static double cc__cal_rate(const cc_world *w)
{
    double de = (double)(w->stats.events - w->cal_e0), dt = w->now - w->cal_t0;
    if (w->stats.events < w->cal_e0 || !(dt > 0.0))
        return 0.0;
    return de / dt;
}

/* The window moved on by cal_nb blocks (cal_cur a multiple of it): the overflow's bodies whose
 * block has come within it go to their buckets (or the heap). */
static void cc__cal_rescan(cc_world *w)
{
    int32_t *head = cc__cal_head(w), *link = cc__cal_link(w);
    int32_t j = head[w->cal_nb];
    while (j >= 0) {
        int32_t nx = link[3 * j];
        double key = cc__cal_key(w, j);
        if (cc__cal_block(w, key) < (double)(w->cal_cur + w->cal_nb)) {
            cc__cal_unlink(w, j);
            cc__cal_file(w, j, key);
        }
        j = nx;
    }
}

/* Body j (>= 0), next in a bucket being poured into the heap: what the pouring reads of it, and
 * its state, which its event will read soon, asked for while the one before is filed. */
static inline void cc__cal_prefetch(const cc_world *w, int32_t j)
{
#if defined(__GNUC__)
    if (j >= 0) {
        __builtin_prefetch(&CC__CARR(w, int32_t, off_callink)[3 * j]);
        __builtin_prefetch(&CC__CARR(w, cc__event, off_ev)[j]);
                __builtin_prefetch(&CC__CARR(w, cc__body, off_body)[j]);
    }
#else
    (void)w, (void)j;
#endif
}

/* The heap is empty and the calendar is not: on to the next block that holds anything, its
 * bucket poured into the heap. */
static void cc__cal_advance(cc_world *w)
{
    int32_t *head = cc__cal_head(w), *link = cc__cal_link(w), *hpos = CC__ARR(w, int32_t, off_hpos);
    while (w->heap_n == 0 && w->cal_n > 0) {
        int b, jumped = 0;
        int32_t j;
        if (w->cal_n == w->cal_over) { /* only far events: the window jumps to the earliest */
            double least = HUGE_VAL;
            for (j = head[w->cal_nb]; j >= 0; j = link[3 * j]) {
                double blk = cc__cal_block(w, cc__cal_key(w, j));
                least = blk < least ? blk : least;
            }
            if (!(least < 0x1p52)) { /* out of a block count's reach: the heap takes them all */
                while ((j = head[w->cal_nb]) >= 0) {
                    cc__cal_unlink(w, j);
                    cc__heap_update(w, j, cc__cal_key(w, j));
                }
                return;
            }
            w->cal_cur = ((int64_t)least & ~(int64_t)(w->cal_nb - 1)) - 1;
            jumped = 1; /* (no tuning there: a tuning from now could leave them all far again) */
        }
        w->cal_cur++;
        if ((w->cal_cur & (w->cal_nb - 1)) == 0) {
            double rate = cc__cal_rate(w), want = rate > 0.0 ? CC__CAL_PER_BLOCK / rate : w->cal_w;
            if (!jumped && (want > 2.0 * w->cal_w || want < 0.5 * w->cal_w || w->cal_over > (w->cal_n >> 2))) {
                cc__cal_tune(w, rate > 0.0 ? rate : CC__CAL_PER_BLOCK * w->cal_inv_w);
                continue;
            }
            w->cal_e0 = w->stats.events;
            w->cal_t0 = w->now;
            cc__cal_rescan(w);
        }
        b = (int)(w->cal_cur & (int64_t)(w->cal_nb - 1));
        while ((j = head[b]) >= 0) {
            head[b] = link[3 * j];
            cc__cal_prefetch(w, head[b]);
            hpos[3 * j] = -1;
            w->cal_n--;
            cc__heap_update(w, j, cc__cal_key(w, j));
        }
    }
}

void cc__queue_update(cc_world *w, int id, double key)
{
    int32_t *hpos = CC__ARR(w, int32_t, off_hpos);
    if (!w->cal_tuned) {
        cc__heap_update(w, id, key);
        return;
    }
    if (hpos[3 * id] <= -2)
        cc__cal_unlink(w, id);
    else if (hpos[3 * id] >= 0 && !(cc__cal_block(w, key) < (double)(w->cal_cur + 1)))
        cc__heap_remove(w, id); /* later than the heap's blocks now */
    if (hpos[3 * id] >= 0)
        cc__heap_update(w, id, key);
    else
        cc__cal_file(w, id, key);
}

void cc__queue_remove(cc_world *w, int id)
{
    if (CC__ARR(w, int32_t, off_hpos)[id * w->hpos_stride] <= -2)
        cc__cal_unlink(w, id);
    else
        cc__heap_remove(w, id);
}

int cc__queue_top(cc_world *w, double *key)
{
    if (w->cal_nb > 0) {
        if (!w->cal_tuned) {
            if (w->stats.events < w->cal_e0) /* the counters were reset */
                w->cal_e0 = w->stats.events, w->cal_t0 = w->now;
            if (w->heap_n >= 1024 && w->stats.events - w->cal_e0 > (uint64_t)w->heap_n * CC__CAL_WARM &&
                cc__cal_rate(w) > 0.0)
                cc__cal_tune(w, cc__cal_rate(w));
        }
        if (w->heap_n == 0 && w->cal_n > 0)
            cc__cal_advance(w);
    }
    *key = cc__heap_top_key(w);
    return cc__heap_top(w);
}

void cc__queue_clear(cc_world *w)
{
    int32_t *head;
    int b;
    if (w->cal_nb == 0)
        return;
    head = cc__cal_head(w);
    for (b = 0; b <= w->cal_nb; b++)
        head[b] = -1;
    w->cal_n = w->cal_over = 0;
    /* the width stays (the world's pace is the same); blocks count from now again */
    w->cal_base = w->now;
    w->cal_cur = 0;
}
