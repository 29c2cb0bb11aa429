# Installs headers, library, the export set (namespace cvms::), a package
# config that re-finds GMP through our own installed find module, and a
# pkg-config file.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(CVMS_CONFIG_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/cvms")

install(TARGETS cvms EXPORT cvmsTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  FILE_SET HEADERS DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

install(EXPORT cvmsTargets NAMESPACE cvms:: DESTINATION ${CVMS_CONFIG_DIR})
export(EXPORT cvmsTargets NAMESPACE cvms:: FILE "${PROJECT_BINARY_DIR}/cvmsTargets.cmake")

configure_package_config_file("${PROJECT_SOURCE_DIR}/cmake/cvmsConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/cvmsConfig.cmake" INSTALL_DESTINATION ${CVMS_CONFIG_DIR})
write_basic_package_version_file("${PROJECT_BINARY_DIR}/cvmsConfigVersion.cmake"
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
# The build tree is usable as a package too (export() above): put the find module beside it.
configure_file("${PROJECT_SOURCE_DIR}/cmake/FindCvmsGMP.cmake" "${PROJECT_BINARY_DIR}/FindCvmsGMP.cmake" COPYONLY)

install(FILES
  "${PROJECT_BINARY_DIR}/cvmsConfig.cmake"
  "${PROJECT_BINARY_DIR}/cvmsConfigVersion.cmake"
  "${PROJECT_SOURCE_DIR}/cmake/FindCvmsGMP.cmake"
  DESTINATION ${CVMS_CONFIG_DIR})

configure_file("${PROJECT_SOURCE_DIR}/cmake/cvms.pc.in" "${PROJECT_BINARY_DIR}/cvms.pc" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/cvms.pc" DESTINATION "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
