/* The exact reference for the sweeps: from the exact double (or float) inputs, the exact answer
 * (miss, hit or overlap, decided with rational arithmetic, GMP), the time of impact to far more
 * than double precision (MPFR), the problem's condition, the residual of a returned time, and
 * the rounding band. Test-only code (needs libgmp and libmpfr), never linked into the library.
 *
 * A problem is a list of input scalars (ref_problem); build it with ref_circles* or
 * ref_segment*, then ask ref_solve. All inputs must be valid in the sense of the API. */
#ifndef CC_REFERENCE_H
#define CC_REFERENCE_H

#include "circlecollide.h"

enum { REF_CIRCLES = 0, REF_SEGMENT = 1, REF_ROLL_CIRCLES = 2, REF_ROLL_SEGMENT = 3 };

typedef struct ref_problem {
    int kind;     /* REF_CIRCLES, REF_SEGMENT, or their rolling versions (reference_rolling.c) */
    int is_float; /* inputs are floats (widened exactly): t beyond FLT_MAX is unrepresentable */
    int n;        /* number of scalars in x */
    /* REF_CIRCLES: pa.x pa.y va.x va.y ra pb.x pb.y vb.x vb.y rb t_max
     * REF_SEGMENT: p.x p.y v.x v.y r a.x a.y b.x b.y t_max
     * REF_ROLL_CIRCLES: pa.x pa.y va.x va.y ra pb.x pb.y vb.x vb.y rb decel_a decel_b t_max
     * REF_ROLL_SEGMENT: p.x p.y v.x v.y r a.x a.y b.x b.y decel t_max */
    double x[13];
} ref_problem;

typedef struct ref_result {
    int code;         /* CC_MISS, CC_HIT or CC_OVERLAP: exact */
    double t_hi, t_lo; /* exact contact time = t_hi + t_lo to ~106 bits (CC_HIT), else 0 */
    int feature;      /* REF_SEGMENT hits: -1 the interior, 0 end a, 1 end b; else -1 */
    /* Condition of t (a time): (|dp| + |dv| t + R) / closing speed at contact, where dp, dv are
     * the relative position and velocity (for a segment: of the circle's centre relative to
     * the touched end point, or to the nearer end point for the interior) and R the contact
     * distance. An error in t of eps * cond is what rounding the inputs' differences once
     * causes; HUGE_VAL at grazing contact. */
    double cond;
    double normal_x, normal_y; /* exact unit normal at t (rounded), for CC_HIT */
    double closing;   /* closing speed at contact (CC_HIT), rounded */
    /* Rolling problems only: 1 when a decision was a tie at the working precision (a margin
     * below 2^-(REF_ROLL_PREC - 70) of its scale: a tangency, a touch exactly at a stop or at
     * t_max), taken as exactly zero; such cases are counted apart, not measured. */
    int degenerate;
} ref_result;

void ref_circles(ref_problem *p, const cc_circle *a, const cc_circle *b, double t_max);
void ref_circlesf(ref_problem *p, const cc_circlef *a, const cc_circlef *b, float t_max);
void ref_segment(ref_problem *p, const cc_circle *c, const cc_segment *s, double t_max);
void ref_segmentf(ref_problem *p, const cc_circlef *c, const cc_segmentf *s, float t_max);

/* Rolling to rest (cc_sweep_rolling, cc_sweep_segment_rolling and the f versions): the same
 * questions for decelerating circles (reference_rolling.c). Decisions and times there are
 * computed with MPFR at REF_ROLL_PREC bits (the rolling coefficient decel / (2 |v|) is
 * irrational, so rationals cannot hold them), not with exact rationals: see ref_result's
 * `degenerate`. */
void ref_roll_circles(ref_problem *p, const cc_circle *a, double decel_a, const cc_circle *b, double decel_b,
                      double t_max);
void ref_roll_circlesf(ref_problem *p, const cc_circlef *a, float decel_a, const cc_circlef *b, float decel_b,
                       float t_max);
void ref_roll_segment(ref_problem *p, const cc_circle *c, double decel, const cc_segment *s, double t_max);
void ref_roll_segmentf(ref_problem *p, const cc_circlef *c, float decel, const cc_segmentf *s, float t_max);

/* The exact answer. A hit later than the largest finite number of the inputs' precision is a
 * miss (no such t can be returned). Returns out->code. */
int ref_solve(const ref_problem *p, ref_result *out);

/* |t - t_exact| for a returned t, to far better than an ulp of t. */
double ref_t_error(const ref_result *r, double t);

/* The residual | |pb(t) - pa(t)| - R | / R at the given t, from the exact inputs (for a segment:
 * the distance of the centre at t from the segment, minus r, over r). */
double ref_residual(const ref_problem *p, double t);

/* 1 when `answer` is the exact answer of some problem whose every input lies within k ulps (of
 * the inputs' precision) of p's: the answer is then inside the rounding band, since input
 * rounding alone can produce it. Searched with the exact solver over perturbations aimed at
 * each decision of the exact answer (its margins), so a found witness is certain; not finding
 * one means the answer is wrong. */
int ref_in_band(const ref_problem *p, int answer, int k);

/* For a segment problem whose exact answer is a hit: 1 when t is within tol condition-scaled
 * ulps (eps * cond of that problem) of the exact contact time of some problem whose every input
 * lies within k ulps of p's and whose first contact is with another feature (the interior or
 * an end point). Where the first contact jumps between features under input rounding, no bound
 * on |t - t*| can hold; this is the test that still does. Searched as ref_in_band. */
int ref_t_in_band(const ref_problem *p, double t, double tol, int k);

#endif
