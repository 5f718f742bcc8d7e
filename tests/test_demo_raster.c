/* The demo's rasterizer: anti-aliased shapes cover their true area, blending and rounding do
 * what the header says, and nothing is painted outside the canvas. Also the speed colour map. */
#include "unity.h"

#include "colour.h"
#include "raster.h"

#include <math.h>
#include <stdlib.h>

#define W 64
#define H 64

static float pixels[W * H * 3];
static demo_canvas canvas;

void setUp(void)
{
    canvas.w = W;
    canvas.h = H;
    canvas.px = pixels;
    demo_canvas_fill(&canvas, demo_rgb_make(0.0f, 0.0f, 0.0f));
}

void tearDown(void)
{
}

static const demo_rgb white = {255.0f, 255.0f, 255.0f};

/* Painted area in pixels: white over black, so each pixel's red / 255 is its coverage. */
static double area(void)
{
    double sum = 0.0;
    int i;
    for (i = 0; i < W * H; ++i)
        sum += pixels[3 * i] / 255.0;
    return sum;
}

static void test_disc_covers_its_area(void)
{
    /* pi r^2 = pi * 100 = 314.159. The straight-edge coverage ramp (1/2 - d over one pixel)
       integrates to pi (r - 1/2)^2 + 2 pi (r/2 - 1/12) = pi r^2 + pi/12: 0.26 over */
    demo_canvas_disc(&canvas, 32.3, 31.7, 10.0, white, 1.0, DEMO_OVER);
    TEST_ASSERT_DOUBLE_WITHIN(1.0, 314.159, area());
}

static void test_disc_smaller_than_a_pixel_keeps_its_area(void)
{
    /* r = 0.3 centred in pixel (10, 10): area pi * 0.09 = 0.2827, all inside that pixel.
       The 8x8 grid finds the 4x4 samples within 0.3 of the centre, 16/64 = 0.25: for a shape
       this small the error is one ring of samples, 0.033 here, never "no circle at all" */
    demo_canvas_disc(&canvas, 10.5, 10.5, 0.3, white, 1.0, DEMO_OVER);
    TEST_ASSERT_DOUBLE_WITHIN(0.04, 0.2827, area());
    TEST_ASSERT_DOUBLE_WITHIN(0.04, 0.2827, pixels[3 * (10 * W + 10)] / 255.0);
}

static void test_capsule_covers_a_rectangle_and_two_half_discs(void)
{
    /* length 20, half-width 2: 20 * 4 + pi * 2^2 = 92.566 (+ pi/12 from the ramp at the
       round ends, as for a disc) */
    demo_canvas_capsule(&canvas, 20.0, 30.0, 40.0, 30.0, 2.0, white, 1.0, DEMO_OVER);
    TEST_ASSERT_DOUBLE_WITHIN(0.5, 92.566, area());
}

static void test_ring_covers_an_annulus(void)
{
    /* radius 10, half-width 1: pi (11^2 - 9^2) = 40 pi = 125.664 (the ramp adds pi/12 on the
       outer edge and takes it back on the inner one) */
    demo_canvas_ring(&canvas, 32.0, 32.0, 10.0, 1.0, white, 1.0, DEMO_OVER);
    TEST_ASSERT_DOUBLE_WITHIN(1.0, 125.664, area());
    /* the centre stays dark */
    TEST_ASSERT_EQUAL_FLOAT(0.0f, pixels[3 * (32 * W + 32)]);
}

static void test_rect_covers_fractional_pixels_in_proportion(void)
{
    /* [1.5, 3.5) x [0, 1): pixel 1 half, pixel 2 whole, pixel 3 half */
    demo_canvas_rect(&canvas, 1.5, 0.0, 3.5, 1.0, white, 1.0, DEMO_OVER);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, pixels[0]);
    TEST_ASSERT_EQUAL_FLOAT(127.5f, pixels[3 * 1]);
    TEST_ASSERT_EQUAL_FLOAT(255.0f, pixels[3 * 2]);
    TEST_ASSERT_EQUAL_FLOAT(127.5f, pixels[3 * 3]);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, pixels[3 * 4]);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, pixels[3 * W + 3 * 2]); /* the next row is untouched */
}

static void test_over_mixes_and_add_saturates(void)
{
    demo_rgb grey = {100.0f, 100.0f, 100.0f};
    /* over, alpha 0.5: 0 + (255 - 0) * 0.5 = 127.5 */
    demo_canvas_rect(&canvas, 0.0, 0.0, 1.0, 1.0, white, 0.5, DEMO_OVER);
    TEST_ASSERT_EQUAL_FLOAT(127.5f, pixels[0]);
    /* add twice 100 * 1.0 on 127.5: 227.5, then 327.5 clamped to 255 */
    demo_canvas_rect(&canvas, 0.0, 0.0, 1.0, 1.0, grey, 1.0, DEMO_ADD);
    TEST_ASSERT_EQUAL_FLOAT(227.5f, pixels[0]);
    demo_canvas_rect(&canvas, 0.0, 0.0, 1.0, 1.0, grey, 1.0, DEMO_ADD);
    TEST_ASSERT_EQUAL_FLOAT(255.0f, pixels[0]);
}

static void test_shapes_are_clipped_to_the_canvas(void)
{
    /* a disc mostly outside the top-left corner: pixel (0, 0) is deep inside it; the memory
       around the canvas is guarded by the sanitizer build */
    demo_canvas_disc(&canvas, -5.0, -5.0, 10.0, white, 1.0, DEMO_OVER);
    demo_canvas_capsule(&canvas, -100.0, 70.0, 200.0, 70.0, 3.0, white, 1.0, DEMO_OVER);
    demo_canvas_rect(&canvas, -10.0, -10.0, 1000.0, -1.0, white, 1.0, DEMO_OVER);
    TEST_ASSERT_EQUAL_FLOAT(255.0f, pixels[0]);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, pixels[3 * (W * H - 1)]);
}

static void test_clip_keeps_paint_inside_a_column(void)
{
    /* a disc of radius 25 at the centre (columns 7..56), clipped to columns 10..19: 9 and 20
       stay dark, column 10 is painted on the centre row */
    demo_canvas_clip(&canvas, 10, 0, 20, H);
    demo_canvas_disc(&canvas, 32.0, 32.0, 25.0, white, 1.0, DEMO_OVER);
    demo_canvas_rect(&canvas, 0.0, 0.0, W, 1.0, white, 1.0, DEMO_OVER);
    demo_canvas_unclip(&canvas);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, pixels[3 * (32 * W + 9)]);
    TEST_ASSERT_EQUAL_FLOAT(255.0f, pixels[3 * (32 * W + 10)]);
    TEST_ASSERT_EQUAL_FLOAT(255.0f, pixels[3 * (32 * W + 19)]);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, pixels[3 * (32 * W + 20)]);
    /* the rectangle's row: only its pixels 10..19 */
    TEST_ASSERT_EQUAL_FLOAT(0.0f, pixels[3 * 9]);
    TEST_ASSERT_EQUAL_FLOAT(255.0f, pixels[3 * 10]);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, pixels[3 * 20]);
}

static void test_bytes_round_to_nearest_and_clamp(void)
{
    unsigned char out[W * H * 3];
    pixels[0] = -3.0f;
    pixels[1] = 300.0f;
    pixels[2] = 127.49f;
    pixels[3] = 127.5f;
    demo_canvas_to_bytes(&canvas, out);
    TEST_ASSERT_EQUAL_INT(0, out[0]);
    TEST_ASSERT_EQUAL_INT(255, out[1]);
    TEST_ASSERT_EQUAL_INT(127, out[2]);
    TEST_ASSERT_EQUAL_INT(128, out[3]);
}

static void test_mask_paints_overlapping_shapes_once(void)
{
    static float mask[W * H];
    /* two capsules crossing at (32, 32), each at alpha 0.5: painted directly the crossing gets
       0.5 + 0.5 * 0.5 = 0.75 of white; through the mask it gets max(0.5, 0.5) = 0.5, like the
       arms (127.5) */
    demo_canvas_capsule(&canvas, 22.0, 32.5, 42.0, 32.5, 2.0, white, 0.5, DEMO_OVER);
    demo_canvas_capsule(&canvas, 32.5, 22.0, 32.5, 42.0, 2.0, white, 0.5, DEMO_OVER);
    TEST_ASSERT_EQUAL_FLOAT(191.25f, pixels[3 * (32 * W + 32)]);
    setUp();
    canvas.mask = mask;
    demo_mask_begin(&canvas);
    demo_mask_capsule(&canvas, 22.0, 32.5, 42.0, 32.5, 2.0, 0.5, white, DEMO_OVER);
    demo_mask_capsule(&canvas, 32.5, 22.0, 32.5, 42.0, 2.0, 0.5, white, DEMO_OVER);
    demo_mask_end(&canvas, white, DEMO_OVER);
    canvas.mask = NULL;
    TEST_ASSERT_EQUAL_FLOAT(127.5f, pixels[3 * (32 * W + 32)]);
    TEST_ASSERT_EQUAL_FLOAT(127.5f, pixels[3 * (32 * W + 25)]);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, mask[32 * W + 32]); /* cleared for the next use */
}

static void test_text_draws_known_glyphs_and_skips_unknown_ones(void)
{
    /* 5 columns per glyph and 1 of spacing: "AB" is 11 wide at scale 1, 22 at scale 2 */
    TEST_ASSERT_EQUAL_INT(11, demo_text_width("AB", 1));
    TEST_ASSERT_EQUAL_INT(22, demo_text_width("AB", 2));
    TEST_ASSERT_EQUAL_INT(0, demo_text_width("", 3));
    /* 'I' is a bar in column 2 between serifs: rows 1..5 have only column 2 lit */
    demo_canvas_text(&canvas, 0, 0, 1, "I", white);
    TEST_ASSERT_EQUAL_FLOAT(255.0f, pixels[3 * (3 * W + 2)]);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, pixels[3 * (3 * W + 1)]);
    TEST_ASSERT_EQUAL_FLOAT(255.0f, pixels[3 * (0 * W + 1)]); /* the top serif */
    /* lower case is drawn as upper case; '~' is not in the font and paints nothing */
    setUp();
    demo_canvas_text(&canvas, 0, 0, 1, "~", white);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, (float)area());
    demo_canvas_text(&canvas, 0, 0, 1, "i", white);
    TEST_ASSERT_EQUAL_FLOAT(255.0f, pixels[3 * (3 * W + 2)]);
}

static void test_speed_colours_follow_the_stops(void)
{
    demo_rgb rest = demo_speed_colour(0.0), mid = demo_speed_colour(0.5);
    demo_rgb top = demo_speed_colour(1.0), beyond = demo_speed_colour(7.0);
    demo_rgb nan = demo_speed_colour(sqrt(-1.0)), eighth = demo_speed_colour(0.125);
    TEST_ASSERT_EQUAL_FLOAT(38.0f, rest.r);   /* stop 0: (38, 64, 190) */
    TEST_ASSERT_EQUAL_FLOAT(190.0f, rest.b);
    TEST_ASSERT_EQUAL_FLOAT(205.0f, mid.g);   /* stop 2: (80, 205, 110) */
    TEST_ASSERT_EQUAL_FLOAT(235.0f, top.r);   /* stop 4: (235, 60, 40) */
    TEST_ASSERT_EQUAL_FLOAT(top.r, beyond.r); /* clamped */
    TEST_ASSERT_EQUAL_FLOAT(rest.b, nan.b);   /* NaN counts as at rest */
    /* halfway between stop 0 and stop 1 (40, 165, 225): green (64 + 165) / 2 = 114.5 */
    TEST_ASSERT_EQUAL_FLOAT(114.5f, eighth.g);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_disc_covers_its_area);
    RUN_TEST(test_disc_smaller_than_a_pixel_keeps_its_area);
    RUN_TEST(test_capsule_covers_a_rectangle_and_two_half_discs);
    RUN_TEST(test_ring_covers_an_annulus);
    RUN_TEST(test_rect_covers_fractional_pixels_in_proportion);
    RUN_TEST(test_over_mixes_and_add_saturates);
    RUN_TEST(test_shapes_are_clipped_to_the_canvas);
    RUN_TEST(test_clip_keeps_paint_inside_a_column);
    RUN_TEST(test_bytes_round_to_nearest_and_clamp);
    RUN_TEST(test_mask_paints_overlapping_shapes_once);
    RUN_TEST(test_text_draws_known_glyphs_and_skips_unknown_ones);
    RUN_TEST(test_speed_colours_follow_the_stops);
    return UNITY_END();
}
