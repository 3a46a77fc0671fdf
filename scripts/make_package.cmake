# Writes one drop-in package as a folder and a .tar.gz archive.
# Run as: cmake -DROOT=<repo> -DNAME=<package> -DOUT=<dir> -P scripts/make_package.cmake
# The folder holds the package's files in their repository folders (Interfaces/, Physics/, Collision/),
# MANIFEST.txt (one file a line) and INTEGRATION.md (from packages/<name>/).
cmake_minimum_required(VERSION 3.20)
include(${ROOT}/packages/packages.cmake)
include(${ROOT}/scripts/package_files.cmake)
if(NOT DEFINED GUARDIAN_PACKAGE_${NAME}_MODULES)
  message(FATAL_ERROR "unknown package '${NAME}' (known: ${GUARDIAN_PACKAGES})")
endif()
guardian_package_files(files "${ROOT}" ${GUARDIAN_PACKAGE_${NAME}_MODULES})
set(dest "${OUT}/${NAME}")
file(REMOVE_RECURSE "${dest}")
foreach(f ${files})
  get_filename_component(sub "${f}" DIRECTORY)
  file(COPY "${ROOT}/${f}" DESTINATION "${dest}/${sub}")
endforeach()
# Standalone/: the three course-framework headers the engine includes, for a project with no framework (the
# examples). A course project already has its own: INTEGRATION.md says not to copy this folder there.
foreach(f iFrame.h Frame.h iUtilities.h)
  file(COPY "${ROOT}/Framework/${f}" DESTINATION "${dest}/Standalone")
endforeach()
list(JOIN files "\n" manifest)
file(WRITE "${dest}/MANIFEST.txt" "${manifest}\n")
file(COPY "${ROOT}/packages/${NAME}/INTEGRATION.md" DESTINATION "${dest}")
# example/: INTEGRATION.md's program (packages/<name>/example/main.cpp) with the one build file every
# package's example shares, built from this package alone (plus Eigen).
if(EXISTS "${ROOT}/packages/${NAME}/example")
  file(COPY "${ROOT}/packages/${NAME}/example" DESTINATION "${dest}")
  configure_file("${ROOT}/packages/example-CMakeLists.txt" "${dest}/example/CMakeLists.txt" COPYONLY)
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E tar czf "${OUT}/${NAME}.tar.gz" "${NAME}"
  WORKING_DIRECTORY "${OUT}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "could not write ${OUT}/${NAME}.tar.gz")
endif()
list(LENGTH files count)
message(STATUS "package ${NAME}: ${count} files -> ${dest} and ${NAME}.tar.gz")
