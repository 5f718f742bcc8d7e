/* The demo's output files: the P6 header, the bytes after it, the frame names, and the seeded
 * random numbers that make every run the same. */
#include "unity.h"

#include "ppm.h"
#include "prng.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>

void setUp(void)
{
}

void tearDown(void)
{
}

static void test_header_is_p6_width_height_255(void)
{
    char buf[64];
    size_t n = demo_ppm_header(buf, sizeof buf, 640, 360);
    TEST_ASSERT_EQUAL_STRING("P6\n640 360\n255\n", buf);
    TEST_ASSERT_EQUAL_INT(15, (int)n);
}

static void test_file_is_header_then_rows_of_rgb(void)
{
    /* 3x2 pixels: 11 header bytes + 18 pixel bytes = 29 */
    const unsigned char rgb[18] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 0};
    unsigned char back[64];
    const char *path = "test_demo_ppm_out.ppm";
    size_t n;
    FILE *f;
    TEST_ASSERT_EQUAL_INT(0, demo_ppm_write(path, rgb, 3, 2));
    f = fopen(path, "rb");
    TEST_ASSERT_NOT_NULL(f);
    n = fread(back, 1, sizeof back, f);
    fclose(f);
    remove(path);
    TEST_ASSERT_EQUAL_INT(29, (int)n);
    TEST_ASSERT_EQUAL_MEMORY("P6\n3 2\n255\n", back, 11);
    TEST_ASSERT_EQUAL_MEMORY(rgb, back + 11, 18);
}

static void test_write_into_a_missing_folder_fails(void)
{
    const unsigned char rgb[3] = {0, 0, 0};
    TEST_ASSERT_EQUAL_INT(-1, demo_ppm_write("no_such_folder_here/x.ppm", rgb, 1, 1));
}

static void test_frame_names_sort_in_order(void)
{
    char buf[32];
    TEST_ASSERT_EQUAL_INT(0, demo_frame_path(buf, sizeof buf, "out", 7));
    TEST_ASSERT_EQUAL_STRING("out/frame_0007.ppm", buf);
    TEST_ASSERT_EQUAL_INT(0, demo_frame_path(buf, sizeof buf, "out", 12345));
    TEST_ASSERT_EQUAL_STRING("out/frame_12345.ppm", buf);
    /* "out/frame_0007.ppm" needs 19 bytes with its NUL */
    TEST_ASSERT_EQUAL_INT(-1, demo_frame_path(buf, 18, "out", 7));
    TEST_ASSERT_EQUAL_INT(0, demo_frame_path(buf, 19, "out", 7));
}

static void test_prng_is_splitmix64(void)
{
    demo_rng a, b;
    int i, differ = 0;
    /* SplitMix64 from state 0: the published first output is 0xe220a8397b1dcdaf */
    demo_rng_seed(&a, 0);
    TEST_ASSERT_EQUAL_UINT64(UINT64_C(0xe220a8397b1dcdaf), demo_rng_next(&a));
    /* the same seed repeats the sequence; another seed does not */
    demo_rng_seed(&a, 42);
    demo_rng_seed(&b, 42);
    for (i = 0; i < 100; ++i)
        TEST_ASSERT_EQUAL_UINT64(demo_rng_next(&a), demo_rng_next(&b));
    demo_rng_seed(&b, 43);
    for (i = 0; i < 100; ++i)
        differ += demo_rng_next(&a) != demo_rng_next(&b);
    TEST_ASSERT_EQUAL_INT(100, differ);
}

static void test_prng_units_and_directions(void)
{
    demo_rng r;
    int i;
    double mean = 0.0;
    demo_rng_seed(&r, 7);
    for (i = 0; i < 10000; ++i) {
        double u = demo_rng_unit(&r), x, y;
        TEST_ASSERT_TRUE(u >= 0.0 && u < 1.0);
        mean += u / 10000.0;
        demo_rng_direction(&r, &x, &y);
        TEST_ASSERT_DOUBLE_WITHIN(1e-15, 1.0, x * x + y * y); /* a few ulps */
    }
    /* the mean of 10000 uniform numbers: 0.5 with standard deviation 1 / sqrt(12 * 10000) =
       0.0029; 0.01 is more than three of them */
    TEST_ASSERT_DOUBLE_WITHIN(0.01, 0.5, mean);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_header_is_p6_width_height_255);
    RUN_TEST(test_file_is_header_then_rows_of_rgb);
    RUN_TEST(test_write_into_a_missing_folder_fails);
    RUN_TEST(test_frame_names_sort_in_order);
    RUN_TEST(test_prng_is_splitmix64);
    RUN_TEST(test_prng_units_and_directions);
    return UNITY_END();
}
