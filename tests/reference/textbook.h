/* The textbook time of impact, as the seed tutorial and most code write it: the comparison
 * column of docs/NUMERICS.md and of the benchmarks. Test-only code, never linked into the
 * library.
 *
 * Faithful to common practice, not improved:
 *   - the quadratic |dp + dv t|^2 = R^2 with dp = pb - pa, dv = vb - va as
 *       A = dv.dv, B = 2 dp.dv, C = dp.dp - R*R, disc = B*B - 4*A*C,
 *       t = (-B - sqrt(disc)) / (2*A);
 *   - C < 0 is an overlap at t = 0; A == 0, disc <= 0 (tangent), t < 0 or t > t_max is a miss;
 *   - the contact is built in the absolute frame: both centres advanced to t
 *     (pa + va t, pb + vb t), the normal is their normalised difference, the point pa(t) + ra n;
 *   - a segment is its line (distance along the unit normal, measured from end a) with the foot
 *     checked inside, then both end points as zero-radius circles through the same quadratic.
 * Same signatures and result codes as cc_sweep*, so that a caller can swap them; no input
 * validation (callers give valid input). The f versions compute in float only. */
#ifndef CC_TEXTBOOK_H
#define CC_TEXTBOOK_H

#include "circlecollide.h"

int tb_sweep(const cc_circle *a, const cc_circle *b, double t_max, cc_contact *out);
int tb_sweep_segment(const cc_circle *c, const cc_segment *s, double t_max, cc_contact *out);
/* Two rolling circles (textbook_quartic.c): the quartic before the first stop solved in closed
 * form (Ferrari), as event-driven billiards code writes it; double only. */
int tb_sweep_rolling(const cc_circle *a, double decel_a, const cc_circle *b, double decel_b, double t_max,
                     cc_contact *out);
int tb_sweepf(const cc_circlef *a, const cc_circlef *b, float t_max, cc_contactf *out);
int tb_sweep_segmentf(const cc_circlef *c, const cc_segmentf *s, float t_max, cc_contactf *out);

#endif
