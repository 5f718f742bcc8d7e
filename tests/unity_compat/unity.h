/* Our test runner for the subset of ThrowTheSwitch Unity's API that the tests use.
 *
 * Same macro names, argument order and semantics as Unity (built with UNITY_INCLUDE_DOUBLE and
 * UNITY_SUPPORT_64), so that every test also builds against the real src/unity.c
 * (-DCC_UNITY_DIR=...). Kept to exactly that subset on purpose: a test that needs more must
 * work with both runners. Behaviour that matters and is copied from Unity's documentation:
 *   - a failing assertion ends the current test at once (setjmp/longjmp), tearDown still runs;
 *   - EQUAL_FLOAT / EQUAL_DOUBLE pass within |expected| * 1e-5f / |expected| * 1e-12 (so an
 *     expected 0 must match exactly), infinities of the same sign are equal, NaN equals NaN;
 *   - output lines are `file:line:test:PASS`, `file:line:test:FAIL: detail`,
 *     `file:line:test:IGNORE: message`, then a summary `N Tests N Failures N Ignored` and
 *     `OK` or `FAIL`; UNITY_END() returns the number of failures (main returns it). */
#ifndef CC_UNITY_COMPAT_H
#define CC_UNITY_COMPAT_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Unity's tolerances for the EQUAL_FLOAT / EQUAL_DOUBLE shorthands. */
#ifndef UNITY_FLOAT_PRECISION
#define UNITY_FLOAT_PRECISION (0.00001f)
#endif
#ifndef UNITY_DOUBLE_PRECISION
#define UNITY_DOUBLE_PRECISION (1e-12)
#endif

/* Each test file defines both (they may be empty). */
void setUp(void);
void tearDown(void);

typedef void (*UnityTestFunction)(void);

void UnityBegin(const char *filename);
int UnityEnd(void);
void UnityDefaultTestRun(UnityTestFunction func, const char *name, int line);

/* Like Unity, failing and ignoring never return (they jump out of the test): the compiler may
 * rely on a TEST_ASSERT's condition holding after it, as it does with the real Unity. */
#if defined(__GNUC__) || defined(__clang__)
#define CC_UNITY_NORETURN __attribute__((__noreturn__))
#else
#define CC_UNITY_NORETURN
#endif
CC_UNITY_NORETURN void UnityFail(const char *msg, int line);
CC_UNITY_NORETURN void UnityIgnore(const char *msg, int line);
void UnityMessage(const char *msg, int line);
void UnityAssertEqualIntNumber(long long expected, long long actual, const char *msg, int line,
                               int is_unsigned);
void UnityAssertFloatsWithin(float delta, float expected, float actual, const char *msg, int line);
void UnityAssertDoublesWithin(double delta, double expected, double actual, const char *msg,
                              int line);
void UnityAssertEqualMemory(const void *expected, const void *actual, unsigned long len,
                            const char *msg, int line);
void UnityAssertEqualString(const char *expected, const char *actual, const char *msg, int line);

#define UNITY_BEGIN() UnityBegin(__FILE__)
#define UNITY_END() UnityEnd()
#define RUN_TEST(func) UnityDefaultTestRun(func, #func, __LINE__)

#define TEST_FAIL_MESSAGE(message) UnityFail((message), __LINE__)
#define TEST_IGNORE_MESSAGE(message) UnityIgnore((message), __LINE__)
#define TEST_MESSAGE(message) UnityMessage((message), __LINE__)

#define CC_UNITY_ASSERT(condition, line, message)                                                  \
    do {                                                                                           \
        if (condition) {                                                                           \
        } else {                                                                                   \
            UnityFail((message), (line));                                                          \
        }                                                                                          \
    } while (0)

/* The default detail texts are Unity's own. */
#define TEST_ASSERT_MESSAGE(condition, message) CC_UNITY_ASSERT((condition), __LINE__, (message))
#define TEST_ASSERT(condition) TEST_ASSERT_MESSAGE((condition), " Expression Evaluated To FALSE")
#define TEST_ASSERT_TRUE_MESSAGE(condition, message) TEST_ASSERT_MESSAGE((condition), (message))
#define TEST_ASSERT_TRUE(condition) TEST_ASSERT_MESSAGE((condition), " Expected TRUE Was FALSE")
#define TEST_ASSERT_FALSE_MESSAGE(condition, message) TEST_ASSERT_MESSAGE(!(condition), (message))
#define TEST_ASSERT_FALSE(condition) TEST_ASSERT_MESSAGE(!(condition), " Expected FALSE Was TRUE")
#define TEST_ASSERT_NULL_MESSAGE(pointer, message) TEST_ASSERT_MESSAGE(((pointer) == NULL), (message))
#define TEST_ASSERT_NULL(pointer) TEST_ASSERT_MESSAGE(((pointer) == NULL), " Expected NULL")
#define TEST_ASSERT_NOT_NULL_MESSAGE(pointer, message)                                             \
    TEST_ASSERT_MESSAGE(((pointer) != NULL), (message))
#define TEST_ASSERT_NOT_NULL(pointer) TEST_ASSERT_MESSAGE(((pointer) != NULL), " Expected Non-NULL")

/* Integers compare as 64-bit values, as Unity does with UNITY_SUPPORT_64. */
#define TEST_ASSERT_EQUAL_INT_MESSAGE(expected, actual, message)                                   \
    UnityAssertEqualIntNumber((long long)(expected), (long long)(actual), (message), __LINE__, 0)
#define TEST_ASSERT_EQUAL_INT(expected, actual) TEST_ASSERT_EQUAL_INT_MESSAGE(expected, actual, NULL)
#define TEST_ASSERT_EQUAL_UINT64_MESSAGE(expected, actual, message)                                \
    UnityAssertEqualIntNumber((long long)(expected), (long long)(actual), (message), __LINE__, 1)
#define TEST_ASSERT_EQUAL_UINT64(expected, actual)                                                 \
    TEST_ASSERT_EQUAL_UINT64_MESSAGE(expected, actual, NULL)

#define TEST_ASSERT_FLOAT_WITHIN_MESSAGE(delta, expected, actual, message)                         \
    UnityAssertFloatsWithin((float)(delta), (float)(expected), (float)(actual), (message), __LINE__)
#define TEST_ASSERT_FLOAT_WITHIN(delta, expected, actual)                                          \
    TEST_ASSERT_FLOAT_WITHIN_MESSAGE(delta, expected, actual, NULL)
#define TEST_ASSERT_EQUAL_FLOAT_MESSAGE(expected, actual, message)                                 \
    TEST_ASSERT_FLOAT_WITHIN_MESSAGE((float)(expected) * (float)UNITY_FLOAT_PRECISION, expected,    \
                                     actual, message)
#define TEST_ASSERT_EQUAL_FLOAT(expected, actual)                                                  \
    TEST_ASSERT_EQUAL_FLOAT_MESSAGE(expected, actual, NULL)

#define TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(delta, expected, actual, message)                        \
    UnityAssertDoublesWithin((double)(delta), (double)(expected), (double)(actual), (message),      \
                             __LINE__)
#define TEST_ASSERT_DOUBLE_WITHIN(delta, expected, actual)                                         \
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(delta, expected, actual, NULL)
#define TEST_ASSERT_EQUAL_DOUBLE_MESSAGE(expected, actual, message)                                \
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE((double)(expected) * (double)UNITY_DOUBLE_PRECISION,         \
                                      expected, actual, message)
#define TEST_ASSERT_EQUAL_DOUBLE(expected, actual)                                                 \
    TEST_ASSERT_EQUAL_DOUBLE_MESSAGE(expected, actual, NULL)

#define TEST_ASSERT_EQUAL_MEMORY_MESSAGE(expected, actual, len, message)                           \
    UnityAssertEqualMemory((const void *)(expected), (const void *)(actual),                       \
                           (unsigned long)(len), (message), __LINE__)
#define TEST_ASSERT_EQUAL_MEMORY(expected, actual, len)                                            \
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(expected, actual, len, NULL)
#define TEST_ASSERT_EQUAL_STRING_MESSAGE(expected, actual, message)                                \
    UnityAssertEqualString((const char *)(expected), (const char *)(actual), (message), __LINE__)
#define TEST_ASSERT_EQUAL_STRING(expected, actual)                                                 \
    TEST_ASSERT_EQUAL_STRING_MESSAGE(expected, actual, NULL)

#ifdef __cplusplus
}
#endif

#endif /* CC_UNITY_COMPAT_H */
