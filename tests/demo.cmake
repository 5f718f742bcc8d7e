# cc_demo's tests (label demo): unit tests of its parts, then runs of the program itself.
#
#   test_demo_raster, test_demo_ppm, test_demo_args   Unity tests of the rasterizer, the PPM
#                                                     writer and PRNG, the command line
#   demo_golden_<scene>   a short, small run of each scene (tests/demo_run.cmake): every frame
#                         is a P6 header of the right size followed by w*h*3 bytes, the last frame
#                         differs from the first, and the SHA-256 of all frames equals
#                         tests/demo_golden/<scene>.sha256
#   demo_cli_<case>       bad command lines exit 2 with a message naming the problem on stderr;
#                         an unusable --out exits 1; --help exits 0; --mode swept and discrete
#                         run (no golden: those modes are the world's to change)
#
# Refreshing the golden checksums. They are the program's own output, taken when its frames
# were looked at and judged right; they change whenever the world's behaviour changes (e.g.
# simultaneous collisions, new SWEPT/DISCRETE code). Then look at the new frames (the failing
# test prints their folder; `convert frame_0010.ppm x.png`), and if they are right run
#     scripts/demo-golden.sh            (or: CC_DEMO_UPDATE_GOLDEN=1 ctest -L demo-golden)
# and commit tests/demo_golden/. The golden values hold for x86-64 (SSE2 arithmetic, the
# compilers' ISO C mode without FMA contraction); elsewhere the runs are checked for
# determinism (two runs, same bytes) instead.

if(NOT CC_BUILD_DEMO OR NOT EXISTS ${PROJECT_SOURCE_DIR}/src/world/sources.cmake)
  return() # demo/CMakeLists.txt builds nothing yet
endif()

cc_add_test(NAME test_demo_raster SOURCES test_demo_raster.c LIBS cc_demo_core LABELS demo)
cc_add_test(NAME test_demo_ppm SOURCES test_demo_ppm.c LIBS cc_demo_core LABELS demo)
cc_add_test(NAME test_demo_args SOURCES test_demo_args.c LIBS cc_demo_core LABELS demo)

if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$")
  set(_demo_golden_check ON)
else()
  set(_demo_golden_check OFF)
endif()

# demo_golden(SCENE args...): a short run of one scene, checked as described above.
function(demo_golden scene)
  string(REPLACE ";" " " _args "${ARGN}")
  add_test(NAME demo_golden_${scene}
    COMMAND ${CMAKE_COMMAND} -DDEMO=$<TARGET_FILE:cc_demo> "-DEMULATOR=${CMAKE_CROSSCOMPILING_EMULATOR}" -DSCENE=${scene} "-DARGS=${_args}"
      -DOUT=${CMAKE_CURRENT_BINARY_DIR}/demo_frames/${scene}
      -DGOLDEN=${CMAKE_CURRENT_SOURCE_DIR}/demo_golden/${scene}.sha256
      -DCHECK_GOLDEN=${_demo_golden_check} -P ${CMAKE_CURRENT_SOURCE_DIR}/demo_run.cmake)
  set_tests_properties(demo_golden_${scene} PROPERTIES LABELS "demo;demo-golden" TIMEOUT 120)
endfunction()

# Small frames, and enough simulated time for each scene's first events: the cue ball reaches
# the rack at 0.2 s, the cradle's balls meet at 0.4 s, the puck reaches a mallet and a rail and
# enters the first goal (a sensor) before 1.5 s. The hard disks (a periodic box, 1040 disks) make
# about 1600 collisions a frame at 20 fps, and their short caption shows the pressure from frame 1.
demo_golden(pool --size 160x90 --frames 24 --fps 20)
demo_golden(air-hockey --size 160x90 --frames 30 --fps 20 --seed 3)
demo_golden(cradle --size 160x90 --frames 16 --fps 20)
demo_golden(gas --size 160x90 --frames 4 --fps 20 --seed 7)
demo_golden(tunnel --size 192x108 --frames 12 --fps 30)
demo_golden(hard-disks --size 192x108 --frames 6 --fps 20 --seed 2)

# demo_cli(NAME EXIT TEXT args...): cc_demo exits with EXIT and stderr (on success stdout or
# stderr) contains TEXT.
function(demo_cli name code text)
  string(REPLACE ";" " " _args "${ARGN}")
  add_test(NAME demo_cli_${name}
    COMMAND ${CMAKE_COMMAND} -DDEMO=$<TARGET_FILE:cc_demo> "-DEMULATOR=${CMAKE_CROSSCOMPILING_EMULATOR}" "-DARGS=${_args}" -DEXPECT_EXIT=${code}
      "-DEXPECT_TEXT=${text}" -DOUT=${CMAKE_CURRENT_BINARY_DIR}/demo_frames/cli_${name}
      -P ${CMAKE_CURRENT_SOURCE_DIR}/demo_run.cmake)
  set_tests_properties(demo_cli_${name} PROPERTIES LABELS "demo" TIMEOUT 60)
endfunction()

set(_ok --scene cradle --frames 1)
demo_cli(help 0 "usage: cc_demo --scene NAME --frames N --out DIR" --help)
demo_cli(help_hard_disks 0 "hard-disks  1040 disks in a periodic box" --help)
demo_cli(mode_swept 0 "SWEPT   : world time 0.500" --scene air-hockey --frames 11 --fps 20
  --size 64x36 --mode swept --out @OUT@)
demo_cli(mode_discrete 0 "DISCRETE: world time 0.500" --scene pool --frames 11 --fps 20
  --size 64x36 --mode discrete --out @OUT@)
# the hard disks' summary gives the pressure from the world's virial (about 9 while the lattice
# melts, 10 once it has: hard disks at area fraction 0.70)
demo_cli(hard_disks_pressure 0 "pressure Z = PA/(N kT) = 9." --scene hard-disks --frames 11
  --fps 20 --size 64x36 --out @OUT@)
demo_cli(no_arguments 2 "cc_demo: missing --scene")
demo_cli(missing_frames 2 "missing --frames" --scene pool --out @OUT@)
demo_cli(missing_out 2 "missing --out" --scene pool --frames 2)
demo_cli(unknown_option 2 "unknown option '--speed'" ${_ok} --out @OUT@ --speed 3)
demo_cli(stray_word 2 "unexpected argument 'now'" ${_ok} --out @OUT@ now)
demo_cli(no_value 2 "option --mode needs a value" ${_ok} --out @OUT@ --mode)
demo_cli(bad_scene 2 "unknown scene 'snooker'" --scene snooker --frames 1 --out @OUT@)
demo_cli(bad_frames 2 "--frames wants a whole number" --scene pool --frames 0 --out @OUT@)
demo_cli(bad_size 2 "--size wants WxH" ${_ok} --out @OUT@ --size 640by360)
demo_cli(bad_fps 2 "--fps wants a number" ${_ok} --out @OUT@ --fps -5)
demo_cli(bad_mode 2 "--mode wants exact, swept or discrete" ${_ok} --out @OUT@ --mode fast)
demo_cli(bad_seed 2 "--seed wants an unsigned whole number" ${_ok} --out @OUT@ --seed -1)
demo_cli(bad_out 2 "--out wants a folder name" ${_ok} --out @EMPTY@)
# a folder that cannot be made: a path through a regular file
demo_cli(unwritable_out 1 "cannot create the folder" ${_ok} --out @FILE@/frames)
