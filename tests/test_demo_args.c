/* cc_demo's command line: defaults, every accepted form, and every way to get it wrong (each must
 * be refused with a reason that names the option). */
#include "unity.h"

#include "args.h"

#include <circlecollide.h>
#include <stdarg.h>
#include <stdint.h>
#include <string.h>

#define END ((const char *)0) /* ends an argument list (a bare NULL may be an int) */

static demo_options o;
static char err[256];

void setUp(void)
{
    memset(&o, 0, sizeof o);
    err[0] = '\0';
}

void tearDown(void)
{
}

/* Parses a NULL-terminated list of arguments (argv[0] added). */
static int parse(const char *a0, ...)
{
    char *argv[32];
    int argc = 0;
    const char *a;
    va_list ap;
    argv[argc++] = (char *)"cc_demo";
    va_start(ap, a0);
    for (a = a0; a != NULL && argc < 31; a = va_arg(ap, const char *))
        argv[argc++] = (char *)a;
    va_end(ap);
    argv[argc] = NULL;
    return demo_parse_args(argc, argv, &o, err, sizeof err);
}

/* The parse fails and the reason mentions what. */
static void refused(int r, const char *what)
{
    TEST_ASSERT_EQUAL_INT(DEMO_ARGS_ERROR, r);
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(err, what), err);
}

static void test_minimal_command_takes_the_defaults(void)
{
    TEST_ASSERT_EQUAL_INT(DEMO_ARGS_RUN, parse("--scene", "pool", "--frames", "3", "--out", "d", END));
    TEST_ASSERT_EQUAL_STRING("pool", o.scene);
    TEST_ASSERT_EQUAL_STRING("d", o.out);
    TEST_ASSERT_EQUAL_INT(3, (int)o.frames);
    TEST_ASSERT_EQUAL_INT(640, o.width);
    TEST_ASSERT_EQUAL_INT(360, o.height);
    TEST_ASSERT_EQUAL_DOUBLE(60.0, o.fps);
    TEST_ASSERT_EQUAL_INT(CC_MODE_EXACT, o.mode);
    TEST_ASSERT_EQUAL_UINT64(1, o.seed);
    TEST_ASSERT_EQUAL_STRING("", err);
}

static void test_every_option_is_read(void)
{
    TEST_ASSERT_EQUAL_INT(DEMO_ARGS_RUN,
                          parse("--out", "x/y", "--size", "160x90", "--fps", "29.97", "--mode",
                                "discrete", "--seed", "18446744073709551615", "--scene", "gas",
                                "--frames", "1000000", END));
    TEST_ASSERT_EQUAL_STRING("gas", o.scene);
    TEST_ASSERT_EQUAL_INT(160, o.width);
    TEST_ASSERT_EQUAL_INT(90, o.height);
    TEST_ASSERT_EQUAL_DOUBLE(29.97, o.fps);
    TEST_ASSERT_EQUAL_INT(CC_MODE_DISCRETE, o.mode);
    TEST_ASSERT_EQUAL_UINT64(UINT64_C(18446744073709551615), o.seed); /* 2^64 - 1 */
    TEST_ASSERT_EQUAL_INT(1000000, (int)o.frames);
    TEST_ASSERT_EQUAL_INT(DEMO_ARGS_RUN, parse("--scene", "tunnel", "--frames", "1", "--out", "d",
                                               "--mode", "swept", "--size", "16x8192", END));
    TEST_ASSERT_EQUAL_INT(CC_MODE_SWEPT, o.mode);
    TEST_ASSERT_EQUAL_INT(8192, o.height);
}

static void test_every_scene_name_is_known(void)
{
    const char *names[6] = {"pool", "air-hockey", "cradle", "gas", "tunnel", "hard-disks"};
    int i;
    for (i = 0; i < 6; ++i)
        TEST_ASSERT_EQUAL_INT(DEMO_ARGS_RUN,
                              parse("--scene", names[i], "--frames", "1", "--out", "d", END));
}

static void test_help_wins(void)
{
    TEST_ASSERT_EQUAL_INT(DEMO_ARGS_HELP, parse("--help", END));
    TEST_ASSERT_EQUAL_INT(DEMO_ARGS_HELP, parse("--scene", "pool", "-h", END));
}

static void test_missing_required_options(void)
{
    refused(parse(END), "missing --scene");
    refused(parse("--frames", "1", "--out", "d", END), "missing --scene");
    refused(parse("--scene", "pool", "--out", "d", END), "missing --frames");
    refused(parse("--scene", "pool", "--frames", "2", END), "missing --out");
}

static void test_unknown_options_and_stray_words(void)
{
    refused(parse("--scene", "pool", "--frames", "1", "--out", "d", "--colour", "red", END),
            "unknown option '--colour'");
    refused(parse("pool", END), "unexpected argument 'pool'");
    refused(parse("-s", "pool", END), "unexpected argument '-s'");
}

static void test_options_without_values(void)
{
    refused(parse("--scene", END), "--scene needs a value");
    refused(parse("--scene", "pool", "--frames", "1", "--out", END), "--out needs a value");
    refused(parse("--scene", "pool", "--seed", END), "--seed needs a value");
}

static void test_bad_scene(void)
{
    refused(parse("--scene", "snooker", END), "unknown scene 'snooker'");
    refused(parse("--scene", "", END), "unknown scene ''");
    refused(parse("--scene", "POOL", END), "unknown scene 'POOL'");
}

static void test_bad_frames(void)
{
    refused(parse("--frames", "0", END), "--frames");
    refused(parse("--frames", "-3", END), "--frames");
    refused(parse("--frames", "ten", END), "--frames");
    refused(parse("--frames", "10x", END), "--frames");
    refused(parse("--frames", "", END), "--frames");
    refused(parse("--frames", "1000001", END), "--frames");
    refused(parse("--frames", "99999999999999999999999", END), "--frames");
}

static void test_bad_size(void)
{
    refused(parse("--size", "640", END), "--size");
    refused(parse("--size", "x360", END), "--size");
    refused(parse("--size", "640x", END), "--size");
    refused(parse("--size", "8x8", END), "--size");         /* below 16 */
    refused(parse("--size", "640x8193", END), "--size");    /* above 8192 */
    refused(parse("--size", "640x360x2", END), "--size");
    refused(parse("--size", "-640x360", END), "--size");
    refused(parse("--size", "640X360", END), "--size");
    refused(parse("--size", "640 x 360", END), "--size");
}

static void test_bad_fps(void)
{
    refused(parse("--fps", "0", END), "--fps");
    refused(parse("--fps", "-30", END), "--fps");
    refused(parse("--fps", "fast", END), "--fps");
    refused(parse("--fps", "nan", END), "--fps");
    refused(parse("--fps", "inf", END), "--fps");
    refused(parse("--fps", "1001", END), "--fps");
    refused(parse("--fps", "30fps", END), "--fps");
    refused(parse("--fps", "1e999", END), "--fps");
}

static void test_bad_mode(void)
{
    refused(parse("--mode", "EXACT", END), "--mode wants exact, swept or discrete");
    refused(parse("--mode", "continuous", END), "--mode");
    refused(parse("--mode", "", END), "--mode");
}

static void test_bad_seed(void)
{
    refused(parse("--seed", "-1", END), "--seed");
    refused(parse("--seed", "one", END), "--seed");
    refused(parse("--seed", "12abc", END), "--seed");
    refused(parse("--seed", "18446744073709551616", END), "--seed"); /* 2^64 */
}

static void test_bad_out(void)
{
    refused(parse("--scene", "pool", "--frames", "1", "--out", "", END), "--out");
}

static void test_error_text_fits_a_small_buffer(void)
{
    char small[8];
    char *argv[3] = {(char *)"cc_demo", (char *)"--bogus", NULL};
    TEST_ASSERT_EQUAL_INT(DEMO_ARGS_ERROR, demo_parse_args(2, argv, &o, small, sizeof small));
    TEST_ASSERT_EQUAL_INT(7, (int)strlen(small)); /* cut, and NUL-terminated */
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_minimal_command_takes_the_defaults);
    RUN_TEST(test_every_option_is_read);
    RUN_TEST(test_every_scene_name_is_known);
    RUN_TEST(test_help_wins);
    RUN_TEST(test_missing_required_options);
    RUN_TEST(test_unknown_options_and_stray_words);
    RUN_TEST(test_options_without_values);
    RUN_TEST(test_bad_scene);
    RUN_TEST(test_bad_frames);
    RUN_TEST(test_bad_size);
    RUN_TEST(test_bad_fps);
    RUN_TEST(test_bad_mode);
    RUN_TEST(test_bad_seed);
    RUN_TEST(test_bad_out);
    RUN_TEST(test_error_text_fits_a_small_buffer);
    return UNITY_END();
}
