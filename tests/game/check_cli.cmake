# The reference game's command line, as a new user meets it: --help prints usage and exits 0 (scripts/game.sh
# --help too, building nothing, with the same options), bad arguments exit 2 with the usage on stderr, and a
# scene ends with its verdict line "OK <scene>"; --csv writes its file (one per scene with --scene all),
# --track prints its body each second, --record writes a recording (one per scene with --scene all) that
# --replay plays back with the live run's summary lines, a damaged one is refused with exit 2, and
# scripts/plot.sh turns a CSV into PNGs (when gnuplot is installed).
# Run as: cmake -DGAME=<ReferenceGame> -DROOT=<source dir> -DWORK=<scratch dir> -P check_cli.cmake
cmake_minimum_required(VERSION 3.20)

function(run out_rc out_stdout out_stderr)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
  set(${out_rc} "${rc}" PARENT_SCOPE)
  set(${out_stdout} "${o}" PARENT_SCOPE)
  set(${out_stderr} "${e}" PARENT_SCOPE)
endfunction()

# The option lines ("  --name ...") of a usage text, for comparing two of them.
function(option_lines out text)
  string(REGEX MATCHALL "\n  --[^\n]*" lines "${text}")
  set(${out} "${lines}" PARENT_SCOPE)
endfunction()

run(rc out err "${GAME}" --help)
if(NOT rc EQUAL 0 OR NOT out MATCHES "usage: ReferenceGame")
  message(FATAL_ERROR "ReferenceGame --help: exit ${rc}, stdout:\n${out}")
endif()
option_lines(game_options "${out}")

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
foreach(bad "--bogus" "--frames;0" "--frames;x" "--scene" "--scene;nosuch" "--csv" "--csv-every" "--csv-every;0"
            "--csv-every;x" "--csv;${WORK}/a.csv;--csv-every;-3" "--csv-every;5" "--track"
            "--scene;cradle;--csv;${WORK}/no/such/dir/x.csv" "--image" "--image-every;0" "--record" "--replay"
            "--replay;${WORK}/nosuch.rec" "--replay;${WORK}/nosuch.rec;--frames;5" "--record;${WORK}/a.rec;--replay;x"
            "--scene;cradle;--record;${WORK}/no/such/dir/x.rec")
  run(rc out err "${GAME}" ${bad})
  if(NOT rc EQUAL 2 OR NOT err MATCHES "usage: ReferenceGame|no scene|cannot write|--replay: cannot read")
    message(FATAL_ERROR "ReferenceGame ${bad}: exit ${rc} (want 2), stderr:\n${err}")
  endif()
endforeach()

run(rc out err "${GAME}" --scene cradle --frames 30)
if(NOT rc EQUAL 0 OR NOT out MATCHES "\nOK cradle\n$")
  message(FATAL_ERROR "ReferenceGame --scene cradle: exit ${rc}, want a last line \"OK cradle\":\n${out}")
endif()

# --csv and --track: a header, a row at t = 0 and one per summary line (1.008 s and the last frame, 1.12 s);
# the tracked ball's line under each summary line.
run(rc out err "${GAME}" --scene cradle --frames 70 --csv "${WORK}/cradle.csv" --track cue --track 4
    --record "${WORK}/cradle.rec")
if(NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/cradle.csv")
  message(FATAL_ERROR "ReferenceGame --csv: exit ${rc}, no ${WORK}/cradle.csv:\n${out}\n${err}")
endif()
file(STRINGS "${WORK}/cradle.csv" rows)
list(LENGTH rows n)
list(GET rows 0 header)
if(NOT n EQUAL 4 OR NOT header MATCHES "^time_s,sim_time_s,frame,kinetic_energy_J,.*,cue_y_m,.*,4_z_m,ms_per_frame$")
  message(FATAL_ERROR "ReferenceGame --csv: want a header and 3 rows, got ${n} lines:\n${rows}")
endif()
string(REGEX MATCHALL "\n  track cue +pos \\( *[-0-9.]+, +[-0-9.]+, +[-0-9.]+\\) m" tracks "${out}")
list(LENGTH tracks n)
if(NOT n EQUAL 2 OR NOT out MATCHES "\n  track 4 +pos")
  message(FATAL_ERROR "ReferenceGame --track cue: want 2 lines \"  track cue  pos (x, y, z) m\":\n${out}")
endif()

# --replay of that recording: the live run's summary lines (up to the wall time) and verdict, exit 0; the
# same file cut short: exit 2, saying so.
string(REGEX MATCHALL "\nt [^|\n]*" live_lines "${out}")
run(rc out err "${GAME}" --replay "${WORK}/cradle.rec")
string(REGEX MATCHALL "\nt [^|\n]*" replay_lines "${out}")
list(LENGTH live_lines n)
if(NOT rc EQUAL 0 OR NOT n EQUAL 2 OR NOT replay_lines STREQUAL live_lines OR NOT out MATCHES "\nOK cradle\n$")
  message(FATAL_ERROR "ReferenceGame --replay cradle.rec: exit ${rc}, want the live lines\n${live_lines}\n"
                      "got:\n${out}\n${err}")
endif()
file(READ "${WORK}/cradle.rec" recording)
string(LENGTH "${recording}" n)
math(EXPR n "${n} * 2 / 3")
string(SUBSTRING "${recording}" 0 ${n} recording)
file(WRITE "${WORK}/cut.rec" "${recording}")
run(rc out err "${GAME}" --replay "${WORK}/cut.rec")
if(NOT rc EQUAL 2 OR NOT err MATCHES "^ReferenceGame: --replay: [^\n]*cut.rec:[0-9]+: ")
  message(FATAL_ERROR "ReferenceGame --replay of a cut recording: exit ${rc} (want 2), stderr:\n${err}")
endif()

# --scene all --csv FILE --record FILE: one file each per scene, FILE's name with the scene's joined before
# .csv and .rec.
run(rc out err "${GAME}" --scene all --frames 2 --csv "${WORK}/runs.csv" --record "${WORK}/runs.rec")
foreach(scene tower pyramid ballpit dominoes cradle shooting cradle-strings cradle-strings-2 cradle-strings-3
              hinge-chain door ragdoll rope-bridge cloth soft-blob)
  if(NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/runs-${scene}.csv" OR NOT EXISTS "${WORK}/runs-${scene}.rec")
    message(FATAL_ERROR "ReferenceGame --scene all --csv runs.csv --record runs.rec: exit ${rc}, no "
                        "runs-${scene}.csv or .rec:\n${err}")
  endif()
endforeach()

# scripts/plot.sh: bad arguments exit 2 with its usage; with gnuplot, four PNG files from the cradle's CSV.
run(rc out err "${ROOT}/scripts/plot.sh")
if(NOT rc EQUAL 2 OR NOT err MATCHES "usage: scripts/plot.sh")
  message(FATAL_ERROR "scripts/plot.sh without arguments: exit ${rc} (want 2), stderr:\n${err}")
endif()
run(rc out err "${ROOT}/scripts/plot.sh" "${WORK}/nosuch.csv" "${WORK}/plots")
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "scripts/plot.sh on a missing CSV: exit ${rc} (want 2), stderr:\n${err}")
endif()
find_program(GNUPLOT gnuplot)
if(GNUPLOT)
  run(rc out err "${ROOT}/scripts/plot.sh" "${WORK}/cradle.csv" "${WORK}/plots")
  foreach(png cradle cradle-kinetic cradle-awake cradle-overlap)
    if(NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/plots/${png}.png")
      message(FATAL_ERROR "scripts/plot.sh: exit ${rc}, no ${png}.png:\n${out}\n${err}")
    endif()
  endforeach()
else()
  message(STATUS "gnuplot not installed: scripts/plot.sh's plotting not checked")
endif()

run(rc out err "${ROOT}/scripts/game.sh" --help)
if(NOT rc EQUAL 0 OR NOT out MATCHES "usage: scripts/game.sh")
  message(FATAL_ERROR "scripts/game.sh --help: exit ${rc}, stdout:\n${out}\nstderr:\n${err}")
endif()
if(err MATCHES "building")
  message(FATAL_ERROR "scripts/game.sh --help started a build:\n${err}")
endif()
option_lines(script_options "${out}")
if(NOT script_options STREQUAL game_options)
  message(FATAL_ERROR "scripts/game.sh --help and ReferenceGame --help list different options:\n"
                      "${script_options}\n---\n${game_options}")
endif()
