/* Private to the reference (reference.c and reference_rolling.c): the rolling problems' entry
 * points, and the margins of the straight problems (reused by the rolling wall sweep). */
#ifndef CC_REFERENCE_INTERNAL_H
#define CC_REFERENCE_INTERNAL_H

#include <gmp.h>
#include <mpfr.h>

#include "reference.h"

/* bits of the rolling problems' arithmetic */
#define REF_ROLL_PREC 320

int ref__roll_solve(const ref_problem *p, ref_result *out);
double ref__roll_residual(const ref_problem *p, double t);
/* margins of the decisions (see reference.c): for any kind; rolling ones in reference_rolling.c */
int ref__margins(const ref_problem *p, const double *x, mpfr_t *m, mpfr_t *v, mpfr_t *tmp);
int ref__roll_margins(const ref_problem *p, const double *x, mpfr_t *m, mpfr_t *v, mpfr_t *tmp);

#endif
