/* The overlap queries (issue 14): the circles that overlap a disc or meet a box, found through
 * the grid (region.h), tested exactly, and written in increasing id order. */
#include "filter.h"
#include "region.h"

#include "precision_double.h"
#include "helpers.inc"
#include "precision_end.h"

typedef struct cc__query {
    const cc_world *w;
    double cx, cy, r;         /* a disc, or (box) */
    double x0, y0, x1, y1;    /* a box */
    int box;
    int full[2];              /* periodic axis k that the box spans a whole period of: every coordinate */
    uint32_t mask;
    int ignore;               /* the storage index of the circle the filter leaves out, or -1 */
    int *ids, capacity, count;
} cc__query;

/* The lowest `capacity` ids seen so far, kept as a max-heap in ids[0..min(count, capacity)). */
static void cc__keep(cc__query *q, int id)
{
    int n = q->count < q->capacity ? q->count : q->capacity, k;
    q->count++;
    if (q->capacity == 0)
        return;
    if (n == q->capacity) {
        if (id >= q->ids[0])
            return;
        k = 0; /* replace the largest, sift it down */
        for (;;) {
            int c = 2 * k + 1, big;
            if (c >= n)
                break;
            big = c + 1 < n && q->ids[c + 1] > q->ids[c] ? c + 1 : c;
            if (q->ids[big] <= id)
                break;
            q->ids[k] = q->ids[big];
            k = big;
        }
        q->ids[k] = id;
        return;
    }
    for (k = n; k > 0 && q->ids[(k - 1) / 2] < id; k = (k - 1) / 2) /* sift up */
        q->ids[k] = q->ids[(k - 1) / 2];
    q->ids[k] = id;
}

/* The kept ids in increasing order (heapsort of the max-heap in place). */
static void cc__sort_kept(cc__query *q)
{
    int n = q->count < q->capacity ? q->count : q->capacity, end;
    for (end = n - 1; end > 0; end--) {
        int top = q->ids[0], last = q->ids[end], k = 0;
        q->ids[end] = top;
        for (;;) {
            int c = 2 * k + 1, big;
            if (c >= end)
                break;
            big = c + 1 < end && q->ids[c + 1] > q->ids[c] ? c + 1 : c;
            if (q->ids[big] <= last)
                break;
            q->ids[k] = q->ids[big];
            k = big;
        }
        q->ids[k] = last;
    }
}

/* dx^2 + dy^2 against R^2 (R >= 0): -1, 0 or 1 as it is below, equal or above. Lengths beyond
 * 2^500 are scaled by 2^-600 first (exact, and the squares no longer overflow: world fuzzer D3,
 * a circle of radius 1e155 covering the query was missed); below, the plain comparison. */
static int cc__cmp_dist(double dx, double dy, double R)
{
    double d2, r2;
    if (fabs(dx) > 0x1p500 || fabs(dy) > 0x1p500 || R > 0x1p500) {
        dx *= 0x1p-600;
        dy *= 0x1p-600;
        R *= 0x1p-600;
    }
    d2 = dx * dx + dy * dy;
    r2 = R * R;
    return d2 < r2 ? -1 : d2 > r2 ? 1 : 0;
}

static void cc__query_visit(void *ctx, int j, double sx, double sy)
{
    cc__query *q = (cc__query *)ctx;
    const cc_world *w = q->w;
    const cc__body *b = &CC__CARR(w, cc__body, off_body)[j];
    double x, y, dx, dy;
    (void)sx, (void)sy;
    if (j == q->ignore || !cc__category_meets(w, j, q->mask))
        return;
    cc__body_pos(w, j, w->now, &x, &y);
    if (w->features & CC__F_PERIODIC) { /* the image nearest the query (each circle once) */
        x += cc__near_shift(w, 0.5 * (q->x0 + q->x1), x, 0);
        y += cc__near_shift(w, 0.5 * (q->y0 + q->y1), y, 1);
    }
    if (q->box) {
        /* the centre's distance from the closed box, against the (closed) disc */
        dx = q->full[0] ? 0.0 : x < q->x0 ? q->x0 - x : x > q->x1 ? x - q->x1 : 0.0;
        dy = q->full[1] ? 0.0 : y < q->y0 ? q->y0 - y : y > q->y1 ? y - q->y1 : 0.0;
        if (dx > b->r || dy > b->r || cc__cmp_dist(dx, dy, b->r) > 0)
            return;
    } else {
        double R = q->r + b->r;
        dx = x - q->cx;
        dy = y - q->cy;
        if (!(cc__cmp_dist(dx, dy, R) < 0)) /* (NaN: not within) */
            return;
    }
    cc__keep(q, cc__idx2id(w, j));
}

/* Along a periodic axis the query (a disc's centre: lo = hi; or a box) is taken to its image
 * whose low side lies in [0, period), so that the circles' nearest images are looked for within
 * half a period of it (world fuzzer D6); a box as wide as the period holds every coordinate
 * along it (D23). */
static void cc__query_to_period(cc__query *q)
{
    double *lo[2], *hi[2];
    int k;
    lo[0] = &q->x0, lo[1] = &q->y0, hi[0] = &q->x1, hi[1] = &q->y1;
    for (k = 0; k < 2; k++)
        if (q->w->period[k] > 0.0) {
            double width = *hi[k] - *lo[k];
            int32_t turns;
            if (!(width < q->w->period[k])) {
                q->full[k] = 1;
                *lo[k] = 0.0, *hi[k] = q->w->period[k];
            } else {
                *lo[k] = cc__wrap_coord(q->w, *lo[k], k, &turns);
                *hi[k] = *lo[k] + width;
            }
        }
}

static int cc__query_run(cc__query *q)
{
    double g = q->box ? 0.0 : q->r;
    cc__visit_region(q->w, q->x0 - g, q->y0 - g, q->x1 + g, q->y1 + g, 0, cc__query_visit, q);
    cc__sort_kept(q);
    return q->count;
}

static int cc__query_ok(const cc_world *w, const int *ids, int capacity)
{
    return w != NULL && w->magic == CC__WORLD_MAGIC && capacity >= 0 && (ids != NULL || capacity == 0);
}

CC_API int cc_world_query_circle(const cc_world *w, cc_vec2 c, double radius, uint32_t mask, int *ids, int capacity)
{
    cc_query_filter f = cc__filter_of_mask(mask);
    return cc_world_query_circle_filtered(w, c, radius, &f, ids, capacity);
}

CC_API int cc_world_query_circle_filtered(const cc_world *w, cc_vec2 c, double radius, const cc_query_filter *filter,
                                          int *ids, int capacity)
{
    cc__query q;
    if (!cc__query_ok(w, ids, capacity) || !isfinite(c.x) || !isfinite(c.y) || !(radius >= 0.0) || !isfinite(radius))
        return CC_ERR_INVALID;
    memset(&q, 0, sizeof q);
    if (cc__filter_read(w, filter, &q.mask, &q.ignore) != CC_OK)
        return CC_ERR_VERSION;
    q.w = w;
    q.x0 = q.x1 = c.x;
    q.y0 = q.y1 = c.y;
    cc__query_to_period(&q);
    q.cx = q.x0;
    q.cy = q.y0;
    q.r = radius;
    q.ids = ids;
    q.capacity = capacity;
    return cc__query_run(&q);
}

CC_API int cc_world_query_box(const cc_world *w, cc_vec2 lo, cc_vec2 hi, uint32_t mask, int *ids, int capacity)
{
    cc_query_filter f = cc__filter_of_mask(mask);
    return cc_world_query_box_filtered(w, lo, hi, &f, ids, capacity);
}

CC_API int cc_world_query_box_filtered(const cc_world *w, cc_vec2 lo, cc_vec2 hi, const cc_query_filter *filter,
                                       int *ids, int capacity)
{
    cc__query q;
    if (!cc__query_ok(w, ids, capacity) || !isfinite(lo.x) || !isfinite(lo.y) || !isfinite(hi.x) ||
        !isfinite(hi.y) || !(lo.x <= hi.x) || !(lo.y <= hi.y))
        return CC_ERR_INVALID;
    memset(&q, 0, sizeof q);
    if (cc__filter_read(w, filter, &q.mask, &q.ignore) != CC_OK)
        return CC_ERR_VERSION;
    q.w = w;
    q.box = 1;
    q.x0 = lo.x;
    q.y0 = lo.y;
    q.x1 = hi.x;
    q.y1 = hi.y;
    cc__query_to_period(&q);
    q.ids = ids;
    q.capacity = capacity;
    return cc__query_run(&q);
}
