# lib/pkgconfig/dcel.pc, for projects built without CMake:
#   c++ -std=c++20 app.cpp $(pkg-config --cflags --libs dcel)
# The prefix is found from the .pc file's own place (${pcfiledir}), so the
# file is right wherever `cmake --install --prefix` puts the tree. Cflags
# carry the library's public compile definitions (the contract level must be
# the same in the library and in every file that includes its headers); the
# language level stays the user's choice (C++20 or later).
set(dcel_pc_dir ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}" OR IS_ABSOLUTE "${CMAKE_INSTALL_INCLUDEDIR}")
  set(dcel_pc_prefix "${CMAKE_INSTALL_PREFIX}")
else()
  file(RELATIVE_PATH dcel_pc_up "/prefix/${dcel_pc_dir}" "/prefix")
  string(REGEX REPLACE "/$" "" dcel_pc_up "${dcel_pc_up}")
  set(dcel_pc_prefix "\${pcfiledir}/${dcel_pc_up}")
endif()
get_target_property(dcel_pc_definitions dcel INTERFACE_COMPILE_DEFINITIONS)
set(dcel_pc_cflags "")
foreach(definition IN LISTS dcel_pc_definitions)
  string(APPEND dcel_pc_cflags " -D${definition}")
endforeach()
configure_file(${CMAKE_CURRENT_LIST_DIR}/dcel.pc.in ${PROJECT_BINARY_DIR}/dcel.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/dcel.pc DESTINATION ${dcel_pc_dir})
