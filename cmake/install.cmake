# Install rules, the CMake package and the pkg-config file (included last by
# the top-level CMakeLists.txt, so every target below exists by then):
#   include/dcel/**.hpp                 the public headers (src/dcel/public-headers.txt)
#   lib/libdcel.a                       dcel::dcel, always
#   lib/libdcel_gen.a                   dcel::gen (and dcel::check_testing), when built
#   bin/dcel                            dcel::cli, when built
#   lib/cmake/dcel/dcelConfig.cmake     find_package(dcel CONFIG), with
#   lib/cmake/dcel/dcelConfigVersion.cmake  (SameMajorVersion) and
#   lib/cmake/dcel/dcel*Targets*.cmake  the targets, in namespace dcel::
#   lib/pkgconfig/dcel.pc               pkg-config --cflags --libs dcel
#
# The generators and the CLI are optional parts: `cmake --build B --target dcel`
# followed by `cmake --install B` installs the library alone. Each optional
# part has its own export set, installed with OPTIONAL, and dcelConfig.cmake
# loads a part's targets only when its file was installed (so
# find_package(dcel COMPONENTS cli) fails cleanly when the CLI is absent).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(dcel_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/dcel)

# The library and its public headers (src/dcel/public-headers.txt, the list
# that scripts/check-layers enforces); internal headers stay in the source tree.
set_target_properties(dcel PROPERTIES EXPORT_NAME dcel)
install(TARGETS dcel
  EXPORT dcelTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT dcelTargets NAMESPACE dcel:: DESTINATION ${dcel_cmake_dir})
file(STRINGS ${PROJECT_SOURCE_DIR}/src/dcel/public-headers.txt dcel_public_headers REGEX "^dcel/")
foreach(header IN LISTS dcel_public_headers)
  get_filename_component(header_dir ${header} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/src/${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/${header_dir})
endforeach()

# dcel_optional_part(NAME TARGET... ) installs the targets (the first one has
# a file; the others may be INTERFACE libraries riding along) in the export
# set dcel<Name>Targets and records, for dcelConfig.cmake, the installed path
# of the first target's file, whose presence says the part was installed.
set(dcel_optional_parts "")
function(dcel_optional_part part)
  set(targets "")
  foreach(t IN LISTS ARGN)
    if(TARGET ${t})
      list(APPEND targets ${t})
    endif()
  endforeach()
  if(NOT targets)
    return()
  endif()
  list(GET targets 0 first)
  get_target_property(type ${first} TYPE)
  get_target_property(name ${first} OUTPUT_NAME)
  if(NOT name)
    set(name ${first})
  endif()
  if(type STREQUAL "EXECUTABLE")
    set(file ${CMAKE_INSTALL_BINDIR}/${name}${CMAKE_EXECUTABLE_SUFFIX})
  elseif(type STREQUAL "SHARED_LIBRARY")
    set(file ${CMAKE_INSTALL_LIBDIR}/${CMAKE_SHARED_LIBRARY_PREFIX}${name}${CMAKE_SHARED_LIBRARY_SUFFIX})
  else()
    set(file ${CMAKE_INSTALL_LIBDIR}/${CMAKE_STATIC_LIBRARY_PREFIX}${name}${CMAKE_STATIC_LIBRARY_SUFFIX})
  endif()
  install(TARGETS ${targets}
    EXPORT dcel${part}Targets
    OPTIONAL
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(EXPORT dcel${part}Targets NAMESPACE dcel:: DESTINATION ${dcel_cmake_dir})
  string(TOLOWER ${part} component)
  set(dcel_optional_parts "${dcel_optional_parts}dcel_optional_part(${component} ${part} \"${file}\")\n" PARENT_SCOPE)
endfunction()

if(TARGET dcel_gen)
  set_target_properties(dcel_gen PROPERTIES EXPORT_NAME gen)
endif()
if(TARGET dcel_check_testing)
  # The header-only GoogleTest/RapidCheck helpers, which need dcel::gen.
  set_target_properties(dcel_check_testing PROPERTIES EXPORT_NAME check_testing)
endif()
if(TARGET dcel_cli)
  set_target_properties(dcel_cli PROPERTIES EXPORT_NAME cli)
endif()
dcel_optional_part(Gen dcel_gen dcel_check_testing)
dcel_optional_part(Cli dcel_cli)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/dcelConfig.cmake.in
  ${PROJECT_BINARY_DIR}/dcelConfig.cmake
  INSTALL_DESTINATION ${dcel_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/dcelConfigVersion.cmake
  COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/dcelConfig.cmake ${PROJECT_BINARY_DIR}/dcelConfigVersion.cmake
  DESTINATION ${dcel_cmake_dir})

include(${CMAKE_CURRENT_LIST_DIR}/pkg_config.cmake)
