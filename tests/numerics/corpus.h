/* The extreme-case corpus of docs/NUMERICS.md: sweep problems in classes (large offsets,
 * scaled scenes, radius ratios, grazing contacts, ...), generated reproducibly from a seed:
 * case (seed, class, index) is always the same problem, on every platform (integer PRNG,
 * inputs built with exactly rounded operations only: + - * / sqrt and powers of ten taken from
 * a table). */
#ifndef CC_CORPUS_H
#define CC_CORPUS_H

#include <stdint.h>

#include "circlecollide.h"

/* classes 0..14: the straight sweeps; CORPUS_ROLL_FIRST..: rolling to rest (issue 12) */
enum { CORPUS_CLASSES = 26, CORPUS_ROLL_FIRST = 15 };

typedef struct corpus_case {
    int is_segment; /* 1: circle a against segment s; 0: circle a against circle b */
    cc_circle a, b;
    cc_segment s;
    double t_max;
    int rolling;              /* 1: cc_sweep_rolling / cc_sweep_segment_rolling with the decelerations */
    double decel_a, decel_b;  /* a's (the circle's, against a segment), b's */
} corpus_case;

/* A float problem: the same case rounded to float (cases for float are generated with ranges
 * fitted to float: grazing margins down to 1e-7 instead of 1e-15, offsets up to 1e6, ...). */
typedef struct corpus_casef {
    int is_segment;
    cc_circlef a, b;
    cc_segmentf s;
    float t_max;
    int rolling;
    float decel_a, decel_b;
} corpus_casef;

const char *corpus_class_name(int cls);
/* Case `index` of class `cls` for the given seed; for_float picks float-fitted ranges. */
void corpus_make(uint64_t seed, int cls, uint32_t index, int for_float, corpus_case *out);
/* The float problem of a case made with for_float = 1. */
void corpus_to_float(const corpus_case *c, corpus_casef *out);

#endif
