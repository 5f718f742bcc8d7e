# Runs cc_demo once for a ctest test (see tests/demo.cmake). Two uses:
#   golden:  -DDEMO= -DSCENE= -DARGS= -DOUT= -DGOLDEN= -DCHECK_GOLDEN=ON|OFF
#            runs the scene into OUT and checks the frames (P6 header, size, first != last) and
#            the SHA-256 of all of them against GOLDEN; with the environment variable
#            CC_DEMO_UPDATE_GOLDEN=1 it writes GOLDEN instead.
#   cli:     -DDEMO= -DARGS= -DEXPECT_EXIT= -DEXPECT_TEXT= -DOUT=
#   both take -DEMULATOR= (CMAKE_CROSSCOMPILING_EMULATOR: qemu-arm ... in a cross build).
#            runs cc_demo with ARGS (@OUT@ stands for OUT/frames, @FILE@ for a regular file,
#            @EMPTY@ as the last word for an empty argument) and checks its exit code, that
#            stderr (stdout or stderr when EXIT is 0) contains EXPECT_TEXT, and that a failed run
#            wrote nothing.

separate_arguments(_args UNIX_COMMAND "${ARGS}")

if(DEFINED EXPECT_EXIT)
  file(REMOVE_RECURSE "${OUT}")
  file(MAKE_DIRECTORY "${OUT}")
  file(WRITE "${OUT}/a_file" "not a folder\n")
  set(_run)
  foreach(_a IN LISTS _args)
    string(REPLACE "@OUT@" "${OUT}/frames" _a "${_a}")
    string(REPLACE "@FILE@" "${OUT}/a_file" _a "${_a}")
    list(APPEND _run "${_a}")
  endforeach()
  if(_run MATCHES "@EMPTY@$")
    # an empty word does not survive a CMake list: pass it explicitly
    list(REMOVE_AT _run -1)
    execute_process(COMMAND ${EMULATOR} "${DEMO}" ${_run} "" RESULT_VARIABLE _rc OUTPUT_VARIABLE _out
      ERROR_VARIABLE _err)
  else()
    execute_process(COMMAND ${EMULATOR} "${DEMO}" ${_run} RESULT_VARIABLE _rc OUTPUT_VARIABLE _out
      ERROR_VARIABLE _err)
  endif()
  if(NOT _rc STREQUAL "${EXPECT_EXIT}")
    message(FATAL_ERROR "cc_demo ${ARGS}: exit code ${_rc}, expected ${EXPECT_EXIT}\n"
      "stdout: ${_out}\nstderr: ${_err}")
  endif()
  if(EXPECT_EXIT EQUAL 0)
    set(_text "${_out}${_err}")
  else()
    set(_text "${_err}")
    if(NOT _out STREQUAL "")
      message(FATAL_ERROR "cc_demo ${ARGS}: wrote to stdout on failure: ${_out}")
    endif()
    file(GLOB _frames "${OUT}/frames/*.ppm")
    if(_frames)
      message(FATAL_ERROR "cc_demo ${ARGS}: failed but wrote frames: ${_frames}")
    endif()
  endif()
  string(FIND "${_text}" "${EXPECT_TEXT}" _at)
  if(_at LESS 0)
    message(FATAL_ERROR "cc_demo ${ARGS}: output lacks '${EXPECT_TEXT}':\n${_text}")
  endif()
  message(STATUS "cc_demo ${ARGS}: exit ${_rc} and '${EXPECT_TEXT}' as expected")
  return()
endif()

# ---- golden run ---------------------------------------------------------------------------
function(run_into dir digest_var)
  file(REMOVE_RECURSE "${dir}")
  execute_process(COMMAND ${EMULATOR} "${DEMO}" --scene ${SCENE} ${_args} --out "${dir}"
    RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cc_demo --scene ${SCENE} ${ARGS} failed (exit ${rc}):\n${err}")
  endif()
  message(STATUS "cc_demo --scene ${SCENE} ${ARGS}:\n${err}")
  # the expected frame: count and size from the arguments
  list(FIND _args --frames i)
  math(EXPR i "${i} + 1")
  list(GET _args ${i} frames)
  set(w 640)
  set(h 360)
  list(FIND _args --size i)
  if(i GREATER -1)
    math(EXPR i "${i} + 1")
    list(GET _args ${i} size)
    string(REPLACE "x" ";" size "${size}")
    list(GET size 0 w)
    list(GET size 1 h)
  endif()
  string(HEX "P6\n${w} ${h}\n255\n" head_hex)
  string(LENGTH "P6\n${w} ${h}\n255\n" head_len)
  math(EXPR want_size "${head_len} + ${w} * ${h} * 3")
  set(hashes "")
  math(EXPR last "${frames} - 1")
  foreach(f RANGE 0 ${last})
    string(LENGTH "${f}" n)
    set(name "${f}")
    while(n LESS 4)
      set(name "0${name}")
      math(EXPR n "${n} + 1")
    endwhile()
    set(path "${dir}/frame_${name}.ppm")
    if(NOT EXISTS "${path}")
      message(FATAL_ERROR "${path} missing")
    endif()
    file(SIZE "${path}" size)
    if(NOT size EQUAL want_size)
      message(FATAL_ERROR "${path}: ${size} bytes, expected ${want_size} (${w}x${h} P6)")
    endif()
    file(READ "${path}" got_hex LIMIT ${head_len} HEX)
    if(NOT got_hex STREQUAL head_hex)
      message(FATAL_ERROR "${path}: header ${got_hex}, expected ${head_hex} (P6 ${w} ${h} 255)")
    endif()
    file(SHA256 "${path}" hash)
    if(f EQUAL 0)
      set(first "${hash}")
    endif()
    list(APPEND hashes "${hash}")
  endforeach()
  file(GLOB all "${dir}/*")
  list(LENGTH all count)
  if(NOT count EQUAL frames)
    message(FATAL_ERROR "${dir}: ${count} files, expected ${frames} frames")
  endif()
  if(hash STREQUAL first)
    message(FATAL_ERROR "${dir}: the last frame equals the first: nothing moved")
  endif()
  string(SHA256 digest "${hashes}")
  set(${digest_var} "${digest}" PARENT_SCOPE)
endfunction()

run_into("${OUT}" digest)

if("$ENV{CC_DEMO_UPDATE_GOLDEN}" STREQUAL "1")
  file(WRITE "${GOLDEN}" "${digest}\n")
  message(STATUS "updated ${GOLDEN}: ${digest} (look at ${OUT} before committing it)")
  return()
endif()

if(NOT CHECK_GOLDEN)
  run_into("${OUT}-again" again)
  if(NOT again STREQUAL digest)
    message(FATAL_ERROR "cc_demo --scene ${SCENE} ${ARGS}: two runs wrote different frames "
      "(${digest} and ${again}): the demo is not deterministic")
  endif()
  message(STATUS "not x86-64: golden checksum skipped; two runs gave the same frames")
  return()
endif()

if(NOT EXISTS "${GOLDEN}")
  message(FATAL_ERROR "no golden checksum ${GOLDEN} yet: frames hash to ${digest}. Look at "
    "the frames in ${OUT}; if right, refresh with scripts/demo-golden.sh (tests/demo.cmake).")
endif()
file(STRINGS "${GOLDEN}" want LIMIT_COUNT 1)
if(NOT want STREQUAL digest)
  message(FATAL_ERROR "golden checksum mismatch for the demo scene '${SCENE}': the frames hash "
    "to ${digest}, ${GOLDEN} says ${want}. The goldens change whenever the world's behaviour "
    "changes (simultaneous collisions, SWEPT/DISCRETE, ...). Look at the frames in ${OUT} "
    "(convert frame_0010.ppm x.png); if they are right, refresh with scripts/demo-golden.sh "
    "(or CC_DEMO_UPDATE_GOLDEN=1 ctest -L demo-golden) and commit tests/demo_golden/.")
endif()
message(STATUS "golden checksum of '${SCENE}' matches: ${digest}")
