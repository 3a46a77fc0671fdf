# `cmake --build <build> --target packages` writes each drop-in package under <build>/packages/ as a folder
# (files + MANIFEST.txt + INTEGRATION.md) and a .tar.gz archive, generated from the sources.
include(${PROJECT_SOURCE_DIR}/packages/packages.cmake)
set(package_commands "")
foreach(name ${GUARDIAN_PACKAGES})
  list(APPEND package_commands COMMAND ${CMAKE_COMMAND} -DROOT=${PROJECT_SOURCE_DIR} -DNAME=${name}
       -DOUT=${CMAKE_BINARY_DIR}/packages -P ${PROJECT_SOURCE_DIR}/scripts/make_package.cmake)
endforeach()
add_custom_target(packages ${package_commands} COMMENT "Writing the drop-in packages" VERBATIM)
