/* The properties that every call must have, whatever the input (see fuzz_checks.h):
 *   - the result is one of the function's documented codes;
 *   - invalid input (NaN/Inf coordinates, radius <= 0, mass <= 0 or NaN, t_max < 0 or NaN,
 *     restitution outside [0, 1], a normal not of unit length, two immovable bodies) gives
 *     CC_ERR_INVALID, valid input never does;
 *   - on an error and on CC_MISS every output is untouched, bit for bit;
 *   - for valid input: outputs finite, t in [0, t_max], the normal a unit vector, depth 0 on a
 *     hit and > 0 on an overlap; velocities after an impulse finite (when the inputs are below
 *     2^(max exponent - 8), so that the answer is representable); cc_sweep_many bit-identical
 *     to cc_sweep per pair;
 *   - rolling to rest (1.1): the same for cc_sweep_rolling and cc_sweep_segment_rolling, and
 *     cc_sweep's bits when both decelerations are 0; on moderate inputs (magnitudes 2^-20..2^20)
 *     the gap at a hit's t is ~0 and a brute-force sampling (64 times, the contract's motion in
 *     long double) finds no deeper overlap before t (or anywhere up to the last stop or t_max
 *     on a miss); cc_rolling_advance keeps the direction, never speeds up, stops at s / decel,
 *     follows the contract's path, changes nothing on an error.
 * The sanitizers (ASan, UBSan) add: no out-of-bounds access, no undefined behaviour. */
#include "fuzz_checks.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "circlecollide.h"

typedef struct reader {
    const uint8_t *p;
    size_t n;
    int valid; /* flag bit 0: numbers made valid */
} reader;

static double rd(reader *r)
{
    uint8_t b[8] = {0};
    double x;
    size_t k = r->n < 8 ? r->n : 8;
    memcpy(b, r->p, k);
    r->p += k, r->n -= k;
    memcpy(&x, b, 8);
    return x;
}

static float rf(reader *r)
{
    uint8_t b[4] = {0};
    float x;
    size_t k = r->n < 4 ? r->n : 4;
    memcpy(b, r->p, k);
    r->p += k, r->n -= k;
    memcpy(&x, b, 4);
    return x;
}

/* in "valid" mode: a finite number (NaN and infinities become 1) */
static double fin(const reader *r, double x) { return r->valid && !isfinite(x) ? 1.0 : x; }
static double pos(const reader *r, double x) /* > 0 and finite */
{
    if (!r->valid)
        return x;
    x = fabs(fin(r, x));
    return x > 0.0 ? x : 1.0;
}
static double massv(const reader *r, double x) /* > 0, finite or +inf */
{
    if (!r->valid)
        return x;
    return isinf(x) ? HUGE_VAL : pos(r, x);
}
static double unit01(const reader *r, double x)
{
    if (!r->valid)
        return x;
    x = fabs(fin(r, x));
    return x <= 1.0 ? x : 1.0 / x;
}

/* ---- contract helpers, written independently of the library ------------------------------- */

static int fails; /* violations in the current input */

static void fail(const char *fn, const char *what)
{
    fprintf(stderr, "fuzz: %s: %s\n", fn, what);
    fails++;
}

#define CHECK(cond, fn, what)                                                                                        \
    do {                                                                                                             \
        if (!(cond))                                                                                                 \
            fail(fn, what);                                                                                          \
    } while (0)

static int v_ok(double x, double y) { return isfinite(x) && isfinite(y); }
static int circle_ok(double px, double py, double vx, double vy, double r, double m)
{
    return v_ok(px, py) && v_ok(vx, vy) && isfinite(r) && r > 0.0 && m > 0.0;
}
static int tmax_ok(double t) { return t >= 0.0; }
/* |n|^2 within a few ulps of 1 in precision eps */
static int unit_ok(double x, double y, double eps) { return v_ok(x, y) && fabs(x * x + y * y - 1.0) <= 8.0 * eps; }
/* the contract's caller normal: |n| within tol of 1 (checked with margin both ways below); hypot,
 * so that a length whose square would be subnormal (speeds near 1e-161) keeps its digits */
static double norm(double x, double y) { return hypot(x, y); }
static int below(double x, int max_exp) { return fabs(x) < ldexp(1.0, max_exp - 8); }
/* moderate numbers (every nonzero magnitude in 2^-20..2^20): where the rolling brute-force checks run */
static int moderate(double x) { return x == 0.0 || (fabs(x) > 0x1p-20 && fabs(x) < 0x1p20); }

/* One template per precision for the pair functions: FZ_R, FZ_V, ..., FZ_FN, FZ_READ, FZ_EPS,
 * FZ_MAX_EXP, FZ_TOL bound below. */
#define FZ_R double
#define FZ_V cc_vec2
#define FZ_CIRCLE cc_circle
#define FZ_SEGMENT cc_segment
#define FZ_CONTACT cc_contact
#define FZ_FN(name) name
#define FZ_READ rd
#define FZ_EPS DBL_EPSILON
#define FZ_MAX_EXP DBL_MAX_EXP
#define FZ_TOL 1e-6
#define FZ_SUFFIX ""
#include "fuzz_pair.inc"
#undef FZ_R
#undef FZ_V
#undef FZ_CIRCLE
#undef FZ_SEGMENT
#undef FZ_CONTACT
#undef FZ_FN
#undef FZ_READ
#undef FZ_EPS
#undef FZ_MAX_EXP
#undef FZ_TOL
#undef FZ_SUFFIX
#define FZ_CAT2(a, b) a##b
#define FZ_CAT(a, b) FZ_CAT2(a, b)
#define FZ_R float
#define FZ_V cc_vec2f
#define FZ_CIRCLE cc_circlef
#define FZ_SEGMENT cc_segmentf
#define FZ_CONTACT cc_contactf
#define FZ_FN(name) FZ_CAT(name, f)
#define FZ_READ rf
#define FZ_EPS FLT_EPSILON
#define FZ_MAX_EXP FLT_MAX_EXP
#define FZ_TOL 1e-4
#define FZ_SUFFIX "f"
#include "fuzz_pair.inc"

/* cc_sweep_many over n <= 4 pairs: all or nothing, and bit-identical to cc_sweep per pair */
static void fuzz_sweep_many(reader *r, size_t n)
{
    double col[10][4], t_max, t_out[4], t_ref[4], before[4];
    int res[4], i, k, valid = 1;
    long got;
    cc_circle_soa a, b;
    for (i = 0; i < (int)n; i++)
        for (k = 0; k < 10; k++)
            col[k][i] = (k == 4 || k == 9) ? pos(r, rd(r)) : fin(r, rd(r));
    t_max = r->valid ? fabs(rd(r)) : rd(r);
    a.px = col[0], a.py = col[1], a.vx = col[2], a.vy = col[3], a.radius = col[4];
    b.px = col[5], b.py = col[6], b.vx = col[7], b.vy = col[8], b.radius = col[9];
    for (i = 0; i < (int)n; i++) {
        valid &= circle_ok(col[0][i], col[1][i], col[2][i], col[3][i], col[4][i], 1.0);
        valid &= circle_ok(col[5][i], col[6][i], col[7][i], col[8][i], col[9][i], 1.0);
    }
    valid &= tmax_ok(t_max);
    memset(t_out, 0xA5, sizeof t_out);
    memcpy(before, t_out, sizeof before);
    got = cc_sweep_many(n, &a, &b, t_max, t_out, res);
    if (!valid) {
        CHECK(got == CC_ERR_INVALID, "cc_sweep_many", "invalid input not reported");
        CHECK(!memcmp(before, t_out, sizeof t_out), "cc_sweep_many", "output written on an error");
        return;
    }
    CHECK(got >= 0 && got <= (long)n, "cc_sweep_many", "count outside [0, n]");
    for (i = 0; i < (int)n; i++) {
        cc_circle ca, cb;
        cc_contact k;
        int rr;
        ca.pos.x = col[0][i], ca.pos.y = col[1][i], ca.vel.x = col[2][i], ca.vel.y = col[3][i];
        ca.radius = col[4][i], ca.mass = 1.0;
        cb.pos.x = col[5][i], cb.pos.y = col[6][i], cb.vel.x = col[7][i], cb.vel.y = col[8][i];
        cb.radius = col[9][i], cb.mass = 1.0;
        rr = cc_sweep(&ca, &cb, t_max, &k);
        t_ref[i] = rr == CC_HIT ? k.t : rr == CC_OVERLAP ? 0.0 : HUGE_VAL;
        CHECK(rr == res[i], "cc_sweep_many", "result differs from cc_sweep");
        CHECK(!memcmp(&t_ref[i], &t_out[i], sizeof(double)), "cc_sweep_many", "t not bit-identical to cc_sweep");
    }
}

int fuzz_function(uint8_t b0) { return b0 < 240 ? b0 % 15 : 15 + (b0 - 240) % 6; }

int fuzz_one(const uint8_t *data, size_t size)
{
    reader r;
    int fn;
    size_t count;
    if (size < 3)
        return 0;
    fn = fuzz_function(data[0]);
    r.valid = data[1] & 1;
    count = data[2] % 5; /* 0..4 pairs for cc_sweep_many */
    r.p = data + 3, r.n = size - 3;
    fails = 0;
    switch (fn) {
    case 0: fuzz_sweep(&r); break;
    case 1: fuzz_sweepf(&r); break;
    case 2: fuzz_sweep_segment(&r); break;
    case 3: fuzz_sweep_segmentf(&r); break;
    case 4: fuzz_detect_static(&r); break;
    case 5: fuzz_detect_staticf(&r); break;
    case 6: fuzz_separate(&r); break;
    case 7: fuzz_separatef(&r); break;
    case 8: fuzz_respond(&r); break;
    case 9: fuzz_respondf(&r); break;
    case 10: fuzz_respond_segment(&r); break;
    case 11: fuzz_respond_segmentf(&r); break;
    case 12: fuzz_closest_point(&r); break;
    case 13: fuzz_closest_pointf(&r); break;
    case 14: fuzz_sweep_many(&r, count); break;
    case 15: fuzz_sweep_rolling(&r); break;
    case 16: fuzz_sweep_rollingf(&r); break;
    case 17: fuzz_sweep_segment_rolling(&r); break;
    case 18: fuzz_sweep_segment_rollingf(&r); break;
    case 19: fuzz_rolling_advance(&r); break;
    default: fuzz_rolling_advancef(&r); break;
    }
    return fails;
}
