/* The grid: a uniform cell list over the unbounded plane. A body is filed under the cell of its
 * centre; cells are hashed into a power-of-two table of list heads (about two slots per
 * circle), so memory follows max_circles, not the extent of the scene. Two cells may share a
 * slot: readers compare the cell coordinates. Bodies wider than a cell (immovable ones only)
 * go on a separate large list that every body checks. */
#include "world_internal.h"

int64_t cc__grid_coord(const cc_world *w, double x)
{
    double c = floor(x * w->inv_cs);
    if (!(c > (double)-CC__CELL_MAX))
        return -CC__CELL_MAX; /* also NaN, which valid input never gives */
    if (c > (double)CC__CELL_MAX)
        return CC__CELL_MAX;
    return (int64_t)c;
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
    cc__cell *c = CC__ARR(w, cc__cell, off_cell);
    c[id].prev = -1;
    c[id].next = *head;
    if (*head >= 0)
        c[*head].prev = id;
    *head = id;
}

static int32_t *cc__head_of(cc_world *w, int id)
{
    const cc__body *b = &CC__CARR(w, cc__body, off_body)[id];
    const cc__cell *c = &CC__CARR(w, cc__cell, off_cell)[id];
    if (b->flags & CC__LARGE)
        return &w->large_head;
    return &CC__ARR(w, int32_t, off_slot)[cc__grid_slot(w, c->cx, c->cy)];
}

void cc__grid_insert(cc_world *w, int id)
{
    cc__body *b = &CC__ARR(w, cc__body, off_body)[id];
    cc__cell *c = &CC__ARR(w, cc__cell, off_cell)[id];
    b->flags &= ~CC__LARGE;
    if (!w->use_grid)
        return; /* a small world tests all pairs */
    if (2.0 * b->r * 1.0625 > w->cs)
        b->flags |= CC__LARGE;
    c->cx = cc__grid_coord(w, cc__bx(b, w->now));
    c->cy = cc__grid_coord(w, cc__by(b, w->now));
    cc__link(w, id, cc__head_of(w, id));
}

void cc__grid_remove(cc_world *w, int id)
{
    cc__cell *c = CC__ARR(w, cc__cell, off_cell);
    if (!w->use_grid)
        return;
    if (c[id].prev >= 0)
        c[c[id].prev].next = c[id].next;
    else
        *cc__head_of(w, id) = c[id].next;
    if (c[id].next >= 0)
        c[c[id].next].prev = c[id].prev;
}

void cc__grid_move(cc_world *w, int id, int dir)
{
    cc__cell *c = &CC__ARR(w, cc__cell, off_cell)[id];
    cc__grid_remove(w, id);
    if (dir == 0)
        c->cx++;
    else if (dir == 1)
        c->cx--;
    else if (dir == 2)
        c->cy++;
    else
        c->cy--;
    cc__link(w, id, cc__head_of(w, id));
}
