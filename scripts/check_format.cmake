# Fails when any of our C++ sources differs from what clang-format (with .clang-format) would write.
# Run as: cmake -DROOT=<repo> -DCLANG_FORMAT=<clang-format> -P scripts/check_format.cmake
cmake_minimum_required(VERSION 3.20)
set(dirs Interfaces Physics Collision Framework ReferenceGame testbed tests bench packages)
set(files "")
foreach(d ${dirs})
  file(GLOB_RECURSE found "${ROOT}/${d}/*.h" "${ROOT}/${d}/*.cpp")
  list(APPEND files ${found})
endforeach()
# fixtures, and the test course host: a stand-in for someone else's code, kept in its own style.
list(FILTER files EXCLUDE REGEX "/fixtures/|/course_host/framework/")
execute_process(COMMAND ${CLANG_FORMAT} --dry-run --Werror ${files}
  WORKING_DIRECTORY ${ROOT} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "clang-format differences (run scripts/format.sh):\n${err}")
endif()
