# Installation and the exported CMake package: find_package(Signorini) then link
# Signorini::signorini (see examples/).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS signorini EXPORT SignoriniTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
# The installed program finds the installed library next to it, wherever the prefix is.
file(RELATIVE_PATH SIGNORINI_BIN_TO_LIB ${CMAKE_INSTALL_FULL_BINDIR} ${CMAKE_INSTALL_FULL_LIBDIR})
set_target_properties(signorini_app PROPERTIES INSTALL_RPATH "$ORIGIN/${SIGNORINI_BIN_TO_LIB}")
install(TARGETS signorini_app RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/signorini DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${PROJECT_BINARY_DIR}/include/signorini/core/Version.hpp
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/signorini/core)
install(FILES ${PROJECT_SOURCE_DIR}/cmake/FindMETIS.cmake ${PROJECT_SOURCE_DIR}/cmake/SignoriniTrilinos.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Signorini)
install(EXPORT SignoriniTargets NAMESPACE Signorini:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Signorini)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/SignoriniConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/SignoriniConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Signorini)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/SignoriniConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/SignoriniConfig.cmake ${PROJECT_BINARY_DIR}/SignoriniConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Signorini)
