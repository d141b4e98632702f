# `cmake --install build --prefix P` (README.md, "Install"): the command, libflexmoor, its
# headers, its CMake package and pkg-config file, the data and the documents:
#   P/bin/flexmoor (and libflexmoor_mpi.so beside it when built with MPI)
#   P/lib/libflexmoor.so -> libflexmoor.so.0 -> libflexmoor.so.0.1.0
#   P/include/flexmoor/{libstruct,libhydro,apps}/...   (and P/include/flexmoor.h: the C API)
#   P/lib/cmake/flexmoor/   find_package(flexmoor): the target flexmoor::flexmoor
#   P/lib/pkgconfig/flexmoor.pc
#   P/share/flexmoor/{cases,plot}/   found at run time from the library (apps/common/data_dir.hpp)
#   P/share/doc/flexmoor/
# The build tree has share/flexmoor too, its folders links to the source's, so that a command or
# library run from the build tree finds them by the same relative path.
include(CMakePackageConfigHelpers)

set(FLEXMOOR_BUILD_DATA_DIR ${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_DATADIR}/flexmoor)
file(MAKE_DIRECTORY ${FLEXMOOR_BUILD_DATA_DIR})
file(CREATE_LINK ${PROJECT_SOURCE_DIR}/cases ${FLEXMOOR_BUILD_DATA_DIR}/cases SYMBOLIC)
file(CREATE_LINK ${PROJECT_SOURCE_DIR}/apps/plot ${FLEXMOOR_BUILD_DATA_DIR}/plot SYMBOLIC)

install(TARGETS flexmoor RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(FLEXMOOR_MPI)
  # Beside the command, where it loads it from (apps/mpi/mpi_study.cpp).
  install(TARGETS flexmoor_mpi LIBRARY DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
install(TARGETS flexmoor_library EXPORT flexmoorTargets LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})

# Every header, where it is in the source, so `#include "libstruct/model/model.hpp"` works with
# -I P/include/flexmoor; the folders are read at install time, so new headers need no change here.
foreach(part libstruct libhydro apps)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${part} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/flexmoor
          FILES_MATCHING PATTERN "*.hpp" PATTERN "*.h" PATTERN "plot" EXCLUDE)
endforeach()
install(FILES ${PROJECT_SOURCE_DIR}/apps/capi/flexmoor.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        OPTIONAL)

# The CMake package: the exported target, the version (same major version is compatible) and
# the dependencies its headers need (flexmoorConfig.cmake.in).
set(FLEXMOOR_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/flexmoor)
install(EXPORT flexmoorTargets NAMESPACE flexmoor:: DESTINATION ${FLEXMOOR_CMAKE_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/flexmoorConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/flexmoorConfig.cmake
                              INSTALL_DESTINATION ${FLEXMOOR_CMAKE_DIR})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/flexmoorConfigVersion.cmake
                                 COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_BINARY_DIR}/flexmoorConfig.cmake
              ${CMAKE_BINARY_DIR}/flexmoorConfigVersion.cmake
              ${CMAKE_CURRENT_LIST_DIR}/flexmoorSuiteSparse.cmake
        DESTINATION ${FLEXMOOR_CMAKE_DIR})

# pkg-config: relocatable (its prefix is found from where the file is).
file(RELATIVE_PATH FLEXMOOR_PC_PREFIX ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig
     ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" FLEXMOOR_PC_PREFIX "${FLEXMOOR_PC_PREFIX}")
configure_file(${CMAKE_CURRENT_LIST_DIR}/flexmoor.pc.in ${CMAKE_BINARY_DIR}/flexmoor.pc @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/flexmoor.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/cases/ DESTINATION ${CMAKE_INSTALL_DATADIR}/flexmoor/cases)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/apps/plot/
        DESTINATION ${CMAKE_INSTALL_DATADIR}/flexmoor/plot
        FILES_MATCHING PATTERN "*.py" PATTERN "__pycache__" EXCLUDE)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/LICENSE
        DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs DESTINATION ${CMAKE_INSTALL_DOCDIR})

# The Python module where Debian's python3 finds a prefix's modules (P/lib/python3/dist-packages:
# /usr/local/lib/python3/dist-packages is on its path), finding libflexmoor in P/lib.
if(FLEXMOOR_PYTHON)
  set(FLEXMOOR_PYTHON_INSTALL_DIR lib/python3/dist-packages CACHE STRING
      "Where `cmake --install` puts the Python module, under the prefix")
  file(RELATIVE_PATH FLEXMOOR_LIBDIR_FROM_PYTHON
       ${CMAKE_INSTALL_PREFIX}/${FLEXMOOR_PYTHON_INSTALL_DIR} ${CMAKE_INSTALL_FULL_LIBDIR})
  set_target_properties(flexmoor_python PROPERTIES
                        INSTALL_RPATH "$ORIGIN/${FLEXMOOR_LIBDIR_FROM_PYTHON}")
  install(TARGETS flexmoor_python LIBRARY DESTINATION ${FLEXMOOR_PYTHON_INSTALL_DIR})
endif()
# The example hosts' sources, to read and build against the installed library.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples
        PATTERN "CMakeLists.txt" EXCLUDE)
