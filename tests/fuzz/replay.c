/* Replays the fuzz corpus (tests/fuzz/corpus/, every file given on the command line) through
 * the fuzz target's checks, with the ordinary compiler and no libFuzzer: the regression test
 * for every input the fuzzer found interesting, including those that once broke the
 * contract. */
#include <stdio.h>
#include <stdlib.h>

#include "fuzz_checks.h"
#include "unity.h"

static int n_files;
static char **files;

void setUp(void) {}
void tearDown(void) {}

static void test_every_corpus_input_keeps_the_contract(void)
{
    static unsigned char buf[1 << 16];
    int i, bad = 0, functions[FUZZ_FUNCTIONS] = {0};
    for (i = 0; i < n_files; i++) {
        FILE *f = fopen(files[i], "rb");
        size_t n;
        TEST_ASSERT_NOT_NULL_MESSAGE(f, files[i]);
        n = fread(buf, 1, sizeof buf, f);
        fclose(f);
        if (n > 0)
            functions[fuzz_function(buf[0])]++;
        if (fuzz_one(buf, n) != 0) {
            fprintf(stderr, "replay: %s breaks the contract\n", files[i]);
            bad++;
        }
    }
    printf("replayed %d inputs\n", n_files);
    TEST_ASSERT_EQUAL_INT(0, bad);
    /* the corpus must reach every function, or a part of the API is not replayed */
    for (i = 0; i < FUZZ_FUNCTIONS; i++)
        TEST_ASSERT_TRUE_MESSAGE(functions[i] > 0, "a function with no input in the corpus");
}

int main(int argc, char **argv)
{
    n_files = argc - 1;
    files = argv + 1;
    UNITY_BEGIN();
    RUN_TEST(test_every_corpus_input_keeps_the_contract);
    return UNITY_END();
}
