/* Anti-aliasing by coverage: each shape is a signed distance function d (negative inside). A
 * shape at least a pixel thick covers a pixel by the area of a straight edge through it, which
 * for a pixel-sized box filter is clamp(1/2 - d, 0, 1) at the pixel centre; a thinner shape (a
 * small circle, a fine rim) is sampled on an 8x8 grid on the pixels its edge crosses, so that even
 * a circle smaller than a pixel gets its true area. Plain arithmetic only: the same input paints
 * the same bytes. */
#include "raster.h"

#include <math.h>
#include <stddef.h>

#define DEMO_SUB 8            /* sub-samples per pixel side on edge pixels */
#define DEMO_HALF_DIAG 0.7072 /* just above sqrt(2)/2: beyond it a pixel is all in or all out */

typedef struct shape {
    int kind; /* 0 disc, 1 capsule, 2 ring */
    int thin; /* narrower than a pixel somewhere: sample instead of the straight-edge formula */
    double ax, ay, bx, by, r, hw;
    double dx, dy, inv_len2; /* capsule: b - a and 1/|b - a|^2 (0 for a point) */
} shape;

static double shape_distance(const shape *s, double x, double y)
{
    double px = x - s->ax, py = y - s->ay;
    switch (s->kind) {
    case 0:
        return sqrt(px * px + py * py) - s->r;
    case 1: {
        double t = (px * s->dx + py * s->dy) * s->inv_len2;
        double qx, qy;
        t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
        qx = px - t * s->dx;
        qy = py - t * s->dy;
        return sqrt(qx * qx + qy * qy) - s->hw;
    }
    default:
        return fabs(sqrt(px * px + py * py) - s->r) - s->hw;
    }
}

static double coverage(const shape *s, double x0, double y0)
{
    double d = shape_distance(s, x0 + 0.5, y0 + 0.5);
    int i, j, in = 0;
    if (d <= -DEMO_HALF_DIAG)
        return 1.0;
    if (d >= DEMO_HALF_DIAG)
        return 0.0;
    if (!s->thin)
        return d <= -0.5 ? 1.0 : (d >= 0.5 ? 0.0 : 0.5 - d);
    for (j = 0; j < DEMO_SUB; ++j)
        for (i = 0; i < DEMO_SUB; ++i)
            if (shape_distance(s, x0 + (i + 0.5) / DEMO_SUB, y0 + (j + 0.5) / DEMO_SUB) < 0.0)
                ++in;
    return (double)in / (DEMO_SUB * DEMO_SUB);
}

static void blend(demo_canvas *c, int x, int y, demo_rgb col, double a, demo_blend mode)
{
    float *p = c->px + ((size_t)y * (size_t)c->w + (size_t)x) * 3u;
    float fa = (float)a;
    if (mode == DEMO_ADD) {
        p[0] += col.r * fa;
        p[1] += col.g * fa;
        p[2] += col.b * fa;
        p[0] = p[0] > 255.0f ? 255.0f : p[0];
        p[1] = p[1] > 255.0f ? 255.0f : p[1];
        p[2] = p[2] > 255.0f ? 255.0f : p[2];
    } else {
        p[0] += (col.r - p[0]) * fa;
        p[1] += (col.g - p[1]) * fa;
        p[2] += (col.b - p[2]) * fa;
    }
}

static int clampi(double v, int lo, int hi)
{
    if (!(v > lo)) /* also NaN */
        return lo;
    if (v > hi)
        return hi;
    return (int)v;
}

/* The pixel rectangle painting may touch: the canvas, or its clip rectangle. */
static void limits(const demo_canvas *c, int *x0, int *y0, int *x1, int *y1)
{
    *x0 = 0;
    *y0 = 0;
    *x1 = c->w;
    *y1 = c->h;
    if (c->clipped) {
        *x0 = c->cx0 > 0 ? c->cx0 : 0;
        *y0 = c->cy0 > 0 ? c->cy0 : 0;
        *x1 = c->cx1 < c->w ? c->cx1 : c->w;
        *y1 = c->cy1 < c->h ? c->cy1 : c->h;
    }
}

void demo_canvas_clip(demo_canvas *c, int x0, int y0, int x1, int y1)
{
    c->clipped = 1;
    c->cx0 = x0;
    c->cy0 = y0;
    c->cx1 = x1;
    c->cy1 = y1;
}

void demo_canvas_unclip(demo_canvas *c)
{
    c->clipped = 0;
}

/* Paints the shape inside the pixel box [x0, x1] x [y0, y1] (its bounds plus a margin), or with
 * to_mask raises the mask to alpha * coverage there. */
static void paint_or_mask(demo_canvas *c, const shape *s, double x0, double y0, double x1,
                          double y1, demo_rgb col, double alpha, demo_blend mode, int to_mask)
{
    int lx0, ly0, lx1, ly1, i0, i1, j0, j1, i, j;
    limits(c, &lx0, &ly0, &lx1, &ly1);
    i0 = clampi(floor(x0 - 1.0), lx0, lx1);
    i1 = clampi(ceil(x1 + 1.0), lx0, lx1);
    j0 = clampi(floor(y0 - 1.0), ly0, ly1);
    j1 = clampi(ceil(y1 + 1.0), ly0, ly1);
    if (!(alpha > 0.0) || i0 >= i1 || j0 >= j1)
        return;
    if (to_mask) {
        c->mx0 = i0 < c->mx0 ? i0 : c->mx0;
        c->my0 = j0 < c->my0 ? j0 : c->my0;
        c->mx1 = i1 > c->mx1 ? i1 : c->mx1;
        c->my1 = j1 > c->my1 ? j1 : c->my1;
    }
    for (j = j0; j < j1; ++j)
        for (i = i0; i < i1; ++i) {
            double cov = coverage(s, i, j);
            if (cov <= 0.0)
                continue;
            if (to_mask) {
                float *m = &c->mask[(size_t)j * (size_t)c->w + (size_t)i];
                float a = (float)(alpha * cov);
                *m = a > *m ? a : *m;
            } else {
                blend(c, i, j, col, alpha * cov, mode);
            }
        }
}

static void paint(demo_canvas *c, const shape *s, double x0, double y0, double x1, double y1,
                  demo_rgb col, double alpha, demo_blend mode)
{
    paint_or_mask(c, s, x0, y0, x1, y1, col, alpha, mode, 0);
}

demo_rgb demo_rgb_make(float r, float g, float b)
{
    demo_rgb c;
    c.r = r;
    c.g = g;
    c.b = b;
    return c;
}

void demo_canvas_fill(demo_canvas *c, demo_rgb col)
{
    size_t i, n = (size_t)c->w * (size_t)c->h;
    for (i = 0; i < n; ++i) {
        c->px[3 * i] = col.r;
        c->px[3 * i + 1] = col.g;
        c->px[3 * i + 2] = col.b;
    }
}

static double overlap1(double a0, double a1, double p)
{
    /* length of [a0, a1) inside the pixel [p, p + 1) */
    double lo = a0 > p ? a0 : p, hi = a1 < p + 1.0 ? a1 : p + 1.0;
    return hi > lo ? hi - lo : 0.0;
}

void demo_canvas_rect(demo_canvas *c, double x0, double y0, double x1, double y1, demo_rgb col,
                      double alpha, demo_blend mode)
{
    int lx0, ly0, lx1, ly1, i0, i1, j0, j1, i, j;
    limits(c, &lx0, &ly0, &lx1, &ly1);
    i0 = clampi(floor(x0), lx0, lx1);
    i1 = clampi(ceil(x1), lx0, lx1);
    j0 = clampi(floor(y0), ly0, ly1);
    j1 = clampi(ceil(y1), ly0, ly1);
    for (j = j0; j < j1; ++j) {
        double cy = overlap1(y0, y1, j);
        for (i = i0; i < i1; ++i) {
            double cov = cy * overlap1(x0, x1, i);
            if (cov > 0.0)
                blend(c, i, j, col, alpha * cov, mode);
        }
    }
}

void demo_canvas_disc(demo_canvas *c, double cx, double cy, double r, demo_rgb col, double alpha,
                      demo_blend mode)
{
    shape s = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    s.ax = cx;
    s.ay = cy;
    s.r = r;
    s.thin = r < 1.0;
    paint(c, &s, cx - r, cy - r, cx + r, cy + r, col, alpha, mode);
}

/* The segment a-b thickened by hw on each side, as paint() reads it. */
static shape capsule_shape(double ax, double ay, double bx, double by, double hw)
{
    shape s = {1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    double len2;
    s.ax = ax;
    s.ay = ay;
    s.bx = bx;
    s.by = by;
    s.hw = hw;
    s.thin = hw < 0.5;
    s.dx = bx - ax;
    s.dy = by - ay;
    len2 = s.dx * s.dx + s.dy * s.dy;
    s.inv_len2 = len2 > 0.0 ? 1.0 / len2 : 0.0;
    return s;
}

void demo_canvas_capsule(demo_canvas *c, double ax, double ay, double bx, double by, double hw,
                         demo_rgb col, double alpha, demo_blend mode)
{
    shape s = capsule_shape(ax, ay, bx, by, hw);
    paint(c, &s, (ax < bx ? ax : bx) - hw, (ay < by ? ay : by) - hw, (ax > bx ? ax : bx) + hw,
          (ay > by ? ay : by) + hw, col, alpha, mode);
}

void demo_mask_begin(demo_canvas *c)
{
    c->mx0 = c->w;
    c->my0 = c->h;
    c->mx1 = 0;
    c->my1 = 0;
}

void demo_mask_capsule(demo_canvas *c, double ax, double ay, double bx, double by, double hw,
                       double alpha, demo_rgb col, demo_blend mode)
{
    shape s = capsule_shape(ax, ay, bx, by, hw);
    paint_or_mask(c, &s, (ax < bx ? ax : bx) - hw, (ay < by ? ay : by) - hw,
                  (ax > bx ? ax : bx) + hw, (ay > by ? ay : by) + hw, col, alpha, mode,
                  c->mask != NULL);
}

void demo_mask_end(demo_canvas *c, demo_rgb col, demo_blend mode)
{
    int i, j;
    if (c->mask == NULL)
        return;
    for (j = c->my0; j < c->my1; ++j)
        for (i = c->mx0; i < c->mx1; ++i) {
            float *m = &c->mask[(size_t)j * (size_t)c->w + (size_t)i];
            if (*m > 0.0f) {
                blend(c, i, j, col, *m, mode);
                *m = 0.0f;
            }
        }
    demo_mask_begin(c);
}

void demo_canvas_ring(demo_canvas *c, double cx, double cy, double r, double hw, demo_rgb col,
                      double alpha, demo_blend mode)
{
    shape s = {2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    s.ax = cx;
    s.ay = cy;
    s.r = r;
    s.hw = hw;
    s.thin = hw < 0.5;
    paint(c, &s, cx - r - hw, cy - r - hw, cx + r + hw, cy + r + hw, col, alpha, mode);
}

void demo_canvas_to_bytes(const demo_canvas *c, unsigned char *rgb)
{
    size_t i, n = (size_t)c->w * (size_t)c->h * 3u;
    for (i = 0; i < n; ++i) {
        float v = c->px[i];
        rgb[i] = (unsigned char)(v <= 0.0f ? 0 : (v >= 255.0f ? 255 : (int)(v + 0.5f)));
    }
}
