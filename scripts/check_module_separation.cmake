# Fails when Physics/ or Collision/ includes anything but its own files, Interfaces/ and the three course
# framework headers the engine may use (the host's own iFrame.h, Frame.h, iUtilities.h), or when
# Interfaces/ includes anything but itself and those three.
# Run as: cmake -DROOT=<repo> -P scripts/check_module_separation.cmake
# This is what lets the sim-only and collision-only packages separate: the two modules meet only through the
# public headers in Interfaces/; and what lets a package drop into a course project: of the framework, the
# engine needs only what every course framework has.
cmake_minimum_required(VERSION 3.20)
if(NOT ROOT)
  get_filename_component(ROOT "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
endif()
set(failures "")
# GeneralConstants.h: the framework's MODEL_Z_AXIS, included by MathDefinitions.h only when the host has it.
set(host_headers iFrame.h Frame.h iUtilities.h GeneralConstants.h)
foreach(module Physics Collision Interfaces)
  file(GLOB_RECURSE files "${ROOT}/${module}/*.h" "${ROOT}/${module}/*.hpp" "${ROOT}/${module}/*.cpp")
  foreach(f ${files})
    file(STRINGS "${f}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
    get_filename_component(dir "${f}" DIRECTORY)
    foreach(line ${lines})
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*" "\\1" inc "${line}")
      # Where the include could resolve: beside the file, in the module root, or in Interfaces/.
      # It passes only if it resolves inside this module or inside Interfaces/.
      get_filename_component(beside "${dir}/${inc}" ABSOLUTE)
      get_filename_component(inModule "${ROOT}/${module}/${inc}" ABSOLUTE)
      get_filename_component(public "${ROOT}/Interfaces/${inc}" ABSOLUTE)
      set(ok FALSE)
      if(inc IN_LIST host_headers)
        set(ok TRUE)
      endif()
      foreach(pair "${beside}|${ROOT}/${module}/" "${inModule}|${ROOT}/${module}/" "${public}|${ROOT}/Interfaces/")
        string(REPLACE "|" ";" parts "${pair}")
        list(GET parts 0 path)
        list(GET parts 1 prefix)
        string(FIND "${path}" "${prefix}" at)
        if(EXISTS "${path}" AND at EQUAL 0)
          set(ok TRUE)
        endif()
      endforeach()
      if(NOT ok)
        file(RELATIVE_PATH rel "${ROOT}" "${f}")
        list(APPEND failures "${rel}: #include \"${inc}\" is not in ${module}/, Interfaces/ or the host headers")
      endif()
    endforeach()
  endforeach()
endforeach()
if(failures)
  list(JOIN failures "\n  " text)
  message(FATAL_ERROR "Module separation broken:\n  ${text}")
endif()
message(STATUS "Physics/ and Collision/ include only their own files and Interfaces/")
