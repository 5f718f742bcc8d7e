/* The world against the reference world (tests/reference_world/): random scenes played call by
 * call through both, every result code, contact event and state compared (issue 11); and the
 * all-pairs world against the gridded one on the same scenes.
 *
 *   test_world_reference [--scenes N] [--seed S] [--events E] [--verbose]
 *
 * Each scene's comparison ends done (its steps or event budget compared), at a legitimate doubt
 * (a near tie, graze or threshold approach, which rounding decides), diverged (states apart
 * after such a doubt), or failed (a difference nothing explains). Any failure fails the test,
 * which prints the scene's seed; the figures printed say how much was compared. */
#include "unity.h"

#include "reference_world/differential.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

static unsigned long g_scenes = 4000, g_events = 50; /* small vs grid: a fifth of the scenes */
static uint64_t g_seed = 1;
static int g_verbose;

static void run(dw_pairing pairing, const char *name, unsigned long scenes, double min_share)
{
    unsigned long ends[DW_END_COUNT] = {0}, events = 0, sensed = 0, calls = 0, steps = 0, batches = 0, refused = 0, s;
    double worst_dt = 0.0, worst_dp = 0.0;
    char first[600] = "";
    for (s = 0; s < scenes; s++) {
        dw_result r;
        dw_run_scene(g_seed + s, pairing, g_events, &r);
        ends[r.end]++;
        events += r.events_compared;
        sensed += r.sensor_events_compared;
        calls += r.calls;
        batches += r.batches;
        refused += r.batches_refused;
        steps += r.steps_compared;
        worst_dt = r.worst_dt > worst_dt ? r.worst_dt : worst_dt;
        worst_dp = r.worst_dp > worst_dp ? r.worst_dp : worst_dp;
        if (r.end == DW_END_FAILED && first[0] == '\0')
            snprintf(first, sizeof first, "%s", r.why);
        if (g_verbose && r.end != DW_END_DONE)
            printf("  scene %llu: %s %s\n", (unsigned long long)(g_seed + s),
                   r.end == DW_END_TIE        ? "doubt"
                   : r.end == DW_END_DIVERGED ? "diverged"
                   : r.end == DW_END_JAMMED   ? "jammed"
                                              : "FAILED", r.why);
    }
    printf("%s: %lu scenes, %lu calls (%lu batch adds, %lu of them refused), %lu steps, %lu contact events and %lu "
           "sensor events compared; ended: done %lu, at a doubt %lu, diverged %lu, jammed %lu, failed %lu; worst |dt| "
           "%.3g T, worst |dp| %.3g L\n",
           name, scenes, calls, batches, refused, steps, events, sensed, ends[DW_END_DONE], ends[DW_END_TIE], ends[DW_END_DIVERGED],
           ends[DW_END_JAMMED], ends[DW_END_FAILED], worst_dt, worst_dp);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, (int)ends[DW_END_FAILED], first);
    /* the comparison must not be vacuous: most of the event budget is compared (chaos ends some
     * scenes early; without the reference's resynchronisation, two worlds drift apart sooner;
     * a third of the scenes roll to rest, and balls at rest collide less) */
    TEST_ASSERT_TRUE_MESSAGE((double)events >= min_share * (double)scenes * (double)g_events,
                             "fewer contact events compared than the test requires");
}

static void test_world_against_reference(void) { run(DW_WORLD_VS_REFERENCE, "world vs reference", g_scenes, 0.5); }
static void test_all_pairs_against_grid(void) { run(DW_SMALL_VS_GRID, "all pairs vs grid", g_scenes / 5, 0.3); }

/* Found by the reference (scene 68): a circle added onto a large kinematic circle (immovable,
 * wider than a cell, so kept on the large list) was pushed out of where that circle was when its
 * state was last written, not where it is now. */
static void test_add_onto_large_kinematic_circle_pushes_out_of_where_it_is_now(void)
{
    cc_world_def d;
    cc_world *w;
    void *mem;
    cc_circle small = {{-20.0, 0.0}, {0.0, 0.0}, 1.0, 1.0};         /* cells of 2.125: movable */
    cc_circle big = {{0.0, 0.0}, {1.0, 0.0}, 1.5, HUGE_VAL};       /* diameter 3: on the large list */
    cc_circle onto = {{12.0, 0.0}, {0.0, 0.0}, 1.0, 1.0}, got;     /* overlaps big at x = 10 by 0.5 */
    cc_world_def_init(&d);
    d.max_circles = 64; /* a grid */
    mem = malloc(cc_world_size(&d));
    w = cc_world_init(mem, cc_world_size(&d), &d, NULL);
    TEST_ASSERT_EQUAL_INT(0, cc_world_add_circle(w, &small));
    TEST_ASSERT_EQUAL_INT(1, cc_world_add_circle(w, &big));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 10.0)); /* big now at (10, 0), nothing in its way */
    TEST_ASSERT_EQUAL_INT(2, cc_world_add_circle(w, &onto));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 2, &got));
    /* pushed out along +x to just touch big at (10, 0): x = 10 + 1.5 + 1 */
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 12.5, got.pos.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.0, got.pos.y);
    free(mem);
}

int main(int argc, char **argv)
{
    int i;
    for (i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--scenes") == 0 && i + 1 < argc)
            g_scenes = strtoul(argv[++i], NULL, 10);
        else if (strcmp(argv[i], "--seed") == 0 && i + 1 < argc)
            g_seed = strtoull(argv[++i], NULL, 10);
        else if (strcmp(argv[i], "--events") == 0 && i + 1 < argc)
            g_events = strtoul(argv[++i], NULL, 10);
        else if (strcmp(argv[i], "--verbose") == 0)
            g_verbose = 1;
        else if (strcmp(argv[i], "--trace") == 0)
            dw_trace = g_verbose = 1;
    }
    UNITY_BEGIN();
    RUN_TEST(test_add_onto_large_kinematic_circle_pushes_out_of_where_it_is_now);
    RUN_TEST(test_world_against_reference);
    RUN_TEST(test_all_pairs_against_grid);
    return UNITY_END();
}
