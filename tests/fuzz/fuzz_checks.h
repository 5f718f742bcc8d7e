/* The fuzz target's body, shared by the libFuzzer harness (fuzz_pair.c, built with clang
 * -fsanitize=fuzzer) and the corpus replay test (replay.c, any compiler).
 *
 * An input is: byte 0 selects the function (FUZZ_FUNCTIONS of them, see fuzz_function), byte 1 holds flags (bit 0: make the numbers valid
 * first, so that the valid paths are reached often), byte 2 a count for cc_sweep_many, then
 * the raw bytes of the arguments' numbers (8 per double, 4 per float; missing bytes are 0).
 * Any bit pattern is allowed: NaN, infinities, subnormals, huge values. */
#ifndef CC_FUZZ_CHECKS_H
#define CC_FUZZ_CHECKS_H

#include <stddef.h>
#include <stdint.h>

#define FUZZ_FUNCTIONS 21

/* The function an input's byte 0 selects: 0..14 (byte 0 below 240, modulo 15: every pair
 * function of 1.0 in double and float, cc_sweep_many), 15..20 (byte 0 from 240: the rolling
 * ones of 1.1, cc_sweep_rolling, cc_sweep_segment_rolling, cc_rolling_advance, double then float
 * each), so that the corpus of 1.0 selects what it did. */
int fuzz_function(uint8_t b0);

/* Runs one input and checks the contract (see fuzz_checks.c); returns the number of
 * violations, each printed to stderr. */
int fuzz_one(const uint8_t *data, size_t size);

#endif
