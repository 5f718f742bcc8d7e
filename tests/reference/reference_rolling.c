/* The reference for rolling to rest (see reference.h): cc_sweep_rolling and
 * cc_sweep_segment_rolling answered at REF_ROLL_PREC bits from the exact inputs.
 *
 * Two circles: each is at p + v g(t), g(t) = t - k t^2 (k = decel / (2|v|)) until its stop at
 * ts = |v| / decel, then at p + v ts / 2 (a circle without deceleration: g(t) = t). Between the
 * stops (and t_max) the offset o(t) = dp + vb gb(t) - va ga(t) is a polynomial of degree two
 * in t, so f(t) = |o|^2 - R^2 is a polynomial of degree <= 4 on each piece: its coefficients
 * are formed (at REF_ROLL_PREC bits, where the expansion's cancellation costs nothing that
 * matters) and its real roots isolated by the classical cascade: the root of f''' (linear),
 * then the sign changes of f'', f', f between them, each bisected. The first part on which f
 * falls from > 0 through 0 gives the contact, bisected to ~140 bits. Overlap at t = 0, and the
 * touching-and-approaching hit at t = 0, are decided exactly by the straight reference
 * (rationals), as the library decides them with cc_sweep over [0, 0].
 *
 * A circle against a wall: the circle moves along a straight line, its path length |v| g(t)
 * growing monotonically until the stop; so the first contact is the straight sweep's first
 * contact at "straight time" tau (decided exactly, with rationals, by the straight reference),
 * reached at the t with g(t) = tau, t = 2 tau / (1 + sqrt(1 - 4 k tau)), provided tau < g(ts)
 * = 1 / (4k) and t <= t_max (compared at REF_ROLL_PREC bits).
 *
 * Ties: a value within 2^-(REF_ROLL_PREC - 70) of its scale is taken as exactly zero, and the
 * result is marked `degenerate` (tangency, a touch exactly at a stop, a contact exactly at
 * t_max): such cases are counted apart by the accuracy measure, not judged. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "reference_internal.h"

#define RP REF_ROLL_PREC
#define TIE_BITS (RP - 70)
#define ROOT_BITS 170 /* bisection of the derivatives' roots: relative width 2^-ROOT_BITS */
#define TIME_BITS 140 /* of the contact time */

/* ---- building problems ------------------------------------------------------------------ */

void ref_roll_circles(ref_problem *p, const cc_circle *a, double decel_a, const cc_circle *b, double decel_b,
                      double t_max)
{
    ref_circles(p, a, b, t_max);
    p->kind = REF_ROLL_CIRCLES, p->n = 13;
    p->x[10] = decel_a, p->x[11] = decel_b, p->x[12] = t_max;
}

void ref_roll_segment(ref_problem *p, const cc_circle *c, double decel, const cc_segment *s, double t_max)
{
    ref_segment(p, c, s, t_max);
    p->kind = REF_ROLL_SEGMENT, p->n = 11;
    p->x[9] = decel, p->x[10] = t_max;
}

void ref_roll_circlesf(ref_problem *p, const cc_circlef *a, float decel_a, const cc_circlef *b, float decel_b,
                       float t_max)
{
    ref_circlesf(p, a, b, t_max);
    p->kind = REF_ROLL_CIRCLES, p->n = 13;
    p->x[10] = decel_a, p->x[11] = decel_b, p->x[12] = t_max;
}

void ref_roll_segmentf(ref_problem *p, const cc_circlef *c, float decel, const cc_segmentf *s, float t_max)
{
    ref_segmentf(p, c, s, t_max);
    p->kind = REF_ROLL_SEGMENT, p->n = 11;
    p->x[9] = decel, p->x[10] = t_max;
}

static double t_limit(const ref_problem *p, const double *x)
{
    double big = p->is_float ? FLT_MAX : DBL_MAX, t = x[p->n - 1];
    return t < big ? t : big;
}

/* The straight problem behind a rolling one (inputs x), with the given t_max. */
static void straight(const ref_problem *p, const double *x, double t_max, ref_problem *q)
{
    int i;
    q->is_float = p->is_float;
    if (p->kind == REF_ROLL_CIRCLES) {
        q->kind = REF_CIRCLES, q->n = 11;
        for (i = 0; i < 10; i++)
            q->x[i] = x[i];
        q->x[10] = t_max;
    } else {
        q->kind = REF_SEGMENT, q->n = 10;
        for (i = 0; i < 9; i++)
            q->x[i] = x[i];
        q->x[9] = t_max;
    }
}

static int rolls(double decel, double vx, double vy) { return decel > 0.0 && (vx != 0.0 || vy != 0.0); }

/* ---- two circles ---------------------------------------------------------------------------- */

enum { V_DPX, V_DPY, V_R, V_VAX, V_VAY, V_VBX, V_VBY, V_SA, V_SB, V_KA, V_KB, V_TSA, V_TSB,
       V_C0X, V_C0Y, V_C1X, V_C1Y, V_C2X, V_C2Y, V_N0, V_N1, V_N2,
       V_T, V_U, V_W, V_A, V_B, V_C, V_D, V_E, V_LO, V_HI, V_MID, V_ROOT,
       V_MIN, V_FIRSTMIN, V_FEND, V_FSA, V_FSB, V_CLOSING, V_TSTAR, V_COUNT };

typedef struct roll {
    mpfr_t v[V_COUNT];
    mpfr_t D[4][5]; /* D[j][i]: coefficient of t^(i - j) in the j-th derivative of f */
    int deg;
    int rolla, rollb;
    int degenerate;
    int have_first_min;
} roll;

#define RV(r, name) ((r)->v[V_##name])

static void roll_init(roll *r)
{
    int i, j;
    for (i = 0; i < V_COUNT; i++)
        mpfr_init2(r->v[i], RP);
    for (j = 0; j < 4; j++)
        for (i = 0; i < 5; i++)
            mpfr_init2(r->D[j][i], RP);
    r->deg = 0, r->degenerate = 0, r->have_first_min = 0;
}

static void roll_clear(roll *r)
{
    int i, j;
    for (i = 0; i < V_COUNT; i++)
        mpfr_clear(r->v[i]);
    for (j = 0; j < 4; j++)
        for (i = 0; i < 5; i++)
            mpfr_clear(r->D[j][i]);
}

/* derivative j of f at t, into out (distinct from t) */
static void f_at(roll *r, int j, mpfr_t t, mpfr_t out)
{
    int i;
    if (j > r->deg) {
        mpfr_set_zero(out, 1);
        return;
    }
    mpfr_set(out, r->D[j][r->deg], MPFR_RNDN);
    for (i = r->deg - 1; i >= j; i--) {
        mpfr_mul(out, out, t, MPFR_RNDN);
        mpfr_add(out, out, r->D[j][i], MPFR_RNDN);
    }
}

/* the scale of |o| at t (|c0| + |c1| t + |c2| t^2 + R), squared times 2^-TIE_BITS: f's tie band;
 * for f' (j = 1) the scale times that of o' (|c1| + 2 |c2| t) */
static void tie(roll *r, int j, mpfr_t t, mpfr_t out)
{
    mpfr_t s, d;
    mpfr_inits2(RP, s, d, (mpfr_ptr)0);
    mpfr_mul(s, RV(r, N2), t, MPFR_RNDN);
    mpfr_add(s, s, RV(r, N1), MPFR_RNDN);
    mpfr_mul(s, s, t, MPFR_RNDN);
    mpfr_add(s, s, RV(r, N0), MPFR_RNDN);
    mpfr_add(s, s, RV(r, R), MPFR_RNDN);
    if (j == 0)
        mpfr_sqr(out, s, MPFR_RNDN);
    else {
        mpfr_mul_2ui(d, RV(r, N2), 1, MPFR_RNDN);
        mpfr_mul(d, d, t, MPFR_RNDN);
        mpfr_add(d, d, RV(r, N1), MPFR_RNDN);
        mpfr_mul(out, s, d, MPFR_RNDN);
    }
    mpfr_mul_2si(out, out, -TIE_BITS, MPFR_RNDN);
    mpfr_clears(s, d, (mpfr_ptr)0);
}

/* -1, 0 (within the tie band) or +1: the sign of derivative j of f at t */
static int f_sign(roll *r, int j, mpfr_t t)
{
    mpfr_t y, z;
    int s;
    mpfr_inits2(RP, y, z, (mpfr_ptr)0);
    f_at(r, j, t, y);
    if (j <= 1) {
        tie(r, j, t, z);
        s = mpfr_cmpabs(y, z) <= 0 ? 0 : mpfr_sgn(y);
    } else {
        s = mpfr_sgn(y);
    }
    mpfr_clears(y, z, (mpfr_ptr)0);
    return s;
}

/* the root of derivative j in [lo, hi], whose signs at the ends differ (bisection to `bits`;
 * geometric while the interval spans many orders of magnitude) */
static void bisect(roll *r, int j, mpfr_t lo_in, mpfr_t hi_in, int bits, mpfr_t root)
{
    mpfr_t lo, hi, mid, y, w;
    int slo;
    mpfr_inits2(RP, lo, hi, mid, y, w, (mpfr_ptr)0);
    mpfr_set(lo, lo_in, MPFR_RNDN);
    mpfr_set(hi, hi_in, MPFR_RNDN);
    f_at(r, j, lo, y);
    slo = mpfr_sgn(y);
    for (;;) {
        mpfr_sub(w, hi, lo, MPFR_RNDN);
        mpfr_mul_2si(y, hi, -bits, MPFR_RNDN);
        if (mpfr_cmpabs(w, y) <= 0)
            break;
        if (mpfr_sgn(lo) > 0 && mpfr_cmp(hi, lo) > 0 && mpfr_cmp_d(w, 0.0) > 0) {
            mpfr_div(y, hi, lo, MPFR_RNDN);
            if (mpfr_cmp_ui(y, 16) > 0) {
                mpfr_mul(mid, lo, hi, MPFR_RNDN);
                mpfr_sqrt(mid, mid, MPFR_RNDN);
            } else {
                mpfr_add(mid, lo, hi, MPFR_RNDN);
                mpfr_mul_2si(mid, mid, -1, MPFR_RNDN);
            }
        } else if (mpfr_zero_p(lo) && mpfr_cmp_d(hi, 1.0) > 0) {
            mpfr_sqrt(mid, hi, MPFR_RNDN);
        } else {
            mpfr_add(mid, lo, hi, MPFR_RNDN);
            mpfr_mul_2si(mid, mid, -1, MPFR_RNDN);
        }
        if (!(mpfr_cmp(mid, lo) > 0 && mpfr_cmp(mid, hi) < 0))
            break;
        f_at(r, j, mid, y);
        if (mpfr_sgn(y) == 0) {
            mpfr_set(lo, mid, MPFR_RNDN);
            mpfr_set(hi, mid, MPFR_RNDN);
            break;
        }
        if ((mpfr_sgn(y) > 0) == (slo > 0))
            mpfr_set(lo, mid, MPFR_RNDN);
        else
            mpfr_set(hi, mid, MPFR_RNDN);
    }
    mpfr_set(root, hi, MPFR_RNDN);
    mpfr_clears(lo, hi, mid, y, w, (mpfr_ptr)0);
}

/* the points in (lo, hi) where derivative j changes sign, ascending (at most 3); returns how many */
static int sign_changes(roll *r, int j, mpfr_t lo, mpfr_t hi, mpfr_t *out)
{
    mpfr_t cuts[5], a, b;
    int n = 0, m, k;
    if (j >= r->deg)
        return 0; /* constant */
    mpfr_inits2(RP, a, b, (mpfr_ptr)0);
    for (k = 0; k < 5; k++)
        mpfr_init2(cuts[k], RP);
    mpfr_set(cuts[0], lo, MPFR_RNDN);
    m = 1 + (j + 1 < r->deg ? sign_changes(r, j + 1, lo, hi, cuts + 1) : 0);
    mpfr_set(cuts[m++], hi, MPFR_RNDN);
    for (k = 0; k + 1 < m; k++) {
        f_at(r, j, cuts[k], a);
        f_at(r, j, cuts[k + 1], b);
        if (mpfr_sgn(a) != 0 && mpfr_sgn(b) != 0 && mpfr_sgn(a) != mpfr_sgn(b) && n < 3)
            bisect(r, j, cuts[k], cuts[k + 1], ROOT_BITS, out[n++]);
    }
    for (k = 0; k < 5; k++)
        mpfr_clear(cuts[k]);
    mpfr_clears(a, b, (mpfr_ptr)0);
    return n;
}

/* |x, y| into out */
static void hyp(mpfr_t out, mpfr_t x, mpfr_t y) { mpfr_hypot(out, x, y, MPFR_RNDN); }

/* one circle's part of the offset on the piece starting at lo: sign +1 for b, -1 for a */
static void add_motion(roll *r, int sgn, int rolling, mpfr_t vx, mpfr_t vy, mpfr_t k, mpfr_t ts, mpfr_t lo)
{
    mpfr_t q;
    mpfr_init2(q, RP);
    if (!rolling) { /* straight (or at rest, v = 0) */
        mpfr_mul_si(q, vx, sgn, MPFR_RNDN), mpfr_add(RV(r, C1X), RV(r, C1X), q, MPFR_RNDN);
        mpfr_mul_si(q, vy, sgn, MPFR_RNDN), mpfr_add(RV(r, C1Y), RV(r, C1Y), q, MPFR_RNDN);
    } else if (mpfr_cmp(lo, ts) < 0) { /* rolling: v t - k v t^2 */
        mpfr_mul_si(q, vx, sgn, MPFR_RNDN), mpfr_add(RV(r, C1X), RV(r, C1X), q, MPFR_RNDN);
        mpfr_mul_si(q, vy, sgn, MPFR_RNDN), mpfr_add(RV(r, C1Y), RV(r, C1Y), q, MPFR_RNDN);
        mpfr_mul(q, vx, k, MPFR_RNDN), mpfr_mul_si(q, q, -sgn, MPFR_RNDN), mpfr_add(RV(r, C2X), RV(r, C2X), q, MPFR_RNDN);
        mpfr_mul(q, vy, k, MPFR_RNDN), mpfr_mul_si(q, q, -sgn, MPFR_RNDN), mpfr_add(RV(r, C2Y), RV(r, C2Y), q, MPFR_RNDN);
    } else { /* at rest: v ts / 2 */
        mpfr_mul(q, vx, ts, MPFR_RNDN), mpfr_mul_2si(q, q, -1, MPFR_RNDN), mpfr_mul_si(q, q, sgn, MPFR_RNDN);
        mpfr_add(RV(r, C0X), RV(r, C0X), q, MPFR_RNDN);
        mpfr_mul(q, vy, ts, MPFR_RNDN), mpfr_mul_2si(q, q, -1, MPFR_RNDN), mpfr_mul_si(q, q, sgn, MPFR_RNDN);
        mpfr_add(RV(r, C0Y), RV(r, C0Y), q, MPFR_RNDN);
    }
    mpfr_clear(q);
}

/* the coefficients of f on the piece starting at lo */
static void set_piece(roll *r, mpfr_t lo)
{
    mpfr_t q, s;
    int i, j;
    mpfr_inits2(RP, q, s, (mpfr_ptr)0);
    mpfr_set(RV(r, C0X), RV(r, DPX), MPFR_RNDN), mpfr_set(RV(r, C0Y), RV(r, DPY), MPFR_RNDN);
    mpfr_set_zero(RV(r, C1X), 1), mpfr_set_zero(RV(r, C1Y), 1), mpfr_set_zero(RV(r, C2X), 1), mpfr_set_zero(RV(r, C2Y), 1);
    add_motion(r, 1, r->rollb, RV(r, VBX), RV(r, VBY), RV(r, KB), RV(r, TSB), lo);
    add_motion(r, -1, r->rolla, RV(r, VAX), RV(r, VAY), RV(r, KA), RV(r, TSA), lo);
    hyp(RV(r, N0), RV(r, C0X), RV(r, C0Y));
    hyp(RV(r, N1), RV(r, C1X), RV(r, C1Y));
    hyp(RV(r, N2), RV(r, C2X), RV(r, C2Y));
    /* e0 = c0.c0 - R^2, e1 = 2 c0.c1, e2 = c1.c1 + 2 c0.c2, e3 = 2 c1.c2, e4 = c2.c2 */
#define DOT(o, ax, ay, bx, by) (mpfr_mul(o, RV(r, ax), RV(r, bx), MPFR_RNDN), mpfr_fma(o, RV(r, ay), RV(r, by), o, MPFR_RNDN))
    DOT(r->D[0][0], C0X, C0Y, C0X, C0Y);
    mpfr_sqr(q, RV(r, R), MPFR_RNDN);
    mpfr_sub(r->D[0][0], r->D[0][0], q, MPFR_RNDN);
    DOT(r->D[0][1], C0X, C0Y, C1X, C1Y);
    mpfr_mul_2ui(r->D[0][1], r->D[0][1], 1, MPFR_RNDN);
    DOT(r->D[0][2], C0X, C0Y, C2X, C2Y);
    mpfr_mul_2ui(r->D[0][2], r->D[0][2], 1, MPFR_RNDN);
    DOT(s, C1X, C1Y, C1X, C1Y);
    mpfr_add(r->D[0][2], r->D[0][2], s, MPFR_RNDN);
    DOT(r->D[0][3], C1X, C1Y, C2X, C2Y);
    mpfr_mul_2ui(r->D[0][3], r->D[0][3], 1, MPFR_RNDN);
    DOT(r->D[0][4], C2X, C2Y, C2X, C2Y);
#undef DOT
    r->deg = 4;
    while (r->deg > 0 && mpfr_zero_p(r->D[0][r->deg]))
        r->deg--;
    for (j = 1; j < 4; j++)
        for (i = 0; i < 5; i++) {
            if (i < j || i > r->deg)
                mpfr_set_zero(r->D[j][i], 1);
            else
                mpfr_mul_ui(r->D[j][i], r->D[j - 1][i], (unsigned long)(i - j + 1), MPFR_RNDN);
        }
    mpfr_clears(q, s, (mpfr_ptr)0);
}

/* inputs x into r; returns 1 when some circle rolls */
static int roll_load(roll *r, const double *x)
{
    mpfr_set_d(RV(r, DPX), x[5], MPFR_RNDN), mpfr_sub_d(RV(r, DPX), RV(r, DPX), x[0], MPFR_RNDN);
    mpfr_set_d(RV(r, DPY), x[6], MPFR_RNDN), mpfr_sub_d(RV(r, DPY), RV(r, DPY), x[1], MPFR_RNDN);
    mpfr_set_d(RV(r, R), x[4], MPFR_RNDN), mpfr_add_d(RV(r, R), RV(r, R), x[9], MPFR_RNDN);
    mpfr_set_d(RV(r, VAX), x[2], MPFR_RNDN), mpfr_set_d(RV(r, VAY), x[3], MPFR_RNDN);
    mpfr_set_d(RV(r, VBX), x[7], MPFR_RNDN), mpfr_set_d(RV(r, VBY), x[8], MPFR_RNDN);
    hyp(RV(r, SA), RV(r, VAX), RV(r, VAY));
    hyp(RV(r, SB), RV(r, VBX), RV(r, VBY));
    r->rolla = rolls(x[10], x[2], x[3]);
    r->rollb = rolls(x[11], x[7], x[8]);
    /* k = decel / (2 s), ts = s / decel; +inf for a circle that does not roll */
    if (r->rolla) {
        mpfr_div_d(RV(r, TSA), RV(r, SA), x[10], MPFR_RNDN);
        mpfr_ui_div(RV(r, KA), 1, RV(r, TSA), MPFR_RNDN), mpfr_mul_2si(RV(r, KA), RV(r, KA), -1, MPFR_RNDN);
    } else {
        mpfr_set_inf(RV(r, TSA), 1), mpfr_set_zero(RV(r, KA), 1);
    }
    if (r->rollb) {
        mpfr_div_d(RV(r, TSB), RV(r, SB), x[11], MPFR_RNDN);
        mpfr_ui_div(RV(r, KB), 1, RV(r, TSB), MPFR_RNDN), mpfr_mul_2si(RV(r, KB), RV(r, KB), -1, MPFR_RNDN);
    } else {
        mpfr_set_inf(RV(r, TSB), 1), mpfr_set_zero(RV(r, KB), 1);
    }
    return r->rolla || r->rollb;
}

static void fmin_update(roll *r, mpfr_t t)
{
    mpfr_t y;
    mpfr_init2(y, RP);
    f_at(r, 0, t, y);
    if (mpfr_cmp(y, RV(r, MIN)) < 0)
        mpfr_set(RV(r, MIN), y, MPFR_RNDN);
    mpfr_clear(y);
}

/* Scans [0, tlim] piece by piece: returns 1 with the contact time in V_TSTAR when f first falls
 * through zero, else 0. Records on the way (for the margins): the least f seen (V_MIN), f at
 * the first local minimum (V_FIRSTMIN), at tlim (V_FEND) and at the stops (V_FSA, V_FSB). */
static int roll_scan(roll *r, double tlim_d)
{
    mpfr_t cuts[4], parts[6], tl, a, b;
    int nc = 0, k, hit = 0, i;
    mpfr_inits2(RP, tl, a, b, (mpfr_ptr)0);
    for (i = 0; i < 4; i++)
        mpfr_init2(cuts[i], RP);
    for (i = 0; i < 6; i++)
        mpfr_init2(parts[i], RP);
    mpfr_set_d(tl, tlim_d, MPFR_RNDN);
    mpfr_set_inf(RV(r, MIN), 1);
    mpfr_set_zero(RV(r, FSA), 1), mpfr_set_zero(RV(r, FSB), 1);
    r->have_first_min = 0;
    /* cuts: 0, the stops before tlim in order, tlim */
    mpfr_set_zero(cuts[nc++], 1);
    {
        int first_a = mpfr_cmp(RV(r, TSA), RV(r, TSB)) <= 0;
        mpfr_ptr s1 = first_a ? RV(r, TSA) : RV(r, TSB), s2 = first_a ? RV(r, TSB) : RV(r, TSA);
        if (mpfr_number_p(s1) && mpfr_cmp(s1, tl) < 0 && mpfr_sgn(s1) > 0)
            mpfr_set(cuts[nc++], s1, MPFR_RNDN);
        if (mpfr_number_p(s2) && mpfr_cmp(s2, tl) < 0 && mpfr_cmp(s2, cuts[nc - 1]) > 0)
            mpfr_set(cuts[nc++], s2, MPFR_RNDN);
    }
    mpfr_set(cuts[nc++], tl, MPFR_RNDN);
    for (k = 0; k + 1 < nc && !hit; k++) {
        int np, q;
        set_piece(r, cuts[k]);
        if (mpfr_equal_p(cuts[k], RV(r, TSA)))
            f_at(r, 0, cuts[k], RV(r, FSA));
        if (mpfr_equal_p(cuts[k], RV(r, TSB)))
            f_at(r, 0, cuts[k], RV(r, FSB));
        mpfr_set(parts[0], cuts[k], MPFR_RNDN);
        np = 1 + sign_changes(r, 1, cuts[k], cuts[k + 1], parts + 1);
        mpfr_set(parts[np++], cuts[k + 1], MPFR_RNDN);
        for (q = 0; q < np; q++)
            fmin_update(r, parts[q]);
        for (q = 0; q + 1 < np && !hit; q++) {
            int su = f_sign(r, 0, parts[q]), sw = f_sign(r, 0, parts[q + 1]);
            f_at(r, 1, parts[q], a);
            if (!r->have_first_min && q > 0 && mpfr_sgn(a) > 0) { /* f' turned from - to + at parts[q] */
                f_at(r, 0, parts[q], RV(r, FIRSTMIN));
                r->have_first_min = 1;
            }
            if (su > 0 && sw < 0) {
                bisect(r, 0, parts[q], parts[q + 1], TIME_BITS, RV(r, TSTAR));
                hit = 1;
            } else if (su > 0 && sw == 0) {
                /* reaches 0 at the part's end: a tangency (no crossing) unless still approaching */
                r->degenerate = 1;
                if (f_sign(r, 1, parts[q + 1]) < 0) {
                    mpfr_set(RV(r, TSTAR), parts[q + 1], MPFR_RNDN);
                    hit = 1;
                }
            } else if (su == 0 && sw < 0) {
                /* from a touch into overlap: at t = 0 (cc_sweep over [0, 0] found no approach) a
                 * second-order touch, no hit by the contract (approach speed 0: the pair is
                 * pushed into overlap), the scan goes on for a later crossing after parting;
                 * later (after a tie) the contact is at the touch */
                r->degenerate = 1;
                if (k > 0 || q > 0) {
                    mpfr_set(RV(r, TSTAR), parts[q], MPFR_RNDN);
                    hit = 1;
                }
            }
        }
        if (!hit && k + 2 == nc)
            f_at(r, 0, cuts[k + 1], RV(r, FEND));
    }
    if (!r->have_first_min)
        mpfr_set(RV(r, FIRSTMIN), RV(r, MIN), MPFR_RNDN);
    if (hit) { /* the closing speed there: -f' / (2R) */
        f_at(r, 1, RV(r, TSTAR), RV(r, CLOSING));
        mpfr_neg(RV(r, CLOSING), RV(r, CLOSING), MPFR_RNDN);
        mpfr_div(RV(r, CLOSING), RV(r, CLOSING), RV(r, R), MPFR_RNDN);
        mpfr_mul_2si(RV(r, CLOSING), RV(r, CLOSING), -1, MPFR_RNDN);
        f_at(r, 0, RV(r, TSTAR), RV(r, FEND));
    }
    for (i = 0; i < 4; i++)
        mpfr_clear(cuts[i]);
    for (i = 0; i < 6; i++)
        mpfr_clear(parts[i]);
    mpfr_clears(tl, a, b, (mpfr_ptr)0);
    return hit;
}

static void put_time(ref_result *out, mpfr_t t)
{
    mpfr_t lo;
    mpfr_init2(lo, RP);
    out->t_hi = mpfr_get_d(t, MPFR_RNDN);
    mpfr_sub_d(lo, t, out->t_hi, MPFR_RNDN);
    out->t_lo = mpfr_get_d(lo, MPFR_RNDN);
    mpfr_clear(lo);
}

static int solve_roll_circles(const ref_problem *p, ref_result *out)
{
    ref_problem q;
    ref_result sr;
    roll r;
    int code;
    /* no circle rolls: the straight problem, exactly */
    if (!rolls(p->x[10], p->x[2], p->x[3]) && !rolls(p->x[11], p->x[7], p->x[8])) {
        straight(p, p->x, p->x[12], &q);
        code = ref_solve(&q, out);
        return code;
    }
    /* overlapping now, or touching and approaching: cc_sweep over [0, 0], exactly */
    straight(p, p->x, 0.0, &q);
    code = ref_solve(&q, &sr);
    if (code != CC_MISS) {
        if (out != NULL)
            *out = sr;
        return code;
    }
    roll_init(&r);
    roll_load(&r, p->x);
    code = roll_scan(&r, t_limit(p, p->x)) ? CC_HIT : CC_MISS;
    if (out != NULL) {
        out->degenerate = r.degenerate;
        if (code == CC_HIT) {
            mpfr_t s, u;
            mpfr_inits2(RP, s, u, (mpfr_ptr)0);
            put_time(out, RV(&r, TSTAR));
            out->closing = mpfr_get_d(RV(&r, CLOSING), MPFR_RNDN);
            /* normal o(t) / |o(t)| (the piece of t*: set by the scan) */
            mpfr_mul(s, RV(&r, C2X), RV(&r, TSTAR), MPFR_RNDN), mpfr_add(s, s, RV(&r, C1X), MPFR_RNDN);
            mpfr_mul(s, s, RV(&r, TSTAR), MPFR_RNDN), mpfr_add(s, s, RV(&r, C0X), MPFR_RNDN);
            mpfr_mul(u, RV(&r, C2Y), RV(&r, TSTAR), MPFR_RNDN), mpfr_add(u, u, RV(&r, C1Y), MPFR_RNDN);
            mpfr_mul(u, u, RV(&r, TSTAR), MPFR_RNDN), mpfr_add(u, u, RV(&r, C0Y), MPFR_RNDN);
            hyp(RV(&r, A), s, u);
            mpfr_div(s, s, RV(&r, A), MPFR_RNDN), mpfr_div(u, u, RV(&r, A), MPFR_RNDN);
            out->normal_x = mpfr_get_d(s, MPFR_RNDN), out->normal_y = mpfr_get_d(u, MPFR_RNDN);
            /* cond = (|dp| + |va| min(t, tsa) + |vb| min(t, tsb) + R) / closing */
            hyp(s, RV(&r, DPX), RV(&r, DPY));
            mpfr_min(u, RV(&r, TSTAR), RV(&r, TSA), MPFR_RNDN), mpfr_mul(u, u, RV(&r, SA), MPFR_RNDN);
            mpfr_add(s, s, u, MPFR_RNDN);
            mpfr_min(u, RV(&r, TSTAR), RV(&r, TSB), MPFR_RNDN), mpfr_mul(u, u, RV(&r, SB), MPFR_RNDN);
            mpfr_add(s, s, u, MPFR_RNDN);
            mpfr_add(s, s, RV(&r, R), MPFR_RNDN);
            if (mpfr_sgn(RV(&r, CLOSING)) <= 0)
                out->cond = HUGE_VAL;
            else {
                mpfr_div(s, s, RV(&r, CLOSING), MPFR_RNDN);
                out->cond = mpfr_get_d(s, MPFR_RNDU);
            }
            mpfr_clears(s, u, (mpfr_ptr)0);
        }
    }
    roll_clear(&r);
    return code;
}

/* ---- a circle against a wall ------------------------------------------------------------------ */

/* From the straight answer (tau, in "straight time"), the rolling one: t with g(t) = tau, if
 * tau < 1 / (4k) and t <= tlim. k from x. Returns CC_HIT (t in t_out) or CC_MISS; *tie set
 * when a comparison was within the tie band. */
static int roll_time(const double *x, double tlim, mpfr_t tau, mpfr_t t_out, mpfr_t gd_out, int *tie_out)
{
    mpfr_t s, k, q, lim;
    int code = CC_MISS;
    mpfr_inits2(RP, s, k, q, lim, (mpfr_ptr)0);
    mpfr_set_d(s, x[2], MPFR_RNDN), mpfr_set_d(q, x[3], MPFR_RNDN);
    mpfr_hypot(s, s, q, MPFR_RNDN);
    mpfr_set_d(k, x[9], MPFR_RNDN), mpfr_div(k, k, s, MPFR_RNDN), mpfr_mul_2si(k, k, -1, MPFR_RNDN);
    /* 1 - 4 k tau > 0 */
    mpfr_mul(q, k, tau, MPFR_RNDN), mpfr_mul_2ui(q, q, 2, MPFR_RNDN), mpfr_ui_sub(q, 1, q, MPFR_RNDN);
    /* (tau comes from the straight reference as t_hi + t_lo, ~106 bits: ties at 2^-96) */
    if (mpfr_cmp_d(q, 0x1p-96) <= 0) {
        if (mpfr_cmp_d(q, -0x1p-96) >= 0)
            *tie_out = 1;
        goto done; /* reached at the stop or beyond: at rest there, no approach */
    }
    mpfr_sqrt(lim, q, MPFR_RNDN);
    mpfr_set(gd_out, lim, MPFR_RNDN); /* g'(t) = 1 - 2 k t = sqrt(1 - 4 k tau) */
    mpfr_add_ui(lim, lim, 1, MPFR_RNDN);
    mpfr_mul_2ui(t_out, tau, 1, MPFR_RNDN);
    mpfr_div(t_out, t_out, lim, MPFR_RNDN);
    mpfr_set_d(lim, tlim, MPFR_RNDN);
    mpfr_sub(q, lim, t_out, MPFR_RNDN);
    mpfr_mul_2si(lim, lim, -96, MPFR_RNDN);
    if (mpfr_cmpabs(q, lim) <= 0 && !mpfr_zero_p(q))
        *tie_out = 1;
    if (mpfr_sgn(q) >= 0)
        code = CC_HIT;
done:
    mpfr_clears(s, k, q, lim, (mpfr_ptr)0);
    return code;
}

static int solve_roll_segment(const ref_problem *p, ref_result *out)
{
    ref_problem q;
    ref_result sr;
    mpfr_t tau, t, gd;
    int code, tie = 0;
    if (!rolls(p->x[9], p->x[2], p->x[3])) {
        straight(p, p->x, p->x[10], &q);
        return ref_solve(&q, out);
    }
    straight(p, p->x, HUGE_VAL, &q);
    q.is_float = 0; /* the straight time may exceed FLT_MAX before the real time does not */
    code = ref_solve(&q, &sr);
    if (code != CC_HIT) {
        if (out != NULL)
            *out = sr;
        return code;
    }
    mpfr_inits2(RP, tau, t, gd, (mpfr_ptr)0);
    mpfr_set_d(tau, sr.t_hi, MPFR_RNDN);
    mpfr_add_d(tau, tau, sr.t_lo, MPFR_RNDN);
    code = roll_time(p->x, t_limit(p, p->x), tau, t, gd, &tie);
    if (out != NULL) {
        memset(out, 0, sizeof *out);
        out->feature = -1;
        out->degenerate = tie;
        if (code == CC_HIT) {
            put_time(out, t);
            out->feature = sr.feature;
            out->normal_x = sr.normal_x, out->normal_y = sr.normal_y;
            /* the closing speed is the straight one times g'(t); cond likewise over g'(t) */
            out->closing = sr.closing * mpfr_get_d(gd, MPFR_RNDN);
            out->cond = out->closing > 0.0 ? sr.cond / mpfr_get_d(gd, MPFR_RNDD) : HUGE_VAL;
        }
    }
    mpfr_clears(tau, t, gd, (mpfr_ptr)0);
    return code;
}

int ref__roll_solve(const ref_problem *p, ref_result *out)
{
    int code;
    if (out != NULL) {
        memset(out, 0, sizeof *out);
        out->feature = -1;
    }
    code = p->kind == REF_ROLL_CIRCLES ? solve_roll_circles(p, out) : solve_roll_segment(p, out);
    if (out != NULL)
        out->code = code;
    return code;
}

/* ---- residual, margins ------------------------------------------------------------------------ */

/* position offset of a circle along its motion at t: v g(t) into (ox, oy) */
static void motion_at(double vx, double vy, double decel, mpfr_t t, mpfr_t ox, mpfr_t oy)
{
    mpfr_t g, s, k;
    mpfr_inits2(RP, g, s, k, (mpfr_ptr)0);
    mpfr_set(g, t, MPFR_RNDN);
    if (rolls(decel, vx, vy)) {
        mpfr_set_d(s, vx, MPFR_RNDN), mpfr_set_d(k, vy, MPFR_RNDN), mpfr_hypot(s, s, k, MPFR_RNDN);
        mpfr_div_d(s, s, decel, MPFR_RNDN); /* ts */
        if (mpfr_cmp(t, s) >= 0)
            mpfr_mul_2si(g, s, -1, MPFR_RNDN);
        else { /* t - t^2 / (2 ts) */
            mpfr_sqr(k, t, MPFR_RNDN), mpfr_div(k, k, s, MPFR_RNDN), mpfr_mul_2si(k, k, -1, MPFR_RNDN);
            mpfr_sub(g, t, k, MPFR_RNDN);
        }
    }
    mpfr_mul_d(ox, g, vx, MPFR_RNDN);
    mpfr_mul_d(oy, g, vy, MPFR_RNDN);
    mpfr_clears(g, s, k, (mpfr_ptr)0);
}

double ref__roll_residual(const ref_problem *p, double t_d)
{
    mpfr_t t, ax, ay, bx, by, d, R;
    const double *x = p->x;
    double res;
    mpfr_inits2(RP, t, ax, ay, bx, by, d, R, (mpfr_ptr)0);
    mpfr_set_d(t, t_d, MPFR_RNDN);
    if (p->kind == REF_ROLL_CIRCLES) {
        motion_at(x[2], x[3], x[10], t, ax, ay);
        motion_at(x[7], x[8], x[11], t, bx, by);
        mpfr_sub(bx, bx, ax, MPFR_RNDN), mpfr_add_d(bx, bx, x[5], MPFR_RNDN), mpfr_sub_d(bx, bx, x[0], MPFR_RNDN);
        mpfr_sub(by, by, ay, MPFR_RNDN), mpfr_add_d(by, by, x[6], MPFR_RNDN), mpfr_sub_d(by, by, x[1], MPFR_RNDN);
        mpfr_hypot(d, bx, by, MPFR_RNDN);
        mpfr_set_d(R, x[4], MPFR_RNDN), mpfr_add_d(R, R, x[9], MPFR_RNDN);
    } else { /* the centre's distance from the segment: w = c - a, u = b - a, lambda clamped */
        mpfr_t ux, uy, lam, uu;
        mpfr_inits2(RP, ux, uy, lam, uu, (mpfr_ptr)0);
        motion_at(x[2], x[3], x[9], t, ax, ay);
        mpfr_add_d(ax, ax, x[0], MPFR_RNDN), mpfr_sub_d(ax, ax, x[5], MPFR_RNDN);
        mpfr_add_d(ay, ay, x[1], MPFR_RNDN), mpfr_sub_d(ay, ay, x[6], MPFR_RNDN);
        mpfr_set_d(ux, x[7], MPFR_RNDN), mpfr_sub_d(ux, ux, x[5], MPFR_RNDN);
        mpfr_set_d(uy, x[8], MPFR_RNDN), mpfr_sub_d(uy, uy, x[6], MPFR_RNDN);
        mpfr_mul(uu, ux, ux, MPFR_RNDN), mpfr_fma(uu, uy, uy, uu, MPFR_RNDN);
        mpfr_mul(lam, ax, ux, MPFR_RNDN), mpfr_fma(lam, ay, uy, lam, MPFR_RNDN);
        if (mpfr_zero_p(uu) || mpfr_sgn(lam) <= 0)
            mpfr_set_zero(lam, 1);
        else {
            mpfr_div(lam, lam, uu, MPFR_RNDN);
            if (mpfr_cmp_ui(lam, 1) > 0)
                mpfr_set_ui(lam, 1, MPFR_RNDN);
        }
        mpfr_mul(bx, lam, ux, MPFR_RNDN), mpfr_sub(bx, ax, bx, MPFR_RNDN);
        mpfr_mul(by, lam, uy, MPFR_RNDN), mpfr_sub(by, ay, by, MPFR_RNDN);
        mpfr_hypot(d, bx, by, MPFR_RNDN);
        mpfr_set_d(R, x[4], MPFR_RNDN);
        mpfr_clears(ux, uy, lam, uu, (mpfr_ptr)0);
    }
    mpfr_sub(d, d, R, MPFR_RNDN);
    mpfr_div(d, d, R, MPFR_RNDN);
    res = fabs(mpfr_get_d(d, MPFR_RNDN));
    mpfr_clears(t, ax, ay, bx, by, d, R, (mpfr_ptr)0);
    return res;
}

/* The margins of a rolling problem's answer (see reference.c): for two circles, f(0), the
 * approach at 0, the least f over [0, t_max], f at its first local minimum, at the end (or at
 * the contact), at each stop, the closing speed and t_max - t at contact; for a wall, the
 * straight problem's margins with t_max replaced by the straight time of min(t_max, stop). */
int ref__roll_margins(const ref_problem *p, const double *x, mpfr_t *m, mpfr_t *v, mpfr_t *tmp)
{
    ref_problem q;
    if (p->kind == REF_ROLL_SEGMENT) {
        double tl = t_limit(p, x), tau_lim = tl;
        if (rolls(x[9], x[2], x[3])) {
            double ts = hypot(x[2], x[3]) / x[9];
            double t = tl < ts ? tl : ts;
            tau_lim = t - 0.5 * t * t / ts;
        }
        straight(p, x, tau_lim, &q);
        q.is_float = 0;
        return ref__margins(&q, q.x, m, v, tmp);
    }
    if (!rolls(x[10], x[2], x[3]) && !rolls(x[11], x[7], x[8])) {
        straight(p, x, x[12], &q);
        return ref__margins(&q, q.x, m, v, tmp);
    }
    {
        roll r;
        int hit;
        roll_init(&r);
        roll_load(&r, x);
        mpfr_mul(m[0], RV(&r, DPX), RV(&r, DPX), MPFR_RNDN), mpfr_fma(m[0], RV(&r, DPY), RV(&r, DPY), m[0], MPFR_RNDN);
        mpfr_sqr(RV(&r, A), RV(&r, R), MPFR_RNDN), mpfr_sub(m[0], m[0], RV(&r, A), MPFR_RNDN);
        mpfr_sub(RV(&r, A), RV(&r, VBX), RV(&r, VAX), MPFR_RNDN), mpfr_sub(RV(&r, B), RV(&r, VBY), RV(&r, VAY), MPFR_RNDN);
        mpfr_mul(m[1], RV(&r, DPX), RV(&r, A), MPFR_RNDN), mpfr_fma(m[1], RV(&r, DPY), RV(&r, B), m[1], MPFR_RNDN);
        hit = roll_scan(&r, t_limit(p, x));
        mpfr_set(m[2], RV(&r, MIN), MPFR_RNDN);
        mpfr_set(m[3], RV(&r, FIRSTMIN), MPFR_RNDN);
        mpfr_set(m[4], RV(&r, FEND), MPFR_RNDN);
        mpfr_set(m[5], RV(&r, FSA), MPFR_RNDN);
        mpfr_set(m[6], RV(&r, FSB), MPFR_RNDN);
        if (hit) {
            mpfr_set(m[7], RV(&r, CLOSING), MPFR_RNDN);
            mpfr_d_sub(m[8], t_limit(p, x), RV(&r, TSTAR), MPFR_RNDN);
        } else {
            mpfr_set(m[7], RV(&r, MIN), MPFR_RNDN);
            mpfr_set(m[8], RV(&r, FEND), MPFR_RNDN);
        }
        roll_clear(&r);
        return 9;
    }
}
