/* test_wasm_libc: the C library pieces of the freestanding WebAssembly build (demo/wasm/libc.c)
 * against the host's C library, which C99 pins down exactly for these functions: frexp and ldexp
 * are exact but for ldexp's one rounding into the subnormals (to nearest even), and the mem*
 * functions are byte copies and fills. The wasm module's results equal the native library's only if these
 * do (the browser test checks the whole library bit for bit; this finds which piece is wrong).
 * libc.c is compiled here with its names prefixed wasm_ so that both can be linked. */
#include "unity.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#define CC_WASM_LIBC_NAME(n) wasm_##n
#include "../../demo/wasm/libc.c"

void setUp(void) {}
void tearDown(void) {}

static uint64_t rng = 0x9e3779b97f4a7c15u;
static uint64_t next(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return rng;
}

static double from_bits(uint64_t u)
{
    double d;
    memcpy(&d, &u, sizeof d);
    return d;
}
static uint64_t bits(double d)
{
    uint64_t u;
    memcpy(&u, &d, sizeof u);
    return u;
}
static float from_bits32(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}
static uint32_t bits32(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

/* same bits, or both NaN */
static int same(double a, double b) { return bits(a) == bits(b) || (a != a && b != b); }
static int same32(float a, float b) { return bits32(a) == bits32(b) || (a != a && b != b); }

static const double special[] = {0.0, -0.0, 1.0, -1.0, 0.5, 3.0, DBL_MAX, -DBL_MAX, DBL_MIN, -DBL_MIN,
                                 0x1p-1074, -0x1p-1074, 0x1.fffffffffffffp-1023, 0x1p-1050, 1e300, 1e-300,
                                 HUGE_VAL, -HUGE_VAL};
static const int exponents[] = {0, 1, -1, 52, -52, 53, -53, 1023, -1022, 1024, -1023, -1074, -1075, -1076,
                                2046, -2045, 2098, -2099, 5000, -5000, 20000, -20000};

static void test_frexp(void)
{
    long k;
    for (k = 0; k < 200000; ++k) {
        double x = k < (long)(sizeof special / sizeof special[0]) ? special[k] : from_bits(next());
        int e1 = 0, e2 = 0;
        double a = wasm_frexp(x, &e1), b = frexp(x, &e2);
        TEST_ASSERT_TRUE_MESSAGE(same(a, b), "frexp: mantissa");
        if (isfinite(x))
            TEST_ASSERT_EQUAL_INT_MESSAGE(e2, e1, "frexp: exponent");
    }
}

static void test_ldexp(void)
{
    long k;
    size_t i, j;
    for (i = 0; i < sizeof special / sizeof special[0]; ++i)
        for (j = 0; j < sizeof exponents / sizeof exponents[0]; ++j)
            TEST_ASSERT_TRUE_MESSAGE(same(wasm_ldexp(special[i], exponents[j]), ldexp(special[i], exponents[j])),
                                     "ldexp: special");
    for (k = 0; k < 400000; ++k) {
        double x = from_bits(next());
        /* exponents that reach the subnormals, overflow, and everything between */
        int n = (int)(next() % 4400u) - 2200;
        TEST_ASSERT_TRUE_MESSAGE(same(wasm_ldexp(x, n), ldexp(x, n)), "ldexp");
    }
    /* the one rounding into the subnormals: halfway cases go to even */
    TEST_ASSERT_TRUE(same(wasm_ldexp(0x1.8p0, -1074), ldexp(0x1.8p0, -1074)));
    TEST_ASSERT_TRUE(same(wasm_ldexp(0x1.000001p0, -1075), 0x1p-1074));
    TEST_ASSERT_TRUE(same(wasm_ldexp(1.0, -1075), 0.0));
}

static void test_float(void)
{
    long k;
    for (k = 0; k < 400000; ++k) {
        float x = from_bits32((uint32_t)next());
        int n = (int)(next() % 600u) - 300, e1 = 0, e2 = 0;
        float a = wasm_frexpf(x, &e1), b = frexpf(x, &e2);
        TEST_ASSERT_TRUE_MESSAGE(same32(a, b), "frexpf: mantissa");
        if (isfinite(x))
            TEST_ASSERT_EQUAL_INT_MESSAGE(e2, e1, "frexpf: exponent");
        TEST_ASSERT_TRUE_MESSAGE(same32(wasm_ldexpf(x, n), ldexpf(x, n)), "ldexpf");
    }
    TEST_ASSERT_TRUE(same32(wasm_ldexpf(1.0f, -150), 0.0f));
    TEST_ASSERT_TRUE(same32(wasm_ldexpf(0x1.8p0f, -149), ldexpf(0x1.8p0f, -149)));
}

static void test_mem(void)
{
    unsigned char a[96], b[96], ref[96];
    int off, len, dst;
    for (off = 0; off < 32; ++off)
        for (len = 0; len < 48; ++len)
            for (dst = 0; dst < 32; dst += 3) {
                int i;
                for (i = 0; i < 96; ++i)
                    a[i] = b[i] = (unsigned char)(next() & 0xff);
                /* memcpy between two buffers, memset */
                memcpy(ref, a, 96);
                memcpy(ref + dst, b + off, (size_t)len);
                TEST_ASSERT_TRUE(wasm_memcpy(a + dst, b + off, (size_t)len) == a + dst);
                TEST_ASSERT_EQUAL_MEMORY(ref, a, 96);
                memset(ref + off, dst * 7, (size_t)len);
                TEST_ASSERT_TRUE(wasm_memset(a + off, dst * 7, (size_t)len) == a + off);
                TEST_ASSERT_EQUAL_MEMORY(ref, a, 96);
            }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_frexp);
    RUN_TEST(test_ldexp);
    RUN_TEST(test_float);
    RUN_TEST(test_mem);
    return UNITY_END();
}
