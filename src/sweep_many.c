/* cc_sweep_many: the circle-circle sweep over columns of inputs (structure of arrays), for
 * bulk queries from bindings and for vector units. Double precision only. */
#include "cc_internal.h"

#include "precision_double.h"
#include "helpers.inc"
#include "solver.inc"

static int cc__columns_ok(const cc_circle_soa *c)
{
    return c != NULL && c->px != NULL && c->py != NULL && c->vx != NULL && c->vy != NULL && c->radius != NULL;
}

/* The contract validates everything before writing anything. x - x is 0 for finite x and NaN
 * otherwise, and NaN survives the sum: the pass is branch-free. */
static int cc__inputs_ok(size_t n, const cc_circle_soa *c)
{
    size_t i;
    double z = 0.0;
    int positive = 1;
    for (i = 0; i < n; i++) {
        z += (c->px[i] - c->px[i]) + (c->py[i] - c->py[i]) + (c->vx[i] - c->vx[i]) + (c->vy[i] - c->vy[i]) +
             (c->radius[i] - c->radius[i]);
        positive &= c->radius[i] > 0.0;
    }
    return z == 0.0 && positive;
}

CC_API long cc_sweep_many(size_t n, const cc_circle_soa *a, const cc_circle_soa *b, double t_max, double *t_out,
                          int *result_out)
{
    size_t i;
    long hits = 0;
    if (!cc__columns_ok(a) || !cc__columns_ok(b) || (t_out == NULL && n > 0) || !(t_max >= 0.0) ||
        !cc__inputs_ok(n, a) || !cc__inputs_ok(n, b))
        return CC_ERR_INVALID;
    for (i = 0; i < n; i++) {
        int eL, eV, r;
        double t = HUGE_VAL, R = a->radius[i] + b->radius[i];
        cc_vec2 n, pa = cc__v(a->px[i], a->py[i]), va = cc__v(a->vx[i], a->vy[i]);
        cc_vec2 dp = cc__sub(cc__v(b->px[i], b->py[i]), pa), dv = cc__sub(cc__v(b->vx[i], b->vy[i]), va);
        double sL = fabs(dp.x) + fabs(dp.y) + R, sV = fabs(dv.x) + fabs(dv.y);
        /* as in cc_sweep: in the safe range (the common case) the solver needs no rescaling */
        if (CC__FAST_PATHS && sL > CC_SAFE_LO && sL < CC_SAFE_HI && sV < CC_SAFE_HI && (sV > CC_SAFE_LO || sV == 0.0)) {
            r = cc__sweep_core(dp, dv, R, dp, 0, 0, t_max, &t, &n);
        } else {
            dp = cc__diff(pa, cc__v(b->px[i], b->py[i]), &eL);
            dv = cc__diff(va, cc__v(b->vx[i], b->vy[i]), &eV);
            r = cc__sweep_rel(dp, dv, eL ? R * 0.5 : R, eL, eV, t_max, &t, &n);
        }
        /* as cc_sweep: a contact point beyond the representable plane is a miss (found by the
         * fuzzer: the batch said CC_HIT where cc_sweep said CC_MISS) */
        if (r == CC_HIT && !cc__vec_ok(cc__advance(cc__advance(pa, va, t), n, a->radius[i])))
            r = CC_MISS;
        if (r == CC_MISS)
            t = HUGE_VAL;
        else
            hits++;
        t_out[i] = t;
        if (result_out != NULL)
            result_out[i] = r;
    }
    return hits;
}
