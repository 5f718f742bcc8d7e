/* The grid: a uniform cell list over the unbounded plane. A body is filed under the cell of its
 * centre; cells are hashed into a power-of-two table of list heads (about two slots per
 * circle), so memory follows max_circles, not the extent of the scene. Two cells may share a
 * slot: readers compare the cell coordinates. Bodies wider than a cell (immovable ones only)
 * go on a separate large list that every body checks. A small world has no grid at all. */
#include "world_internal.h"

int32_t cc__grid_coord(const cc_world *w, double x)
{
    double c = floor(x * w->inv_cs);
    if (!(c > (double)-CC__CELL_MAX))
        return -CC__CELL_MAX; /* also NaN, which valid input never gives */
    if (c > (double)CC__CELL_MAX)
        return CC__CELL_MAX;
    return (int32_t)c;
}

void cc__grid_clear(cc_world *w)
{
    int32_t *slot = CC__ARR(w, int32_t, off_slot);
    uint32_t i;
    for (i = 0; i <= w->slot_mask; i++)
        slot[i] = -1;
    w->large_head = -1;
}

static void cc__link(cc_world *w, int id, int32_t *head)
{
    cc__body *B = CC__ARR(w, cc__body, off_body);
    cc__cold *C = CC__ARR(w, cc__cold, off_cold);
    C[id].prev = -1;
    B[id].next = *head;
    if (*head >= 0)
        C[*head].prev = id;
    *head = id;
}

static int32_t *cc__head_of(cc_world *w, int id)
{
    const cc__body *b = &CC__CARR(w, cc__body, off_body)[id];
    if (CC__CARR(w, cc__cold, off_cold)[id].flags & CC__LARGE)
        return &w->large_head;
    return &CC__ARR(w, int32_t, off_slot)[cc__grid_slot(w, b->cx, b->cy)];
}

void cc__grid_insert(cc_world *w, int id)
{
    cc__body *b = &CC__ARR(w, cc__body, off_body)[id];
    cc__cold *k = &CC__ARR(w, cc__cold, off_cold)[id];
    k->flags &= ~CC__LARGE;
    if (!w->use_grid)
        return; /* a small world tests all pairs */
    if (2.0 * b->r * 1.0625 > w->cs)
        k->flags |= CC__LARGE;
    b->cx = cc__grid_coord(w, cc__bx(b, w->now));
    b->cy = cc__grid_coord(w, cc__by(b, w->now));
    cc__link(w, id, cc__head_of(w, id));
}

void cc__grid_remove(cc_world *w, int id)
{
    cc__body *B = CC__ARR(w, cc__body, off_body);
    cc__cold *C = CC__ARR(w, cc__cold, off_cold);
    if (!w->use_grid)
        return;
    if (C[id].prev >= 0)
        B[C[id].prev].next = B[id].next;
    else
        *cc__head_of(w, id) = B[id].next;
    if (B[id].next >= 0)
        C[B[id].next].prev = C[id].prev;
}

void cc__grid_move(cc_world *w, int id, int dir)
{
    cc__body *b = &CC__ARR(w, cc__body, off_body)[id];
    cc__grid_remove(w, id);
    if (dir == 0)
        b->cx++;
    else if (dir == 1)
        b->cx--;
    else if (dir == 2)
        b->cy++;
    else
        b->cy--;
    cc__link(w, id, cc__head_of(w, id));
}
