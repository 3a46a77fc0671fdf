# ReferenceGame --image: pictures without a window. A short pyramid run writes DIR/pyramid_<frame>.svg every
# 60 frames (the default) and at the last frame, each a whole SVG document with the scene's lines in it. The
# same run's --record, replayed with --image (no engine running), writes the very same files, byte for byte.
# Run as: cmake -DGAME=<ReferenceGame> -DDIR=<scratch dir> -P check_images.cmake
cmake_minimum_required(VERSION 3.20)

file(REMOVE_RECURSE "${DIR}" "${DIR}-replay")
file(MAKE_DIRECTORY "${DIR}" "${DIR}-replay")
execute_process(COMMAND "${GAME}" --scene pyramid --frames 120 --image "${DIR}" --record "${DIR}.rec" RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "ReferenceGame --image: exit ${rc}\n${out}\n${err}")
endif()

file(GLOB written RELATIVE "${DIR}" "${DIR}/*")
list(SORT written)
if(NOT written STREQUAL "pyramid_00060.svg;pyramid_00120.svg")
  message(FATAL_ERROR "want pyramid_00060.svg and pyramid_00120.svg in ${DIR}, got: ${written}")
endif()
foreach(name ${written})
  file(READ "${DIR}/${name}" svg)
  string(REGEX MATCHALL "<line " lines "${svg}")
  list(LENGTH lines count)
  # 210 boxes of 12 edges each, besides the ground's grid and the contacts' normals.
  if(NOT svg MATCHES "^<svg " OR NOT svg MATCHES "</svg>\n$" OR count LESS 2520)
    message(FATAL_ERROR "${name} is not a whole SVG picture of the pyramid (${count} lines)")
  endif()
endforeach()

execute_process(COMMAND "${GAME}" --replay "${DIR}.rec" --image "${DIR}-replay" RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
file(GLOB replayed RELATIVE "${DIR}-replay" "${DIR}-replay/*")
list(SORT replayed)
if(NOT rc EQUAL 0 OR NOT replayed STREQUAL written)
  message(FATAL_ERROR "ReferenceGame --replay --image: exit ${rc}, wrote ${replayed}, want ${written}\n${out}\n${err}")
endif()
foreach(name ${written})
  execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${DIR}/${name}" "${DIR}-replay/${name}" RESULT_VARIABLE differ)
  if(differ)
    message(FATAL_ERROR "the replay's ${name} differs from the live run's")
  endif()
endforeach()
file(REMOVE "${DIR}.rec") # 19 MB
