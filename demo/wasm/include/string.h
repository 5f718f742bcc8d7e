/* string.h for the freestanding WebAssembly build: the two functions the library and the
 * compiler (structure copies) call, defined in demo/wasm/libc.c. */
#ifndef CC_WASM_STRING_H
#define CC_WASM_STRING_H

#include <stddef.h>

void *memcpy(void *restrict dst, const void *restrict src, size_t n);
void *memset(void *dst, int c, size_t n);

#endif
