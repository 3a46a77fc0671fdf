# Builds a package's example/ from the generated package alone (its own folders, Standalone/ and Eigen;
# nothing else of this repository) and runs it: the example checks its own physics and exits non-zero when
# a check fails.
# Run as: cmake -DROOT=<repo> -DPACKAGE=<name> -DWORK=<scratch dir> [-DCHECKER=<program>] [-DCXX=<compiler>]
#   -P run_example.cmake
# (CHECKER: a program that runs the example and checks what it prints).
cmake_minimum_required(VERSION 3.20)
set(compiler "")
if(CXX) # the compiler of this project (tests/integration/CMakeLists.txt)
  set(compiler -DCMAKE_CXX_COMPILER=${CXX})
endif()
file(REMOVE_RECURSE "${WORK}")
execute_process(COMMAND ${CMAKE_COMMAND} -DROOT=${ROOT} -DNAME=${PACKAGE} -DOUT=${WORK}
                        -P ${ROOT}/scripts/make_package.cmake RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "could not generate package ${PACKAGE}")
endif()
set(example "${WORK}/${PACKAGE}/example")
# One unity file for the whole program: Eigen is parsed and instantiated once (39 s of CPU where batches of
# eight took 69 s), and the package's file-local names must not clash, as in a user's unity build.
execute_process(COMMAND ${CMAKE_COMMAND} -S "${example}" -B "${WORK}/build" -DCMAKE_BUILD_TYPE= ${compiler}
                        -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=0 "-DCMAKE_CXX_FLAGS=-Wall -Wextra -Wpedantic -Werror"
                        RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the ${PACKAGE} example did not configure")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build "${WORK}/build" -j 2 RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the ${PACKAGE} example did not build from its package alone")
endif()
if(CHECKER)
  execute_process(COMMAND "${CHECKER}" "${WORK}/build/example" RESULT_VARIABLE rc)
else()
  execute_process(COMMAND "${WORK}/build/example" RESULT_VARIABLE rc)
endif()
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the ${PACKAGE} example ran, but its checks failed (${rc})")
endif()
