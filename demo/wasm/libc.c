/* The few C library functions the freestanding WebAssembly build needs, since no libc is
 * linked (scripts/wasm.sh): memcpy (called by the library and by the compiler for structure
 * copies) and memset, frexp and ldexp in double and float (the library's exact
 * power-of-two scaling of very large or small inputs; WebAssembly has no instruction for them).
 * Nothing calls memmove (the linked module shows it), so there is none.
 * sqrt, fabs, floor and ceil are instructions (demo/wasm/include/math.h).
 *
 * Every result is exact or, for ldexp into the subnormal range, rounded once to nearest even,
 * as C99 requires: the wasm build must compute what the native one does, bit for bit. The
 * native test test_wasm_libc compares each function with the host's C library; it builds this
 * file with CC_WASM_LIBC_NAME(n) = wasm_##n so that the two can be linked side by side. */
#include <stddef.h>
#include <stdint.h>

#ifndef CC_WASM_LIBC_NAME
#define CC_WASM_LIBC_NAME(n) n
#endif

void *CC_WASM_LIBC_NAME(memcpy)(void *restrict dst, const void *restrict src, size_t n);
void *CC_WASM_LIBC_NAME(memset)(void *dst, int c, size_t n);
double CC_WASM_LIBC_NAME(frexp)(double x, int *e);
float CC_WASM_LIBC_NAME(frexpf)(float x, int *e);
double CC_WASM_LIBC_NAME(ldexp)(double x, int n);
float CC_WASM_LIBC_NAME(ldexpf)(float x, int n);

void *CC_WASM_LIBC_NAME(memcpy)(void *restrict dst, const void *restrict src, size_t n)
{
    unsigned char *d = (unsigned char *)dst;
    const unsigned char *s = (const unsigned char *)src;
    while (n--)
        *d++ = *s++;
    return dst;
}

void *CC_WASM_LIBC_NAME(memset)(void *dst, int c, size_t n)
{
    unsigned char *d = (unsigned char *)dst;
    while (n--)
        *d++ = (unsigned char)c;
    return dst;
}

/* the bits of a double or a float, through a union (defined in C99) */
typedef union {
    double f;
    uint64_t u;
} cc__bits64;
typedef union {
    float f;
    uint32_t u;
} cc__bits32;

double CC_WASM_LIBC_NAME(frexp)(double x, int *e)
{
    cc__bits64 b;
    int ex;
    b.f = x;
    ex = (int)(b.u >> 52 & 0x7ff);
    if (ex == 0) {
        if (x == 0.0) { /* +-0: exponent 0 */
            *e = 0;
            return x;
        }
        /* subnormal: made normal by an exact scaling of 2^64 */
        x = CC_WASM_LIBC_NAME(frexp)(x * 0x1p64, e);
        *e -= 64;
        return x;
    }
    if (ex == 0x7ff) { /* inf or NaN: returned as is, exponent unspecified (0 here) */
        *e = 0;
        return x;
    }
    *e = ex - 1022; /* the mantissa gets exponent -1: |result| in [0.5, 1) */
    b.u = (b.u & ~((uint64_t)0x7ff << 52)) | ((uint64_t)1022 << 52);
    return b.f;
}

float CC_WASM_LIBC_NAME(frexpf)(float x, int *e)
{
    cc__bits32 b;
    int ex;
    b.f = x;
    ex = (int)(b.u >> 23 & 0xff);
    if (ex == 0) {
        if (x == 0.0f) {
            *e = 0;
            return x;
        }
        x = CC_WASM_LIBC_NAME(frexpf)(x * 0x1p32f, e);
        *e -= 32;
        return x;
    }
    if (ex == 0xff) {
        *e = 0;
        return x;
    }
    *e = ex - 126;
    b.u = (b.u & ~((uint32_t)0xff << 23)) | ((uint32_t)126 << 23);
    return b.f;
}

/* x * 2^n: the factor is applied in at most three multiplications by normal powers of two.
 * Only the last one can round (into the subnormals), and the factors towards tiny results keep
 * 53 bits of headroom (2^-1022 * 2^53 per step), so that the one rounding is the only one. */
double CC_WASM_LIBC_NAME(ldexp)(double x, int n)
{
    cc__bits64 p;
    if (n > 1023) {
        x *= 0x1p1023;
        n -= 1023;
        if (n > 1023) {
            x *= 0x1p1023;
            n -= 1023;
            if (n > 1023)
                n = 1023; /* the result overflows to +-inf whatever the rest */
        }
    } else if (n < -1022) {
        x *= 0x1p-1022 * 0x1p53;
        n += 1022 - 53;
        if (n < -1022) {
            x *= 0x1p-1022 * 0x1p53;
            n += 1022 - 53;
            if (n < -1022)
                n = -1022; /* the result underflows to +-0 whatever the rest */
        }
    }
    p.u = (uint64_t)(0x3ff + n) << 52;
    return x * p.f;
}

float CC_WASM_LIBC_NAME(ldexpf)(float x, int n)
{
    cc__bits32 p;
    if (n > 127) {
        x *= 0x1p127f;
        n -= 127;
        if (n > 127) {
            x *= 0x1p127f;
            n -= 127;
            if (n > 127)
                n = 127;
        }
    } else if (n < -126) {
        x *= 0x1p-126f * 0x1p24f;
        n += 126 - 24;
        if (n < -126) {
            x *= 0x1p-126f * 0x1p24f;
            n += 126 - 24;
            if (n < -126)
                n = -126;
        }
    }
    p.u = (uint32_t)(0x7f + n) << 23;
    return x * p.f;
}
