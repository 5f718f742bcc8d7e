/* cc_version, cc_version_string and cc_result_string: the loaded library agrees with the header
 * it was built from, and every result code has its own name. */
#include <stdio.h>
#include <string.h>

#include "circlecollide.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

/* (MAJOR << 16) | (MINOR << 8) | PATCH, as CC_VERSION; the major is the ABI (SONAME). */
static void test_version_number(void)
{
    unsigned v = cc_version();
    TEST_ASSERT_EQUAL_INT(CC_VERSION, (int)v);
    TEST_ASSERT_EQUAL_INT(CC_VERSION_MAJOR, (int)(v >> 16));
    TEST_ASSERT_EQUAL_INT(CC_VERSION_MINOR, (int)((v >> 8) & 0xFF));
    TEST_ASSERT_EQUAL_INT(CC_VERSION_PATCH, (int)(v & 0xFF));
}

/* "MAJOR.MINOR.PATCH" spelled from the header's numbers; the same static string each call. */
static void test_version_string(void)
{
    char expected[32];
    sprintf(expected, "%d.%d.%d", CC_VERSION_MAJOR, CC_VERSION_MINOR, CC_VERSION_PATCH);
    TEST_ASSERT_EQUAL_STRING(expected, cc_version_string());
    TEST_ASSERT_TRUE(cc_version_string() == cc_version_string());
}

/* Each code's name starts with its macro's name; codes are distinct; unknown codes get
 * "unknown result code". 0 is both CC_OK and CC_MISS: its text names both and says what it
 * means for each, an action's success first (a step's "no contact" read as a failure). */
static void test_result_strings(void)
{
    static const int codes[] = {CC_HIT,         CC_OVERLAP,  CC_EVENT_LIMIT, CC_ERR_INVALID, CC_ERR_NOT_FOUND,
                                CC_ERR_FULL,    CC_ERR_MEMORY, CC_ERR_VERSION, CC_ERR_RANGE, CC_ERR_BUSY};
    static const char *const names[] = {"CC_HIT",        "CC_OVERLAP",    "CC_EVENT_LIMIT", "CC_ERR_INVALID",
                                        "CC_ERR_NOT_FOUND", "CC_ERR_FULL", "CC_ERR_MEMORY",  "CC_ERR_VERSION",
                                        "CC_ERR_RANGE",  "CC_ERR_BUSY"};
    const char *zero = cc_result_string(0);
    size_t i, j, n = sizeof codes / sizeof codes[0];
    for (i = 0; i < n; i++) {
        const char *s = cc_result_string(codes[i]);
        TEST_ASSERT_NOT_NULL(s);
        TEST_ASSERT_EQUAL_INT_MESSAGE(0, strncmp(s, names[i], strlen(names[i])), names[i]);
        TEST_ASSERT_TRUE(s[strlen(names[i])] == ':');
        TEST_ASSERT_TRUE(codes[i] != 0);
        for (j = 0; j < i; j++)
            TEST_ASSERT_TRUE(codes[i] != codes[j]);
    }
    TEST_ASSERT_TRUE(CC_OK == CC_MISS);
    TEST_ASSERT_EQUAL_INT(0, strncmp(zero, "CC_OK / CC_MISS (0):", strlen("CC_OK / CC_MISS (0):")));
    TEST_ASSERT_NOT_NULL(strstr(zero, "an action succeeded"));
    TEST_ASSERT_NOT_NULL(strstr(zero, "no contact"));
    TEST_ASSERT_TRUE(strstr(zero, "an action succeeded") < strstr(zero, "no contact"));
    /* the 1.2 codes follow 1.1's, each a new value */
    TEST_ASSERT_EQUAL_INT(-6, CC_ERR_RANGE);
    TEST_ASSERT_EQUAL_INT(-7, CC_ERR_BUSY);
    TEST_ASSERT_EQUAL_STRING("unknown result code", cc_result_string(4));
    TEST_ASSERT_EQUAL_STRING("unknown result code", cc_result_string(-8));
    TEST_ASSERT_EQUAL_STRING("unknown result code", cc_result_string(12345));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_version_number);
    RUN_TEST(test_version_string);
    RUN_TEST(test_result_strings);
    return UNITY_END();
}
