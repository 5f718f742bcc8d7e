/* Recipe: Newton's cradle (docs/RECIPES.md). Five steel balls in a row, each touching the next,
 * on a table (no gravity: the library has none; what a cradle shows is the impact). k balls
 * swing in at 1 m/s from the left: exactly k balls leave on the right at 1 m/s, the rest stay
 * still, because EXACT resolves every contact touching the impact at once (simultaneous impact,
 * "Simultaneous" in the header) instead of one pair after another. The same holds whichever
 * order the balls were added in. Checks what it prints; exits 1 if a check fails. */
#include <circlecollide.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define N 5
#define R 0.0125 /* 25 mm balls */
#define M 0.064  /* kg */

static int check(int ok, const char *what)
{
    printf("%s %s\n", ok ? "ok  " : "FAIL", what);
    return ok ? 0 : 1;
}

/* k balls (the leftmost) move at 1 m/s towards the others; balls added left to right, or right
 * to left when reversed. Runs 0.2 s; fills v[i] with ball i's final x velocity (i from the
 * left) and returns the number of collisions (impulses). */
static unsigned long long cradle(int k, int reversed, double v[N], double *energy, double *momentum)
{
    cc_world_def def;
    cc_world_stats st;
    void *mem;
    size_t bytes;
    cc_world *w;
    int i, id[N];
    cc_world_def_init(&def);
    def.max_circles = N;
    def.restitution = 1.0; /* steel on steel, idealised */
    bytes = cc_world_size(&def);
    mem = malloc(bytes);
    w = cc_world_init(mem, bytes, &def, NULL);
    if (w == NULL)
        exit(1);
    for (i = 0; i < N; i++) {
        int j = reversed ? N - 1 - i : i;
        /* the moving group starts 5 cm to the left of the row, its balls touching each other */
        cc_circle c = {{2.0 * R * j - (j < k ? 0.05 : 0.0), 0.0}, {j < k ? 1.0 : 0.0, 0.0}, R, M};
        id[j] = cc_world_add_circle(w, &c);
    }
    for (i = 0; i < 20; i++) /* 0.2 s in frames of 10 ms: the impact comes at t = 0.05 s */
        cc_world_step(w, 0.01);
    *energy = *momentum = 0.0;
    for (i = 0; i < N; i++) {
        cc_circle c;
        cc_world_get_circle(w, id[i], &c);
        v[i] = c.vel.x;
        *energy += 0.5 * M * (c.vel.x * c.vel.x + c.vel.y * c.vel.y);
        *momentum += M * c.vel.x;
    }
    st.struct_size = sizeof st;
    cc_world_get_stats(w, &st);
    free(mem);
    return (unsigned long long)st.collisions;
}

int main(void)
{
    int k, rev, i, failures = 0;
    for (k = 1; k <= 2; k++)
        for (rev = 0; rev <= 1; rev++) {
            double v[N], e, p, e0 = k * 0.5 * M, p0 = k * M;
            unsigned long long coll = cradle(k, rev, v, &e, &p);
            int out_ok = 1;
            char what[160];
            printf("%d in, balls added %s: velocities after", k, rev ? "right to left" : "left to right");
            for (i = 0; i < N; i++)
                printf(" %.3g", v[i]);
            printf(" m/s (%llu impulses)\n", coll);
            for (i = 0; i < N; i++) /* the last k at 1 m/s, the others at rest */
                out_ok &= fabs(v[i] - (i >= N - k ? 1.0 : 0.0)) <= 1e-12;
            snprintf(what, sizeof what, "exactly %d ball%s out at 1 m/s, the others at rest", k, k > 1 ? "s" : "");
            failures += check(out_ok, what);
            failures += check(fabs(e - e0) <= 1e-12 * e0 && fabs(p - p0) <= 1e-12 * p0,
                              "kinetic energy and momentum kept");
        }
    return failures ? 1 : 0;
}
