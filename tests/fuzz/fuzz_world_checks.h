/* The world fuzzer's body, shared by the libFuzzer target (fuzz_world.c, clang
 * -fsanitize=fuzzer) and the corpus replay test (replay_world.c, any compiler).
 *
 * An input is a world def followed by a sequence of world API calls (fuzz_world_checks.c gives
 * the byte layout). Every call's result and the world after it are checked against the contract
 * of include/circlecollide.h; a violation prints a message and calls abort(). */
#ifndef CC_FUZZ_WORLD_CHECKS_H
#define CC_FUZZ_WORLD_CHECKS_H

#include <stddef.h>
#include <stdint.h>

/* Runs one input; returns only when every check held (a violation aborts). */
void fuzz_world_one(const uint8_t *data, size_t size);

/* Set by the replay to name the file in a violation's message (may stay NULL). */
extern const char *fuzz_world_input_name;

/* Counters for the replay's summary (summed over every input run so far). */
typedef struct fuzz_world_counts {
    unsigned long inputs, worlds, calls, steps, contacts, sensors, refused, copies;
    unsigned long casts_judged, casts_judged_periodic; /* casts checked against the brute force */
} fuzz_world_counts;
extern fuzz_world_counts fuzz_world_counted;

#endif
