# Install rules and the package config: after `cmake --install`, find_package(rbdc) gives the
# runtime library (rbdc::runtime) and rbdc_generate(); <prefix>/bin/rbdc runs the generator from
# <prefix>/share/rbdc with <prefix>/bin/rbdc-model.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(RBDC_INSTALL_SHAREDIR ${CMAKE_INSTALL_DATADIR}/rbdc)
set(RBDC_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/rbdc)

set_target_properties(rbdc_runtime PROPERTIES EXPORT_NAME runtime)
install(TARGETS rbdc_runtime EXPORT rbdcTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/runtime/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
foreach(tool rbdc-model rbdc-eval rbdc-info)
  if(TARGET ${tool})
    install(TARGETS ${tool} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  endif()
endforeach()
install(PROGRAMS ${PROJECT_SOURCE_DIR}/rbdc DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/generator/rbdcgen DESTINATION ${RBDC_INSTALL_SHAREDIR}/generator
        PATTERN __pycache__ EXCLUDE)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/templates ${PROJECT_SOURCE_DIR}/scenes ${PROJECT_SOURCE_DIR}/robots
        DESTINATION ${RBDC_INSTALL_SHAREDIR})
install(FILES ${CMAKE_BINARY_DIR}/rbdc-verify.json DESTINATION ${RBDC_INSTALL_SHAREDIR})

install(EXPORT rbdcTargets NAMESPACE rbdc:: DESTINATION ${RBDC_INSTALL_CMAKEDIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/rbdcConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/rbdcConfig.cmake
                              INSTALL_DESTINATION ${RBDC_INSTALL_CMAKEDIR}
                              PATH_VARS CMAKE_INSTALL_BINDIR RBDC_INSTALL_SHAREDIR)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/rbdcConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/rbdcConfig.cmake ${CMAKE_BINARY_DIR}/rbdcConfigVersion.cmake
              ${CMAKE_CURRENT_LIST_DIR}/RbdcGenerate.cmake
        DESTINATION ${RBDC_INSTALL_CMAKEDIR})
