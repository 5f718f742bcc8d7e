/* The walls' tree (walls.c): a bounding-volume hierarchy over the walls' boxes, built when walls
 * were added (at the next step), so that every look at the walls near a circle -- predictions,
 * the push-apart passes, the gathering of a cluster, SWEPT's sweeps, casts -- costs what the
 * walls near it hold, not what the world holds. Walls added since the last build are looked at
 * one by one after the tree's. Private. */
#ifndef CC_WORLD_WALLS_H
#define CC_WORLD_WALLS_H

#include "world_internal.h"

/* A wall's box, exact and grown by 2^-30 of the size of its coordinates (for tests that must be
 * conservative to far above rounding). */
typedef struct cc__wall_box {
    double x0, y0, x1, y1;     /* exact */
    double gx0, gy0, gx1, gy1; /* grown */
} cc__wall_box;

/* A node: a leaf (count > 0) holds walls order[first .. first + count); an inner node (count ==
 * 0) has its children at nodes first and first + 1. Its box covers its walls' grown boxes. */
typedef struct cc__wall_node {
    double x0, y0, x1, y1;
    int32_t first, count;
} cc__wall_node;

#define CC__WALL_LEAF 4       /* walls per leaf: a scene of 4 walls is one leaf, as before */
#define CC__WALL_DEPTH 64     /* far above log2 of the largest capacity */

/* Builds the tree over every wall (w->wall_tree_n = n_segments afterwards). */
void cc__walls_build(cc_world *w);

/* Walks the walls whose (grown) box meets [x0, x1] x [y0, y1]: each wall once, in a fixed order.
 *     cc__wall_walk k; int s;
 *     cc__walls_begin(w, &k, x0, y0, x1, y1);
 *     while ((s = cc__walls_next(w, &k)) >= 0) ... */
typedef struct cc__wall_walk {
    double x0, y0, x1, y1;
    int32_t stack[CC__WALL_DEPTH];
    int sp;
    int leaf, leaf_end; /* the leaf being read: order[leaf .. leaf_end) */
    int rest;           /* walls added since the build: rest .. n_segments - 1 */
} cc__wall_walk;

static inline const cc__wall_box *cc__wall_boxes(const cc_world *w)
{
    return CC__CARR(w, cc__wall_box, off_wallbox);
}

static inline cc__wall_box cc__wall_box_of(const cc_segment *g)
{
    cc__wall_box k;
    double m;
    k.x0 = g->a.x < g->b.x ? g->a.x : g->b.x;
    k.x1 = g->a.x < g->b.x ? g->b.x : g->a.x;
    k.y0 = g->a.y < g->b.y ? g->a.y : g->b.y;
    k.y1 = g->a.y < g->b.y ? g->b.y : g->a.y;
    m = 0x1p-30 * (fabs(k.x0) + fabs(k.x1) + fabs(k.y0) + fabs(k.y1));
    k.gx0 = k.x0 - m;
    k.gx1 = k.x1 + m;
    k.gy0 = k.y0 - m;
    k.gy1 = k.y1 + m;
    return k;
}

static inline void cc__walls_begin(const cc_world *w, cc__wall_walk *k, double x0, double y0, double x1, double y1)
{
    k->x0 = x0, k->y0 = y0, k->x1 = x1, k->y1 = y1;
    k->sp = 0;
    k->leaf = k->leaf_end = 0;
    k->rest = w->wall_tree_n;
    if (w->wall_tree_n > 0)
        k->stack[k->sp++] = 0;
}

static inline int cc__walls_meet(const cc__wall_walk *k, double x0, double y0, double x1, double y1)
{
    return !((x0 > k->x1) | (x1 < k->x0) | (y0 > k->y1) | (y1 < k->y0)); /* | : one branch */
}

static inline int cc__walls_next(const cc_world *w, cc__wall_walk *k)
{
    const cc__wall_node *node = CC__CARR(w, cc__wall_node, off_wallnode);
    const int32_t *order = CC__CARR(w, int32_t, off_wallorder);
    const cc__wall_box *box = cc__wall_boxes(w);
    for (;;) {
        while (k->leaf < k->leaf_end) {
            int s = order[k->leaf++];
            const cc__wall_box *g = &box[s];
            if (cc__walls_meet(k, g->gx0, g->gy0, g->gx1, g->gy1))
                return s;
        }
        if (k->sp == 0)
            break;
        {
            const cc__wall_node *n = &node[k->stack[--k->sp]];
            if (!cc__walls_meet(k, n->x0, n->y0, n->x1, n->y1))
                continue;
            if (n->count > 0) {
                k->leaf = n->first;
                k->leaf_end = n->first + n->count;
            } else { /* the second child is read after the first: pushed first */
                k->stack[k->sp++] = n->first + 1;
                k->stack[k->sp++] = n->first;
            }
        }
    }
    while (k->rest < w->n_segments) { /* added since the build: each looked at */
        int s = k->rest++;
        cc__wall_box g = cc__wall_box_of(&CC__CARR(w, cc_segment, off_seg)[s]);
        if (cc__walls_meet(k, g.gx0, g.gy0, g.gx1, g.gy1))
            return s;
    }
    return -1;
}

#endif
