# `cmake --install <build> --prefix P` installs the libraries and public headers, and
# find_package(GuardianPhysics CONFIG) then provides Guardian::interfaces, Guardian::framework,
# Guardian::physics and Guardian::collision.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(install_targets guardian_host guardian_interfaces guardian_framework)
set_target_properties(guardian_host PROPERTIES EXPORT_NAME host)
set_target_properties(guardian_interfaces PROPERTIES EXPORT_NAME interfaces)
set_target_properties(guardian_framework PROPERTIES EXPORT_NAME framework)
foreach(module physics collision)
  if(TARGET guardian_${module})
    set_target_properties(guardian_${module} PROPERTIES EXPORT_NAME ${module})
    list(APPEND install_targets guardian_${module})
  endif()
endforeach()

install(TARGETS ${install_targets} EXPORT GuardianPhysicsTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
file(GLOB public_headers ${PROJECT_SOURCE_DIR}/Interfaces/*.h)
list(REMOVE_ITEM public_headers ${PROJECT_SOURCE_DIR}/Interfaces/MathEigen.h) # the engine's .cpp files only
file(GLOB framework_headers ${PROJECT_SOURCE_DIR}/Framework/*.h)
install(FILES ${public_headers} ${framework_headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/guardian)
install(EXPORT GuardianPhysicsTargets NAMESPACE Guardian::
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/GuardianPhysics)
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/GuardianPhysicsConfig.cmake.in [=[
@PACKAGE_INIT@
include(CMakeFindDependencyMacro)
find_dependency(Eigen3 3.4 CONFIG)
include("${CMAKE_CURRENT_LIST_DIR}/GuardianPhysicsTargets.cmake")
]=])
configure_package_config_file(${CMAKE_CURRENT_BINARY_DIR}/GuardianPhysicsConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/GuardianPhysicsConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/GuardianPhysics)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/GuardianPhysicsConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/GuardianPhysicsConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/GuardianPhysicsConfigVersion.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/GuardianPhysics)
