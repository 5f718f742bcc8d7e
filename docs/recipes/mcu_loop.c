/* Recipe: the float pair functions alone, as on a microcontroller (docs/RECIPES.md). No world,
 * no allocation, no double: eight balls in a fixed static buffer, four walls, a 50 Hz control
 * loop. Each frame is a small event loop: find the earliest impact within the frame's time left
 * (cc_sweepf over the pairs, cc_sweep_segmentf over the walls), move every ball to it, respond
 * (cc_respondf / cc_respond_segmentf), repeat. This file includes no <math.h> and calls no libm
 * function; the float pair functions themselves use sqrtf, and frexpf / ldexpf for exact
 * power-of-two scaling (what scripts/test.d/40-embedded.sh allows on the Cortex-M4F).
 * The part below `firmware` is what a device would run; main() is the host's harness: it runs
 * 20 s (1000 frames) and checks that no ball left the box, no two overlap by more than float
 * rounding, and kinetic energy is kept to float accuracy. Exits 1 if a check fails. */
#include <circlecollide.h>

#include <stdio.h>

/* ---- firmware ---------------------------------------------------------------------------- */

#define N 8
#define N_WALLS 4
#define MAX_EVENTS_PER_FRAME 64

static cc_circlef g_balls[N];                   /* the fixed buffer: all the state there is */
static const cc_segmentf g_walls[N_WALLS] = {   /* a 1 x 0.5 m box */
    {{0.0f, 0.0f}, {1.0f, 0.0f}}, {{1.0f, 0.0f}, {1.0f, 0.5f}}, {{1.0f, 0.5f}, {0.0f, 0.5f}}, {{0.0f, 0.5f}, {0.0f, 0.0f}}};

static void advance(float t)
{
    int i;
    for (i = 0; i < N; i++) {
        g_balls[i].pos.x += g_balls[i].vel.x * t;
        g_balls[i].pos.y += g_balls[i].vel.y * t;
    }
}

/* One frame of dt seconds; returns the number of impacts processed (at most
 * MAX_EVENTS_PER_FRAME: the rest of the frame then runs without them, as a real-time loop
 * must bound its work). */
static int frame(float dt)
{
    float left = dt;
    int events = 0;
    while (events < MAX_EVENTS_PER_FRAME) {
        cc_contactf best, c;
        int i, j, bi = -1, bj = -1, bw = -1;
        float t = left;
        for (i = 0; i < N; i++) {
            for (j = i + 1; j < N; j++) {
                int r = cc_sweepf(&g_balls[i], &g_balls[j], t, &c);
                /* an overlap left by float rounding counts when the pair approaches (then
                 * cc_respondf gives it its impulse at once; it answers CC_MISS otherwise) */
                if ((r == CC_HIT && c.t < t) || (r == CC_OVERLAP && bi < 0 && bw < 0)) {
                    cc_circlef a = g_balls[i], b = g_balls[j];
                    if (r == CC_OVERLAP && cc_respondf(&a, &b, &c, 1.0f) != CC_HIT)
                        continue;
                    best = c, t = c.t, bi = i, bj = j, bw = -1;
                }
            }
            for (j = 0; j < N_WALLS; j++) {
                int r = cc_sweep_segmentf(&g_balls[i], &g_walls[j], t, &c);
                if ((r == CC_HIT && c.t < t) || (r == CC_OVERLAP && bi < 0 && bw < 0)) {
                    cc_circlef a = g_balls[i];
                    if (r == CC_OVERLAP && cc_respond_segmentf(&a, &c, 1.0f) != CC_HIT)
                        continue;
                    best = c, t = c.t, bi = i, bj = -1, bw = j;
                }
            }
        }
        advance(t);
        left -= t;
        if (bi < 0)
            break; /* nothing more in this frame */
        if (bw >= 0)
            cc_respond_segmentf(&g_balls[bi], &best, 1.0f);
        else
            cc_respondf(&g_balls[bi], &g_balls[bj], &best, 1.0f);
        events++;
    }
    if (left > 0.0f)
        advance(left);
    return events;
}

/* ---- host harness ------------------------------------------------------------------------ */

static float kinetic(void)
{
    float e = 0.0f;
    int i;
    for (i = 0; i < N; i++)
        e += 0.5f * g_balls[i].mass * (g_balls[i].vel.x * g_balls[i].vel.x + g_balls[i].vel.y * g_balls[i].vel.y);
    return e;
}

static float absf(float x) { return x < 0.0f ? -x : x; }

static int check(int ok, const char *what)
{
    printf("%s %s\n", ok ? "ok  " : "FAIL", what);
    return ok ? 0 : 1;
}

int main(void)
{
    int i, j, f, impacts = 0, outside = 0, failures = 0;
    float e0, worst_depth = 0.0f, drift;
    for (i = 0; i < N; i++) { /* two rows of four, radii 0.03 to 0.05 m, speeds up to 1 m/s */
        g_balls[i].pos.x = 0.15f + 0.23f * (float)(i % 4);
        g_balls[i].pos.y = 0.15f + 0.2f * (float)(i / 4);
        g_balls[i].vel.x = 0.9f - 0.25f * (float)i;
        g_balls[i].vel.y = (i % 3 == 0 ? 0.7f : -0.4f) + 0.05f * (float)i;
        g_balls[i].radius = 0.03f + 0.003f * (float)i;
        g_balls[i].mass = g_balls[i].radius * g_balls[i].radius * 1000.0f;
    }
    e0 = kinetic();
    for (f = 0; f < 1000; f++) {
        impacts += frame(0.02f);
        for (i = 0; i < N; i++) {
            const cc_circlef *b = &g_balls[i];
            /* outside the box by more than float rounding of the walls' positions */
            if (b->pos.x < b->radius - 1e-5f || b->pos.x > 1.0f - b->radius + 1e-5f || b->pos.y < b->radius - 1e-5f ||
                b->pos.y > 0.5f - b->radius + 1e-5f)
                outside++;
            for (j = i + 1; j < N; j++) {
                cc_contactf c;
                if (cc_detect_staticf(b, &g_balls[j], &c) == CC_OVERLAP && c.depth > worst_depth)
                    worst_depth = c.depth;
            }
        }
    }
    drift = absf(kinetic() - e0) / e0;
    printf("20 s at 50 Hz: %d impacts, deepest overlap %.2g m, kinetic energy drift %.2g, %d ball-frames outside\n",
           impacts, (double)worst_depth, (double)drift, outside);
    failures += check(impacts > 100, "the balls collide (with each other and the walls)");
    failures += check(outside == 0, "no ball leaves the box");
    failures += check(worst_depth < 1e-5f, "no overlap deeper than 10 um (float rounding at 1 m)");
    failures += check(drift < 1e-4f, "kinetic energy kept to float accuracy (restitution 1)");
    return failures ? 1 : 0;
}
