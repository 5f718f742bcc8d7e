/* A program written against the 1.0 header and nothing newer: the pair functions in double and
 * float, the world in its three modes with walls, callbacks, adds, sets, removes, stats and a
 * memcpy of a world between steps. It prints one digest of every number it saw (the bits of
 * every double and float, every return code, every callback's fields).
 *
 * tests/compat.cmake builds it twice, against the 1.0 header kept in tests/compat/v1_0/ and
 * against today's header, both linked to today's shared library, and checks that each prints
 * the digest the 1.0 library printed (recorded in compat.cmake). So a program built against 1.0
 * keeps running unchanged against 1.1: same struct sizes read, same defaults, same results to
 * the bit. Only the 1.0 API is used here; nothing may be added that 1.0 lacks. */
#include <circlecollide.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint64_t digest = 1469598103934665603u; /* FNV-1a over everything seen */

static void mix_bytes(const void *p, size_t n)
{
    const unsigned char *b = (const unsigned char *)p;
    size_t i;
    for (i = 0; i < n; i++) {
        digest ^= b[i];
        digest *= 1099511628211u;
    }
}

static void mix_d(double x)
{
    uint64_t u;
    if (x == 0.0) x = 0.0; /* -0 and +0 alike: the sign of a zero is not a result */
    memcpy(&u, &x, sizeof u);
    mix_bytes(&u, sizeof u);
}

static void mix_f(float x)
{
    uint32_t u;
    if (x == 0.0f) x = 0.0f;
    memcpy(&u, &x, sizeof u);
    mix_bytes(&u, sizeof u);
}

static void mix_i(long long v)
{
    mix_bytes(&v, sizeof v);
}

static void mix_circle(const cc_circle *c)
{
    mix_d(c->pos.x), mix_d(c->pos.y), mix_d(c->vel.x), mix_d(c->vel.y), mix_d(c->radius), mix_d(c->mass);
}

static void mix_contact(const cc_contact *c)
{
    mix_d(c->t), mix_d(c->point.x), mix_d(c->point.y), mix_d(c->normal.x), mix_d(c->normal.y), mix_d(c->depth);
}

static void mix_contactf(const cc_contactf *c)
{
    mix_f(c->t), mix_f(c->point.x), mix_f(c->point.y), mix_f(c->normal.x), mix_f(c->normal.y), mix_f(c->depth);
}

static uint64_t rng = 88172645463325252u;

static double uniform(double lo, double hi) /* xorshift64, the same numbers on every target */
{
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    return lo + (hi - lo) * (double)(rng >> 11) * (1.0 / 9007199254740992.0);
}

static long contacts_seen;

static void on_contact(const cc_contact_event *e, void *user)
{
    (void)user;
    contacts_seen++;
    mix_i(e->a), mix_i(e->b), mix_i(e->segment);
    mix_d(e->t), mix_d(e->point.x), mix_d(e->point.y), mix_d(e->normal.x), mix_d(e->normal.y), mix_d(e->impulse);
}

static void pairs(void)
{
    int i;
    cc_segment s = {{-3.0, 2.0}, {4.0, -1.0}};
    for (i = 0; i < 200; i++) {
        cc_circle a, b;
        cc_contact c;
        cc_circlef af, bf;
        cc_contactf cf;
        cc_segmentf sf = {{-3.0f, 2.0f}, {4.0f, -1.0f}};
        cc_vec2 p;
        cc_vec2f pf;
        a.pos.x = uniform(-5, 5), a.pos.y = uniform(-5, 5), a.vel.x = uniform(-3, 3), a.vel.y = uniform(-3, 3);
        a.radius = uniform(0.1, 1.5), a.mass = i % 17 == 0 ? HUGE_VAL : uniform(0.5, 4);
        b.pos.x = uniform(-5, 5), b.pos.y = uniform(-5, 5), b.vel.x = uniform(-3, 3), b.vel.y = uniform(-3, 3);
        b.radius = uniform(0.1, 1.5), b.mass = uniform(0.5, 4);
        af.pos.x = (float)a.pos.x, af.pos.y = (float)a.pos.y, af.vel.x = (float)a.vel.x, af.vel.y = (float)a.vel.y;
        af.radius = (float)a.radius, af.mass = (float)a.mass;
        bf.pos.x = (float)b.pos.x, bf.pos.y = (float)b.pos.y, bf.vel.x = (float)b.vel.x, bf.vel.y = (float)b.vel.y;
        bf.radius = (float)b.radius, bf.mass = (float)b.mass;

        memset(&c, 0, sizeof c);
        mix_i(cc_detect_static(&a, &b, &c)), mix_contact(&c);
        memset(&c, 0, sizeof c);
        mix_i(cc_sweep(&a, &b, 4.0, &c)), mix_contact(&c);
        if (c.t >= 0.0 && c.t <= 4.0) {
            mix_i(cc_respond(&a, &b, &c, 0.8)), mix_circle(&a), mix_circle(&b);
        }
        memset(&c, 0, sizeof c);
        mix_i(cc_sweep_segment(&b, &s, 4.0, &c)), mix_contact(&c);
        if (c.t >= 0.0 && c.t <= 4.0) mix_i(cc_respond_segment(&b, &c, 0.9)), mix_circle(&b);
        mix_i(cc_separate(&a, &b)), mix_circle(&a), mix_circle(&b);
        p = cc_closest_point_on_segment(a.pos, &s), mix_d(p.x), mix_d(p.y);

        memset(&cf, 0, sizeof cf);
        mix_i(cc_detect_staticf(&af, &bf, &cf)), mix_contactf(&cf);
        memset(&cf, 0, sizeof cf);
        mix_i(cc_sweepf(&af, &bf, 4.0f, &cf)), mix_contactf(&cf);
        if (cf.t >= 0.0f && cf.t <= 4.0f) mix_i(cc_respondf(&af, &bf, &cf, 0.8f));
        memset(&cf, 0, sizeof cf);
        mix_i(cc_sweep_segmentf(&bf, &sf, 4.0f, &cf)), mix_contactf(&cf);
        if (cf.t >= 0.0f && cf.t <= 4.0f) mix_i(cc_respond_segmentf(&bf, &cf, 0.9f));
        mix_i(cc_separatef(&af, &bf));
        pf = cc_closest_point_on_segmentf(af.pos, &sf), mix_f(pf.x), mix_f(pf.y);
        mix_f(af.pos.x), mix_f(af.vel.y), mix_f(bf.pos.y), mix_f(bf.vel.x);
    }
}

static void many(void)
{
    enum { N = 64 };
    static double ax[N], ay[N], avx[N], avy[N], ar[N], bx[N], by[N], bvx[N], bvy[N], br[N], t[N];
    static int r[N];
    cc_circle_soa a, b;
    int i;
    for (i = 0; i < N; i++) {
        ax[i] = uniform(-5, 5), ay[i] = uniform(-5, 5), avx[i] = uniform(-2, 2), avy[i] = uniform(-2, 2);
        bx[i] = uniform(-5, 5), by[i] = uniform(-5, 5), bvx[i] = uniform(-2, 2), bvy[i] = uniform(-2, 2);
        ar[i] = uniform(0.1, 1), br[i] = uniform(0.1, 1);
    }
    a.px = ax, a.py = ay, a.vx = avx, a.vy = avy, a.radius = ar;
    b.px = bx, b.py = by, b.vx = bvx, b.vy = bvy, b.radius = br;
    mix_i(cc_sweep_many(N, &a, &b, 3.0, t, r));
    for (i = 0; i < N; i++) mix_d(t[i]), mix_i(r[i]);
}

static void stats(const cc_world *w)
{
    cc_world_stats st;
    memset(&st, 0, sizeof st);
    st.struct_size = sizeof st;
    mix_i(cc_world_get_stats(w, &st));
    mix_i((long long)st.collisions), mix_i((long long)st.events), mix_i((long long)st.stale_events);
    mix_i((long long)st.pairs_tested), mix_i((long long)st.cell_crossings), mix_d(st.max_overlap);
}

static void snapshot(const cc_world *w)
{
    static int ids[256];
    static cc_circle out[256];
    int n = cc_world_get_circles(w, ids, out, 256), i;
    mix_i(n), mix_d(cc_world_time(w));
    for (i = 0; i < n; i++) mix_i(ids[i]), mix_circle(&out[i]);
}

/* A walled box of 60 circles (some immovable, one kinematic), stepped with adds, sets and
 * removes between steps; then the world's bytes copied and both copies stepped on. */
static void world(int mode, int max_circles)
{
    cc_world_def def;
    cc_world *w, *w2;
    void *mem, *mem2;
    size_t bytes;
    int status = -100, i, step;
    cc_segment walls[4] = {{{-20, -20}, {20, -20}}, {{20, -20}, {20, 20}}, {{20, 20}, {-20, 20}}, {{-20, 20}, {-20, -20}}};

    cc_world_def_init(&def);
    def.max_circles = max_circles, def.max_segments = 8, def.mode = mode;
    def.restitution = 0.9, def.rest_speed = 1e-3, def.on_contact = on_contact, def.user = NULL;
    bytes = cc_world_size(&def);
    mem = malloc(bytes), mem2 = malloc(bytes);
    if (!mem || !mem2) exit(2);
    w = cc_world_init(mem, bytes, &def, &status);
    mix_i(status);
    if (!w) return;
    for (i = 0; i < 4; i++) mix_i(cc_world_add_segment(w, &walls[i]));
    for (i = 0; i < 60; i++) {
        cc_circle c;
        c.pos.x = uniform(-18, 18), c.pos.y = uniform(-18, 18), c.vel.x = uniform(-6, 6), c.vel.y = uniform(-6, 6);
        c.radius = uniform(0.3, 1.2), c.mass = i % 13 == 5 ? HUGE_VAL : c.radius * c.radius;
        if (i % 13 == 5 && i != 18) c.vel.x = c.vel.y = 0.0;
        mix_i(cc_world_add_circle(w, &c));
    }
    for (step = 0; step < 40; step++) {
        cc_circle c;
        mix_i(cc_world_step(w, 0.05 + 0.01 * (step % 7)));
        if (step % 5 == 1) mix_i(cc_world_remove_circle(w, (step * 7) % 60));
        if (step % 5 == 3) {
            c.pos.x = uniform(-15, 15), c.pos.y = uniform(-15, 15), c.vel.x = uniform(-9, 9), c.vel.y = uniform(-9, 9);
            c.radius = 0.5, c.mass = 1.0;
            mix_i(cc_world_add_circle(w, &c));
        }
        if (step % 7 == 2 && cc_world_get_circle(w, 3, &c) == CC_OK) {
            c.vel.x = -c.vel.x * 1.5, c.vel.y += 1.0;
            mix_i(cc_world_set_circle(w, 3, &c));
        }
        if (step % 10 == 9) snapshot(w), stats(w);
    }
    { cc_segment s; mix_i(cc_world_get_segment(w, 2, &s)); mix_d(s.a.x), mix_d(s.b.y); }
    mix_i(cc_world_step(NULL, 1.0)), mix_i(cc_world_step(w, -1.0)), mix_i(cc_world_add_circle(w, NULL));

    memcpy(mem2, mem, bytes); /* the header: a world may be copied and used from there */
    w2 = (cc_world *)mem2;
    for (step = 0; step < 10; step++) mix_i(cc_world_step(w, 0.07)), mix_i(cc_world_step(w2, 0.07));
    {
        uint64_t before = digest;
        snapshot(w);
        {
            uint64_t first = digest;
            digest = before;
            snapshot(w2);
            if (digest != first) {
                printf("compat: the memcpy'd world went another way (mode %d)\n", mode);
                exit(1);
            }
        }
    }
    stats(w);
    free(mem), free(mem2);
}

int main(void)
{
    int mode;
    mix_i((long long)cc_version() >> 16);
    mix_i(CC_OK), mix_i(CC_HIT), mix_i(CC_ERR_INVALID), mix_i(CC_EVENT_LIMIT);
    pairs();
    many();
    for (mode = CC_MODE_EXACT; mode <= CC_MODE_DISCRETE; mode++) {
        world(mode, 24);  /* all pairs, no grid */
        world(mode, 256); /* the grid */
    }
    printf("compat: header %d.%d, library %s: digest %016llx, %ld contacts\n", CC_VERSION_MAJOR,
           CC_VERSION_MINOR, cc_version_string(), (unsigned long long)digest, contacts_seen);
    return 0;
}
