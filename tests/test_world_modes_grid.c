/* SWEPT's choice of candidate pairs through the grid (src/world/swept.c): slow bodies meet in
 * neighbouring cells, a fast body looks over the cells its own motion covers, bodies at rest
 * look nowhere. None of this may change the outcome: one step from a scene without overlaps
 * must end bit for bit the same whatever the grid (cells of the default size or one cell
 * holding everything) and whatever the storage order (circles added in reverse), since each
 * body keeps its earliest impact and the impacts run in time order. */
#include "unity.h"

#include "test_world_util.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

enum { N = 240, WALLS = 4 };
static const double L = 80.0; /* the box [0, L]^2 */

static cc_circle scene[N];

/* N circles without overlaps, inside the box. First four head-on pairs of radius 0.25 in lanes
 * at y = 10, 30, 50, 70, from x = 5 and 75 at speeds +100 and -100: they travel 50 each in a
 * step, exactly as far as each other, and meet at t = 69.5 / 200 (found only if the body that
 * sweeps the pair looks twice its own travel ahead, and a tie still gives the pair to one of
 * them). Then, off the lanes, radii 0.25, 0.5 and 1: a quarter at rest, half slow (speeds
 * below 1), the rest fast (20 to 120: up to 28 cells in a step of 0.5); two of the slow ones
 * immovable (one of them moving: a kinematic body). */
static void make_scene(void)
{
    uint64_t s = 20261122u;
    int i, j;
    for (i = 0; i < 8; i++) {
        cc_circle *c = &scene[i];
        c->radius = 0.25;
        c->mass = 1.0;
        c->pos.x = i % 2 ? 75.0 : 5.0;
        c->pos.y = 10.0 + 20.0 * (i / 2);
        c->vel.x = i % 2 ? -100.0 : 100.0;
        c->vel.y = 0.0;
    }
    while (i < N) {
        cc_circle c;
        double ang = 6.283185307179586 * tw_rand(&s), speed;
        int kind = i % 4, ok = 1;
        c.radius = i % 3 == 0 ? 1.0 : (i % 3 == 1 ? 0.5 : 0.25);
        c.pos.x = c.radius + (L - 2.0 * c.radius) * tw_rand(&s);
        c.pos.y = c.radius + (L - 2.0 * c.radius) * tw_rand(&s);
        speed = kind == 0 ? 0.0 : (kind == 3 ? 20.0 + 100.0 * tw_rand(&s) : tw_rand(&s));
        c.vel.x = speed * cos(ang);
        c.vel.y = speed * sin(ang);
        c.mass = i == 9 || i == 13 ? (double)INFINITY : c.radius * c.radius;
        ok = fabs(fmod(c.pos.y, 20.0) - 10.0) > 1.5 + c.radius; /* off the lanes */
        for (j = 0; j < i && ok; j++) { /* a gap of at least 0.01 to everyone */
            double dx = c.pos.x - scene[j].pos.x, dy = c.pos.y - scene[j].pos.y, R = c.radius + scene[j].radius + 0.01;
            ok = dx * dx + dy * dy > R * R;
        }
        if (ok)
            scene[i++] = c;
    }
}

/* One SWEPT step of 0.5 of the scene, added in reverse when asked, with the given cell size;
 * the circles after it in the scene's order. Returns the collisions. */
static uint64_t run(double cell_size, int reverse, size_t offset, cc_circle *out)
{
    tw_mem m;
    cc_world_def d;
    cc_world *w;
    cc_world_stats st;
    cc_segment box[WALLS];
    int ids[N], i;
    cc_world_def_init(&d);
    d.mode = CC_MODE_SWEPT;
    d.max_circles = N;
    d.max_segments = WALLS;
    d.cell_size = cell_size;
    w = tw_make(&m, &d, offset);
    TEST_ASSERT_NOT_NULL(w);
    for (i = 0; i < WALLS; i++) {
        double x0 = i == 1 ? L : 0.0, y0 = i == 2 ? L : 0.0;
        box[i].a.x = x0;
        box[i].a.y = y0;
        box[i].b.x = i == 0 || i == 2 ? L : x0;
        box[i].b.y = i == 1 || i == 3 ? L : y0;
        TEST_ASSERT_EQUAL_INT(i, cc_world_add_segment(w, &box[i]));
    }
    for (i = 0; i < N; i++) {
        int k = reverse ? N - 1 - i : i;
        ids[k] = cc_world_add_circle(w, &scene[k]);
        TEST_ASSERT_TRUE(ids[k] >= 0);
    }
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 0.5));
    for (i = 0; i < N; i++)
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, ids[i], &out[i]));
    st.struct_size = sizeof st;
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_stats(w, &st));
    TEST_ASSERT_TRUE(tw_canary_ok(&m));
    tw_free(&m);
    return st.collisions;
}

static cc_circle ref[N], got[N];

/* The default cells (1.0625 x the largest movable diameter: 2.125) against one cell of 1e4
 * holding the whole box, where every pair is looked at. */
static void test_swept_cells_do_not_matter(void)
{
    uint64_t a = run(0.0, 0, 0, ref), b = run(1e4, 0, 0, got);
    printf("swept step: %llu collisions\n", (unsigned long long)a);
    /* the fast quarter (60 circles crossing up to 60 of the 2.125-wide cells) meets something */
    TEST_ASSERT_TRUE(a >= 20);
    TEST_ASSERT_EQUAL_UINT64(a, b);
    TEST_ASSERT_EQUAL_MEMORY(ref, got, sizeof ref);
}

/* The head-on pairs meet (equal masses, restitution 1: they swap velocities at x = 39.75 and
 * 40.25, t = 0.3475, then travel back 100 * 0.1525 = 15.25, to 24.5 and 55.5) unless a fast
 * circle crossing their lane hits one first: in this scene, that spares one lane of the four
 * (a pair that was missed passes through, to 55 and 25). */
static void test_swept_head_on_pairs_meet(void)
{
    int i, met = 0;
    (void)run(0.0, 0, 0, got);
    for (i = 0; i < 8; i += 2) {
        printf("lane at y = %g: %.17g %.17g\n", scene[i].pos.y, got[i].pos.x, got[i + 1].pos.x);
        met += fabs(got[i].pos.x - 24.5) < 1e-9 && fabs(got[i + 1].pos.x - 55.5) < 1e-9;
    }
    TEST_ASSERT_TRUE(met >= 1);
}

/* Storage in reverse: who sweeps a pair (the body that travels further, the higher index on a
 * tie) changes, the outcome does not; nor does the buffer's address. */
static void test_swept_storage_order_does_not_matter(void)
{
    uint64_t a = run(0.0, 0, 0, ref), b = run(0.0, 1, 8, got);
    TEST_ASSERT_EQUAL_UINT64(a, b);
    TEST_ASSERT_EQUAL_MEMORY(ref, got, sizeof ref);
}

/* The scene must move: a test that passes with nothing happening proves nothing. */
static void test_scene_moves(void)
{
    int i, moved = 0;
    (void)run(0.0, 0, 0, got);
    for (i = 0; i < N; i++)
        moved += memcmp(&got[i], &scene[i], sizeof got[i]) != 0;
    TEST_ASSERT_TRUE(moved >= N / 2);
}

/* A bullet at 1e40 whose reach spans every cell (2^31 + 1 of them along x, the grid's whole
 * range): its neighbourhood is counted without overflowing the cell arithmetic (UBSan
 * watches), and it still finds the first circle in its way. Equal masses, restitution 1: the
 * bullet stops where it touches the first circle of the row (centres 2 apart: x = 98, at
 * t = 9.8e-39) and that circle leaves at 1e40 (through the others: SWEPT predicts no second
 * impact within the step). */
static void test_swept_path_over_every_cell(void)
{
    enum { M = 40 };
    tw_mem m;
    cc_world_def d;
    cc_world *w;
    cc_circle c, got;
    int i, bullet;
    cc_world_def_init(&d);
    d.mode = CC_MODE_SWEPT;
    d.max_circles = M;
    w = tw_make(&m, &d, 0);
    TEST_ASSERT_NOT_NULL(w);
    memset(&c, 0, sizeof c);
    c.radius = 1.0;
    c.mass = 1.0;
    for (i = 0; i < M - 1; i++) { /* a row at rest from x = 100, 10 apart */
        c.pos.x = 100.0 + 10.0 * i;
        TEST_ASSERT_EQUAL_INT(i, cc_world_add_circle(w, &c));
    }
    c.pos.x = 0.0;
    c.vel.x = 1e40;
    bullet = cc_world_add_circle(w, &c);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(w, 1.0));
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, bullet, &got));
    TEST_ASSERT_EQUAL_DOUBLE(0.0, got.vel.x);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 98.0, got.pos.x);
    TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_get_circle(w, 0, &got));
    TEST_ASSERT_EQUAL_DOUBLE(1e40, got.vel.x);
    TEST_ASSERT_TRUE(tw_canary_ok(&m));
    tw_free(&m);
}

int main(void)
{
    make_scene();
    UNITY_BEGIN();
    RUN_TEST(test_swept_cells_do_not_matter);
    RUN_TEST(test_swept_head_on_pairs_meet);
    RUN_TEST(test_swept_storage_order_does_not_matter);
    RUN_TEST(test_scene_moves);
    RUN_TEST(test_swept_path_over_every_cell);
    return UNITY_END();
}
