/* The libFuzzer target over every pair function (see fuzz_checks.h): built with clang
 * -fsanitize=fuzzer,address,undefined by scripts/test.d/30-fuzz.sh. A contract violation
 * aborts, so that libFuzzer keeps the input as a crash. */
#include <stdlib.h>

#include "fuzz_checks.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    /* FUZZ_PAIR_SKIP_ROLLING set (30-fuzz.sh with CC_FUZZ_ROLLING=0, while a rolling find is open
     * in pair_defects/): the six rolling functions (selector 15 and up) are not fuzzed. Their
     * corpus is replayed in full by test_fuzz_replay. */
    static int skip_rolling = -1;
    if (skip_rolling < 0)
        skip_rolling = getenv("FUZZ_PAIR_SKIP_ROLLING") != NULL;
    if (skip_rolling && size >= 1 && fuzz_function(data[0]) >= 15)
        return 0;
    if (fuzz_one(data, size) != 0)
        abort();
    return 0;
}
