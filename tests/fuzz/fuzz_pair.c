/* The libFuzzer target over every pair function (see fuzz_checks.h): built with clang
 * -fsanitize=fuzzer,address,undefined by scripts/test.d/30-fuzz.sh. A contract violation
 * aborts, so that libFuzzer keeps the input as a crash. */
#include <stdlib.h>

#include "fuzz_checks.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (fuzz_one(data, size) != 0)
        abort();
    return 0;
}
