# SuiteSparse's CHOLMOD and UMFPACK (Debian's libsuitesparse-dev, which ships neither a CMake
# package nor a pkg-config file) as the imported target flexmoor::SuiteSparse. Included by the
# build and, installed beside it, by flexmoorConfig.cmake for a project that uses flexmoor (the
# headers of libstruct/solve include Eigen's CHOLMOD and UMFPACK wrappers). Sets
# flexmoor_SuiteSparse_FOUND.
set(flexmoor_SuiteSparse_FOUND TRUE)
if(NOT TARGET flexmoor::SuiteSparse)
  find_path(FLEXMOOR_SUITESPARSE_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
  set(_flexmoor_suitesparse_libraries)
  foreach(_flexmoor_lib cholmod umfpack amd suitesparseconfig)
    find_library(FLEXMOOR_${_flexmoor_lib}_LIBRARY ${_flexmoor_lib})
    if(NOT FLEXMOOR_${_flexmoor_lib}_LIBRARY)
      set(flexmoor_SuiteSparse_FOUND FALSE)
    endif()
    list(APPEND _flexmoor_suitesparse_libraries ${FLEXMOOR_${_flexmoor_lib}_LIBRARY})
  endforeach()
  if(NOT FLEXMOOR_SUITESPARSE_INCLUDE_DIR)
    set(flexmoor_SuiteSparse_FOUND FALSE)
  endif()
  if(flexmoor_SuiteSparse_FOUND)
    add_library(flexmoor::SuiteSparse INTERFACE IMPORTED)
    set_target_properties(flexmoor::SuiteSparse PROPERTIES
                          INTERFACE_INCLUDE_DIRECTORIES ${FLEXMOOR_SUITESPARSE_INCLUDE_DIR}
                          INTERFACE_LINK_LIBRARIES "${_flexmoor_suitesparse_libraries}")
  endif()
endif()
