# The reference game's command line, as a new user meets it: --help prints usage and exits 0 (scripts/game.sh
# --help too, building nothing, with the same options), bad arguments exit 2 with the usage on stderr, and a
# scene ends with its verdict line "OK <scene>".
# Run as: cmake -DGAME=<ReferenceGame> -DROOT=<source dir> -P check_cli.cmake
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

foreach(bad "--bogus" "--frames;0" "--frames;x" "--scene" "--scene;nosuch" "--image" "--image-every;0")
  run(rc out err "${GAME}" ${bad})
  if(NOT rc EQUAL 2 OR NOT err MATCHES "usage: ReferenceGame|no scene")
    message(FATAL_ERROR "ReferenceGame ${bad}: exit ${rc} (want 2), stderr:\n${err}")
  endif()
endforeach()

run(rc out err "${GAME}" --scene cradle --frames 30)
if(NOT rc EQUAL 0 OR NOT out MATCHES "\nOK cradle\n$")
  message(FATAL_ERROR "ReferenceGame --scene cradle: exit ${rc}, want a last line \"OK cradle\":\n${out}")
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
