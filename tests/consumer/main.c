/* The smallest real user of the installed library: one sweep and one response, checked. */
#include <circlecollide.h>

#include <stdio.h>

int main(void)
{
    /* Head-on: centres 10 apart, radii 1 + 1, closing at 1 + 1 = 2: the gap of 8 closes at t = 4.
     * Equal masses and restitution 1 exchange the velocities: a gets -1, b gets +1. */
    cc_circle a = {{0.0, 0.0}, {1.0, 0.0}, 1.0, 1.0};
    cc_circle b = {{10.0, 0.0}, {-1.0, 0.0}, 1.0, 1.0};
    cc_contact c;
    int r = cc_sweep(&a, &b, 100.0, &c);
    if (r != CC_HIT || c.t != 4.0) {
        printf("consumer: cc_sweep gave %s, t = %g; expected CC_HIT at t = 4\n", cc_result_string(r), c.t);
        return 1;
    }
    r = cc_respond(&a, &b, &c, 1.0);
    if (r != CC_HIT || a.vel.x != -1.0 || b.vel.x != 1.0) {
        printf("consumer: cc_respond gave %s, velocities %g and %g; expected -1 and 1\n",
               cc_result_string(r), a.vel.x, b.vel.x);
        return 1;
    }
    if ((cc_version() >> 16) != CC_VERSION_MAJOR) {
        printf("consumer: header major %d but library %s\n", CC_VERSION_MAJOR, cc_version_string());
        return 1;
    }
    printf("consumer: circlecollide %s: hit at t = %g, velocities after %g and %g\n",
           cc_version_string(), c.t, a.vel.x, b.vel.x);
    return 0;
}
