/* Our implementation of the Unity API subset declared in unity.h: runs tests, checks
 * assertions with Unity's rules and prints Unity's report format. */
#include "unity.h"

#include <math.h>
#include <setjmp.h>
#include <stdio.h>

static struct {
    const char *file;      /* the test file, as given to UNITY_BEGIN (__FILE__), as Unity does */
    const char *test_name; /* the running test */
    int test_line;         /* line of its RUN_TEST */
    unsigned long tests, failures, ignores;
    int failed, ignored; /* state of the running test */
    jmp_buf abort_frame; /* where a failing assertion jumps to end the test */
} unity;

static void results_begin(int line)
{
    printf("%s:%d:%s:", unity.file, line, unity.test_name ? unity.test_name : "");
}

/* Like Unity: "FAIL:" then the assertion's detail, then ":message" when there is one. */
static void fail_begin(int line)
{
    results_begin(line);
    fputs("FAIL:", stdout);
}

static void add_message(const char *msg)
{
    if (msg) {
        putchar(':');
        fputs(msg, stdout);
    }
}

CC_UNITY_NORETURN static void fail_and_bail(void)
{
    unity.failed = 1;
    fflush(stdout);
    longjmp(unity.abort_frame, 1);
}

/* A test that already failed or was ignored stops at its next assertion too (tearDown). */
static void return_if_fail_or_ignore(void)
{
    if (unity.failed || unity.ignored)
        longjmp(unity.abort_frame, 1);
}

static void print_double(double x, int digits)
{
    if (isnan(x))
        fputs("NaN", stdout);
    else if (isinf(x))
        fputs(x > 0 ? "Infinity" : "Negative Infinity", stdout);
    else
        printf("%.*g", digits, x);
}

void UnityBegin(const char *filename)
{
    unity.file = filename;
    unity.test_name = NULL;
    unity.test_line = 0;
    unity.tests = unity.failures = unity.ignores = 0;
    unity.failed = unity.ignored = 0;
}

int UnityEnd(void)
{
    printf("\n-----------------------\n%lu Tests %lu Failures %lu Ignored \n%s\n", unity.tests,
           unity.failures, unity.ignores, unity.failures == 0 ? "OK" : "FAIL");
    fflush(stdout);
    return (int)unity.failures;
}

void UnityDefaultTestRun(UnityTestFunction func, const char *name, int line)
{
    unity.test_name = name;
    unity.test_line = line;
    unity.tests++;
    if (setjmp(unity.abort_frame) == 0) {
        setUp();
        func();
    }
    if (setjmp(unity.abort_frame) == 0)
        tearDown();
    if (unity.ignored) {
        unity.ignores++;
    } else if (!unity.failed) {
        results_begin(unity.test_line);
        fputs("PASS", stdout);
    } else {
        unity.failures++;
    }
    unity.failed = unity.ignored = 0;
    putchar('\n');
    fflush(stdout);
}

void UnityFail(const char *msg, int line)
{
    return_if_fail_or_ignore();
    results_begin(line);
    fputs("FAIL", stdout);
    add_message(msg);
    fail_and_bail();
}

void UnityIgnore(const char *msg, int line)
{
    return_if_fail_or_ignore();
    results_begin(line);
    fputs("IGNORE", stdout);
    if (msg)
        printf(": %s", msg);
    unity.ignored = 1;
    fflush(stdout);
    longjmp(unity.abort_frame, 1);
}

void UnityMessage(const char *msg, int line)
{
    results_begin(line);
    fputs("INFO", stdout);
    if (msg)
        printf(": %s", msg);
    putchar('\n');
}

void UnityAssertEqualIntNumber(long long expected, long long actual, const char *msg, int line,
                               int is_unsigned)
{
    return_if_fail_or_ignore();
    if (expected == actual)
        return;
    fail_begin(line);
    if (is_unsigned)
        printf(" Expected %llu Was %llu", (unsigned long long)expected, (unsigned long long)actual);
    else
        printf(" Expected %lld Was %lld", expected, actual);
    add_message(msg);
    fail_and_bail();
}

/* Unity's rule (UNITY_FLOAT_OR_DOUBLE_WITHIN), computed in the assertion's own precision:
 * equal infinities and two NaNs pass; otherwise |actual - expected| <= |delta|, and a NaN or
 * infinite difference fails. */
static int floats_within(float delta, float expected, float actual)
{
    float diff;
    if (isinf(expected) && isinf(actual) && ((expected < 0) == (actual < 0)))
        return 1;
    if (isnan(expected) && isnan(actual))
        return 1;
    diff = actual - expected;
    if (diff < 0)
        diff = -diff;
    if (delta < 0)
        delta = -delta;
    return !(isnan(diff) || isinf(diff) || diff > delta);
}

static int doubles_within(double delta, double expected, double actual)
{
    double diff;
    if (isinf(expected) && isinf(actual) && ((expected < 0) == (actual < 0)))
        return 1;
    if (isnan(expected) && isnan(actual))
        return 1;
    diff = actual - expected;
    if (diff < 0)
        diff = -diff;
    if (delta < 0)
        delta = -delta;
    return !(isnan(diff) || isinf(diff) || diff > delta);
}

void UnityAssertFloatsWithin(float delta, float expected, float actual, const char *msg, int line)
{
    return_if_fail_or_ignore();
    if (floats_within(delta, expected, actual))
        return;
    fail_begin(line);
    fputs(" Expected ", stdout);
    print_double((double)expected, 9);
    fputs(" Was ", stdout);
    print_double((double)actual, 9);
    add_message(msg);
    fail_and_bail();
}

void UnityAssertDoublesWithin(double delta, double expected, double actual, const char *msg,
                              int line)
{
    return_if_fail_or_ignore();
    if (doubles_within(delta, expected, actual))
        return;
    fail_begin(line);
    fputs(" Expected ", stdout);
    print_double(expected, 17);
    fputs(" Was ", stdout);
    print_double(actual, 17);
    add_message(msg);
    fail_and_bail();
}

void UnityAssertEqualMemory(const void *expected, const void *actual, unsigned long len,
                            const char *msg, int line)
{
    const unsigned char *e = (const unsigned char *)expected;
    const unsigned char *a = (const unsigned char *)actual;
    unsigned long i;
    return_if_fail_or_ignore();
    if (len == 0) {
        fail_begin(line);
        fputs(" You Asked Me To Compare Nothing, Which Was Pointless.", stdout);
        add_message(msg);
        fail_and_bail();
    }
    if (expected == actual)
        return; /* both NULL or the same memory */
    if (expected == NULL || actual == NULL) {
        fail_begin(line);
        fputs(expected == NULL ? " Expected pointer to be NULL" : " Actual pointer was NULL",
              stdout);
        add_message(msg);
        fail_and_bail();
    }
    for (i = 0; i < len; i++) {
        if (e[i] != a[i]) {
            fail_begin(line);
            printf(" Memory Mismatch. Byte %lu Expected 0x%02X Was 0x%02X", i, (unsigned)e[i],
                   (unsigned)a[i]);
            add_message(msg);
            fail_and_bail();
        }
    }
}

void UnityAssertEqualString(const char *expected, const char *actual, const char *msg, int line)
{
    size_t i;
    int differ = 0;
    return_if_fail_or_ignore();
    if (expected && actual) {
        for (i = 0; expected[i] || actual[i]; i++) {
            if (expected[i] != actual[i]) {
                differ = 1;
                break;
            }
        }
    } else {
        differ = (expected || actual); /* one NULL fails, both NULL pass */
    }
    if (!differ)
        return;
    fail_begin(line);
    fputs(" Expected ", stdout);
    if (expected)
        printf("'%s'", expected);
    else
        fputs("NULL", stdout);
    fputs(" Was ", stdout);
    if (actual)
        printf("'%s'", actual);
    else
        fputs("NULL", stdout);
    add_message(msg);
    fail_and_bail();
}
