# Driver of the package_consumer test (see tests/packaging.cmake): install, build a consumer with
# find_package and with pkg-config, run both. Fails with the failing step's output.
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${ARGN}\n${out}\n${err}")
  endif()
  message(STATUS "${what}: ok")
  if(out MATCHES "^consumer:")
    message("${out}")
  endif()
endfunction()

set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
set(cfg "")
if(CONFIG)
  set(cfg --config ${CONFIG})
endif()

run("install into ${prefix}" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} ${cfg})

# 1. CMake package
set(flags "")
if(C_FLAGS)
  set(flags "-DCMAKE_C_FLAGS=${C_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${C_FLAGS}")
endif()
run("configure the consumer with find_package(circlecollide)" ${CMAKE_COMMAND}
  -S ${SOURCE_DIR} -B ${WORK_DIR}/build -G "${GENERATOR}" -DCMAKE_C_COMPILER=${C_COMPILER}
  -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${CONFIG} ${flags})
run("build the consumer" ${CMAKE_COMMAND} --build ${WORK_DIR}/build ${cfg})
foreach(exe consumer_default consumer_static)
  file(GLOB_RECURSE path ${WORK_DIR}/build/${exe} ${WORK_DIR}/build/${exe}.exe)
  list(GET path 0 path)
  run("run ${exe}" ${path})
endforeach()

# 2. pkg-config, as a Makefile user would: the compiler and the flags it prints, nothing else
if(NOT PKG_CONFIG)
  message(STATUS "pkg-config not installed: the pkg-config consumer is skipped")
  return()
endif()
# Without the shared library, -lcirclecollide finds the static one, which needs Libs.private.
set(static "")
if(NOT SHARED)
  set(static --static)
endif()
file(GLOB_RECURSE pc ${prefix}/circlecollide.pc)
list(GET pc 0 pc)
get_filename_component(pcdir ${pc} DIRECTORY)
set(ENV{PKG_CONFIG_PATH} ${pcdir})
execute_process(COMMAND ${PKG_CONFIG} ${static} --cflags --libs circlecollide RESULT_VARIABLE rc
  OUTPUT_VARIABLE pcflags OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pkg-config ${static} --cflags --libs circlecollide failed (${rc})")
endif()
execute_process(COMMAND ${PKG_CONFIG} --variable=libdir circlecollide
  OUTPUT_VARIABLE libdir OUTPUT_STRIP_TRAILING_WHITESPACE)
message(STATUS "pkg-config ${static} --cflags --libs circlecollide: ${pcflags}")
separate_arguments(pcflags UNIX_COMMAND "${pcflags}")
separate_arguments(cflags UNIX_COMMAND "${C_FLAGS}")
run("compile with pkg-config" ${C_COMPILER} ${cflags} ${SOURCE_DIR}/main.c ${pcflags}
  -Wl,-rpath,${libdir} -o ${WORK_DIR}/consumer_pkgconfig)
run("run consumer_pkgconfig" ${WORK_DIR}/consumer_pkgconfig)
