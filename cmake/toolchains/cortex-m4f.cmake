# Cross-builds the static library for an ARM Cortex-M4F (single-precision FPU, hard-float ABI)
# with Debian's gcc-arm-none-eabi and libnewlib-arm-none-eabi:
#   cmake -S . -B build-m4f --toolchain cmake/toolchains/cortex-m4f.cmake
#   cmake --build build-m4f --target circlecollide_static
# MinSizeRel, static library only (no tests, demo or benchmarks: nothing here can run them).
# scripts/test.d/40-embedded.sh builds it in CI and checks code size and undefined symbols.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
# there is no startup code to link a test program with: compiler checks build a library instead
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

# -fno-math-errno: sqrtf may then become the FPU's vsqrt.f32 instead of a libm call that would
# only set errno (results are the same IEEE square roots). Sections per function, so that a
# firmware's --gc-sections drops what it does not call.
set(CMAKE_C_FLAGS_INIT "-mcpu=cortex-m4 -mfpu=fpv4-sp-d16 -mfloat-abi=hard -mthumb -fno-math-errno -ffunction-sections -fdata-sections")

set(CMAKE_BUILD_TYPE MinSizeRel CACHE STRING "Build type")
set(CC_BUILD_SHARED OFF CACHE BOOL "no shared libraries on a microcontroller")
set(CC_BUILD_TESTS OFF CACHE BOOL "the tests cannot run on the build machine")
set(CC_BUILD_DEMO OFF CACHE BOOL "")
set(CC_BUILD_BENCH OFF CACHE BOOL "")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
