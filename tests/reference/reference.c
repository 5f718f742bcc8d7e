/* The exact reference (see reference.h). Decisions use GMP rationals: every double is a
 * rational, so the signs that make an answer (overlap, approach, tangency, t <= t_max, the foot
 * of a segment contact inside it) are computed without any rounding. Values (the time, the
 * condition, the residual) use MPFR at REF_PREC bits, arranged without cancellation. */
#include "reference.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include <gmp.h>
#include <mpfr.h>

#include "reference_internal.h"

#define REF_PREC 256    /* bits for values: t to ~2^-250 relative */
#define MARGIN_PREC 2400 /* bits for band margins: a few-ulp change of any input shows */
#define MAX_MARGINS 16

/* ---- building problems ------------------------------------------------------------------ */

static void put_circle(double *x, cc_vec2 p, cc_vec2 v, double r)
{
    x[0] = p.x, x[1] = p.y, x[2] = v.x, x[3] = v.y, x[4] = r;
}

void ref_circles(ref_problem *p, const cc_circle *a, const cc_circle *b, double t_max)
{
    p->kind = REF_CIRCLES, p->is_float = 0, p->n = 11;
    put_circle(p->x, a->pos, a->vel, a->radius);
    put_circle(p->x + 5, b->pos, b->vel, b->radius);
    p->x[10] = t_max;
}

void ref_segment(ref_problem *p, const cc_circle *c, const cc_segment *s, double t_max)
{
    p->kind = REF_SEGMENT, p->is_float = 0, p->n = 10;
    put_circle(p->x, c->pos, c->vel, c->radius);
    p->x[5] = s->a.x, p->x[6] = s->a.y, p->x[7] = s->b.x, p->x[8] = s->b.y, p->x[9] = t_max;
}

static cc_circle widen(const cc_circlef *c)
{
    cc_circle w;
    w.pos.x = c->pos.x, w.pos.y = c->pos.y, w.vel.x = c->vel.x, w.vel.y = c->vel.y;
    w.radius = c->radius, w.mass = c->mass;
    return w;
}

void ref_circlesf(ref_problem *p, const cc_circlef *a, const cc_circlef *b, float t_max)
{
    cc_circle wa = widen(a), wb = widen(b);
    ref_circles(p, &wa, &wb, t_max);
    p->is_float = 1;
}

void ref_segmentf(ref_problem *p, const cc_circlef *c, const cc_segmentf *s, float t_max)
{
    cc_circle wc = widen(c);
    cc_segment ws;
    ws.a.x = s->a.x, ws.a.y = s->a.y, ws.b.x = s->b.x, ws.b.y = s->b.y;
    ref_segment(p, &wc, &ws, t_max);
    p->is_float = 1;
}

/* t_max, or the largest finite time of the precision when t_max is larger (or infinite) */
static double t_limit(const ref_problem *p)
{
    double big = p->is_float ? FLT_MAX : DBL_MAX, t = p->x[p->n - 1];
    return t < big ? t : big;
}

/* ---- exact rational helpers --------------------------------------------------------------- */

/* A scratch set of rationals: the exact quantities of one decision. */
typedef struct qs {
    mpq_t v[24];
} qs;

static void qs_init(qs *s)
{
    int i;
    for (i = 0; i < 24; i++)
        mpq_init(s->v[i]);
}

static void qs_clear(qs *s)
{
    int i;
    for (i = 0; i < 24; i++)
        mpq_clear(s->v[i]);
}

/* r = ax * bx + ay * by (r distinct from the arguments) */
static void q_dot(mpq_t r, const mpq_t ax, const mpq_t ay, const mpq_t bx, const mpq_t by, mpq_t tmp)
{
    mpq_mul(r, ax, bx);
    mpq_mul(tmp, ay, by);
    mpq_add(r, r, tmp);
}

/* r = ax * by - ay * bx */
static void q_cross(mpq_t r, const mpq_t ax, const mpq_t ay, const mpq_t bx, const mpq_t by, mpq_t tmp)
{
    mpq_mul(r, ax, by);
    mpq_mul(tmp, ay, bx);
    mpq_sub(r, r, tmp);
}

/* sign of a + b sqrt(n), n >= 0, exactly */
static int q_sign_sqrt(const mpq_t a, const mpq_t b, const mpq_t n)
{
    int sa = mpq_sgn(a), sb = mpq_sgn(b), c;
    mpq_t a2, b2n;
    if (sb == 0 || mpq_sgn(n) == 0)
        return sa;
    if (sa == 0 || sa == sb)
        return sb;
    mpq_inits(a2, b2n, NULL);
    mpq_mul(a2, a, a);
    mpq_mul(b2n, b, b);
    mpq_mul(b2n, b2n, n);
    c = mpq_cmp(a2, b2n);
    mpq_clears(a2, b2n, NULL);
    return c > 0 ? sa : c < 0 ? sb : 0;
}

/* ---- a point against a disc (both sweeps reduce to it) -------------------------------------- */

/* A point at dp moving at dv against a disc of radius R at the origin, decided exactly:
 * CC_OVERLAP (|dp| < R), CC_HIT (first contact at some t in [0, tlim], approaching) or CC_MISS.
 * On CC_HIT, *t gets C / (sqrt(D) - B) (C = |dp|^2 - R^2, B = dp.dv, D = B^2 - |dv|^2 C =
 * |dv|^2 R^2 - (dp x dv)^2: a sum of positive terms, no cancellation), *closing the closing
 * speed sqrt(D) / R, and nx, ny the normal (dp + dv t) / R. */
static int disc_decide(const mpq_t dpx, const mpq_t dpy, const mpq_t dvx, const mpq_t dvy, const mpq_t R,
                       double tlim, mpfr_t t, mpfr_t closing, double *nx, double *ny)
{
    qs s;
    mpq_t *C = &s.v[0], *B = &s.v[1], *A = &s.v[2], *H = &s.v[3], *D = &s.v[4], *L = &s.v[5], *T = &s.v[6],
          *tmp = &s.v[7];
    int code = CC_MISS;
    qs_init(&s);
    q_dot(*C, dpx, dpy, dpx, dpy, *tmp);
    mpq_mul(*tmp, R, R);
    mpq_sub(*C, *C, *tmp);
    if (mpq_sgn(*C) < 0) {
        code = CC_OVERLAP;
        goto done;
    }
    q_dot(*B, dpx, dpy, dvx, dvy, *tmp);
    if (mpq_sgn(*B) >= 0)
        goto done;
    q_dot(*A, dvx, dvy, dvx, dvy, *tmp);
    q_cross(*H, dpx, dpy, dvx, dvy, *tmp);
    mpq_mul(*D, R, R);
    mpq_mul(*D, *D, *A);
    mpq_mul(*H, *H, *H);
    mpq_sub(*D, *D, *H);
    if (mpq_sgn(*D) <= 0)
        goto done; /* tangent or passing wide */
    /* t <= tlim  <=>  C + tlim B <= tlim sqrt(D) */
    mpq_set_d(*T, tlim);
    mpq_mul(*L, *T, *B);
    mpq_add(*L, *L, *C);
    if (mpq_sgn(*L) > 0) {
        mpq_mul(*L, *L, *L);
        mpq_mul(*T, *T, *T);
        mpq_mul(*T, *T, *D);
        if (mpq_cmp(*L, *T) > 0)
            goto done;
    }
    code = CC_HIT;
    if (t != NULL) {
        mpfr_t sd, b, x, y;
        mpfr_inits2(REF_PREC, sd, b, x, y, (mpfr_ptr)0);
        mpfr_set_q(sd, *D, MPFR_RNDN);
        mpfr_sqrt(sd, sd, MPFR_RNDN);
        mpfr_set_q(b, *B, MPFR_RNDN);
        mpfr_sub(b, sd, b, MPFR_RNDN);
        mpfr_set_q(t, *C, MPFR_RNDN);
        mpfr_div(t, t, b, MPFR_RNDN);
        mpfr_set_q(b, R, MPFR_RNDN);
        mpfr_div(closing, sd, b, MPFR_RNDN); /* (assigned before t is read for the normal) */
        mpfr_set_q(x, dvx, MPFR_RNDN);
        mpfr_mul(x, x, t, MPFR_RNDN);
        mpfr_set_q(sd, dpx, MPFR_RNDN);
        mpfr_add(x, x, sd, MPFR_RNDN);
        mpfr_div(x, x, b, MPFR_RNDN);
        mpfr_set_q(y, dvy, MPFR_RNDN);
        mpfr_mul(y, y, t, MPFR_RNDN);
        mpfr_set_q(sd, dpy, MPFR_RNDN);
        mpfr_add(y, y, sd, MPFR_RNDN);
        mpfr_div(y, y, b, MPFR_RNDN);
        *nx = mpfr_get_d(x, MPFR_RNDN);
        *ny = mpfr_get_d(y, MPFR_RNDN);
        mpfr_clears(sd, b, x, y, (mpfr_ptr)0);
    }
done:
    qs_clear(&s);
    return code;
}

/* cond = (|dp| + |dv| t + R) / closing */
static double condition(const mpq_t dpx, const mpq_t dpy, const mpq_t dvx, const mpq_t dvy, const mpq_t R,
                        mpfr_t t, mpfr_t closing)
{
    mpfr_t a, b, c;
    double r;
    mpfr_inits2(REF_PREC, a, b, c, (mpfr_ptr)0);
    mpfr_set_q(a, dpx, MPFR_RNDN);
    mpfr_set_q(b, dpy, MPFR_RNDN);
    mpfr_hypot(a, a, b, MPFR_RNDN);
    mpfr_set_q(b, dvx, MPFR_RNDN);
    mpfr_set_q(c, dvy, MPFR_RNDN);
    mpfr_hypot(b, b, c, MPFR_RNDN);
    mpfr_mul(b, b, t, MPFR_RNDN);
    mpfr_add(a, a, b, MPFR_RNDN);
    mpfr_set_q(b, R, MPFR_RNDN);
    mpfr_add(a, a, b, MPFR_RNDN);
    if (mpfr_zero_p(closing))
        r = HUGE_VAL;
    else {
        mpfr_div(a, a, closing, MPFR_RNDN);
        r = mpfr_get_d(a, MPFR_RNDU);
    }
    mpfr_clears(a, b, c, (mpfr_ptr)0);
    return r;
}

static void set_time(ref_result *out, mpfr_t t)
{
    mpfr_t lo;
    mpfr_init2(lo, REF_PREC);
    out->t_hi = mpfr_get_d(t, MPFR_RNDN);
    mpfr_sub_d(lo, t, out->t_hi, MPFR_RNDN);
    out->t_lo = mpfr_get_d(lo, MPFR_RNDN);
    mpfr_clear(lo);
}

/* ---- the two sweeps --------------------------------------------------------------------- */

static int solve_circles(const ref_problem *p, ref_result *out)
{
    qs s;
    mpq_t *dpx = &s.v[0], *dpy = &s.v[1], *dvx = &s.v[2], *dvy = &s.v[3], *R = &s.v[4], *tmp = &s.v[5];
    mpfr_t t, closing;
    const double *x = p->x;
    int code;
    qs_init(&s);
    mpfr_inits2(REF_PREC, t, closing, (mpfr_ptr)0);
    mpq_set_d(*dpx, x[5]), mpq_set_d(*tmp, x[0]), mpq_sub(*dpx, *dpx, *tmp);
    mpq_set_d(*dpy, x[6]), mpq_set_d(*tmp, x[1]), mpq_sub(*dpy, *dpy, *tmp);
    mpq_set_d(*dvx, x[7]), mpq_set_d(*tmp, x[2]), mpq_sub(*dvx, *dvx, *tmp);
    mpq_set_d(*dvy, x[8]), mpq_set_d(*tmp, x[3]), mpq_sub(*dvy, *dvy, *tmp);
    mpq_set_d(*R, x[4]), mpq_set_d(*tmp, x[9]), mpq_add(*R, *R, *tmp);
    code = disc_decide(*dpx, *dpy, *dvx, *dvy, *R, t_limit(p), out ? t : NULL, closing, out ? &out->normal_x : NULL,
                       out ? &out->normal_y : NULL);
    if (out != NULL && code == CC_HIT) {
        set_time(out, t);
        out->cond = condition(*dpx, *dpy, *dvx, *dvy, *R, t, closing);
        out->closing = mpfr_get_d(closing, MPFR_RNDN);
    }
    mpfr_clears(t, closing, (mpfr_ptr)0);
    qs_clear(&s);
    return code;
}

static int solve_segment(const ref_problem *p, ref_result *out)
{
    qs s;
    mpq_t *ux = &s.v[0], *uy = &s.v[1], *L2 = &s.v[2], *w0x = &s.v[3], *w0y = &s.v[4], *w1x = &s.v[5],
          *w1y = &s.v[6], *vx = &s.v[7], *vy = &s.v[8], *r = &s.v[9], *tmp = &s.v[10], *lam = &s.v[11],
          *d2 = &s.v[12], *C0 = &s.v[13], *K = &s.v[14], *al = &s.v[15], *be = &s.v[16], *W = &s.v[17],
          *V = &s.v[18], *T = &s.v[19], *ex = &s.v[20], *ey = &s.v[21], *nvx = &s.v[22], *nvy = &s.v[23];
    const double *x = p->x;
    double tlim = t_limit(p), nx = 0, ny = 0;
    mpfr_t best, t, closing, bclosing;
    int code = CC_MISS, i, feature = -1;
    qs_init(&s);
    mpfr_inits2(REF_PREC, best, t, closing, bclosing, (mpfr_ptr)0);
    mpq_set_d(*ux, x[7]), mpq_set_d(*tmp, x[5]), mpq_sub(*ux, *ux, *tmp);
    mpq_set_d(*uy, x[8]), mpq_set_d(*tmp, x[6]), mpq_sub(*uy, *uy, *tmp);
    q_dot(*L2, *ux, *uy, *ux, *uy, *tmp);
    mpq_set_d(*w0x, x[0]), mpq_set_d(*tmp, x[5]), mpq_sub(*w0x, *w0x, *tmp);
    mpq_set_d(*w0y, x[1]), mpq_set_d(*tmp, x[6]), mpq_sub(*w0y, *w0y, *tmp);
    mpq_set_d(*w1x, x[0]), mpq_set_d(*tmp, x[7]), mpq_sub(*w1x, *w1x, *tmp);
    mpq_set_d(*w1y, x[1]), mpq_set_d(*tmp, x[8]), mpq_sub(*w1y, *w1y, *tmp);
    mpq_set_d(*vx, x[2]), mpq_set_d(*vy, x[3]), mpq_set_d(*r, x[4]);
    mpq_neg(*nvx, *vx), mpq_neg(*nvy, *vy);

    /* overlap at t = 0: squared distance to the segment (times L2) against r^2 (times L2) */
    q_dot(*lam, *w0x, *w0y, *ux, *uy, *tmp);
    if (mpq_sgn(*L2) == 0 || mpq_sgn(*lam) <= 0) {
        q_dot(*d2, *w0x, *w0y, *w0x, *w0y, *tmp);
        if (mpq_sgn(*L2) != 0)
            mpq_mul(*d2, *d2, *L2);
    } else if (mpq_cmp(*lam, *L2) >= 0) {
        q_dot(*d2, *w1x, *w1y, *w1x, *w1y, *tmp);
        mpq_mul(*d2, *d2, *L2);
    } else {
        q_cross(*d2, *ux, *uy, *w0x, *w0y, *tmp);
        mpq_mul(*d2, *d2, *d2);
    }
    mpq_mul(*tmp, *r, *r);
    if (mpq_sgn(*L2) != 0)
        mpq_mul(*tmp, *tmp, *L2);
    if (mpq_cmp(*d2, *tmp) < 0) {
        code = CC_OVERLAP;
        goto done;
    }

    /* the interior: the line reached from the side the centre is on, the foot inside */
    q_cross(*C0, *ux, *uy, *w0x, *w0y, *tmp);
    q_cross(*K, *ux, *uy, *vx, *vy, *tmp);
    if (mpq_sgn(*L2) != 0 && mpq_sgn(*C0) != 0) {
        int side = mpq_sgn(*C0);
        mpq_mul(*d2, *C0, *C0);
        mpq_mul(*tmp, *r, *r);
        mpq_mul(*tmp, *tmp, *L2);
        if (mpq_cmp(*d2, *tmp) >= 0 && side * mpq_sgn(*K) < 0) {
            /* negK = -side K > 0, |C0|; t_line = (|C0| - r sqrt(L2)) / negK */
            mpq_t *negK = &s.v[12], *absC0 = &s.v[13];
            if (side < 0)
                mpq_neg(*absC0, *C0);
            else
                mpq_set(*absC0, *C0);
            if (side > 0)
                mpq_neg(*negK, *K);
            else
                mpq_set(*negK, *K);
            q_dot(*W, *w0x, *w0y, *ux, *uy, *tmp);
            q_dot(*V, *vx, *vy, *ux, *uy, *tmp);
            /* foot >= 0: negK W + V |C0| - V r sqrt(L2) >= 0 */
            mpq_mul(*al, *negK, *W);
            mpq_mul(*tmp, *V, *absC0);
            mpq_add(*al, *al, *tmp);
            mpq_mul(*be, *V, *r);
            mpq_neg(*be, *be);
            if (q_sign_sqrt(*al, *be, *L2) >= 0) {
                /* foot <= L2: negK L2 - al - be sqrt(L2) >= 0 */
                mpq_t *al2 = &s.v[20], *be2 = &s.v[21];
                mpq_mul(*al2, *negK, *L2);
                mpq_sub(*al2, *al2, *al);
                mpq_neg(*be2, *be);
                if (q_sign_sqrt(*al2, *be2, *L2) >= 0) {
                    /* t_line <= tlim: |C0| - negK tlim - r sqrt(L2) <= 0 */
                    mpq_set_d(*T, tlim);
                    mpq_mul(*T, *T, *negK);
                    mpq_sub(*al2, *absC0, *T);
                    mpq_neg(*be2, *r);
                    if (q_sign_sqrt(*al2, *be2, *L2) <= 0) {
                        /* t = (C0^2 - r^2 L2) / (negK (|C0| + r sqrt(L2))): no cancellation */
                        mpfr_t a, b;
                        mpfr_inits2(REF_PREC, a, b, (mpfr_ptr)0);
                        mpq_mul(*al2, *C0, *C0);
                        mpq_mul(*tmp, *r, *r);
                        mpq_mul(*tmp, *tmp, *L2);
                        mpq_sub(*al2, *al2, *tmp);
                        mpfr_set_q(a, *L2, MPFR_RNDN);
                        mpfr_sqrt(a, a, MPFR_RNDN);
                        mpfr_set_q(b, *r, MPFR_RNDN);
                        mpfr_mul(b, b, a, MPFR_RNDN);
                        mpfr_set_q(t, *absC0, MPFR_RNDN);
                        mpfr_add(b, b, t, MPFR_RNDN);
                        mpfr_set_q(t, *negK, MPFR_RNDN);
                        mpfr_mul(b, b, t, MPFR_RNDN);
                        mpfr_set_q(t, *al2, MPFR_RNDN);
                        mpfr_div(best, t, b, MPFR_RNDN);
                        mpfr_set_q(t, *negK, MPFR_RNDN);
                        mpfr_div(bclosing, t, a, MPFR_RNDN); /* |v.n| = |K| / |u| */
                        mpfr_set_q(t, *uy, MPFR_RNDN);       /* normal -side (-uy, ux) / |u| */
                        mpfr_div(t, t, a, MPFR_RNDN);
                        nx = side * mpfr_get_d(t, MPFR_RNDN);
                        mpfr_set_q(t, *ux, MPFR_RNDN);
                        mpfr_div(t, t, a, MPFR_RNDN);
                        ny = -side * mpfr_get_d(t, MPFR_RNDN);
                        mpfr_clears(a, b, (mpfr_ptr)0);
                        code = CC_HIT;
                    }
                }
            }
        }
    }

    /* the end points: zero-radius discs the circle's centre must come within r of */
    for (i = 0; i < 2; i++) {
        double ex_n = 0, ey_n = 0;
        mpq_set_d(*ex, x[5 + 2 * i]), mpq_set_d(*tmp, x[0]), mpq_sub(*ex, *ex, *tmp);
        mpq_set_d(*ey, x[6 + 2 * i]), mpq_set_d(*tmp, x[1]), mpq_sub(*ey, *ey, *tmp);
        if (disc_decide(*ex, *ey, *nvx, *nvy, *r, tlim, t, closing, &ex_n, &ey_n) == CC_HIT &&
            (code != CC_HIT || mpfr_less_p(t, best))) {
            code = CC_HIT;
            feature = i;
            mpfr_set(best, t, MPFR_RNDN);
            mpfr_set(bclosing, closing, MPFR_RNDN);
            nx = ex_n, ny = ey_n;
        }
    }
    if (out != NULL && code == CC_HIT) {
        set_time(out, best);
        out->closing = mpfr_get_d(bclosing, MPFR_RNDN);
        out->feature = feature;
        out->normal_x = nx, out->normal_y = ny;
        if (feature >= 0) {
            mpq_set_d(*ex, x[5 + 2 * feature]), mpq_set_d(*tmp, x[0]), mpq_sub(*ex, *ex, *tmp);
            mpq_set_d(*ey, x[6 + 2 * feature]), mpq_set_d(*tmp, x[1]), mpq_sub(*ey, *ey, *tmp);
            out->cond = condition(*ex, *ey, *nvx, *nvy, *r, best, bclosing);
        } else {
            /* relative to the nearer end point */
            q_dot(*d2, *w0x, *w0y, *w0x, *w0y, *tmp);
            q_dot(*T, *w1x, *w1y, *w1x, *w1y, *tmp);
            if (mpq_cmp(*d2, *T) <= 0)
                out->cond = condition(*w0x, *w0y, *vx, *vy, *r, best, bclosing);
            else
                out->cond = condition(*w1x, *w1y, *vx, *vy, *r, best, bclosing);
        }
    }
done:
    mpfr_clears(best, t, closing, bclosing, (mpfr_ptr)0);
    qs_clear(&s);
    return code;
}

int ref_solve(const ref_problem *p, ref_result *out)
{
    int code;
    if (out != NULL) {
        memset(out, 0, sizeof *out);
        out->feature = -1;
    }
    if (p->kind == REF_ROLL_CIRCLES || p->kind == REF_ROLL_SEGMENT)
        code = ref__roll_solve(p, out);
    else
        code = p->kind == REF_CIRCLES ? solve_circles(p, out) : solve_segment(p, out);
    if (out != NULL)
        out->code = code;
    return code;
}

double ref_t_error(const ref_result *r, double t)
{
    double d = t - r->t_hi; /* exact when t is within a factor 2 of t_hi; else far off anyway */
    return fabs(d - r->t_lo);
}

/* ---- residual ------------------------------------------------------------------------------ */

double ref_residual(const ref_problem *p, double t)
{
    qs s;
    mpq_t *X = &s.v[0], *Y = &s.v[1], *tmp = &s.v[2], *T = &s.v[3], *R = &s.v[4], *d2 = &s.v[5];
    const double *x = p->x;
    mpfr_t a, b;
    double res;
    if (p->kind == REF_ROLL_CIRCLES || p->kind == REF_ROLL_SEGMENT)
        return ref__roll_residual(p, t);
    qs_init(&s);
    mpfr_inits2(REF_PREC, a, b, (mpfr_ptr)0);
    mpq_set_d(*T, t);
    if (p->kind == REF_CIRCLES) {
        /* (pb - pa) + (vb - va) t */
        mpq_set_d(*X, x[7]), mpq_set_d(*tmp, x[2]), mpq_sub(*X, *X, *tmp), mpq_mul(*X, *X, *T);
        mpq_set_d(*tmp, x[5]), mpq_add(*X, *X, *tmp), mpq_set_d(*tmp, x[0]), mpq_sub(*X, *X, *tmp);
        mpq_set_d(*Y, x[8]), mpq_set_d(*tmp, x[3]), mpq_sub(*Y, *Y, *tmp), mpq_mul(*Y, *Y, *T);
        mpq_set_d(*tmp, x[6]), mpq_add(*Y, *Y, *tmp), mpq_set_d(*tmp, x[1]), mpq_sub(*Y, *Y, *tmp);
        mpq_set_d(*R, x[4]), mpq_set_d(*tmp, x[9]), mpq_add(*R, *R, *tmp);
        q_dot(*d2, *X, *Y, *X, *Y, *tmp);
    } else {
        /* squared distance of c(t) from the segment */
        mpq_t *ux = &s.v[6], *uy = &s.v[7], *L2 = &s.v[8], *lam = &s.v[9], *cx = &s.v[10], *cy = &s.v[11];
        mpq_set_d(*cx, x[2]), mpq_mul(*cx, *cx, *T), mpq_set_d(*tmp, x[0]), mpq_add(*cx, *cx, *tmp);
        mpq_set_d(*cy, x[3]), mpq_mul(*cy, *cy, *T), mpq_set_d(*tmp, x[1]), mpq_add(*cy, *cy, *tmp);
        mpq_set_d(*ux, x[7]), mpq_set_d(*tmp, x[5]), mpq_sub(*ux, *ux, *tmp);
        mpq_set_d(*uy, x[8]), mpq_set_d(*tmp, x[6]), mpq_sub(*uy, *uy, *tmp);
        mpq_set_d(*X, x[5]), mpq_sub(*X, *cx, *X);
        mpq_set_d(*Y, x[6]), mpq_sub(*Y, *cy, *Y);
        q_dot(*L2, *ux, *uy, *ux, *uy, *tmp);
        q_dot(*lam, *X, *Y, *ux, *uy, *tmp);
        if (mpq_sgn(*L2) == 0 || mpq_sgn(*lam) <= 0) {
            q_dot(*d2, *X, *Y, *X, *Y, *tmp);
        } else if (mpq_cmp(*lam, *L2) >= 0) {
            mpq_set_d(*X, x[7]), mpq_sub(*X, *cx, *X);
            mpq_set_d(*Y, x[8]), mpq_sub(*Y, *cy, *Y);
            q_dot(*d2, *X, *Y, *X, *Y, *tmp);
        } else {
            q_cross(*d2, *ux, *uy, *X, *Y, *tmp);
            mpq_mul(*d2, *d2, *d2);
            mpq_div(*d2, *d2, *L2);
        }
        mpq_set_d(*R, x[4]);
    }
    mpfr_set_q(a, *d2, MPFR_RNDN);
    mpfr_sqrt(a, a, MPFR_RNDN);
    mpfr_set_q(b, *R, MPFR_RNDN);
    mpfr_sub(a, a, b, MPFR_RNDN);
    mpfr_div(a, a, b, MPFR_RNDN);
    mpfr_abs(a, a, MPFR_RNDN);
    res = mpfr_get_d(a, MPFR_RNDN);
    mpfr_clears(a, b, (mpfr_ptr)0);
    qs_clear(&s);
    return res;
}

/* ---- rounding band ------------------------------------------------------------------------ */

/* The margins of the decisions behind the answer, as real numbers whose sign flips exactly where
 * the answer can change (computed at MARGIN_PREC; only their response to input changes is used). */
static int disc_margins(mpfr_t *m, mpfr_t dpx, mpfr_t dpy, mpfr_t dvx, mpfr_t dvy, mpfr_t R, double tlim,
                        mpfr_t *tmp)
{
    /* m0 = C, m1 = B, m2 = D, m3 = tlim (sqrt(D) - B) - C */
    mpfr_mul(m[0], dpx, dpx, MPFR_RNDN), mpfr_fma(m[0], dpy, dpy, m[0], MPFR_RNDN);
    mpfr_mul(tmp[0], R, R, MPFR_RNDN), mpfr_sub(m[0], m[0], tmp[0], MPFR_RNDN);
    mpfr_mul(m[1], dpx, dvx, MPFR_RNDN), mpfr_fma(m[1], dpy, dvy, m[1], MPFR_RNDN);
    mpfr_mul(tmp[1], dvx, dvx, MPFR_RNDN), mpfr_fma(tmp[1], dvy, dvy, tmp[1], MPFR_RNDN);
    mpfr_mul(m[2], tmp[1], tmp[0], MPFR_RNDN);
    mpfr_mul(tmp[2], dpx, dvy, MPFR_RNDN), mpfr_mul(tmp[3], dpy, dvx, MPFR_RNDN);
    mpfr_sub(tmp[2], tmp[2], tmp[3], MPFR_RNDN), mpfr_sqr(tmp[2], tmp[2], MPFR_RNDN);
    mpfr_sub(m[2], m[2], tmp[2], MPFR_RNDN);
    if (mpfr_sgn(m[2]) > 0) {
        mpfr_sqrt(m[3], m[2], MPFR_RNDN);
        mpfr_sub(m[3], m[3], m[1], MPFR_RNDN);
        mpfr_mul_d(m[3], m[3], tlim, MPFR_RNDN);
        mpfr_sub(m[3], m[3], m[0], MPFR_RNDN);
    } else {
        mpfr_set_zero(m[3], 1);
    }
    return 4;
}

int ref__margins(const ref_problem *p, const double *x, mpfr_t *m, mpfr_t *v, mpfr_t *tmp)
{
    double tlim = x[p->n - 1] < (p->is_float ? FLT_MAX : DBL_MAX) ? x[p->n - 1] : (p->is_float ? FLT_MAX : DBL_MAX);
    int i, k = 0;
    if (p->kind == REF_ROLL_CIRCLES || p->kind == REF_ROLL_SEGMENT)
        return ref__roll_margins(p, x, m, v, tmp);
    if (p->kind == REF_CIRCLES) {
        mpfr_set_d(v[0], x[5], MPFR_RNDN), mpfr_sub_d(v[0], v[0], x[0], MPFR_RNDN);
        mpfr_set_d(v[1], x[6], MPFR_RNDN), mpfr_sub_d(v[1], v[1], x[1], MPFR_RNDN);
        mpfr_set_d(v[2], x[7], MPFR_RNDN), mpfr_sub_d(v[2], v[2], x[2], MPFR_RNDN);
        mpfr_set_d(v[3], x[8], MPFR_RNDN), mpfr_sub_d(v[3], v[3], x[3], MPFR_RNDN);
        mpfr_set_d(v[4], x[4], MPFR_RNDN), mpfr_add_d(v[4], v[4], x[9], MPFR_RNDN);
        return disc_margins(m, v[0], v[1], v[2], v[3], v[4], tlim, tmp);
    }
    /* segment: v0,1 = u; v2,3 = w0; v4,5 = -vel; v6 = r; v7 = sqrt(L2) */
    mpfr_set_d(v[0], x[7], MPFR_RNDN), mpfr_sub_d(v[0], v[0], x[5], MPFR_RNDN);
    mpfr_set_d(v[1], x[8], MPFR_RNDN), mpfr_sub_d(v[1], v[1], x[6], MPFR_RNDN);
    mpfr_set_d(v[2], x[0], MPFR_RNDN), mpfr_sub_d(v[2], v[2], x[5], MPFR_RNDN);
    mpfr_set_d(v[3], x[1], MPFR_RNDN), mpfr_sub_d(v[3], v[3], x[6], MPFR_RNDN);
    mpfr_set_d(v[4], -x[2], MPFR_RNDN), mpfr_set_d(v[5], -x[3], MPFR_RNDN), mpfr_set_d(v[6], x[4], MPFR_RNDN);
    mpfr_hypot(v[7], v[0], v[1], MPFR_RNDN);
    /* the end points */
    for (i = 0; i < 2; i++) {
        mpfr_set_d(v[8], x[5 + 2 * i], MPFR_RNDN), mpfr_sub_d(v[8], v[8], x[0], MPFR_RNDN);
        mpfr_set_d(v[9], x[6 + 2 * i], MPFR_RNDN), mpfr_sub_d(v[9], v[9], x[1], MPFR_RNDN);
        k += disc_margins(m + k, v[8], v[9], v[4], v[5], v[6], tlim, tmp);
    }
    /* distance to the segment minus r (overlap), via the foot parameter */
    mpfr_mul(tmp[0], v[2], v[0], MPFR_RNDN), mpfr_fma(tmp[0], v[3], v[1], tmp[0], MPFR_RNDN); /* W */
    mpfr_mul(tmp[1], v[0], v[3], MPFR_RNDN), mpfr_mul(tmp[2], v[1], v[2], MPFR_RNDN);
    mpfr_sub(tmp[1], tmp[1], tmp[2], MPFR_RNDN); /* C0 */
    mpfr_set(m[k++], tmp[1], MPFR_RNDN);          /* side of the line */
    if (!mpfr_zero_p(v[7])) {
        mpfr_div(tmp[2], tmp[1], v[7], MPFR_RNDN); /* signed distance s0 */
        mpfr_abs(m[k], tmp[2], MPFR_RNDN);
        mpfr_sub(m[k], m[k], v[6], MPFR_RNDN); /* gap */
        mpfr_set(tmp[4], m[k], MPFR_RNDN);
        k++;
        mpfr_set(m[k++], tmp[0], MPFR_RNDN);   /* foot at t = 0 before a */
        mpfr_sqr(tmp[3], v[7], MPFR_RNDN);
        mpfr_sub(m[k++], tmp[3], tmp[0], MPFR_RNDN); /* and beyond b */
        /* the rate of the signed distance, and the foot and time of the line contact */
        mpfr_mul(tmp[5], v[0], v[5], MPFR_RNDN), mpfr_mul(tmp[6], v[1], v[4], MPFR_RNDN);
        mpfr_sub(tmp[5], tmp[6], tmp[5], MPFR_RNDN); /* u x vel = K */
        mpfr_div(tmp[5], tmp[5], v[7], MPFR_RNDN);    /* ds/dt */
        if (mpfr_sgn(tmp[2]) < 0)
            mpfr_neg(tmp[5], tmp[5], MPFR_RNDN);
        mpfr_set(m[k++], tmp[5], MPFR_RNDN); /* moving towards the line: < 0 */
        if (!mpfr_zero_p(tmp[5])) {
            mpfr_div(tmp[6], tmp[4], tmp[5], MPFR_RNDN);
            mpfr_neg(tmp[6], tmp[6], MPFR_RNDN); /* t_line */
            mpfr_d_sub(m[k++], tlim, tmp[6], MPFR_RNDN);
            /* foot at t_line: W - (vel.u) t_line, with v4,5 = -vel */
            mpfr_mul(tmp[7], v[4], v[0], MPFR_RNDN), mpfr_fma(tmp[7], v[5], v[1], tmp[7], MPFR_RNDN);
            mpfr_mul(tmp[7], tmp[7], tmp[6], MPFR_RNDN);
            mpfr_add(m[k++], tmp[0], tmp[7], MPFR_RNDN);
            mpfr_sub(m[k], tmp[3], m[k - 1], MPFR_RNDN);
            k++;
        }
    }
    return k;
}

/* one ulp of x in the inputs' precision (the gap above |x|; the smallest subnormal at 0) */
static double ulp_of(double x, int is_float)
{
    x = fabs(x);
    return is_float ? (double)nextafterf((float)x, HUGE_VALF) - x : nextafter(x, HUGE_VAL) - x;
}

/* x moved by s ulps of its precision. For float inputs s may be fractional: the moved value is
 * a double between floats, which the exact solver takes as it is, so that a decision window
 * narrower than one float ulp can still be reached. For double inputs s is rounded to whole
 * ulps. Infinities stay. */
static double step_ulps(double x, double s, int is_float)
{
    double y = x;
    long i, n;
    if (isinf(x) || s == 0.0)
        return x;
    if (is_float) {
        y = x + s * ulp_of(x, 1);
        return isfinite(y) ? y : x;
    }
    n = lround(fabs(s));
    for (i = 0; i < n; i++)
        y = nextafter(y, s > 0 ? HUGE_VAL : -HUGE_VAL);
    return isfinite(y) ? y : x;
}

static int is_radius(const ref_problem *p, int i)
{
    return i == 4 || ((p->kind == REF_CIRCLES || p->kind == REF_ROLL_CIRCLES) && i == 9);
}

/* a deceleration (rolling problems): must stay >= 0 */
static int is_decel(const ref_problem *p, int i)
{
    return (p->kind == REF_ROLL_CIRCLES && (i == 10 || i == 11)) || (p->kind == REF_ROLL_SEGMENT && i == 9);
}

/* the problem with every input i moved by s * g[i] ulps; 0 if that makes a radius <= 0 */
static int moved(const ref_problem *p, const double *g, double s, ref_problem *q)
{
    int i;
    *q = *p;
    for (i = 0; i < p->n; i++) {
        q->x[i] = step_ulps(p->x[i], s * g[i], p->is_float);
        if (is_radius(p, i) && !(q->x[i] > 0.0))
            return 0;
        if (is_decel(p, i) && !(q->x[i] >= 0.0))
            return 0;
    }
    return 1;
}

/* what a witness must satisfy: the exact answer `code`, and when check_t, a contact time within
 * tol condition-scaled ulps of t */
typedef struct want {
    int code, check_t, not_feature; /* not_feature: the witness must touch another feature */
    double t, tol;
} want;

static int satisfies(const ref_problem *q, const want *w)
{
    ref_result r;
    if (!w->check_t)
        return ref_solve(q, NULL) == w->code;
    if (ref_solve(q, &r) != CC_HIT || r.feature == w->not_feature)
        return 0;
    return ref_t_error(&r, w->t) <= w->tol * (q->is_float ? FLT_EPSILON : DBL_EPSILON) * r.cond;
}

static int band_search(const ref_problem *p, const want *w, int k)
{
    /* Perturbation directions aimed at each margin m_j: every input moved the way that changes
     * m_j (g = sign of its change over k ulps), all at once or one at a time, by whole ulps
     * 1..k and by the first-order amount that just takes m_j through zero. */
    static const double whole[] = {1, 2, 3, 4, 6, 8};
    mpfr_t m0[MAX_MARGINS], m1[MAX_MARGINS], v[10], tmp[8];
    double delta[MAX_MARGINS][13], g[13], e[13];
    int nm, i, j, l, dir, found = 0;
    ref_problem q;
    if (satisfies(p, w))
        return 1;
    for (i = 0; i < MAX_MARGINS; i++)
        mpfr_inits2(MARGIN_PREC, m0[i], m1[i], (mpfr_ptr)0);
    for (i = 0; i < 10; i++)
        mpfr_init2(v[i], MARGIN_PREC);
    for (i = 0; i < 8; i++)
        mpfr_init2(tmp[i], MARGIN_PREC);
    nm = ref__margins(p, p->x, m0, v, tmp);
    for (i = 0; i < p->n; i++) {
        q = *p;
        q.x[i] = step_ulps(p->x[i], k, p->is_float);
        (void)ref__margins(p, q.x, m1, v, tmp);
        for (j = 0; j < nm; j++) {
            mpfr_sub(m1[j], m1[j], m0[j], MPFR_RNDN);
            delta[j][i] = mpfr_get_d(m1[j], MPFR_RNDN); /* change of m_j over k ulps of input i */
        }
    }
    for (j = 0; j < nm && !found; j++) {
        double sum = 0.0, mj = mpfr_get_d(m0[j], MPFR_RNDN), s;
        for (i = 0; i < p->n; i++) {
            g[i] = delta[j][i] > 0 ? 1.0 : delta[j][i] < 0 ? -1.0 : 0.0;
            sum += fabs(delta[j][i]);
        }
        if (sum == 0.0)
            continue;
        /* all inputs at once: whole ulps both ways, then just through zero (towards -sign m_j) */
        for (dir = -1; dir <= 1 && !found; dir += 2)
            for (l = 0; l < (int)(sizeof whole / sizeof whole[0]) && whole[l] <= k && !found; l++)
                found = moved(p, g, dir * whole[l], &q) && satisfies(&q, w);
        for (l = 1; l <= 4 && !found; l++) {
            s = fabs(mj) / sum * k * (1.0 + 0.25 * (l - 1)) * 1.000001;
            if (s <= k)
                found = moved(p, g, mj > 0 ? -s : s, &q) && satisfies(&q, w);
        }
        /* one input at a time */
        for (i = 0; i < p->n && !found; i++) {
            if (g[i] == 0.0)
                continue;
            memset(e, 0, sizeof e);
            e[i] = g[i];
            for (dir = -1; dir <= 1 && !found; dir += 2)
                for (l = 0; l < (int)(sizeof whole / sizeof whole[0]) && whole[l] <= k && !found; l++)
                    found = moved(p, e, dir * whole[l], &q) && satisfies(&q, w);
            for (l = 1; l <= 4 && !found; l++) {
                s = fabs(mj) / fabs(delta[j][i]) * k * (1.0 + 0.25 * (l - 1)) * 1.000001;
                if (s <= k)
                    found = moved(p, e, mj > 0 ? -s : s, &q) && satisfies(&q, w);
            }
        }
    }
    for (i = 0; i < MAX_MARGINS; i++)
        mpfr_clears(m0[i], m1[i], (mpfr_ptr)0);
    for (i = 0; i < 10; i++)
        mpfr_clear(v[i]);
    for (i = 0; i < 8; i++)
        mpfr_clear(tmp[i]);
    return found;
}

int ref_in_band(const ref_problem *p, int answer, int k)
{
    want w;
    w.code = answer, w.check_t = 0, w.not_feature = -2, w.t = 0.0, w.tol = 0.0;
    return band_search(p, &w, k);
}

int ref_t_in_band(const ref_problem *p, double t, double tol, int k)
{
    want w;
    ref_result r;
    if ((p->kind != REF_SEGMENT && p->kind != REF_ROLL_SEGMENT) || ref_solve(p, &r) != CC_HIT)
        return 0;
    w.code = CC_HIT, w.check_t = 1, w.not_feature = r.feature, w.t = t, w.tol = tol;
    return band_search(p, &w, k);
}
