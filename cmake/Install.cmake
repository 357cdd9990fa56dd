# `cmake --install build [--prefix P]` (scripts/install): the five programs; the libraries with
# their headers and a CMake package (find_package(isosid), targets isosid::isosid_runtime,
# isosid::isosid_prep, isosid::isosid_format, isosid::isosid_format_tools, isosid::isosid_common);
# the Python package in Debian's dist-packages layout.
include(CMakePackageConfigHelpers)

install(TARGETS isosid-prep isosid-run isosid-info isosid-diff isosid-export RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(TARGET isosid-sweep)
  install(TARGETS isosid-sweep RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
install(TARGETS isosid_format isosid_format_tools isosid_common isosid_prep isosid_runtime isosid_options EXPORT isosidTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}/isosid)

# headers: format's and common's as isosid/format, isosid/common; the runtime's and the
# preprocessor's in their own roots, which their targets put on the include path
install(DIRECTORY format/include/ common/include/ ${PROJECT_BINARY_DIR}/format/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp")
install(DIRECTORY runtime/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/isosid/runtime FILES_MATCHING PATTERN "*.hpp" PATTERN tools EXCLUDE)
install(DIRECTORY preprocess/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/isosid/preprocess FILES_MATCHING PATTERN "*.hpp"
        PATTERN tools EXCLUDE)

set(ISOSID_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/isosid)
install(EXPORT isosidTargets NAMESPACE isosid:: DESTINATION ${ISOSID_CMAKE_DIR})
configure_package_config_file(cmake/isosid-config.cmake.in ${PROJECT_BINARY_DIR}/isosid-config.cmake INSTALL_DESTINATION ${ISOSID_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/isosid-config-version.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/isosid-config.cmake ${PROJECT_BINARY_DIR}/isosid-config-version.cmake DESTINATION ${ISOSID_CMAKE_DIR})

if(ISOSID_PYTHON)
  # Debian's Python searches <prefix>/lib/python3.X/dist-packages for /usr/local and /usr
  set(ISOSID_PYTHON_INSTALL_DIR lib/python${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}/dist-packages
      CACHE PATH "where the Python package goes, under the prefix")
  install(DIRECTORY isosid/ DESTINATION ${ISOSID_PYTHON_INSTALL_DIR}/isosid FILES_MATCHING PATTERN "*.py" PATTERN __pycache__ EXCLUDE)
  install(TARGETS _isosid _isosid_prep LIBRARY DESTINATION ${ISOSID_PYTHON_INSTALL_DIR}/isosid)
endif()
