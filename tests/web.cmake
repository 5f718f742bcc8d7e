# The web page's native pieces (issue 17; the page itself is tested in headless Chromium by
# scripts/test.d/70-web.sh):
#   test_wasm_libc  the freestanding WebAssembly build's C library pieces (demo/wasm/libc.c:
#                   memcpy, memmove, memset, frexp, ldexp) against the host's C library
#   web_replay      repeats a journal of the page's calls with this native library (and the page's
#                   plain-C calls, demo/web/calls.c) and prints the
#                   world's state, for the browser test's bit-for-bit comparison (not a ctest test)
cc_add_test(NAME test_wasm_libc SOURCES web/test_wasm_libc.c LABELS web)
add_executable(web_replay web/replay.c ${PROJECT_SOURCE_DIR}/demo/web/calls.c) # the page's own calls
target_include_directories(web_replay PRIVATE ${PROJECT_SOURCE_DIR}/demo/web)
target_link_libraries(web_replay PRIVATE circlecollide_static cc_warnings)
