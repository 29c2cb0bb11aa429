# Install rules and package files:
#  - headers (the cvms target's HEADERS file set), the library, and the export
#    set cvmsTargets with namespace cvms::, under GNUInstallDirs locations;
#  - cvmsConfig.cmake + cvmsConfigVersion.cmake in <libdir>/cmake/cvms, with
#    our FindCvmsGMP.cmake beside them so the config can re-find GMP;
#  - the same three files for the build tree (export()), so another project
#    can use an uninstalled build with -Dcvms_DIR=<build dir>;
#  - cvms.pc for pkg-config, relocatable (paths relative to the .pc file), so
#    `cmake --install --prefix <anywhere>` and packagers moving the tree work;
#  - the licence text, share/doc/cvms/LICENSE (CMAKE_INSTALL_DOCDIR): the MIT
#    licence asks that it travel with every copy, binaries included.
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

# Before 1.0 every minor release may break the API (semantic versioning), so a
# request for 0.1 must not accept 0.2; from 1.0 on the major version decides.
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(CVMS_COMPATIBILITY SameMinorVersion)
else()
  set(CVMS_COMPATIBILITY SameMajorVersion)
endif()

configure_package_config_file("${PROJECT_SOURCE_DIR}/cmake/cvmsConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/cvmsConfig.cmake" INSTALL_DESTINATION ${CVMS_CONFIG_DIR})
write_basic_package_version_file("${PROJECT_BINARY_DIR}/cvmsConfigVersion.cmake"
  VERSION ${PROJECT_VERSION} COMPATIBILITY ${CVMS_COMPATIBILITY})
# The build tree is a package too: put the find module beside its config.
configure_file("${PROJECT_SOURCE_DIR}/cmake/FindCvmsGMP.cmake" "${PROJECT_BINARY_DIR}/FindCvmsGMP.cmake" COPYONLY)

install(FILES
  "${PROJECT_BINARY_DIR}/cvmsConfig.cmake"
  "${PROJECT_BINARY_DIR}/cvmsConfigVersion.cmake"
  "${PROJECT_SOURCE_DIR}/cmake/FindCvmsGMP.cmake"
  DESTINATION ${CVMS_CONFIG_DIR})

# pkg-config: prefix is found from the .pc file's own location (${pcfiledir}),
# because the install prefix is often chosen only at install time.
set(CVMS_PC_DIR "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
if(IS_ABSOLUTE "${CVMS_PC_DIR}")
  set(CVMS_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
else()
  file(RELATIVE_PATH CVMS_PC_UP "/prefix/${CVMS_PC_DIR}" "/prefix")
  string(REGEX REPLACE "/$" "" CVMS_PC_UP "${CVMS_PC_UP}")
  set(CVMS_PC_PREFIX "\${pcfiledir}/${CVMS_PC_UP}")
endif()
foreach(dir IN ITEMS LIBDIR INCLUDEDIR)
  if(IS_ABSOLUTE "${CMAKE_INSTALL_${dir}}")
    set(CVMS_PC_${dir} "${CMAKE_INSTALL_${dir}}")
  else()
    set(CVMS_PC_${dir} "\${prefix}/${CMAKE_INSTALL_${dir}}")
  endif()
endforeach()
configure_file("${PROJECT_SOURCE_DIR}/cmake/cvms.pc.in" "${PROJECT_BINARY_DIR}/cvms.pc" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/cvms.pc" DESTINATION "${CVMS_PC_DIR}")

install(FILES "${PROJECT_SOURCE_DIR}/LICENSE" DESTINATION ${CMAKE_INSTALL_DOCDIR})
