/* Overlaps the caller created (circles added or set on top of others, walls added through
 * circles): one pass pushes each overlapping pair apart with cc_separate (shares inverse to the
 * masses; a circle against a wall moves out along the wall's normal) and resolves the contact
 * if the pair approaches. What one pass leaves (chains of overlaps) heals by itself: an
 * overlapping pair that approaches is a contact now, one that separates is left to drift apart.
 * Also the rebuild of the grid: EXACT's (with every prediction) when something requires it,
 * SWEPT's and DISCRETE's at every step (filing and one pass over neighbouring cells, with quick
 * rejects before the exact tests: about what a plain cell-list step costs). */
#include "world_internal.h"
#include "scan.h"
#include "walls.h"

/* Circles whose position an overlap pass changed are filed again under their new cell. */
static void cc__refile_moved(cc_world *w, int only)
{
    cc__cold *C = CC__ARR(w, cc__cold, off_cold);
    int i, lo = only >= 0 ? only : 0, hi = only >= 0 ? only + 1 : w->id_end;
    for (i = lo; i < hi; i++) {
        if (!(C[i].flags & CC__MOVED))
            continue;
        C[i].flags &= ~CC__MOVED;
        if (w->mode == CC_MODE_EXACT) {
            cc__grid_remove(w, i);
            cc__grid_insert(w, i);
        }
    }
}

/* Quick rejects before the exact tests, so that the pass costs a few comparisons for the pairs
 * and walls that are nowhere near: each is conservative (it rules out only what the exact test
 * in cc__world_unoverlap would find apart, with a margin far above rounding), so the outcome is
 * bit for bit that of testing everything. Both bodies are at w->now. */
static inline int cc__circles_apart(const cc_world *w, const cc__body *a, const cc__body *b)
{
    double dx = cc__near_d(w, b->px - a->px, 0), dy = cc__near_d(w, b->py - a->py, 1), R = a->r + b->r, R2 = R * R;
    /* R2 normal: squares below that lose relative precision */
    return R2 > 0x1p-1000 && dx * dx + dy * dy > R2 * (1.0 + 0x1p-20);
}

/* Circle i against circle j when they may overlap: j brought to now (EXACT keeps lazy states). */
static void cc__unoverlap_pair(cc_world *w, int i, int j)
{
    cc__body *B = CC__ARR(w, cc__body, off_body);
    cc__advance_body(w, &B[j], w->now);
    w->stats.pairs_tested++;
    if (!cc__circles_apart(w, &B[i], &B[j]))
        (void)cc__world_unoverlap(w, i, j, -1);
}

/* Circle i against every wall whose box its own reaches (the walls' tree finds them). */
static void cc__unoverlap_walls(cc_world *w, int i)
{
    const cc__body *b = &CC__CARR(w, cc__body, off_body)[i];
    cc__wall_walk walk;
    double reach;
    int s;
    if (w->n_segments == 0)
        return;
    /* the wall's box and the circle's, each grown by 2^-30 of its numbers, are disjoint: the
     * closest point on the wall lies in the wall's box (to rounding, far inside the margins),
     * so the circle cannot reach it */
    reach = b->r + 0x1p-30 * (b->r + fabs(b->px) + fabs(b->py));
    cc__walls_begin(w, &walk, b->px - reach, b->py - reach, b->px + reach, b->py + reach);
    while ((s = cc__walls_next(w, &walk)) >= 0) {
        if (isinf(CC__CARR(w, cc__cold, off_cold)[i].m))
            return; /* immovable: walls do not hold it */
        w->stats.pairs_tested++; /* as SWEPT counts walls: those the box test lets through */
        (void)cc__world_unoverlap(w, i, -1, s);
    }
}

/* Pushes body i out of everything it overlaps (only_higher: circles of higher index only, for
 * a pass over all pairs); the circles moved are marked (cc__world_mark, CC__MOVED). */
static void cc__unoverlap_body(cc_world *w, int i, int only_higher)
{
    cc__body *B = CC__ARR(w, cc__body, off_body);
    const cc__cold *C = CC__CARR(w, cc__cold, off_cold);
    int j;
    if (!w->use_grid || (C[i].flags & CC__LARGE)) {
        for (j = only_higher ? i + 1 : 0; j < w->id_end; j++)
            if (j != i && (C[j].flags & CC__ALIVE))
                cc__unoverlap_pair(w, i, j);
    } else if (w->features & CC__F_PERIODIC) { /* the cells around, wrapped, each once */
        const int32_t *slot = CC__CARR(w, int32_t, off_slot);
        int32_t xs[9], ys[9];
        int c, nc = cc__cells_around(w, B[i].cx, B[i].cy, xs, ys);
        for (c = 0; c < nc; c++)
            for (j = slot[cc__grid_slot(w, xs[c], ys[c])]; j >= 0; j = B[j].next)
                if (B[j].cx == xs[c] && B[j].cy == ys[c] && j != i && (!only_higher || j > i))
                    cc__unoverlap_pair(w, i, j);
        if (!only_higher)
            for (j = w->large_head; j >= 0; j = B[j].next)
                if (j != i)
                    cc__unoverlap_pair(w, i, j);
    } else {
        const int32_t *slot = CC__CARR(w, int32_t, off_slot);
        int32_t cx = B[i].cx, cy = B[i].cy, x, y;
        uint32_t sl = 0;
        for (y = cy - 1; y <= cy + 1; y++)
            for (x = cx - 1; x <= cx + 1; x++)
                for (sl = cc__row_slot(w, x, y, sl, x == cx - 1), j = slot[sl]; j >= 0; j = B[j].next)
                    if (B[j].cx == x && B[j].cy == y && j != i && (!only_higher || j > i))
                        cc__unoverlap_pair(w, i, j);
        if (!only_higher) /* large circles may be kinematic: carried to now like any other */
            for (j = w->large_head; j >= 0; j = B[j].next)
                if (j != i)
                    cc__unoverlap_pair(w, i, j);
    }
    cc__unoverlap_walls(w, i);
}

/* SWEPT and DISCRETE, every step: every circle carried to now and filed in the cleared grid as
 * cc__grid_insert files it (same cells, same order in each list), without the backward links
 * that only EXACT's removals from the grid need. */
static void cc__file_all(cc_world *w)
{
    cc__body *B = CC__ARR(w, cc__body, off_body);
    cc__cold *C = CC__ARR(w, cc__cold, off_cold);
    int32_t *hpos = CC__ARR(w, int32_t, off_hpos);
    int32_t *slot = CC__ARR(w, int32_t, off_slot);
    int i;
    for (i = 0; i < w->id_end; i++) {
        cc__body *b = &B[i];
        int32_t *head;
        hpos[i * w->hpos_stride] = -1;
        if (!(C[i].flags & CC__ALIVE))
            continue;
        if (w->features & CC__F_PERIODIC)
            cc__wrap_body(w, i); /* carried to now, within the period */
        else
            cc__advance_body(w, b, w->now);
        b->cx = w->ncell[0] ? cc__grid_coord(w, b->px, 0) : cc__cell_of(w, b->px);
        b->cy = w->ncell[1] ? cc__grid_coord(w, b->py, 1) : cc__cell_of(w, b->py);
        C[i].flags &= ~CC__LARGE;
        if (2.0 * b->r * 1.0625 > w->cs) {
            C[i].flags |= CC__LARGE;
            head = &w->large_head;
        } else {
            head = &slot[cc__grid_slot(w, b->cx, b->cy)];
        }
        b->next = *head;
        *head = i;
    }
}

/* SWEPT and DISCRETE, every step: the circles in the grid walked cell by cell in the order of
 * the hash slots, not of storage (neighbouring cells have neighbouring slots, see cc__grid_slot,
 * so what a circle looks at was mostly looked at just before: the pass runs from the caches),
 * each pair once: a circle against those after it in its own cell and all those of the four
 * cells ahead, (x+1, y) and the three of row y+1. */
static void cc__unoverlap_cells(cc_world *w)
{
    if (w->features & CC__F_PERIODIC) { /* each circle against the wrapped cells around it, each pair once */
        int k;
        for (k = 0; k < w->id_end; k++)
            if ((CC__CARR(w, cc__cold, off_cold)[k].flags & (CC__ALIVE | CC__LARGE)) == CC__ALIVE)
                cc__unoverlap_body(w, k, 1);
        return;
    }
    const cc__body *B = CC__CARR(w, cc__body, off_body);
    const int32_t *slot = CC__CARR(w, int32_t, off_slot);
    uint32_t s;
    int i, j;
    for (s = 0; s <= w->slot_mask; s++)
        for (i = slot[s]; i >= 0; i = B[i].next) {
            int32_t cx = B[i].cx, cy = B[i].cy, x;
            uint32_t sl = 0;
            for (j = B[i].next; j >= 0; j = B[j].next)
                if (B[j].cx == cx && B[j].cy == cy)
                    cc__unoverlap_pair(w, i, j);
            if (cx < CC__CELL_MAX)
                for (j = slot[cc__row_slot(w, cx + 1, cy, s, 0)]; j >= 0; j = B[j].next)
                    if (B[j].cx == cx + 1 && B[j].cy == cy)
                        cc__unoverlap_pair(w, i, j);
            if (cy < CC__CELL_MAX)
                for (x = cx - 1; x <= cx + 1; x++)
                    for (sl = cc__row_slot(w, x, cy + 1, sl, x == cx - 1), j = slot[sl]; j >= 0; j = B[j].next)
                        if (B[j].cx == x && B[j].cy == cy + 1)
                            cc__unoverlap_pair(w, i, j);
            cc__unoverlap_walls(w, i);
        }
}

void cc__rebuild(cc_world *w)
{
    cc__body *B = CC__ARR(w, cc__body, off_body);
    cc__cold *C = CC__ARR(w, cc__cold, off_cold);
    int32_t *hpos = CC__ARR(w, int32_t, off_hpos);
    int i, j;
    w->cs = cc__world_cell_size(w);
    for (i = 0; i < 2; i++) /* at most 2^30 cells along a period: cell indices stay int32_t */
        if (w->period[i] > 0.0 && w->period[i] / w->cs > 0x1p30)
            w->cs = w->period[i] * 0x1p-30;
    w->inv_cs = 1.0 / w->cs;
    for (i = 0; i < 2; i++) { /* periodic: whole cells along the period, the last one the wider */
        w->ncell[i] = w->period[i] > 0.0 ? (int32_t)floor(w->period[i] / w->cs) : 0;
        if (w->ncell[i] > 1 && (double)w->ncell[i] * w->cs > w->period[i])
            w->ncell[i]--; /* the division rounded up: the last cell must not be narrower */
    }
    if (w->wall_tree_n != w->n_segments)
        cc__walls_build(w); /* walls were added: the tree is made again */
    w->heap_n = 0;
    cc__queue_clear(w);
    if (w->use_grid)
        cc__grid_clear(w);
    if (w->use_grid && w->mode != CC_MODE_EXACT) {
        cc__file_all(w);
        cc__side_stash(w);
        cc__unoverlap_cells(w);
    } else {
        for (i = 0; i < w->id_end; i++) {
            hpos[i * w->hpos_stride] = -1;
            if (!(C[i].flags & CC__ALIVE))
                continue;
            cc__advance_body(w, &B[i], w->now);
            cc__grid_insert(w, i);
        }
        if (w->mode != CC_MODE_EXACT)
            cc__side_stash(w);
        for (i = 0; i < w->id_end; i++)
            if ((C[i].flags & CC__ALIVE) && !(C[i].flags & CC__LARGE))
                cc__unoverlap_body(w, i, 1);
    }
    for (j = w->large_head; j >= 0; j = B[j].next)
        for (i = 0; i < w->id_end; i++)
            if (i != j && (C[i].flags & CC__ALIVE))
                (void)cc__world_unoverlap(w, i, j, -1);
    if (w->mode != CC_MODE_EXACT) /* a push-apart may have carried a centre past a wall */
        cc__keep_wall_sides(w, 1);
    while (cc__world_take_touched(w) >= 0)
        ; /* everything is predicted below */
    if (w->mode == CC_MODE_EXACT && (w->features & CC__F_SENSOR))
        for (i = 0; i < w->id_end; i++) /* each sensor's overlaps, before anything predicts them */
            if ((C[i].flags & CC__ALIVE) && CC__CARR(w, cc__props, off_props)[i].sensor >= 0)
                cc__sensor_refresh(w, i);
    if (w->mode == CC_MODE_EXACT) {
        cc__refile_moved(w, -1);
        if (w->use_grid) {
            cc__sort_bodies(w); /* storage in cell order, then every prediction */
        } else {
            for (i = 0; i < w->id_end; i++)
                if (C[i].flags & CC__ALIVE)
                    cc__predict(w, i);
        }
    } else {
        for (i = 0; i < w->id_end; i++)
            C[i].flags &= ~CC__MOVED;
    }
    w->dirty = 0;
}

/* After body id was filed and pushed out of what it overlaps: the neighbours pushed away or
 * struck are refiled and predicted again, with whatever moves near them (one of them may now
 * rest in someone's path), then body id itself. */
static void cc__settle_after(cc_world *w, int id)
{
    int j;
    while ((j = cc__world_take_touched(w)) >= 0)
        if (j != id) {
            cc__refile_moved(w, j);
            cc__sensor_refresh(w, j);
            cc__predict(w, j);
            cc__predict_neighbours(w, j);
        }
    cc__refile_moved(w, id);
    cc__sensor_refresh(w, id); /* before the predictions, which start from its overlaps */
    cc__predict(w, id);
    cc__predict_neighbours(w, id);
}

/* One rule for every mode and state: a body put or given properties has its sensor overlaps
 * brought up to date where it is, from inside that call. Only EXACT with a current grid also
 * pushes it apart and predicts it at once; elsewhere (SWEPT, DISCRETE, before the first step,
 * after a wall was added) that waits for the next step, which files everything again, but the
 * sensors' begins and ends cannot: the header gives them "at once". */
static int cc__settles_now(const cc_world *w)
{
    return w->mode == CC_MODE_EXACT && !w->dirty;
}

void cc__settle_body(cc_world *w, int id)
{
    if (!cc__settles_now(w)) {
        cc__sensor_refresh(w, id);
        return;
    }
    cc__grid_insert(w, id);
    cc__unoverlap_body(w, id, 0);
    cc__settle_after(w, id);
}

void cc__settle_props(cc_world *w, int id)
{
    if (w->features & CC__F_ROLL) { /* its deceleration may be another: from now on */
        cc__advance_body(w, &CC__ARR(w, cc__body, off_body)[id], w->now);
        cc__roll_reset(w, id);
    }
    if (!cc__settles_now(w)) {
        cc__sensor_refresh(w, id);
        return; /* the rest waits for the next step, which looks at everything again */
    }
    /* where it is: others' predictions with it go stale, pairs that now interact are pushed
     * apart, and everything about it is predicted again */
    cc__advance_body(w, &CC__ARR(w, cc__body, off_body)[id], w->now); /* the push-apart reads it at now */
    CC__ARR(w, cc__body, off_body)[id].count++;
    cc__unoverlap_body(w, id, 0);
    cc__settle_after(w, id);
}
