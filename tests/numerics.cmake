# Numerics (docs/NUMERICS.md): the exact reference and the textbook formula (tests/reference/,
# also used by the benchmarks), the extreme-case corpus, the accuracy report program and the
# test that asserts its targets; the fuzz corpus replay (tests/fuzz/). The reference needs GMP
# and MPFR (Debian: libgmp-dev, libmpfr-dev); without them these tests are skipped with a
# warning, unless CC_REQUIRE_MPFR is ON.
option(CC_REQUIRE_MPFR "Fail the configure step when GMP/MPFR (for the numerics tests) are missing" OFF)

find_path(CC_MPFR_INCLUDE mpfr.h)
find_path(CC_GMP_INCLUDE gmp.h)
find_library(CC_MPFR_LIB mpfr)
find_library(CC_GMP_LIB gmp)

if(CC_MPFR_INCLUDE AND CC_GMP_INCLUDE AND CC_MPFR_LIB AND CC_GMP_LIB)
  add_library(cc_reference STATIC reference/reference.c reference/reference_rolling.c reference/textbook.c reference/textbook_quartic.c)
  target_include_directories(cc_reference PUBLIC reference ${CC_MPFR_INCLUDE} ${CC_GMP_INCLUDE})
  target_link_libraries(cc_reference PUBLIC circlecollide_static ${CC_MPFR_LIB} ${CC_GMP_LIB} PRIVATE cc_warnings)
  if(UNIX)
    target_link_libraries(cc_reference PUBLIC m)
  endif()

  add_library(cc_numerics STATIC numerics/corpus.c numerics/accuracy.c)
  target_include_directories(cc_numerics PUBLIC numerics)
  target_link_libraries(cc_numerics PUBLIC cc_reference PRIVATE cc_warnings)

  # numerics_report: prints the table of docs/NUMERICS.md (see the comment in report.c)
  add_executable(numerics_report numerics/report.c)
  target_link_libraries(numerics_report PRIVATE cc_numerics cc_warnings)

  cc_add_test(NAME test_numerics SOURCES numerics/test_numerics.c LIBS cc_numerics LABELS numerics TIMEOUT 600)
elseif(CC_REQUIRE_MPFR)
  message(FATAL_ERROR "circlecollide: GMP/MPFR not found (apt-get install libgmp-dev libmpfr-dev)")
else()
  message(WARNING "circlecollide: GMP/MPFR not found: the numerics report and test are skipped")
endif()

# The fuzz corpus, replayed through the fuzz harness's checks with the ordinary compiler.
if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/replay.c)
  include(${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz.cmake)
endif()
