/* Checks the test runner itself: every assertion of the Unity subset on a value that must pass
 * and on one that must fail. Test names say the expected outcome (pass_*, fail_*, ignore_*);
 * check_selftest.cmake runs this program and verifies each reported outcome, the summary and the
 * exit code. The same file runs against the real Unity (-DCC_UNITY_DIR), which is how we know our
 * runner agrees with it. */
#include "unity.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

static int set_ups, tear_downs, ran_past_failure;

void setUp(void)
{
    set_ups++;
}

void tearDown(void)
{
    tear_downs++;
}

/* --- boolean, pointer and integer assertions ------------------------------------------------ */
static void pass_bool_and_pointers(void)
{
    int x = 0;
    TEST_ASSERT(1 + 1 == 2);
    TEST_ASSERT_TRUE(2 > 1);
    TEST_ASSERT_FALSE(2 < 1);
    TEST_ASSERT_NULL(NULL);
    TEST_ASSERT_NOT_NULL(&x);
    TEST_ASSERT_MESSAGE(1, "unused");
    TEST_ASSERT_TRUE_MESSAGE(1, "unused");
    TEST_ASSERT_FALSE_MESSAGE(0, "unused");
    TEST_ASSERT_NULL_MESSAGE(NULL, "unused");
    TEST_ASSERT_NOT_NULL_MESSAGE(&x, "unused");
}
static void fail_assert(void) { TEST_ASSERT(0); }
static void fail_assert_true(void) { TEST_ASSERT_TRUE(0); }
static void fail_assert_false(void) { TEST_ASSERT_FALSE(1); }
static void fail_null(void)
{
    int x = 0;
    TEST_ASSERT_NULL(&x);
}
static void fail_not_null(void) { TEST_ASSERT_NOT_NULL(NULL); }

static void pass_integers(void)
{
    TEST_ASSERT_EQUAL_INT(-3, 1 - 4);
    TEST_ASSERT_EQUAL_INT_MESSAGE(7, 7L, "unused");
    /* 2^63 + 1 does not fit in an int: the comparison is on 64 bits */
    TEST_ASSERT_EQUAL_UINT64(UINT64_C(9223372036854775809), UINT64_C(9223372036854775808) + 1u);
    TEST_ASSERT_EQUAL_UINT64_MESSAGE(0u, 0u, "unused");
}
static void fail_int(void) { TEST_ASSERT_EQUAL_INT(1, 2); }
/* 2^32 differs from 0 only above bit 31: a 32-bit comparison would miss it */
static void fail_uint64_high_bits(void) { TEST_ASSERT_EQUAL_UINT64(UINT64_C(4294967296), 0u); }

/* --- floating point: Unity's default tolerances -------------------------------------------- */
static void pass_double_tolerance(void)
{
    /* EQUAL_DOUBLE allows |expected| * 1e-12: 1 + 5e-13 is within, and so is 1e6 + 5e-7 */
    TEST_ASSERT_EQUAL_DOUBLE(1.0, 1.0 + 5e-13);
    TEST_ASSERT_EQUAL_DOUBLE(1e6, 1e6 + 5e-7);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, 0.0);
    TEST_ASSERT_EQUAL_DOUBLE(INFINITY, INFINITY);
    TEST_ASSERT_EQUAL_DOUBLE(-INFINITY, -INFINITY);
    TEST_ASSERT_EQUAL_DOUBLE(NAN, NAN); /* Unity treats two NaNs as equal */
    TEST_ASSERT_DOUBLE_WITHIN(0.5, 10.0, 10.4);
    TEST_ASSERT_DOUBLE_WITHIN(-0.5, 10.0, 9.6); /* a negative delta counts as its magnitude */
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-3, 2.0, 2.0005, "unused");
    TEST_ASSERT_EQUAL_DOUBLE_MESSAGE(-2.5, -2.5, "unused");
}
/* 1 + 2e-12 is outside 1 * 1e-12 */
static void fail_double_relative(void) { TEST_ASSERT_EQUAL_DOUBLE(1.0, 1.0 + 2e-12); }
/* expected 0 gives delta 0: any non-zero value fails, however tiny */
static void fail_double_zero_exact(void) { TEST_ASSERT_EQUAL_DOUBLE(0.0, 1e-300); }
static void fail_double_inf_sign(void) { TEST_ASSERT_EQUAL_DOUBLE(INFINITY, -INFINITY); }
static void fail_double_nan_vs_number(void) { TEST_ASSERT_EQUAL_DOUBLE(1.0, NAN); }
static void fail_double_within(void) { TEST_ASSERT_DOUBLE_WITHIN(0.5, 10.0, 10.6); }

static void pass_float_tolerance(void)
{
    /* EQUAL_FLOAT allows |expected| * 1e-5: 1 + 5e-6 is within */
    TEST_ASSERT_EQUAL_FLOAT(1.0f, 1.000005f);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, 0.0f);
    TEST_ASSERT_EQUAL_FLOAT(-INFINITY, -INFINITY);
    TEST_ASSERT_FLOAT_WITHIN(0.25f, 3.0f, 3.2f);
    TEST_ASSERT_FLOAT_WITHIN_MESSAGE(0.25f, 3.0f, 2.8f, "unused");
    TEST_ASSERT_EQUAL_FLOAT_MESSAGE(4.0f, 4.0f, "unused");
}
/* 1 + 2e-5 is outside 1 * 1e-5 */
static void fail_float_relative(void) { TEST_ASSERT_EQUAL_FLOAT(1.0f, 1.00002f); }
static void fail_float_within(void) { TEST_ASSERT_FLOAT_WITHIN(0.25f, 3.0f, 3.3f); }

/* --- memory and strings -------------------------------------------------------------------- */
static void pass_memory_and_strings(void)
{
    const unsigned char a[4] = {1, 2, 3, 4}, b[4] = {1, 2, 3, 4};
    TEST_ASSERT_EQUAL_MEMORY(a, b, sizeof a);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(a, b, 2, "unused");
    TEST_ASSERT_EQUAL_STRING("abc", "abc");
    TEST_ASSERT_EQUAL_STRING(NULL, NULL);
    TEST_ASSERT_EQUAL_STRING_MESSAGE("", "", "unused");
}
static void fail_memory_last_byte(void)
{
    const unsigned char a[4] = {1, 2, 3, 4}, b[4] = {1, 2, 3, 5};
    TEST_ASSERT_EQUAL_MEMORY(a, b, sizeof a);
}
static void fail_memory_null(void)
{
    const unsigned char a[1] = {1};
    TEST_ASSERT_EQUAL_MEMORY(a, NULL, 1);
}
static void fail_memory_zero_length(void)
{
    const unsigned char a[1] = {1};
    TEST_ASSERT_EQUAL_MEMORY(a, a, 0); /* Unity calls comparing nothing a failure */
}
static void fail_string(void) { TEST_ASSERT_EQUAL_STRING("abc", "abd"); }
static void fail_string_prefix(void) { TEST_ASSERT_EQUAL_STRING("abc", "ab"); }
static void fail_string_null(void) { TEST_ASSERT_EQUAL_STRING("abc", NULL); }

/* --- control flow -------------------------------------------------------------------------- */
static void fail_message(void) { TEST_FAIL_MESSAGE("a failure on purpose"); }
static void fail_with_message(void) { TEST_ASSERT_EQUAL_INT_MESSAGE(1, 2, "a detail"); }
static void ignore_message(void)
{
    TEST_IGNORE_MESSAGE("an ignored test on purpose");
    ran_past_failure = 1; /* never reached: ignoring ends the test */
}
/* A failing assertion ends the test at once: the line after it must not run. */
static void fail_stops_the_test(void)
{
    TEST_ASSERT_EQUAL_INT(0, 1);
    ran_past_failure = 1;
}
static void pass_message(void) { TEST_MESSAGE("an informational message"); }

/* Runs last: every earlier test got setUp and tearDown (also those that failed or were
 * ignored), and no statement after a failing assertion ran. */
static void pass_setup_teardown_and_bail_out(void)
{
    TEST_ASSERT_EQUAL_INT(0, ran_past_failure);
    TEST_ASSERT_EQUAL_INT(set_ups - 1, tear_downs);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(pass_bool_and_pointers);
    RUN_TEST(fail_assert);
    RUN_TEST(fail_assert_true);
    RUN_TEST(fail_assert_false);
    RUN_TEST(fail_null);
    RUN_TEST(fail_not_null);
    RUN_TEST(pass_integers);
    RUN_TEST(fail_int);
    RUN_TEST(fail_uint64_high_bits);
    RUN_TEST(pass_double_tolerance);
    RUN_TEST(fail_double_relative);
    RUN_TEST(fail_double_zero_exact);
    RUN_TEST(fail_double_inf_sign);
    RUN_TEST(fail_double_nan_vs_number);
    RUN_TEST(fail_double_within);
    RUN_TEST(pass_float_tolerance);
    RUN_TEST(fail_float_relative);
    RUN_TEST(fail_float_within);
    RUN_TEST(pass_memory_and_strings);
    RUN_TEST(fail_memory_last_byte);
    RUN_TEST(fail_memory_null);
    RUN_TEST(fail_memory_zero_length);
    RUN_TEST(fail_string);
    RUN_TEST(fail_string_prefix);
    RUN_TEST(fail_string_null);
    RUN_TEST(fail_message);
    RUN_TEST(fail_with_message);
    RUN_TEST(ignore_message);
    RUN_TEST(fail_stops_the_test);
    RUN_TEST(pass_message);
    RUN_TEST(pass_setup_teardown_and_bail_out);
    return UNITY_END();
}
