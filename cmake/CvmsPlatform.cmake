# The platforms cvms builds on: a 64-bit LP64 target (64-bit pointers and
# long), a GCC-compatible compiler (GCC or Clang) and a GMP with 64-bit limbs. Checked at configure time so an
# unsupported platform fails here, with the reason, rather than deep in the
# library's sources:
#  - the exact arithmetic's fast paths hold products and sums of two 64-bit
#    words in `__int128` / `unsigned __int128` (lib/numeric: rational.cpp,
#    dyadic.cpp, small_direction.cpp/.hpp, fixed_int.hpp; lib/planar:
#    planar_sum.cpp), a GCC/Clang extension that MSVC and 32-bit targets lack;
#  - they read GMP's limbs as 64-bit words (static_assert GMP_NUMB_BITS == 64
#    in lib/numeric: rational.cpp, approx.cpp, small_direction.cpp,
#    fixed_int.hpp, dyadic_points.hpp, limb_arena.cpp) and pass them to GMP's
#    unsigned long functions (mpz_set_ui), so long must be 64 bits too (LP64:
#    Windows' 32-bit long is not);
#  - the library uses GCC attributes (a weak symbol in huge_page_blocks.cpp).
# docs/packaging.md ("Supported platforms") says the same for users.
include(CheckCXXSourceCompiles)
include(CMakePushCheckState)

function(cvms_check_platform)
  set(why "cvms needs a 64-bit LP64 target and a GCC-compatible compiler (GCC or Clang) with a GMP of 64-bit limbs: its exact arithmetic holds 128-bit products in __int128 and reads GMP's limbs as 64-bit words (see docs/packaging.md, \"Supported platforms\").")
  if(NOT CMAKE_SIZEOF_VOID_P EQUAL 8)
    message(FATAL_ERROR "cvms: unsupported target: pointers are ${CMAKE_SIZEOF_VOID_P} bytes, not 8. ${why}")
  endif()
  if(MSVC AND NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "cvms: unsupported compiler: ${CMAKE_CXX_COMPILER_ID} (MSVC has no __int128). ${why}")
  endif()

  # A failed check runs again at the next configure (after the user fixed
  # the cause); a passed one is cached.
  foreach(result IN ITEMS CVMS_HAVE_64BIT_LONG CVMS_HAVE_INT128 CVMS_HAVE_GMP_64BIT_LIMBS)
    if(DEFINED CACHE{${result}} AND NOT ${result})
      unset(${result} CACHE)
    endif()
  endforeach()
  cmake_push_check_state(RESET)
  set(CMAKE_REQUIRED_QUIET ON)
  check_cxx_source_compiles([[
    static_assert(sizeof(long) == 8, "long is not 64-bit");
    int main() { return 0; }]] CVMS_HAVE_64BIT_LONG)
  if(NOT CVMS_HAVE_64BIT_LONG)
    message(FATAL_ERROR "cvms: unsupported target: long is not 64 bits (not LP64, as on Windows); GMP's unsigned long functions would truncate 64-bit limbs. ${why}")
  endif()
  # Multiplication and division of the 128-bit types, linked: some targets
  # compile the type but lack the runtime's helpers (__divti3, __udivti3).
  check_cxx_source_compiles([[
    __extension__ using I = __int128;
    __extension__ using U = unsigned __int128;
    static_assert(sizeof(I) == 16 && sizeof(U) == 16);
    volatile long long a = 1234567890123LL, b = 987654321LL;
    int main() {
      const I p = static_cast<I>(a) * static_cast<I>(a);
      const U q = static_cast<U>(p) / static_cast<U>(b) + static_cast<U>(p % b);
      return static_cast<int>(q & 1u);
    }]] CVMS_HAVE_INT128)
  if(NOT CVMS_HAVE_INT128)
    message(FATAL_ERROR "cvms: unsupported compiler: ${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION} does not build and link __int128 arithmetic for this target. ${why}")
  endif()

  set(CMAKE_REQUIRED_LIBRARIES CvmsGMP::gmp)
  check_cxx_source_compiles([[
    #include <gmp.h>
    static_assert(GMP_NUMB_BITS == 64 && sizeof(mp_limb_t) == 8, "GMP limbs are not 64-bit");
    int main() { return 0; }]] CVMS_HAVE_GMP_64BIT_LIMBS)
  cmake_pop_check_state()
  if(NOT CVMS_HAVE_GMP_64BIT_LIMBS)
    message(FATAL_ERROR "cvms: unsupported GMP: its gmp.h does not declare 64-bit limbs (GMP_NUMB_BITS == 64), or a test program including it does not compile (the compiler's output is in the build tree's CMakeFiles/ logs). A GMP built for a 32-bit ABI (ABI=32) or with nail bits is not supported. ${why}")
  endif()
endfunction()

cvms_check_platform()
