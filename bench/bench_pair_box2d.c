/* The pair benchmark's Box2D peer: b2TimeOfImpact (Box2D 3.1) on two circle proxies in pure
 * translation, the sweep interval [0, 1] being the benchmark's [0, t_max] with t_max = 1. */
#include "bench_pair_methods.h"

#include <box2d/collision.h>
#include <box2d/math_functions.h>
#include <math.h>
#include <string.h>

void bench_run_box2d(const bench_pair_data *d, size_t lo, size_t hi, double *t, int *code);

void bench_run_box2d(const bench_pair_data *d, size_t lo, size_t hi, double *t, int *code)
{
    b2TOIInput in;
    size_t i;
    float tm = (float)d->t_max;
    /* the parts that do not change from pair to pair: one point per proxy at the body origin,
     * no rotation */
    memset(&in, 0, sizeof in);
    in.proxyA.count = in.proxyB.count = 1;
    in.sweepA.q1 = in.sweepA.q2 = in.sweepB.q1 = in.sweepB.q2 = b2Rot_identity;
    in.maxFraction = 1.0f;
    for (i = lo; i < hi; i++) {
        const cc_circlef *a = &d->af[i], *b = &d->bf[i];
        b2TOIOutput out;
        in.proxyA.radius = a->radius;
        in.proxyB.radius = b->radius;
        in.sweepA.c1.x = a->pos.x;
        in.sweepA.c1.y = a->pos.y;
        in.sweepA.c2.x = a->pos.x + a->vel.x * tm;
        in.sweepA.c2.y = a->pos.y + a->vel.y * tm;
        in.sweepB.c1.x = b->pos.x;
        in.sweepB.c1.y = b->pos.y;
        in.sweepB.c2.x = b->pos.x + b->vel.x * tm;
        in.sweepB.c2.y = b->pos.y + b->vel.y * tm;
        out = b2TimeOfImpact(&in);
        if (out.state == b2_toiStateHit) {
            t[i] = (double)(out.fraction * tm);
            code[i] = CC_HIT;
        } else {
            t[i] = INFINITY;
            code[i] = out.state == b2_toiStateOverlapped ? CC_OVERLAP : CC_MISS;
        }
    }
}
