# Finds Box2D 3.x for the cross-check tests and sets CC_HAVE_BOX2D (target box2d::box2d).
# The pyb2d3 wheel installs its CMake package under <prefix>/lib64/cmake/box2d, which Debian's
# CMake does not search by itself, so each CMAKE_PREFIX_PATH entry's lib64 and lib folders are
# given as hints. Without Box2D the cross-check tests are skipped, unless CC_REQUIRE_BOX2D=ON.
set(_cc_box2d_hints "")
foreach(_cc_prefix IN LISTS CMAKE_PREFIX_PATH)
  list(APPEND _cc_box2d_hints ${_cc_prefix}/lib64/cmake/box2d ${_cc_prefix}/lib/cmake/box2d)
endforeach()
find_package(box2d 3.1 CONFIG QUIET HINTS ${_cc_box2d_hints})
if(box2d_FOUND AND TARGET box2d::box2d)
  set(CC_HAVE_BOX2D ON)
  message(STATUS "circlecollide: Box2D ${box2d_VERSION} found (${box2d_DIR}): cross-check tests enabled")
else()
  set(CC_HAVE_BOX2D OFF)
  if(CC_REQUIRE_BOX2D)
    message(FATAL_ERROR "circlecollide: CC_REQUIRE_BOX2D is ON but Box2D 3.1 was not found. "
      "Install it with: pip install --no-deps --target build/_deps/pyb2d3 pyb2d3==0.11.1 and "
      "configure with -DCMAKE_PREFIX_PATH=<that folder> (scripts/test.sh does both).")
  endif()
  message(STATUS "circlecollide: Box2D not found: the cross-check tests will report themselves skipped")
endif()
