# Drops one package into a fresh copy of the sample course project, builds it with plain CMake (nothing else
# from this repository) and runs it headless; the project's Design checks physical outcomes.
# Run as: cmake -DROOT=<repo> -DPACKAGE=<name> -DWORK=<scratch dir> -P run_course_project.cmake
cmake_minimum_required(VERSION 3.20)
include(${ROOT}/scripts/package_files.cmake)
set(template "${ROOT}/tests/integration/course_project")
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/project")
set(project "${WORK}/project")

# 1. The student's working copy: the framework (with the interface headers it uses) and a Design.
file(COPY "${template}/CMakeLists.txt" "${template}/main.cpp" "${template}/CourseDesign.h" DESTINATION "${project}")
guardian_package_files(framework_files "${ROOT}" Framework)
foreach(f ${framework_files})
  get_filename_component(sub "${f}" DIRECTORY)
  file(COPY "${ROOT}/${f}" DESTINATION "${project}/${sub}")
endforeach()
file(COPY "${template}/designs/${PACKAGE}/Design.cpp" DESTINATION "${project}/Design")

# 2. The package, generated from the sources, copied over it: files the framework also has are overwritten.
execute_process(COMMAND ${CMAKE_COMMAND} -DROOT=${ROOT} -DNAME=${PACKAGE} -DOUT=${WORK}/packages
                        -P ${ROOT}/scripts/make_package.cmake RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "could not generate package ${PACKAGE}")
endif()
file(STRINGS "${WORK}/packages/${PACKAGE}/MANIFEST.txt" manifest)
foreach(f ${manifest})
  get_filename_component(sub "${f}" DIRECTORY)
  file(COPY "${WORK}/packages/${PACKAGE}/${f}" DESTINATION "${project}/${sub}")
endforeach()

# 3. Build it as a student would, and run it.
execute_process(COMMAND ${CMAKE_COMMAND} -S "${project}" -B "${project}/build" -DCMAKE_BUILD_TYPE=Debug
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the course project with package ${PACKAGE} did not configure")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build "${project}/build" -j 2 RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the course project with package ${PACKAGE} did not build")
endif()
execute_process(COMMAND "${project}/build/CourseGame" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the course project with package ${PACKAGE} ran, but its physical checks failed (${rc})")
endif()
