/* Measures the sweeps (ours and the textbook formula) against the exact reference on one class
 * of the corpus: the columns of the table in docs/NUMERICS.md. Shared by the report program
 * and the ctest check. */
#ifndef CC_ACCURACY_H
#define CC_ACCURACY_H

#include <stdint.h>

/* An answer differing from the exact one is inside the rounding band when it is the exact
 * answer for inputs moved by at most this many ulps each (ref_in_band). */
#define ACC_BAND_ULPS 4
/* The target for t: within this many condition-scaled ulps of the exact contact time. */
#define ACC_TARGET_ULPS 4.0

typedef struct acc_stats {
    long cases;      /* problems measured */
    long timed;      /* of them, exact and measured answers both CC_HIT: t errors measured */
    long disagree;   /* answer (miss/hit/overlap) differs from the exact one, outside the band */
    long in_band;    /* answer differs from the exact one, inside the band; or t is off by more
                        than ACC_TARGET_ULPS because the first contact jumps to another feature
                        of a segment inside the band (ref_t_in_band): not in the t columns */
    double max_err;  /* t error in condition-scaled ulps: |t - t*| / (eps * cond) */
    double med_err;
    double max_res;  /* residual | |pb(t) - pa(t)| - R | / R at the returned t */
    double med_res;
    double max_rel;  /* relative t error |t - t*| / t* (t* > 0) */
    long degenerate; /* rolling cases whose reference decision was a tie (ref_result.degenerate):
                        not judged */
    long worst;      /* index of the case with max_err; -1 none */
    long first_wrong; /* index of the first disagreement outside the band; -1 none */
} acc_stats;

typedef struct acc_row {
    acc_stats ours, textbook;
} acc_row;

/* Cases [0, n) of class cls for the seed, in double (is_float = 0) or float; the textbook
 * columns only when with_textbook (rolling classes: the textbook quartic, for two circles in
 * double only; elsewhere its columns stay empty). */
/* The reference problem of a corpus case (in the given precision), and one method's answer
 * (textbook = 0: the library's; 1: the textbook's): returns 0 when there is no textbook method
 * for the case. */
struct corpus_case;
struct ref_problem;
void acc_problem(const struct corpus_case *c, int is_float, struct ref_problem *p);
int acc_solve(const struct corpus_case *c, int is_float, int textbook, int *code, double *t);

void acc_measure(uint64_t seed, int cls, uint32_t n, int is_float, int with_textbook, acc_row *row);

#endif
