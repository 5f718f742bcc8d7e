/* The numerics targets of docs/NUMERICS.md, asserted on a smaller corpus (the report program
 * prints the full table): in every class of extreme cases -- the straight sweeps' and, since
 * issue 12, rolling to rest's (cc_sweep_rolling, cc_sweep_segment_rolling against the 320-bit
 * MPFR reference of reference_rolling.c) -- in double and in float,
 *   - no answer (miss / hit / overlap) differs from the exact one outside the rounding band
 *     (the band: answers that are exact for inputs moved by at most 4 ulps each), and
 *   - every contact time is within 4 condition-scaled ulps of the exact one
 *     (|t - t*| <= 4 eps cond, cond = (|dp| + |dv| t + R) / closing speed).
 * The reference is exact (GMP rationals for every decision, MPFR for t), so the expected
 * numbers are not hard-coded: they are computed, per case, from the same inputs. */
#include <stdio.h>

#include "accuracy.h"
#include "corpus.h"
#include "unity.h"

#define SEED 20261122u
#define CASES 2000u /* per class and precision: 60000 cases, a few seconds */

void setUp(void) {}
void tearDown(void) {}

static void check_precision(int is_float)
{
    int cls;
    char msg[160];
    for (cls = 0; cls < CORPUS_CLASSES; cls++) {
        acc_row row;
        acc_measure(SEED, cls, CASES, is_float, 0, &row);
        printf("%-20s %-6s timed %4ld  wrong %ld (in band %ld)  max err %.2f ulps  median %.2f  max rel %.1e  ties %ld\n",
               corpus_class_name(cls), is_float ? "float" : "double", row.ours.timed, row.ours.disagree,
               row.ours.in_band, row.ours.max_err, row.ours.med_err, row.ours.max_rel, row.ours.degenerate);
        snprintf(msg, sizeof msg, "%s (%s): first case answered wrongly, index %ld (numerics_report --show %d %ld%s)",
                 corpus_class_name(cls), is_float ? "float" : "double", row.ours.first_wrong, cls,
                 row.ours.first_wrong, is_float ? " --float" : "");
        TEST_ASSERT_EQUAL_INT_MESSAGE(0, (int)row.ours.disagree, msg);
        snprintf(msg, sizeof msg, "%s (%s): t error above target, index %ld (numerics_report --show %d %ld%s)",
                 corpus_class_name(cls), is_float ? "float" : "double", row.ours.worst, cls, row.ours.worst,
                 is_float ? " --float" : "");
        TEST_ASSERT_TRUE_MESSAGE(row.ours.max_err <= ACC_TARGET_ULPS, msg);
        /* the class must really have exercised contacts, or the t target was never tested */
        TEST_ASSERT_TRUE_MESSAGE(row.ours.timed >= (long)(CASES / 10), "class with too few contacts to measure");
        /* rolling classes: ties of the 320-bit reference (not judged) must stay rare */
        TEST_ASSERT_TRUE_MESSAGE(row.ours.degenerate <= (long)(CASES / 100), "too many reference ties");
    }
}

static void test_double_targets_in_every_class(void) { check_precision(0); }
static void test_float_targets_in_every_class(void) { check_precision(1); }

/* The report must be able to tell a wrong answer from a right one: the textbook formula,
 * measured by the same code, is expected to fail on subnormal scenes (its squares underflow)
 * and to lose many ulps grazing from far (b^2 - 4ac cancels). */
static void test_the_measure_can_fail(void)
{
    acc_row row;
    acc_measure(SEED, 7, 100u, 0, 1, &row); /* subnormal, double */
    TEST_ASSERT_TRUE(row.textbook.disagree > 0);
    acc_measure(SEED, 5, 100u, 0, 1, &row); /* grazing far, double */
    TEST_ASSERT_TRUE(row.textbook.max_err > 100.0 * ACC_TARGET_ULPS);
    /* rolling: the textbook quartic (Ferrari in double) answers wrongly when the deceleration is
     * tiny (its t^4 and t^3 terms are lost against the others) */
    acc_measure(SEED, CORPUS_ROLL_FIRST + 4, 100u, 0, 1, &row); /* roll tiny decel */
    TEST_ASSERT_TRUE(row.textbook.disagree > 0);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_double_targets_in_every_class);
    RUN_TEST(test_float_targets_in_every_class);
    RUN_TEST(test_the_measure_can_fail);
    return UNITY_END();
}
