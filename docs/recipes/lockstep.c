/* Recipe: a lock-step replay checked with the state hash (docs/RECIPES.md). Two peers run the
 * same world from the same inputs (a gas of 200 circles in a box, and a "player" input: a set
 * circle each second); they compare cc_world_hash after every step, as a networked game would
 * send it. A third run gets one input one bit apart: the hashes tell the step where it parts.
 * Exits 1 if a check fails. */
#include <circlecollide.h>

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define N 200

static cc_world *make(void **mem)
{
    cc_world_def def;
    size_t bytes;
    cc_world *w;
    int i;
    uint64_t s = 12345; /* the shared seed: every peer draws the same scene */
    cc_world_def_init(&def);
    def.max_circles = N;
    def.max_segments = 4;
    bytes = cc_world_size(&def);
    *mem = malloc(bytes);
    w = cc_world_init(*mem, bytes, &def, NULL);
    {
        const cc_segment box[4] = {{{0, 0}, {40, 0}}, {{40, 0}, {40, 40}}, {{40, 40}, {0, 40}}, {{0, 40}, {0, 0}}};
        for (i = 0; i < 4; i++)
            cc_world_add_segment(w, &box[i]);
    }
    for (i = 0; i < N; i++) {
        cc_circle c;
        double u[2];
        int k;
        for (k = 0; k < 2; k++) { /* xorshift: the same numbers on every machine */
            s ^= s << 13, s ^= s >> 7, s ^= s << 17;
            u[k] = (double)(s >> 11) / 9007199254740992.0;
        }
        c.pos.x = 2.0 + 36.0 * (i % 14) / 13.0;
        c.pos.y = 2.0 + 36.0 * (i / 14) / 14.0;
        c.vel.x = u[0] - 0.5;
        c.vel.y = u[1] - 0.5;
        c.radius = 0.4;
        c.mass = 1.0;
        cc_world_add_circle(w, &c);
    }
    return w;
}

/* Frame f's input: at each whole second the player's circle 0 is sent towards the centre. */
static void input(cc_world *w, int f, double nudge)
{
    cc_circle c;
    if (f % 60 != 0)
        return;
    cc_world_get_circle(w, 0, &c);
    c.vel.x = (20.0 - c.pos.x) * 0.1 + nudge;
    c.vel.y = (20.0 - c.pos.y) * 0.1;
    cc_world_set_circle(w, 0, &c);
}

int main(void)
{
    void *ma, *mb, *mc;
    cc_world *a = make(&ma), *b = make(&mb), *c = make(&mc);
    int f, equal_ab = 1, parted = -1, failures = 0;
    for (f = 0; f < 600; f++) { /* 10 s at 60 Hz */
        input(a, f, 0.0);
        input(b, f, 0.0);
        input(c, f, f == 120 ? 1e-15 : 0.0); /* one input, one bit or so apart, at 2 s */
        cc_world_step(a, 1.0 / 60);
        cc_world_step(b, 1.0 / 60);
        cc_world_step(c, 1.0 / 60);
        if (cc_world_hash(a) != cc_world_hash(b))
            equal_ab = 0;
        if (parted < 0 && cc_world_hash(a) != cc_world_hash(c))
            parted = f;
    }
    {
        cc_world_stats st;
        st.struct_size = sizeof st;
        cc_world_get_stats(a, &st);
        printf("%llu collisions in 10 s; peers a and b: hashes %s at every step (last %016llx); "
               "peer c parts at frame %d\n", (unsigned long long)st.collisions, equal_ab ? "equal" : "DIFFERENT",
               (unsigned long long)cc_world_hash(a), parted);
    }
    failures += !equal_ab;
    failures += parted != 120; /* the very step of the different input */
    /* a world's memory copied elsewhere is the same world: same hash, same future */
    {
        cc_world_def def;
        size_t bytes;
        void *copy;
        cc_world *w2;
        cc_world_def_init(&def);
        def.max_circles = N;
        def.max_segments = 4;
        bytes = cc_world_size(&def);
        copy = malloc(bytes);
        memcpy(copy, ma, bytes);
        w2 = (cc_world *)copy;
        cc_world_step(a, 1.0);
        cc_world_step(w2, 1.0);
        printf("a copy of the world's memory: hash %s after one more second\n",
               cc_world_hash(a) == cc_world_hash(w2) ? "equal" : "DIFFERENT");
        failures += cc_world_hash(a) != cc_world_hash(w2);
        free(copy);
    }
    free(ma), free(mb), free(mc);
    printf("%s\n", failures ? "FAIL" : "ok");
    return failures ? 1 : 0;
}
