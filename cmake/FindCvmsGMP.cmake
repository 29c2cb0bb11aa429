# Finds GMP and its C++ layer gmpxx. Namespaced (CvmsGMP::) so it never
# clashes with another project's FindGMP. It is installed next to
# cvmsConfig.cmake, which re-runs it for consumers.
#
# Search order, first hit wins:
#   1. A CMake package config named gmp that defines gmp::gmpxx: what conan's
#      CMakeDeps generates for conan-center's gmp (targets gmp::libgmp,
#      gmp::gmpxx, gmp::gmp). Its targets are used as they are, so conan's
#      static/shared and Debug/Release choices carry through.
#   2. find_path / find_library, with pkg-config's gmp.pc and gmpxx.pc as
#      hints when pkg-config is there. This covers Debian/Ubuntu packages,
#      vcpkg (whose gmp config has no C++ target; its toolchain puts the
#      installed tree on CMAKE_PREFIX_PATH), Homebrew, a hand-built GMP in
#      CMAKE_PREFIX_PATH or GMP_ROOT / CvmsGMP_ROOT, and conan without
#      CMakeDeps (CMakeToolchain puts the package folders on
#      CMAKE_LIBRARY_PATH / CMAKE_INCLUDE_PATH).
#
# Input:
#   CvmsGMP_USE_STATIC_LIBS  ON: only accept static libgmp.a/libgmpxx.a (for
#                            fully static executables). Ignored when the
#                            conan targets are used.
#   CvmsGMP_NO_CONFIG        ON: skip step 1.
#   CvmsGMP_LIBRARY_RELEASE, CvmsGMP_LIBRARY_DEBUG, CvmsGMP_GMPXX_LIBRARY_RELEASE,
#   CvmsGMP_GMPXX_LIBRARY_DEBUG  (cache) the libraries, to give them by hand;
#                            CvmsGMP_LIBRARY / CvmsGMP_GMPXX_LIBRARY given
#                            by hand count as the release ones.
# Step 2 looks for release libraries (gmp, gmpxx) and debug ones (gmpd,
# gmpxxd, or gmp, gmpxx under <root>/debug/lib as vcpkg lays them out). When
# both are found and differ, the targets' Debug configuration links the debug
# ones and every other configuration the release ones.
# Result:
#   CvmsGMP_FOUND, CvmsGMP_VERSION (from gmp.h when it can be read),
#   CvmsGMP_FROM_CONFIG (TRUE when step 1 supplied the targets),
#   CvmsGMP_LIBRARY, CvmsGMP_GMPXX_LIBRARY (step 2: see
#   select_library_configurations),
#   imported targets CvmsGMP::gmp and CvmsGMP::gmpxx (gmpxx links gmp).
include(FindPackageHandleStandardArgs)

# 1. conan's CMakeDeps config. Not probed under vcpkg: vcpkg's gmp config
# defines only the C library and aborts configuration (find_library
# REQUIRED) on release-only triplets. Not loaded twice either.
if(NOT TARGET CvmsGMP::gmpxx AND NOT CvmsGMP_NO_CONFIG)
  if(NOT TARGET gmp::gmpxx AND NOT TARGET gmp::gmp AND NOT VCPKG_TOOLCHAIN)
    find_package(gmp CONFIG QUIET)
  endif()
  if(TARGET gmp::gmpxx)
    add_library(CvmsGMP::gmpxx INTERFACE IMPORTED)
    set_target_properties(CvmsGMP::gmpxx PROPERTIES INTERFACE_LINK_LIBRARIES gmp::gmpxx)
    if(NOT TARGET CvmsGMP::gmp)
      add_library(CvmsGMP::gmp INTERFACE IMPORTED)
      if(TARGET gmp::libgmp)
        set_target_properties(CvmsGMP::gmp PROPERTIES INTERFACE_LINK_LIBRARIES gmp::libgmp)
      else()
        set_target_properties(CvmsGMP::gmp PROPERTIES INTERFACE_LINK_LIBRARIES gmp::gmp)
      endif()
    endif()
    set(CvmsGMP_FROM_CONFIG TRUE)
    if(gmp_DIR)
      set(CvmsGMP_CONFIG_SOURCE "${gmp_DIR}")
    else()
      set(CvmsGMP_CONFIG_SOURCE "gmp::gmpxx")
    endif()
  endif()
endif()
if(CvmsGMP_FROM_CONFIG)
  set(CvmsGMP_VERSION "${gmp_VERSION}")
  find_package_handle_standard_args(CvmsGMP REQUIRED_VARS CvmsGMP_CONFIG_SOURCE VERSION_VAR CvmsGMP_VERSION)
  return()
endif()

# 2. pkg-config hints, then the usual search.
find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(PC_CVMS_GMP QUIET gmp)
  pkg_check_modules(PC_CVMS_GMPXX QUIET gmpxx)
endif()

set(_cvms_gmp_roots ${CvmsGMP_ROOT} $ENV{CvmsGMP_ROOT} ${GMP_ROOT} $ENV{GMP_ROOT})

find_path(CvmsGMP_INCLUDE_DIR NAMES gmp.h
  HINTS ${_cvms_gmp_roots} ${PC_CVMS_GMP_INCLUDEDIR} ${PC_CVMS_GMP_INCLUDE_DIRS}
  PATH_SUFFIXES include)
find_path(CvmsGMP_GMPXX_INCLUDE_DIR NAMES gmpxx.h
  HINTS ${_cvms_gmp_roots} ${PC_CVMS_GMPXX_INCLUDEDIR} ${PC_CVMS_GMPXX_INCLUDE_DIRS} ${CvmsGMP_INCLUDE_DIR}
  PATH_SUFFIXES include)

if(CvmsGMP_USE_STATIC_LIBS)
  set(_cvms_gmp_suffixes ${CMAKE_FIND_LIBRARY_SUFFIXES})
  if(WIN32)
    set(CMAKE_FIND_LIBRARY_SUFFIXES .lib .a)
  else()
    set(CMAKE_FIND_LIBRARY_SUFFIXES .a)
  endif()
endif()
# A library given the old way (-DCvmsGMP_LIBRARY=...) is the release one.
foreach(_cvms_lib IN ITEMS CvmsGMP CvmsGMP_GMPXX)
  if(${_cvms_lib}_LIBRARY AND NOT ${_cvms_lib}_LIBRARY_RELEASE AND NOT ${_cvms_lib}_LIBRARY_DEBUG)
    set(${_cvms_lib}_LIBRARY_RELEASE "${${_cvms_lib}_LIBRARY}" CACHE FILEPATH "Path to a library.")
  endif()
endforeach()
unset(_cvms_lib)
# Release: vcpkg's and MSVC builds name the import library gmp.lib or
# libgmp.lib. Debug: the "d" suffix of Windows-style debug builds, or the
# plain name in <root>/debug/lib (vcpkg's layout; its installed tree is a
# root when its toolchain is used).
if(VCPKG_TOOLCHAIN AND DEFINED _VCPKG_INSTALLED_DIR AND DEFINED VCPKG_TARGET_TRIPLET)
  list(APPEND _cvms_gmp_roots "${_VCPKG_INSTALLED_DIR}/${VCPKG_TARGET_TRIPLET}")
endif()
find_library(CvmsGMP_LIBRARY_RELEASE NAMES gmp libgmp NAMES_PER_DIR
  HINTS ${_cvms_gmp_roots} ${PC_CVMS_GMP_LIBDIR} ${PC_CVMS_GMP_LIBRARY_DIRS}
  PATH_SUFFIXES lib)
find_library(CvmsGMP_GMPXX_LIBRARY_RELEASE NAMES gmpxx libgmpxx NAMES_PER_DIR
  HINTS ${_cvms_gmp_roots} ${PC_CVMS_GMPXX_LIBDIR} ${PC_CVMS_GMPXX_LIBRARY_DIRS}
  PATH_SUFFIXES lib)
find_library(CvmsGMP_LIBRARY_DEBUG NAMES gmpd libgmpd NAMES_PER_DIR
  HINTS ${_cvms_gmp_roots} ${PC_CVMS_GMP_LIBDIR} ${PC_CVMS_GMP_LIBRARY_DIRS}
  PATH_SUFFIXES lib)
find_library(CvmsGMP_GMPXX_LIBRARY_DEBUG NAMES gmpxxd libgmpxxd NAMES_PER_DIR
  HINTS ${_cvms_gmp_roots} ${PC_CVMS_GMPXX_LIBDIR} ${PC_CVMS_GMPXX_LIBRARY_DIRS}
  PATH_SUFFIXES lib)
if(_cvms_gmp_roots)
  find_library(CvmsGMP_LIBRARY_DEBUG NAMES gmpd libgmpd gmp libgmp NAMES_PER_DIR
    PATHS ${_cvms_gmp_roots} PATH_SUFFIXES debug/lib NO_DEFAULT_PATH)
  find_library(CvmsGMP_GMPXX_LIBRARY_DEBUG NAMES gmpxxd libgmpxxd gmpxx libgmpxx NAMES_PER_DIR
    PATHS ${_cvms_gmp_roots} PATH_SUFFIXES debug/lib NO_DEFAULT_PATH)
endif()
if(CvmsGMP_USE_STATIC_LIBS)
  set(CMAKE_FIND_LIBRARY_SUFFIXES ${_cvms_gmp_suffixes})
  unset(_cvms_gmp_suffixes)
endif()
unset(_cvms_gmp_roots)
# CvmsGMP_LIBRARY and CvmsGMP_GMPXX_LIBRARY: the release library, or the
# debug one when only it was found, or "optimized;<release>;debug;<debug>".
include(SelectLibraryConfigurations)
select_library_configurations(CvmsGMP)
select_library_configurations(CvmsGMP_GMPXX)

# The version gmp.h declares (the same header gmpxx.h includes).
if(CvmsGMP_INCLUDE_DIR AND EXISTS "${CvmsGMP_INCLUDE_DIR}/gmp.h")
  file(STRINGS "${CvmsGMP_INCLUDE_DIR}/gmp.h" _cvms_gmp_version_lines
    REGEX "^#define[ \t]+__GNU_MP_VERSION(_MINOR|_PATCHLEVEL)?[ \t]+[0-9]+")
  set(_cvms_gmp_parts "")
  foreach(_part IN ITEMS "" _MINOR _PATCHLEVEL)
    foreach(_line IN LISTS _cvms_gmp_version_lines)
      if(_line MATCHES "__GNU_MP_VERSION${_part}[ \t]+([0-9]+)")
        list(APPEND _cvms_gmp_parts "${CMAKE_MATCH_1}")
      endif()
    endforeach()
  endforeach()
  list(LENGTH _cvms_gmp_parts _cvms_gmp_count)
  if(_cvms_gmp_count EQUAL 3)
    list(JOIN _cvms_gmp_parts "." CvmsGMP_VERSION)
  endif()
  unset(_cvms_gmp_version_lines)
  unset(_cvms_gmp_parts)
  unset(_cvms_gmp_count)
elseif(PC_CVMS_GMP_VERSION)
  set(CvmsGMP_VERSION "${PC_CVMS_GMP_VERSION}")
endif()

find_package_handle_standard_args(CvmsGMP
  REQUIRED_VARS CvmsGMP_LIBRARY CvmsGMP_GMPXX_LIBRARY CvmsGMP_INCLUDE_DIR CvmsGMP_GMPXX_INCLUDE_DIR
  VERSION_VAR CvmsGMP_VERSION)

# _cvms_gmp_locations(TARGET PREFIX): IMPORTED_LOCATION is the release
# library (the debug one if it is all there is), which every configuration
# without its own uses; a distinct debug library becomes the Debug
# configuration's.
function(_cvms_gmp_locations target prefix)
  set(release "${${prefix}_LIBRARY_RELEASE}")
  set(debug "${${prefix}_LIBRARY_DEBUG}")
  if(release)
    set_target_properties(${target} PROPERTIES IMPORTED_LOCATION "${release}")
  else()
    set_target_properties(${target} PROPERTIES IMPORTED_LOCATION "${debug}")
  endif()
  if(release AND debug AND NOT release STREQUAL debug)
    set_property(TARGET ${target} APPEND PROPERTY IMPORTED_CONFIGURATIONS RELEASE DEBUG)
    set_target_properties(${target} PROPERTIES
      IMPORTED_LOCATION_RELEASE "${release}"
      IMPORTED_LOCATION_DEBUG "${debug}")
  endif()
endfunction()

if(CvmsGMP_FOUND)
  if(NOT TARGET CvmsGMP::gmp)
    add_library(CvmsGMP::gmp UNKNOWN IMPORTED)
    set_target_properties(CvmsGMP::gmp PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${CvmsGMP_INCLUDE_DIR}")
    _cvms_gmp_locations(CvmsGMP::gmp CvmsGMP)
  endif()
  if(NOT TARGET CvmsGMP::gmpxx)
    add_library(CvmsGMP::gmpxx UNKNOWN IMPORTED)
    set_target_properties(CvmsGMP::gmpxx PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${CvmsGMP_GMPXX_INCLUDE_DIR}"
      INTERFACE_LINK_LIBRARIES CvmsGMP::gmp)
    _cvms_gmp_locations(CvmsGMP::gmpxx CvmsGMP_GMPXX)
  endif()
endif()
mark_as_advanced(CvmsGMP_INCLUDE_DIR CvmsGMP_GMPXX_INCLUDE_DIR CvmsGMP_LIBRARY CvmsGMP_GMPXX_LIBRARY
  CvmsGMP_LIBRARY_RELEASE CvmsGMP_LIBRARY_DEBUG CvmsGMP_GMPXX_LIBRARY_RELEASE CvmsGMP_GMPXX_LIBRARY_DEBUG)
