/* The libFuzzer target over sequences of world calls (fuzz_world_checks.h): built with clang
 * -fsanitize=fuzzer,address,undefined by scripts/test.d/30-fuzz.sh. A contract violation
 * aborts, so that libFuzzer keeps the input as a crash. */
#include "fuzz_world_checks.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_world_one(data, size);
    return 0;
}
