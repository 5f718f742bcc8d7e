/* The grid: a uniform cell list over the unbounded plane. A body is filed under the cell of its
 * centre; cells are hashed into a power-of-two table of list heads (about two slots per
 * circle), so memory follows max_circles, not the extent of the scene. Two cells may share a
 * slot: readers compare the cell coordinates. Bodies wider than a cell (immovable ones only)
 * go on a separate large list that every body checks. A small world has no grid at all. */
#include "world_internal.h"

int32_t cc__grid_coord(const cc_world *w, double x, int axis)
{
    double c = floor(x * w->inv_cs);
    if (w->ncell[axis] > 0) /* periodic: x within [0, period) to rounding; the last cell the wider */
        return c < 0.0 ? 0 : c >= (double)w->ncell[axis] ? w->ncell[axis] - 1 : (int32_t)c;
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
    if (w->features & CC__F_PERIODIC)
        cc__wrap_body(w, id); /* its coordinates within the period, where its cell is */
    b->cx = cc__grid_coord(w, cc__bx(w, b, w->now), 0);
    b->cy = cc__grid_coord(w, cc__by(w, b, w->now), 1);
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
    int axis = dir >> 1, step = dir & 1 ? -1 : 1;
    int32_t *c = axis ? &b->cy : &b->cx;
    cc__grid_remove(w, id);
    *c += step;
    if (w->ncell[axis] > 0 && (*c < 0 || *c >= w->ncell[axis])) {
        /* through the period's edge: the body is taken to its image on the other side (at the
         * edge, so the subtraction is exact), and counts the turn */
        double *p = axis ? &b->py : &b->px;
        *c = step > 0 ? 0 : w->ncell[axis] - 1;
        *p -= step * w->period[axis];
        int32_t *turns = &CC__ARR(w, int32_t, off_wrap)[2 * id + axis]; /* a periodic world has it */
        *turns = cc__turns_add(*turns, step);
    }
    cc__link(w, id, cc__head_of(w, id));
}

/* x - n P for the integer n that leaves a result in (-P, P) with the sign of x, exactly (what
 * fmod computes), by long division with powers of two: the library calls no more of libm than
 * sqrt/fabs/frexp/ldexp/floor/ceil (the embedded build checks it). Each subtraction is of q from
 * a with q <= a < 2q, exact (Sterbenz). */
static double cc__mod_exact(double x, double P)
{
    double a = fabs(x);
    int ea, ep, k;
    if (a < P)
        return x;
    (void)frexp(a, &ea);
    (void)frexp(P, &ep);
    for (k = ea - ep; k >= 0; k--) { /* a < 2 P 2^k holds at every k */
        double q = ldexp(P, k);
        if (a >= q)
            a -= q;
    }
    return x < 0.0 ? -a : a;
}

double cc__wrap_coord(const cc_world *w, double x, int k, int32_t *turns)
{
    double P = w->period[k], r = cc__mod_exact(x, P);
    if (r < 0.0)
        r += P; /* a tiny negative remainder may round to P itself: that is 0 again */
    if (r >= P)
        r = 0.0;
    {   /* the count of periods, saturated: a coordinate 2^30 periods out (1e300 in a period of 20)
         * keeps its image exactly, its count of turns only up to that */
        double q = floor((x - r) / P + 0.5);
        *turns = q > 0x1p30 ? (int32_t)0x40000000 : q < -0x1p30 ? -(int32_t)0x40000000 : (int32_t)q;
    }
    return r;
}

int32_t cc__turns_add(int32_t a, int32_t b)
{
    int64_t s = (int64_t)a + (int64_t)b; /* both within 2^30: no overflow, then saturated */
    return s > 0x40000000 ? (int32_t)0x40000000 : s < -0x40000000 ? -(int32_t)0x40000000 : (int32_t)s;
}

void cc__wrap_body(cc_world *w, int id)
{
    cc__body *b = &CC__ARR(w, cc__body, off_body)[id];
    int32_t *wrap = &CC__ARR(w, int32_t, off_wrap)[2 * id]; /* called in periodic worlds only */
    int k;
    cc__advance_body(w, b, w->now);
    for (k = 0; k < 2; k++) {
        double *x = k ? &b->py : &b->px;
        int32_t turns;
        if (w->period[k] > 0.0 && !(*x >= 0.0 && *x < w->period[k])) {
            *x = cc__wrap_coord(w, *x, k, &turns);
            wrap[k] = cc__turns_add(wrap[k], turns);
        }
    }
}
