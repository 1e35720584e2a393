# Installs the module libraries, their headers, the command-line program and a CMake package so
# that another project can `find_package(ModalTyre)` and link ModalTyre::contact.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(_modaltyre_modules core modal ema solvers rheology ground contact transient studies discover tir
    init uncertainty report fmu)
foreach(module IN LISTS _modaltyre_modules)
  set_target_properties(modaltyre_${module} PROPERTIES EXPORT_NAME ${module})
  install(TARGETS modaltyre_${module} EXPORT ModalTyreTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${module}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()
install(TARGETS modaltyre RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The licence travels with the binaries and headers (README.md, "Licence").
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(EXPORT ModalTyreTargets NAMESPACE ModalTyre::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/ModalTyre)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ModalTyreConfig.cmake.in
  ${PROJECT_BINARY_DIR}/ModalTyreConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/ModalTyre)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/ModalTyreConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/ModalTyreConfig.cmake
              ${PROJECT_BINARY_DIR}/ModalTyreConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/ModalTyre)
