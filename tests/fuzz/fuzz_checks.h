/* The fuzz target's body, shared by the libFuzzer harness (fuzz_pair.c, built with clang
 * -fsanitize=fuzzer) and the corpus replay test (replay.c, any compiler).
 *
 * An input is: byte 0 selects the function (FUZZ_FUNCTIONS of them: every pair function in
 * double and float, and cc_sweep_many), byte 1 holds flags (bit 0: make the numbers valid
 * first, so that the valid paths are reached often), byte 2 a count for cc_sweep_many, then
 * the raw bytes of the arguments' numbers (8 per double, 4 per float; missing bytes are 0).
 * Any bit pattern is allowed: NaN, infinities, subnormals, huge values. */
#ifndef CC_FUZZ_CHECKS_H
#define CC_FUZZ_CHECKS_H

#include <stddef.h>
#include <stdint.h>

#define FUZZ_FUNCTIONS 15

/* Runs one input and checks the contract (see fuzz_checks.c); returns the number of
 * violations, each printed to stderr. */
int fuzz_one(const uint8_t *data, size_t size);

#endif
