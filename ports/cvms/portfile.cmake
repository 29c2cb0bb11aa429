# vcpkg overlay port for cvms. It builds the source tree it lives in
# (<cvms>/ports/cvms/../..), so from a cvms checkout:
#   vcpkg install cvms --overlay-ports=<cvms>/ports
# To build a published release instead (e.g. in a registry), replace the
# SOURCE_PATH lines with:
#   vcpkg_from_git(OUT_SOURCE_PATH SOURCE_PATH URL <cvms git url> REF <commit>)
get_filename_component(SOURCE_PATH "${CMAKE_CURRENT_LIST_DIR}/../.." ABSOLUTE)
if(NOT EXISTS "${SOURCE_PATH}/CMakeLists.txt" OR NOT EXISTS "${SOURCE_PATH}/include/cvms")
  message(FATAL_ERROR "cvms overlay port: no cvms source tree at ${SOURCE_PATH}; "
                      "use the port from inside a cvms checkout or switch to vcpkg_from_git")
endif()

# Feature "tools": the cvms command-line tool (needs CLI11).
vcpkg_check_features(OUT_FEATURE_OPTIONS FEATURE_OPTIONS
  FEATURES
    tools CVMS_BUILD_TOOLS
)

# BUILD_SHARED_LIBS follows VCPKG_LIBRARY_LINKAGE (set by vcpkg_cmake_configure).
# The static library is position-independent either way (cvms's default).
vcpkg_cmake_configure(
  SOURCE_PATH "${SOURCE_PATH}"
  OPTIONS
    ${FEATURE_OPTIONS}
    -DCVMS_BUILD_TESTS=OFF
    -DCVMS_BUILD_BENCHMARKS=OFF
    -DCVMS_BUILD_EXAMPLES=OFF
    -DCVMS_WARNINGS_AS_ERRORS=OFF
)
vcpkg_cmake_install()
vcpkg_cmake_config_fixup(PACKAGE_NAME cvms CONFIG_PATH lib/cmake/cvms)
vcpkg_fixup_pkgconfig()

if("tools" IN_LIST FEATURES)
  # Moves bin/cvms to tools/cvms/ and removes the (then empty) bin folders.
  vcpkg_copy_tools(TOOL_NAMES cvms AUTO_CLEAN)
endif()

# The licence goes to share/cvms/copyright (below), where vcpkg expects it.
file(REMOVE_RECURSE
  "${CURRENT_PACKAGES_DIR}/debug/include"
  "${CURRENT_PACKAGES_DIR}/debug/share"
  "${CURRENT_PACKAGES_DIR}/share/doc"
)

file(INSTALL "${CMAKE_CURRENT_LIST_DIR}/usage" DESTINATION "${CURRENT_PACKAGES_DIR}/share/${PORT}")
vcpkg_install_copyright(FILE_LIST "${SOURCE_PATH}/LICENSE")
