# Conan 2 recipe for cvms. From the source tree:
#   conan create . --build=missing -s compiler.cppstd=20
# builds GMP 6.3.0 and cvms, then builds and runs test_package/.
# Consumers get find_package(cvms CONFIG) and the target cvms::cvms through
# CMakeDeps, and pkg-config module cvms through PkgConfigDeps. With
# -o "cvms/*:tools=True" the package also has the cvms command-line tool.
import os
import re

from conan import ConanFile
from conan.errors import ConanInvalidConfiguration
from conan.tools.build import check_min_cppstd
from conan.tools.cmake import CMake, CMakeDeps, CMakeToolchain, cmake_layout
from conan.tools.files import copy, load, rmdir
from conan.tools.scm import Version

required_conan_version = ">=2.0"


class CvmsConan(ConanFile):
    name = "cvms"
    description = "Exact Minkowski sums of convex polyhedra (GMP rationals)"
    license = "MIT"
    url = "https://github.com/conan-io/conan-center-index"
    homepage = "https://github.com/cvms-project/cvms"
    topics = ("geometry", "minkowski-sum", "convex-polyhedron", "exact-arithmetic", "gmp",
              "computational-geometry")
    package_type = "library"
    settings = "os", "arch", "compiler", "build_type"
    options = {"shared": [True, False], "fPIC": [True, False], "tools": [True, False]}
    # Our public headers include gmpxx.h, so GMP must be built with its C++ layer.
    default_options = {"shared": False, "fPIC": True, "tools": False, "gmp/*:enable_cxx": True}
    # Only what building the library and the tool needs: tests and benchmarks are off.
    exports_sources = "CMakeLists.txt", "LICENSE", "cmake/*", "include/*", "lib/*", "tools/*"

    # Oldest compilers expected to handle the C++20 the library uses. MSVC is
    # not one of them: see validate().
    _min_compiler = {"gcc": "10", "clang": "13", "apple-clang": "14"}
    # 64-bit LP64 targets: the exact arithmetic holds 128-bit products in
    # __int128 and reads GMP's limbs as 64-bit words, passing them to GMP's
    # unsigned long functions (docs/packaging.md, "Supported platforms").
    _64bit_archs = ("x86_64", "armv8", "armv8.3")

    def set_version(self):
        if self.version:
            return
        text = load(self, os.path.join(self.recipe_folder, "CMakeLists.txt"))
        self.version = re.search(r"project\(cvms\s+VERSION\s+([0-9.]+)", text).group(1)

    def config_options(self):
        if self.settings.os == "Windows":
            del self.options.fPIC

    def configure(self):
        if self.options.shared:
            self.options.rm_safe("fPIC")

    def layout(self):
        cmake_layout(self)

    def requirements(self):
        # Public headers include gmpxx.h: consumers need GMP's headers too.
        self.requires("gmp/6.3.0", transitive_headers=True)
        if self.options.tools:
            self.requires("cli11/2.4.2", visible=False)

    def build_requirements(self):
        self.tool_requires("cmake/[>=3.25 <5]")

    def validate(self):
        # The same rule as CMakeLists.txt's platform check (cmake/CvmsPlatform.cmake).
        if self.settings.compiler == "msvc":
            raise ConanInvalidConfiguration(
                "cvms needs GCC or Clang: its exact arithmetic uses __int128, which MSVC lacks")
        if self.settings.os == "Windows":
            raise ConanInvalidConfiguration(
                "cvms needs a 64-bit long (LP64): it passes GMP's 64-bit limbs to GMP's "
                "unsigned long functions, and long is 32 bits on Windows")
        if str(self.settings.arch) not in self._64bit_archs:
            raise ConanInvalidConfiguration(
                f"cvms needs a 64-bit target ({', '.join(self._64bit_archs)}), not "
                f"{self.settings.arch}: it uses __int128 and GMP's 64-bit limbs")
        check_min_cppstd(self, 20)
        minimum = self._min_compiler.get(str(self.settings.compiler))
        if minimum and Version(self.settings.compiler.version) < minimum:
            raise ConanInvalidConfiguration(
                f"cvms needs C++20: {self.settings.compiler} >= {minimum}")
        if not self.dependencies["gmp"].options.enable_cxx:
            raise ConanInvalidConfiguration("cvms needs gmp/*:enable_cxx=True (gmpxx)")

    def generate(self):
        tc = CMakeToolchain(self)
        # Only options our CMakeLists.txt has (BUILD_SHARED_LIBS and the PIC
        # flag come from the shared/fPIC options through the toolchain).
        tc.cache_variables["CVMS_BUILD_TESTS"] = False
        tc.cache_variables["CVMS_BUILD_BENCHMARKS"] = False
        tc.cache_variables["CVMS_BUILD_TOOLS"] = bool(self.options.tools)
        tc.cache_variables["CVMS_BUILD_EXAMPLES"] = False
        tc.cache_variables["CVMS_WARNINGS_AS_ERRORS"] = False
        tc.generate()
        CMakeDeps(self).generate()

    def build(self):
        cmake = CMake(self)
        cmake.configure()
        cmake.build()

    def package(self):
        copy(self, "LICENSE", src=self.source_folder,
             dst=os.path.join(self.package_folder, "licenses"))
        cmake = CMake(self)
        cmake.install()
        # Conan generates its own CMake config and .pc files (package_info);
        # the licence is in licenses/ (above), conan's place for it.
        rmdir(self, os.path.join(self.package_folder, "lib", "cmake"))
        rmdir(self, os.path.join(self.package_folder, "lib", "pkgconfig"))
        rmdir(self, os.path.join(self.package_folder, "share"))

    def package_info(self):
        self.cpp_info.set_property("cmake_file_name", "cvms")
        self.cpp_info.set_property("cmake_target_name", "cvms::cvms")
        self.cpp_info.set_property("pkg_config_name", "cvms")
        self.cpp_info.libs = ["cvms"]
        self.cpp_info.requires = ["gmp::gmpxx"]
        if self.settings.os in ("Linux", "FreeBSD"):
            self.cpp_info.system_libs = ["pthread"]  # Options::threads starts a std::jthread
