/* math.h for the freestanding WebAssembly build (scripts/wasm.sh): only what the library uses.
 * sqrt, fabs, floor and ceil are WebAssembly instructions (f64.sqrt, f64.abs, ...), correctly
 * rounded as IEEE 754 requires, so they map to the compiler's builtins; frexp and ldexp are not
 * instructions and come from demo/wasm/libc.c. */
#ifndef CC_WASM_MATH_H
#define CC_WASM_MATH_H

#define HUGE_VAL (__builtin_huge_val())
#define HUGE_VALF (__builtin_huge_valf())
#define INFINITY (__builtin_inff())
#define NAN (__builtin_nanf(""))

#define isfinite(x) __builtin_isfinite(x)
#define isinf(x) __builtin_isinf(x)
#define isnan(x) __builtin_isnan(x)

#define sqrt(x) __builtin_sqrt(x)
#define sqrtf(x) __builtin_sqrtf(x)
#define fabs(x) __builtin_fabs(x)
#define fabsf(x) __builtin_fabsf(x)
#define floor(x) __builtin_floor(x)
#define floorf(x) __builtin_floorf(x)
#define ceil(x) __builtin_ceil(x)
#define ceilf(x) __builtin_ceilf(x)

double frexp(double x, int *e);
float frexpf(float x, int *e);
double ldexp(double x, int n);
float ldexpf(float x, int n);

#endif
