# `cmake --install build [--prefix DIR]`: the executable, the libraries with their headers and
# a CMake package (find_package(feticon) gives the imported target feticon::feticon, the
# application layer with everything below it), the Gmsh module, the plot scripts and the
# Python module. examples/cpp_library builds against it (tests/cli/cpp_package.sh).
include(CMakePackageConfigHelpers)

set(FETICON_LIBRARIES feticon_flags feticon_third_party feticon_common feticon_la feticon_mesh feticon_fem
  feticon_io feticon_qp feticon_par feticon_decomposition feticon_contact feticon_problems feticon_dual
  feticon_nonlinear feticon_lib feticon_app)
set_target_properties(feticon_app PROPERTIES EXPORT_NAME feticon)
install(TARGETS ${FETICON_LIBRARIES} EXPORT feticonTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}/feticon
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/feticon)
install(TARGETS feticon RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS feticon_gmsh LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/feticon)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/feticon
  FILES_MATCHING PATTERN "*.hpp")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/app/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/feticon/app
  FILES_MATCHING PATTERN "*.hpp")
install(FILES ${PROJECT_SOURCE_DIR}/scripts/plot_hertz.py ${PROJECT_SOURCE_DIR}/scripts/plot_model.py
  DESTINATION ${CMAKE_INSTALL_DATADIR}/feticon/scripts)
install(EXPORT feticonTargets NAMESPACE feticon:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/feticon)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/feticonConfig.cmake.in
  ${PROJECT_BINARY_DIR}/feticonConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/feticon)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/feticonConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/feticonConfig.cmake ${PROJECT_BINARY_DIR}/feticonConfigVersion.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/feticon)
if(FETICON_PYTHON)
  # Where Debian's python3 looks under the prefix (/usr/local/lib/python3.11/dist-packages).
  set(FETICON_PYTHON_INSTALL_DIR
    ${CMAKE_INSTALL_LIBDIR}/python${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}/dist-packages/feticon)
  install(TARGETS _feticon LIBRARY DESTINATION ${FETICON_PYTHON_INSTALL_DIR})
  install(FILES ${PROJECT_SOURCE_DIR}/python/feticon/__init__.py DESTINATION ${FETICON_PYTHON_INSTALL_DIR})
endif()
