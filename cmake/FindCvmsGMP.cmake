# Finds GMP and its C++ layer gmpxx. Namespaced (CvmsGMP::) so it never
# clashes with another project's FindGMP. Works with Debian's packages, vcpkg
# and conan: pkg-config gives hints when available, then find_path /
# find_library search the usual prefixes (CMAKE_PREFIX_PATH, toolchains).
#
# Result: CvmsGMP_FOUND, imported targets CvmsGMP::gmp and CvmsGMP::gmpxx
# (gmpxx links gmp).
include(FindPackageHandleStandardArgs)

find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(PC_CVMS_GMP QUIET gmp)
  pkg_check_modules(PC_CVMS_GMPXX QUIET gmpxx)
endif()

find_path(CvmsGMP_INCLUDE_DIR NAMES gmp.h HINTS ${PC_CVMS_GMP_INCLUDE_DIRS})
find_path(CvmsGMP_GMPXX_INCLUDE_DIR NAMES gmpxx.h HINTS ${PC_CVMS_GMPXX_INCLUDE_DIRS} ${CvmsGMP_INCLUDE_DIR})
find_library(CvmsGMP_LIBRARY NAMES gmp libgmp HINTS ${PC_CVMS_GMP_LIBRARY_DIRS})
find_library(CvmsGMP_GMPXX_LIBRARY NAMES gmpxx libgmpxx HINTS ${PC_CVMS_GMPXX_LIBRARY_DIRS})

find_package_handle_standard_args(CvmsGMP
  REQUIRED_VARS CvmsGMP_LIBRARY CvmsGMP_GMPXX_LIBRARY CvmsGMP_INCLUDE_DIR CvmsGMP_GMPXX_INCLUDE_DIR)

if(CvmsGMP_FOUND)
  if(NOT TARGET CvmsGMP::gmp)
    add_library(CvmsGMP::gmp UNKNOWN IMPORTED)
    set_target_properties(CvmsGMP::gmp PROPERTIES
      IMPORTED_LOCATION "${CvmsGMP_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${CvmsGMP_INCLUDE_DIR}")
  endif()
  if(NOT TARGET CvmsGMP::gmpxx)
    add_library(CvmsGMP::gmpxx UNKNOWN IMPORTED)
    set_target_properties(CvmsGMP::gmpxx PROPERTIES
      IMPORTED_LOCATION "${CvmsGMP_GMPXX_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${CvmsGMP_GMPXX_INCLUDE_DIR}"
      INTERFACE_LINK_LIBRARIES CvmsGMP::gmp)
  endif()
endif()
mark_as_advanced(CvmsGMP_INCLUDE_DIR CvmsGMP_GMPXX_INCLUDE_DIR CvmsGMP_LIBRARY CvmsGMP_GMPXX_LIBRARY)
