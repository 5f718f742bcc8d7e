/* The contact query that simultaneous-impact resolvers use (src/world/near.c): which circles
 * and walls touch a circle now, through the grid and without it. */
#include "unity.h"

#include "test_world_util.h"
#include "world/world_internal.h"

void setUp(void) {}
void tearDown(void) {}

static int g_ids[16], g_segs[16], g_n;
static cc_world *g_w;

static void collect(void *ctx, int j, int seg)
{
    (void)ctx;
    if (g_n < 16) {
        g_ids[g_n] = j >= 0 ? cc__idx2id(g_w, j) : -1;
        g_segs[g_n] = seg;
    }
    g_n++;
}

static int query(int id, double tol)
{
    g_n = 0;
    return cc__world_touching(g_w, CC__ARR(g_w, int32_t, off_id2idx)[id], tol, collect, NULL);
}

static int seen(int id)
{
    int i;
    for (i = 0; i < g_n; i++)
        if (g_ids[i] == id)
            return 1;
    return 0;
}

/* Five unit circles in a row, centres 2 apart (each touches its neighbours), a wall touching
 * the last one, a circle 0.01 away from the first, and 40 far-away circles so that the world
 * has a grid. Asked before the first step (no grid yet) and after it (through the grid). */
static void test_row_of_touching_circles(void)
{
    cc_world_def d;
    tw_mem m;
    cc_segment wall;
    int i, pass;
    cc_world_def_init(&d);
    d.max_circles = 60;
    d.max_segments = 1;
    g_w = tw_make(&m, &d, 0);
    for (i = 0; i < 5; i++) {
        cc_circle c = {{0, 0}, {0, 0}, 1, 1};
        c.pos.x = 2.0 * i;
        (void)cc_world_add_circle(g_w, &c);
    }
    {
        cc_circle c = {{-2.01, 0}, {0, 0}, 1, 1}; /* id 5: a gap of 0.01 to circle 0 */
        (void)cc_world_add_circle(g_w, &c);
    }
    for (i = 0; i < 40; i++) {
        cc_circle c = {{500, 0}, {0, 0}, 1, 1};
        c.pos.y = 3.0 * i;
        (void)cc_world_add_circle(g_w, &c);
    }
    wall.a.x = 9;
    wall.a.y = -5;
    wall.b.x = 9;
    wall.b.y = 5;
    (void)cc_world_add_segment(g_w, &wall);
    for (pass = 0; pass < 2; pass++) {
        TEST_ASSERT_EQUAL_INT(2, query(2, 1e-12));
        TEST_ASSERT_TRUE(seen(1) && seen(3));
        TEST_ASSERT_EQUAL_INT(2, query(4, 1e-12)); /* circle 3 and the wall */
        TEST_ASSERT_TRUE(seen(3) && seen(-1));
        TEST_ASSERT_EQUAL_INT(1, query(0, 1e-12)); /* circle 1; circle 5 is 0.01 away */
        TEST_ASSERT_EQUAL_INT(2, query(0, 0.02));  /* within 0.02 it counts */
        TEST_ASSERT_TRUE(seen(1) && seen(5));
        TEST_ASSERT_EQUAL_INT(CC_OK, cc_world_step(g_w, 0.0)); /* now with the grid */
    }
    tw_free(&m);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_row_of_touching_circles);
    return UNITY_END();
}
