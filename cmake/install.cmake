# Install rules, the CMake package and the pkg-config file (included last by
# the top-level CMakeLists.txt, so every target below exists by then). Each
# component installs its library and exactly the headers of its folder's
# public-headers.txt (scripts/check-layers checks the lists):
#   include/dcel/...                    dcel::dcel, dcel::io, dcel::check: always
#   lib/libdcel.a, libdcel_io.a, libdcel_check.a
#   include/dcel/gen/, include/dcel/testing/   with lib/libdcel_gen.a, when built:
#                                       dcel::gen and the header-only dcel::testing
#   bin/dcel                            dcel::cli, when built
#   lib/cmake/dcel/dcelConfig.cmake     find_package(dcel CONFIG), with
#   lib/cmake/dcel/dcelConfigVersion.cmake  (SameMajorVersion) and
#   lib/cmake/dcel/dcel*Targets*.cmake  the targets, in namespace dcel::
#   lib/pkgconfig/dcel.pc               pkg-config --cflags --libs dcel
# The diff engine (dcel_diff) is internal to the CLI and never installed.
#
# The generators and the CLI are optional parts: `cmake --build B --target dcel_check`
# followed by `cmake --install B` installs the library alone. Each optional
# part has its own export set, installed with OPTIONAL, and dcelConfig.cmake
# loads a part's targets only when its file was installed (so
# find_package(dcel COMPONENTS cli) fails cleanly when the CLI is absent); an
# optional part's headers are installed only with its library.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(dcel_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/dcel)

# dcel_install_headers(FOLDER): the headers listed in
# src/FOLDER/public-headers.txt (paths relative to src/).
function(dcel_install_headers folder)
  file(STRINGS ${PROJECT_SOURCE_DIR}/src/${folder}/public-headers.txt headers REGEX "^dcel/")
  foreach(header IN LISTS headers)
    get_filename_component(header_dir ${header} DIRECTORY)
    install(FILES ${PROJECT_SOURCE_DIR}/src/${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/${header_dir})
  endforeach()
endfunction()

# dcel_install_headers_with(TARGET FOLDER...): the headers of the folders'
# lists, at install time, only when TARGET's library file has been installed.
function(dcel_install_headers_with target)
  set(code "")
  foreach(folder IN LISTS ARGN)
    file(STRINGS ${PROJECT_SOURCE_DIR}/src/${folder}/public-headers.txt headers REGEX "^dcel/")
    foreach(header IN LISTS headers)
      get_filename_component(header_dir ${header} DIRECTORY)
      string(APPEND code "  file(INSTALL DESTINATION \"\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_INCLUDEDIR}/${header_dir}\" "
                         "TYPE FILE FILES \"${PROJECT_SOURCE_DIR}/src/${header}\")\n")
    endforeach()
  endforeach()
  install(CODE "if(EXISTS \"\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/$<TARGET_FILE_NAME:${target}>\")\n${code}endif()")
endfunction()

# The library: the core, io and check, and their public headers; internal
# headers stay in the source tree.
set_target_properties(dcel PROPERTIES EXPORT_NAME dcel)
set_target_properties(dcel_io PROPERTIES EXPORT_NAME io)
set_target_properties(dcel_check PROPERTIES EXPORT_NAME check)
install(TARGETS dcel dcel_io dcel_check
  EXPORT dcelTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT dcelTargets NAMESPACE dcel:: DESTINATION ${dcel_cmake_dir})
dcel_install_headers(dcel)
dcel_install_headers(dcel/io)
dcel_install_headers(dcel/check)

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
if(TARGET dcel_testing)
  # The header-only GoogleTest/RapidCheck/libFuzzer helpers, which need dcel::gen.
  set_target_properties(dcel_testing PROPERTIES EXPORT_NAME testing)
endif()
if(TARGET dcel_cli)
  set_target_properties(dcel_cli PROPERTIES EXPORT_NAME cli)
endif()
dcel_optional_part(Gen dcel_gen dcel_testing)
dcel_optional_part(Cli dcel_cli)
# The generators' and the helpers' headers only with the generators' library
# (installed just above, or not, by the OPTIONAL rule): an install of the
# library alone ships no header that cannot link.
if(TARGET dcel_gen)
  dcel_install_headers_with(dcel_gen dcel/gen dcel/testing)
endif()

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/dcelConfig.cmake.in
  ${PROJECT_BINARY_DIR}/dcelConfig.cmake
  INSTALL_DESTINATION ${dcel_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/dcelConfigVersion.cmake
  COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/dcelConfig.cmake ${PROJECT_BINARY_DIR}/dcelConfigVersion.cmake
  DESTINATION ${dcel_cmake_dir})

include(${CMAKE_CURRENT_LIST_DIR}/pkg_config.cmake)
