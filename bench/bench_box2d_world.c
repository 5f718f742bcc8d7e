/* Peer: Box2D 3.1's world on the benchmark's gas (bench_scenes.h), every circle a bullet
 * (continuous collision between dynamic bodies), restitution 1, no friction, no gravity,
 * single-threaded; judged by the same step checker as our world (bench_check.h).
 *
 * Usage: bench_box2d_world N PHI T_END DT [SUBSTEPS]
 * Prints one line `peer box2d ...` with collisions (begin-touch events) per wall second,
 * tunnelling, escapes, worst overlap and energy drift. */
#include "bench_check.h"
#include "bench_util.h"

#include <box2d/box2d.h>

int main(int argc, char **argv)
{
    bench_scene s;
    bench_check k;
    b2WorldDef wd;
    b2WorldId world;
    b2BodyId *body, ground;
    cc_circle *pre, *post;
    int n, i, w, steps, sub;
    double phi, t_end, dt, spent = 0.0, e0;
    long contacts = 0;
    if (argc < 5) {
        fprintf(stderr, "usage: %s N PHI T_END DT [SUBSTEPS]\n", argv[0]);
        return 2;
    }
    n = atoi(argv[1]);
    phi = atof(argv[2]);
    t_end = atof(argv[3]);
    dt = atof(argv[4]);
    sub = argc > 5 ? atoi(argv[5]) : 4;
    bench_scene_gas(&s, n, phi, 2);
    body = bench_alloc((size_t)n * sizeof *body);
    pre = bench_alloc((size_t)n * sizeof *pre);
    post = bench_alloc((size_t)n * sizeof *post);

    wd = b2DefaultWorldDef();
    wd.gravity = b2Vec2_zero;
    wd.restitutionThreshold = 0.0f; /* every approach bounces, as in ours */
    wd.enableContinuous = true;
    world = b2CreateWorld(&wd);
    {
        b2BodyDef bd = b2DefaultBodyDef();
        b2ShapeDef sd = b2DefaultShapeDef();
        ground = b2CreateBody(world, &bd);
        sd.material.friction = 0.0f;
        sd.material.restitution = 1.0f;
        for (w = 0; w < s.n_walls; w++) {
            b2Segment seg;
            seg.point1.x = (float)s.walls[w].a.x, seg.point1.y = (float)s.walls[w].a.y;
            seg.point2.x = (float)s.walls[w].b.x, seg.point2.y = (float)s.walls[w].b.y;
            b2CreateSegmentShape(ground, &sd, &seg);
        }
    }
    for (i = 0; i < n; i++) {
        b2BodyDef bd = b2DefaultBodyDef();
        b2ShapeDef sd = b2DefaultShapeDef();
        b2Circle circle;
        bd.type = b2_dynamicBody;
        bd.position.x = (float)s.c[i].pos.x, bd.position.y = (float)s.c[i].pos.y;
        bd.linearVelocity.x = (float)s.c[i].vel.x, bd.linearVelocity.y = (float)s.c[i].vel.y;
        bd.isBullet = true;
        bd.fixedRotation = true;
        body[i] = b2CreateBody(world, &bd);
        sd.density = (float)(s.c[i].mass / (3.141592653589793 * s.c[i].radius * s.c[i].radius));
        sd.material.friction = 0.0f;
        sd.material.restitution = 1.0f;
        sd.enableContactEvents = true;
        circle.center = b2Vec2_zero;
        circle.radius = (float)s.c[i].radius;
        b2CreateCircleShape(body[i], &sd, &circle);
    }

    bench_check_init(&k, n);
    memcpy(pre, s.c, (size_t)n * sizeof *pre);
    e0 = bench_energy(s.c, n);
    steps = (int)ceil(t_end / dt - 1e-9);
    for (i = 0; i < steps; i++) {
        double t0 = bench_now();
        int j;
        b2World_Step(world, (float)dt, sub);
        spent += bench_now() - t0;
        contacts += b2World_GetContactEvents(world).beginCount;
        for (j = 0; j < n; j++) {
            b2Vec2 p = b2Body_GetPosition(body[j]), v = b2Body_GetLinearVelocity(body[j]);
            post[j] = s.c[j];
            post[j].pos.x = p.x, post[j].pos.y = p.y;
            post[j].vel.x = v.x, post[j].vel.y = v.y;
        }
        bench_check_step(&k, &s, pre, post, dt);
        memcpy(pre, post, (size_t)n * sizeof *pre);
    }
    printf("peer box2d n=%d phi=%g dt=%g substeps=%d sec_per_sim_s=%.6g collisions=%ld collisions_per_s=%.6g "
           "tunnelling=%ld escaped=%ld max_overlap_r=%.6g energy_drift=%.6g\n",
           n, phi, dt, sub, spent / (steps * dt), contacts, (double)contacts / spent, k.tunnel_circle + k.tunnel_wall,
           k.escaped, k.max_overlap, fabs(bench_energy(post, n) - e0) / e0);
    b2DestroyWorld(world);
    bench_check_free(&k);
    bench_scene_free(&s);
    free(body);
    free(pre);
    free(post);
    return 0;
}
