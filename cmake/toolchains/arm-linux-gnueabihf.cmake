# Cross-builds for 32-bit ARM Linux (armhf) with Debian's gcc-arm-linux-gnueabihf; the test
# programs run under qemu-user (qemu-arm), which ctest calls through CMAKE_CROSSCOMPILING_EMULATOR:
#   cmake -S . -B build-armhf --toolchain cmake/toolchains/arm-linux-gnueabihf.cmake
#   cmake --build build-armhf && ctest --test-dir build-armhf
# scripts/test.d/45-arm-linux.sh does this in CI.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-linux-gnueabihf-gcc)
set(CMAKE_FIND_ROOT_PATH /usr/arm-linux-gnueabihf)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-arm -L /usr/arm-linux-gnueabihf)
# libm on every link: src/CMakeLists.txt adds it only when not cross-compiling (for bare metal)
set(CMAKE_C_STANDARD_LIBRARIES_INIT "-lm")
