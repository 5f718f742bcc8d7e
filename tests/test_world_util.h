/* Helpers shared by the world tests: aligned test memory with a canary after it, scenes, and
 * the invariants every test checks (energy, momentum, overlaps, escapes). Header-only. */
#ifndef TEST_WORLD_UTIL_H
#define TEST_WORLD_UTIL_H

#include "circlecollide.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define TW_CANARY 64 /* bytes checked after the world's buffer */

/* What a world made from this header's def (cc_world_def_init) answers for a cause that 1.2
 * names (CC_ERR_RANGE, CC_ERR_BUSY): the code itself once the def reaches past 1.1's last field,
 * CC_ERR_INVALID before (the header's Results), so that the tests hold on either side of the
 * def's 1.2 fields. */
static inline int tw_code(int code)
{
    return sizeof(cc_world_def) > offsetof(cc_world_def, period) + sizeof(cc_vec2) ? code : CC_ERR_INVALID;
}

/* A world in malloc'ed memory, aligned to 16 bytes by hand (C99 has no aligned_alloc), with
 * TW_CANARY bytes of 0xA5 after exactly cc_world_size(def) bytes. */
typedef struct tw_mem {
    unsigned char *raw;
    unsigned char *mem;
    size_t bytes;
} tw_mem;

static inline cc_world *tw_make(tw_mem *m, const cc_world_def *def, size_t extra_offset)
{
    size_t n = cc_world_size(def);
    int st = 1;
    cc_world *w;
    memset(m, 0, sizeof *m);
    m->bytes = n;
    m->raw = (unsigned char *)malloc(n + TW_CANARY + 32 + extra_offset);
    if (m->raw == NULL)
        return NULL;
    m->mem = m->raw + ((16u - ((size_t)m->raw & 15u)) & 15u) + extra_offset;
    memset(m->mem, 0x5A, n);
    memset(m->mem + n, 0xA5, TW_CANARY);
    w = cc_world_init(m->mem, n, def, &st);
    return st == CC_OK ? w : NULL;
}

/* This header's def with its defaults, in the given mode and with room for the given circles and
 * walls: what most world tests start from. */
static inline cc_world_def tw_def(int mode, int max_circles, int max_segments)
{
    cc_world_def d;
    cc_world_def_init(&d);
    d.mode = mode;
    d.max_circles = max_circles;
    d.max_segments = max_segments;
    return d;
}

/* A circle, a wall and a world's counters in one expression. */
static inline cc_circle tw_circle(double x, double y, double vx, double vy, double r, double m)
{
    cc_circle c;
    c.pos.x = x;
    c.pos.y = y;
    c.vel.x = vx;
    c.vel.y = vy;
    c.radius = r;
    c.mass = m;
    return c;
}

static inline cc_vec2 tw_vec2(double x, double y)
{
    cc_vec2 v;
    v.x = x;
    v.y = y;
    return v;
}

static inline cc_segment tw_segment(double ax, double ay, double bx, double by)
{
    cc_segment s;
    s.a.x = ax;
    s.a.y = ay;
    s.b.x = bx;
    s.b.y = by;
    return s;
}

static inline cc_world_stats tw_stats(const cc_world *w)
{
    cc_world_stats s;
    s.struct_size = sizeof s;
    (void)cc_world_get_stats(w, &s);
    return s;
}

static inline int tw_canary_ok(const tw_mem *m)
{
    size_t i;
    for (i = 0; i < TW_CANARY; i++)
        if (m->mem[m->bytes + i] != 0xA5)
            return 0;
    return 1;
}

static inline void tw_free(tw_mem *m) { free(m->raw); }

/* A deterministic pseudo-random number in [0, 1) (the tests must not depend on libc's rand). */
static inline double tw_rand(uint64_t *s)
{
    *s = *s * UINT64_C(6364136223846793005) + UINT64_C(1442695040888963407);
    return (double)(*s >> 11) / 9007199254740992.0;
}

/* A square box [0, L]^2 of four wall segments holding n circles of radius r and mass 1 on a
 * lattice, with random velocities in [-1, 1]^2. L follows from the area fraction phi:
 * n pi r^2 = phi L^2. Returns L. */
static inline double tw_fill_box(cc_world *w, int n, double r, double phi, uint64_t seed)
{
    double L = sqrt(n * 3.14159265358979323846 * r * r / phi), sp;
    int side = (int)ceil(sqrt((double)n)), i;
    cc_segment walls[4];
    walls[0].a.x = 0; walls[0].a.y = 0; walls[0].b.x = L; walls[0].b.y = 0;
    walls[1].a.x = L; walls[1].a.y = 0; walls[1].b.x = L; walls[1].b.y = L;
    walls[2].a.x = L; walls[2].a.y = L; walls[2].b.x = 0; walls[2].b.y = L;
    walls[3].a.x = 0; walls[3].a.y = L; walls[3].b.x = 0; walls[3].b.y = 0;
    for (i = 0; i < 4; i++)
        (void)cc_world_add_segment(w, &walls[i]);
    sp = L / side;
    for (i = 0; i < n; i++) {
        cc_circle c;
        c.pos.x = sp * (i % side + 0.5);
        c.pos.y = sp * (i / side + 0.5);
        c.vel.x = 2.0 * tw_rand(&seed) - 1.0;
        c.vel.y = 2.0 * tw_rand(&seed) - 1.0;
        c.radius = r;
        c.mass = 1.0;
        (void)cc_world_add_circle(w, &c);
    }
    return L;
}

typedef struct tw_totals {
    double energy, px, py;
} tw_totals;

static inline tw_totals tw_sum(const cc_circle *c, int n)
{
    tw_totals t = {0.0, 0.0, 0.0};
    int i;
    for (i = 0; i < n; i++) {
        if (isinf(c[i].mass))
            continue;
        t.energy += 0.5 * c[i].mass * (c[i].vel.x * c[i].vel.x + c[i].vel.y * c[i].vel.y);
        t.px += c[i].mass * c[i].vel.x;
        t.py += c[i].mass * c[i].vel.y;
    }
    return t;
}

/* Deepest overlap of any two of the n circles, relative to their radius sum: a cell sort would
 * be faster, but the tests keep n small enough for all pairs (sorted by x, pruned). */
static inline int tw_cmp_x(const void *a, const void *b)
{
    double xa = ((const cc_circle *)a)->pos.x, xb = ((const cc_circle *)b)->pos.x;
    return xa < xb ? -1 : xa > xb;
}
static inline double tw_max_rel_overlap(cc_circle *c, int n, double rmax)
{
    double worst = 0.0;
    int i, j;
    qsort(c, (size_t)n, sizeof *c, tw_cmp_x);
    for (i = 0; i < n; i++)
        for (j = i + 1; j < n && c[j].pos.x - c[i].pos.x < 2.0 * rmax; j++) {
            double dx = c[j].pos.x - c[i].pos.x, dy = c[j].pos.y - c[i].pos.y, R = c[i].radius + c[j].radius;
            double o = (R - sqrt(dx * dx + dy * dy)) / R;
            if (o > worst)
                worst = o;
        }
    return worst;
}

/* Circles whose centre left [r, L - r]^2 by more than tol * r: escaped or overlapping a wall. */
static inline int tw_escapes(const cc_circle *c, int n, double L, double tol)
{
    int i, k = 0;
    for (i = 0; i < n; i++) {
        double r = c[i].radius * (1.0 - tol);
        if (!(c[i].pos.x >= r && c[i].pos.x <= L - r && c[i].pos.y >= r && c[i].pos.y <= L - r))
            k++;
    }
    return k;
}

#endif
