/* cc_demo (placeholder): prints one sweep and one response of two circles, step by step, so
 * that the README's first command shows the library at work. */
#include <circlecollide.h>

#include <stdio.h>

int main(void)
{
    /* a comes from the left at speed 2, b waits at x = 10 with three times the mass. The gap
     * between the surfaces is 10 - 1 - 2 = 7, closed at speed 2: contact at t = 3.5. */
    cc_circle a = {{0.0, 0.0}, {2.0, 0.0}, 1.0, 1.0};
    cc_circle b = {{10.0, 0.0}, {0.0, 0.0}, 2.0, 3.0};
    cc_contact c;
    int r;

    printf("circlecollide %s demo: two circles, one head-on collision\n", cc_version_string());
    printf("a: pos (%g, %g) vel (%g, %g) radius %g mass %g\n", a.pos.x, a.pos.y, a.vel.x, a.vel.y,
           a.radius, a.mass);
    printf("b: pos (%g, %g) vel (%g, %g) radius %g mass %g\n", b.pos.x, b.pos.y, b.vel.x, b.vel.y,
           b.radius, b.mass);

    r = cc_sweep(&a, &b, 10.0, &c);
    printf("cc_sweep(t_max = 10): %s\n", cc_result_string(r));
    if (r != CC_HIT)
        return 1;
    printf("  contact at t = %.17g, point (%g, %g), normal (%g, %g)\n", c.t, c.point.x, c.point.y,
           c.normal.x, c.normal.y);

    /* advance both to the contact time, then apply the impulse */
    a.pos.x += a.vel.x * c.t;
    a.pos.y += a.vel.y * c.t;
    b.pos.x += b.vel.x * c.t;
    b.pos.y += b.vel.y * c.t;
    r = cc_respond(&a, &b, &c, 1.0);
    printf("cc_respond(restitution 1): %s\n", cc_result_string(r));
    if (r != CC_HIT)
        return 1;
    /* elastic, masses 1 and 3: a leaves at (1 - 3) / 4 * 2 = -1, b at 2 * 1 / 4 * 2 = 1 */
    printf("  velocities after: a (%g, %g), b (%g, %g)\n", a.vel.x, a.vel.y, b.vel.x, b.vel.y);
    printf("  momentum before %g, after %g; kinetic energy before %g, after %g\n", 1.0 * 2.0,
           a.mass * a.vel.x + b.mass * b.vel.x, 0.5 * 1.0 * 4.0,
           0.5 * (a.mass * a.vel.x * a.vel.x + b.mass * b.vel.x * b.vel.x));
    return 0;
}
