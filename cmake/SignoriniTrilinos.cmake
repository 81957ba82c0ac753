# Wraps the Trilinos libraries found by find_package(Trilinos) into one imported target.
if(NOT TARGET Signorini::Trilinos)
  add_library(Signorini::Trilinos INTERFACE IMPORTED)
  set_target_properties(Signorini::Trilinos PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${Trilinos_INCLUDE_DIRS};${Trilinos_TPL_INCLUDE_DIRS}"
    INTERFACE_LINK_LIBRARIES "${Trilinos_LIBRARIES};${Trilinos_TPL_LIBRARIES};MPI::MPI_CXX")
endif()
