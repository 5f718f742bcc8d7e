/* The walls' tree (walls.h): built top down, each node's walls split at the median of their
 * centres along the longer side of the centres' box, until a node holds CC__WALL_LEAF walls or
 * fewer. Deterministic (ties in the median by wall index) and in place, in the world's memory:
 * the nodes (at most 2 * max_segments), the order of the walls, and their boxes. */
#include "walls.h"

/* The centre of wall s along an axis (twice it: the sum of its ends, exact enough to order). */
static double cc__key(const cc__wall_box *b, int s, int axis)
{
    return axis ? b[s].y0 + b[s].y1 : b[s].x0 + b[s].x1;
}

static int cc__before(const cc__wall_box *b, int axis, int32_t p, int32_t q)
{
    double kp = cc__key(b, p, axis), kq = cc__key(b, q, axis);
    return kp < kq || (kp == kq && p < q);
}

/* Moves o[root] down its subtree within o[0, n) until both children come before it. */
static void cc__sift(const cc__wall_box *b, int axis, int32_t *o, int root, int n)
{
    int child;
    for (; (child = 2 * root + 1) < n; root = child) {
        int32_t t;
        if (child + 1 < n && cc__before(b, axis, o[child], o[child + 1]))
            child++;
        if (!cc__before(b, axis, o[root], o[child]))
            break;
        t = o[root];
        o[root] = o[child];
        o[child] = t;
    }
}

/* Sorts o[0, n) by centre along the axis: heapsort, in place, O(n log n) at worst. */
static void cc__sort(const cc__wall_box *b, int axis, int32_t *o, int n)
{
    int k;
    for (k = n / 2 - 1; k >= 0; k--)
        cc__sift(b, axis, o, k, n);
    for (k = n - 1; k > 0; k--) {
        int32_t t = o[0];
        o[0] = o[k];
        o[k] = t;
        cc__sift(b, axis, o, 0, k);
    }
}

void cc__walls_build(cc_world *w)
{
    cc__wall_box *box = CC__ARR(w, cc__wall_box, off_wallbox);
    cc__wall_node *node = CC__ARR(w, cc__wall_node, off_wallnode);
    int32_t *order = CC__ARR(w, int32_t, off_wallorder);
    const cc_segment *seg = CC__CARR(w, cc_segment, off_seg);
    int32_t stack[CC__WALL_DEPTH][3]; /* node, lo, hi */
    int sp = 0, used = 1, s, n = w->n_segments;
    w->wall_tree_n = 0;
    if (n == 0)
        return;
    for (s = 0; s < n; s++) {
        box[s] = cc__wall_box_of(&seg[s]);
        order[s] = s;
    }
    stack[sp][0] = 0, stack[sp][1] = 0, stack[sp][2] = n, sp++;
    while (sp > 0) {
        int id, lo, hi, k, axis;
        double cx0 = HUGE_VAL, cx1 = -HUGE_VAL, cy0 = HUGE_VAL, cy1 = -HUGE_VAL;
        cc__wall_node *nd;
        sp--;
        id = stack[sp][0], lo = stack[sp][1], hi = stack[sp][2];
        nd = &node[id];
        nd->x0 = nd->y0 = HUGE_VAL;
        nd->x1 = nd->y1 = -HUGE_VAL;
        for (k = lo; k < hi; k++) {
            const cc__wall_box *g = &box[order[k]];
            double kx = cc__key(box, order[k], 0), ky = cc__key(box, order[k], 1);
            nd->x0 = g->gx0 < nd->x0 ? g->gx0 : nd->x0;
            nd->y0 = g->gy0 < nd->y0 ? g->gy0 : nd->y0;
            nd->x1 = g->gx1 > nd->x1 ? g->gx1 : nd->x1;
            nd->y1 = g->gy1 > nd->y1 ? g->gy1 : nd->y1;
            cx0 = kx < cx0 ? kx : cx0, cx1 = kx > cx1 ? kx : cx1;
            cy0 = ky < cy0 ? ky : cy0, cy1 = ky > cy1 ? ky : cy1;
        }
        if (hi - lo <= CC__WALL_LEAF || sp + 2 > CC__WALL_DEPTH) {
            nd->first = lo;
            nd->count = hi - lo;
            continue;
        }
        axis = cy1 - cy0 > cx1 - cx0;
        cc__sort(box, axis, order + lo, hi - lo);
        nd->first = used;
        nd->count = 0;
        stack[sp][0] = used, stack[sp][1] = lo, stack[sp][2] = lo + (hi - lo) / 2, sp++;
        stack[sp][0] = used + 1, stack[sp][1] = lo + (hi - lo) / 2, stack[sp][2] = hi, sp++;
        used += 2;
    }
    w->wall_tree_n = n;
}
