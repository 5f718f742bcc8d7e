/* Replays the world fuzzer's corpus (tests/fuzz/corpus_world/, every file given on the command
 * line) through its checks, with the ordinary compiler and no libFuzzer. A violation aborts
 * naming the file (fuzz_world_checks.c). */
#include <stdio.h>
#include <stdlib.h>

#include "fuzz_world_checks.h"

int main(int argc, char **argv)
{
    static unsigned char buf[1 << 16];
    int i;
    for (i = 1; i < argc; i++) {
        FILE *f = fopen(argv[i], "rb");
        size_t n;
        if (f == NULL) {
            fprintf(stderr, "replay_world: cannot open %s\n", argv[i]);
            return 1;
        }
        n = fread(buf, 1, sizeof buf, f);
        fclose(f);
        fuzz_world_input_name = argv[i];
        fuzz_world_one(buf, n);
    }
    printf("replayed %lu inputs: %lu worlds, %lu calls, %lu steps, %lu contact and %lu sensor events, "
           "%lu callbacks tried every mutator, %lu memcpy copies, %lu casts against the brute force (%lu periodic)\n",
           fuzz_world_counted.inputs, fuzz_world_counted.worlds, fuzz_world_counted.calls,
           fuzz_world_counted.steps, fuzz_world_counted.contacts, fuzz_world_counted.sensors,
           fuzz_world_counted.refused, fuzz_world_counted.copies, fuzz_world_counted.casts_judged,
           fuzz_world_counted.casts_judged_periodic);
    if (argc < 2 || fuzz_world_counted.worlds == 0 || fuzz_world_counted.contacts == 0) {
        fprintf(stderr, "replay_world: the corpus reaches no world or no contact\n");
        return 1;
    }
    return 0;
}
