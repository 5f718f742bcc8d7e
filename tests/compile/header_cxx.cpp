// The public header compiled as C++ (C++98 up to the newest standard the compiler knows) with
// extra warnings as errors, then linked against the library: extern "C" must give the C names,
// and C++ must lay the public types out exactly as C does (compared with header_c.c's numbers).
#include <circlecollide.h>

#include <cstdio>

#include "layout.h"

static size_t cc_layout_cxx(size_t *out, size_t cap)
{
    CC_LAYOUT_LIST(out, cap);
}

int main()
{
    size_t c[64], cxx[64];
    const size_t nc = cc_layout_c(c, 64), ncxx = cc_layout_cxx(cxx, 64);
    if (nc != ncxx || nc > 64) {
        std::printf("FAIL: %u layout numbers in C, %u in C++\n", unsigned(nc), unsigned(ncxx));
        return 1;
    }
    for (size_t i = 0; i < nc; ++i) {
        if (c[i] != cxx[i]) {
            std::printf("FAIL: layout number %u is %u in C but %u in C++\n", unsigned(i),
                        unsigned(c[i]), unsigned(cxx[i]));
            return 1;
        }
    }

    // A call through the C linkage: a head-on pair, gap 10 - 2 = 8 closed at speed 2, so t = 4.
    cc_circle a, b;
    a.pos.x = 0.0;  a.pos.y = 0.0; a.vel.x = 1.0;  a.vel.y = 0.0; a.radius = 1.0; a.mass = 1.0;
    b.pos.x = 10.0; b.pos.y = 0.0; b.vel.x = -1.0; b.vel.y = 0.0; b.radius = 1.0; b.mass = 1.0;
    cc_contact contact;
    const int r = cc_sweep(&a, &b, 100.0, &contact);
    if (r != CC_HIT || contact.t != 4.0) {
        std::printf("FAIL: cc_sweep gave %s, t = %g; expected CC_HIT at t = 4\n",
                    cc_result_string(r), contact.t);
        return 1;
    }
    if ((cc_version() >> 16) != CC_VERSION_MAJOR) {
        std::printf("FAIL: header major %d, library %s\n", CC_VERSION_MAJOR, cc_version_string());
        return 1;
    }
    std::printf("OK: C and C++ agree on %u layout numbers; cc_sweep from C++ hit at t = %g (%s)\n",
                unsigned(nc), contact.t, cc_version_string());
    return 0;
}
