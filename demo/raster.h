/* A float RGB canvas and anti-aliased shapes on it: discs, capsules (thick segments), rings,
 * rectangles and 5x7 text. Coordinates are in pixels, (0, 0) the top-left corner of the top-left
 * pixel, so pixel (i, j) has its centre at (i + 0.5, j + 0.5). */
#ifndef DEMO_RASTER_H
#define DEMO_RASTER_H

typedef struct demo_rgb {
    float r, g, b; /* 0..255 */
} demo_rgb;

typedef struct demo_canvas {
    int w, h;
    float *px;   /* w*h*3 floats, owned by the caller */
    float *mask; /* w*h zeroed floats for demo_mask_*, or NULL (then they paint directly) */
    int mx0, my0, mx1, my1; /* the part of the mask in use */
    int clipped;            /* 1: paint only inside [cx0, cx1) x [cy0, cy1) */
    int cx0, cy0, cx1, cy1;
} demo_canvas;

typedef enum demo_blend {
    DEMO_OVER = 0, /* paint: dst += (colour - dst) * alpha * coverage */
    DEMO_ADD = 1   /* light: dst += colour * alpha * coverage, saturating at 255 */
} demo_blend;

demo_rgb demo_rgb_make(float r, float g, float b);
/* Restricts painting to the pixels [x0, x1) x [y0, y1) (a stage's column), or lifts that. */
void demo_canvas_clip(demo_canvas *c, int x0, int y0, int x1, int y1);
void demo_canvas_unclip(demo_canvas *c);
void demo_canvas_fill(demo_canvas *c, demo_rgb col);
/* Axis-aligned rectangle [x0, x1) x [y0, y1) with fractional edges covered in proportion. */
void demo_canvas_rect(demo_canvas *c, double x0, double y0, double x1, double y1, demo_rgb col,
                      double alpha, demo_blend mode);
void demo_canvas_disc(demo_canvas *c, double cx, double cy, double r, demo_rgb col, double alpha,
                      demo_blend mode);
/* All points within hw of the segment a-b. */
void demo_canvas_capsule(demo_canvas *c, double ax, double ay, double bx, double by, double hw,
                         demo_rgb col, double alpha, demo_blend mode);
/* All points whose distance from the centre is within hw of r. */
void demo_canvas_ring(demo_canvas *c, double cx, double cy, double r, double hw, demo_rgb col,
                      double alpha, demo_blend mode);
/* Upper-case text (A-Z, 0-9, space and . , : - + / = % ( ) < > ') with its top-left corner at
 * (x, y) in whole pixels, each font pixel a scale x scale block. Returns the width drawn. */
int demo_canvas_text(demo_canvas *c, int x, int y, int scale, const char *s, demo_rgb col);
/* Width in pixels demo_canvas_text would draw. */
int demo_text_width(const char *s, int scale);

/* A mask unites several shapes into one before painting, so that where they overlap (the
 * joints of a trail) the paint is not applied twice: each pixel gets the largest alpha * coverage
 * of the shapes, then demo_mask_end paints the colour by it and clears the mask. */
void demo_mask_begin(demo_canvas *c);
void demo_mask_capsule(demo_canvas *c, double ax, double ay, double bx, double by, double hw,
                       double alpha, demo_rgb col, demo_blend mode);
void demo_mask_end(demo_canvas *c, demo_rgb col, demo_blend mode);

/* Rounds to bytes (w*h*3) for output. */
void demo_canvas_to_bytes(const demo_canvas *c, unsigned char *rgb);

#endif
