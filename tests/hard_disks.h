/* What the hard-disk physics test (test_physics_hard_disks.c) and the slow figures' program
 * (physics_eos.c) share: their generator, the literature's equations of state, Enskog's rate and
 * the start of every run (equal disks of radius 1/2 and mass 1 on a square lattice in a periodic
 * box, an EXACT world). Public API only; static functions, header only. */
#ifndef CC_TESTS_HARD_DISKS_H
#define CC_TESTS_HARD_DISKS_H

#include "circlecollide.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define HD_RADIUS 0.5
#define HD_KT 1.0

/* ---- splitmix64: the same numbers on every target ---- */
static uint64_t hd_rng_state;
static inline uint64_t hd_rng_next(void)
{
    uint64_t z = (hd_rng_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
static inline double hd_uniform(void) { return (double)(hd_rng_next() >> 11) * (1.0 / 9007199254740992.0); }

/* ---- the literature ---- */

/* Henderson, Mol. Phys. 30, 971 (1975). */
static inline double hd_z_henderson(double eta) { return (1.0 + eta * eta / 8.0) / ((1.0 - eta) * (1.0 - eta)); }

/* Kolafa and Rottner, Mol. Phys. 104, 3435 (2006), eq. (7) with the rho_max = 0.90 coefficients
 * of their section 3.2: Z = sum_i A_i x^i, x = eta / (1 - eta); a fit to finite-size-corrected
 * simulations and the known virial coefficients, valid to the reduced density rho sigma^2 = 0.90
 * (eta = 0.7069); NaN beyond (the x^57 term takes over). docs/PHYSICS.md. */
static inline double hd_z_kolafa_rottner(double eta)
{
    static const double a[] = {1.0, 2.0, 1.12801775, 0.00181895291, -0.0526134737, 0.0504960168, -0.0325537792,
                               0.0134578632, 0.00140888182, -0.00834273601, 0.00694127367, -0.00262254723,
                               0.000355746352};
    double x = eta / (1.0 - eta), z = 0.0;
    int i;
    if (eta > 0.90 * M_PI / 4.0 + 1e-12)
        return NAN;
    for (i = 12; i >= 0; i--)
        z = z * x + a[i];
    return z - 5.24672938e-9 * pow(x, 22) + 5.88054639e-23 * pow(x, 57);
}

/* Enskog's collision rate per disk in 2D from Z: 4 (Z - 1) / sigma * sqrt(kT / (pi m)). */
static inline double hd_enskog_rate(double z, double sigma) { return 4.0 * (z - 1.0) / sigma * sqrt(HD_KT / M_PI); }

/* ---- the start of a run ---- */
typedef struct hd_box {
    unsigned char *raw; /* malloc'ed; the world sits at its first 16-byte boundary */
    cc_world *w;
    int n;
    double eta, box;
} hd_box;

/* n disks on the first n sites of a square lattice (side ceil(sqrt n)) in a periodic square of
 * side L, n pi r^2 = eta L^2; equal speeds in random directions (a start far from
 * Maxwell-Boltzmann, drawn from hd_uniform), zero momentum, kinetic energy exactly n kT. c (n
 * circles) receives the disks as added. NULL, or what failed. */
static inline const char *hd_box_make(hd_box *s, int n, double eta, cc_circle *c)
{
    cc_world_def d;
    size_t bytes;
    int st = -1, i, side = (int)ceil(sqrt((double)n));
    double mx = 0.0, my = 0.0, ke = 0.0, f, a;
    memset(s, 0, sizeof *s);
    s->n = n;
    s->eta = eta;
    s->box = sqrt(n * M_PI * HD_RADIUS * HD_RADIUS / eta);
    cc_world_def_init(&d);
    d.mode = CC_MODE_EXACT;
    d.max_circles = n;
    d.restitution = 1.0;
    d.period.x = s->box;
    d.period.y = s->box;
    d.max_events = 10000000u; /* blocks of many collisions per disk in one call: an offline run */
    bytes = cc_world_size(&d);
    if (bytes == 0)
        return "cc_world_size";
    s->raw = (unsigned char *)malloc(bytes + 16);
    if (s->raw == NULL)
        return "out of memory";
    s->w = cc_world_init(s->raw + ((16u - ((size_t)s->raw & 15u)) & 15u), bytes, &d, &st);
    if (s->w == NULL || st != CC_OK)
        return "cc_world_init";
    a = s->box / side;
    if (!(a > 2.0 * HD_RADIUS))
        return "the square lattice overlaps at this eta";
    for (i = 0; i < n; i++) {
        double th = 2.0 * M_PI * hd_uniform();
        c[i].pos.x = (i % side + 0.5) * a;
        c[i].pos.y = (i / side + 0.5) * a;
        c[i].vel.x = cos(th);
        c[i].vel.y = sin(th);
        c[i].radius = HD_RADIUS;
        c[i].mass = 1.0;
        mx += c[i].vel.x;
        my += c[i].vel.y;
    }
    mx /= n;
    my /= n;
    for (i = 0; i < n; i++) {
        c[i].vel.x -= mx;
        c[i].vel.y -= my;
        ke += 0.5 * (c[i].vel.x * c[i].vel.x + c[i].vel.y * c[i].vel.y);
    }
    f = sqrt(n * HD_KT / ke);
    for (i = 0; i < n; i++) {
        c[i].vel.x *= f;
        c[i].vel.y *= f;
        if (cc_world_add_circle(s->w, &c[i]) != i)
            return "cc_world_add_circle";
    }
    return NULL;
}

static inline void hd_box_free(hd_box *s)
{
    free(s->raw);
    memset(s, 0, sizeof *s);
}

/* The world's counters (struct_size set). */
static inline int hd_stats(const cc_world *w, cc_world_stats *st)
{
    memset(st, 0, sizeof *st);
    st->struct_size = sizeof *st;
    return cc_world_get_stats(w, st);
}

#endif
