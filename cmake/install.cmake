# Install rules and the CMake package (included last by the top-level
# CMakeLists.txt, so every target below exists by then):
#   include/dcel/**.hpp                 the public headers (src/dcel/public-headers.txt)
#   lib/libdcel*.a                      the libraries in dcel_install_targets
#   bin/dcel                            the CLI (DCEL_BUILD_CLI)
#   lib/cmake/dcel/dcelConfig.cmake     find_package(dcel CONFIG), with
#   lib/cmake/dcel/dcelConfigVersion.cmake  (SameMajorVersion) and
#   lib/cmake/dcel/dcelTargets*.cmake   the targets, in namespace dcel::
# To export a new library, add its target to dcel_install_targets and give it
# an EXPORT_NAME (the name after dcel::). Targets that do not exist in this
# configuration are skipped.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(dcel_install_targets
  dcel        # dcel::dcel
  dcel_gen    # dcel::gen
  dcel_check_testing  # dcel::check_testing, the header-only GoogleTest/RapidCheck helpers
  dcel_cli    # dcel::cli, the command-line tool
)
set_target_properties(dcel PROPERTIES EXPORT_NAME dcel)
if(TARGET dcel_gen)
  set_target_properties(dcel_gen PROPERTIES EXPORT_NAME gen)
endif()
if(TARGET dcel_check_testing)
  set_target_properties(dcel_check_testing PROPERTIES EXPORT_NAME check_testing)
endif()
if(TARGET dcel_cli)
  set_target_properties(dcel_cli PROPERTIES EXPORT_NAME cli)
endif()

set(dcel_existing_targets "")
foreach(t IN LISTS dcel_install_targets)
  if(TARGET ${t})
    list(APPEND dcel_existing_targets ${t})
  endif()
endforeach()

install(TARGETS ${dcel_existing_targets}
  EXPORT dcelTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# The public headers only (src/dcel/public-headers.txt, the list that
# scripts/check-layers enforces); internal headers stay in the source tree.
file(STRINGS ${PROJECT_SOURCE_DIR}/src/dcel/public-headers.txt dcel_public_headers REGEX "^dcel/")
foreach(header IN LISTS dcel_public_headers)
  get_filename_component(header_dir ${header} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/src/${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/${header_dir})
endforeach()

set(dcel_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/dcel)
install(EXPORT dcelTargets NAMESPACE dcel:: DESTINATION ${dcel_cmake_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/dcelConfig.cmake.in
  ${PROJECT_BINARY_DIR}/dcelConfig.cmake
  INSTALL_DESTINATION ${dcel_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/dcelConfigVersion.cmake
  COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/dcelConfig.cmake ${PROJECT_BINARY_DIR}/dcelConfigVersion.cmake
  DESTINATION ${dcel_cmake_dir})
