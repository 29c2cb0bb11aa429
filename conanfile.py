# Conan 2 recipe for cvms. From the source tree:
#   conan create . --build=missing -s compiler.cppstd=20
# builds GMP 6.3.0 and cvms, then builds and runs test_package/.
# Consumers get find_package(cvms CONFIG) and the target cvms::cvms through
# CMakeDeps, and pkg-config module cvms through PkgConfigDeps.
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
    topics = ("geometry", "minkowski-sum", "convex-polyhedron", "exact-arithmetic", "gmp")
    package_type = "library"
    settings = "os", "arch", "compiler", "build_type"
    options = {"shared": [True, False], "fPIC": [True, False]}
    # Our public headers include gmpxx.h, so GMP must be built with its C++ layer.
    default_options = {"shared": False, "fPIC": True, "gmp/*:enable_cxx": True}
    # Only what building the library needs: tests, tools and benchmarks are off.
    exports_sources = "CMakeLists.txt", "LICENSE", "cmake/*", "include/*", "lib/*"

    # Oldest compilers expected to handle the C++20 the library uses.
    _min_compiler = {"gcc": "10", "clang": "13", "apple-clang": "14", "msvc": "193"}

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

    def validate(self):
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
        tc.cache_variables["CVMS_BUILD_TOOLS"] = False
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
        # Conan generates its own CMake config and .pc files (package_info).
        rmdir(self, os.path.join(self.package_folder, "lib", "cmake"))
        rmdir(self, os.path.join(self.package_folder, "lib", "pkgconfig"))

    def package_info(self):
        self.cpp_info.set_property("cmake_file_name", "cvms")
        self.cpp_info.set_property("cmake_target_name", "cvms::cvms")
        self.cpp_info.set_property("pkg_config_name", "cvms")
        self.cpp_info.libs = ["cvms"]
        self.cpp_info.requires = ["gmp::gmpxx"]
        if self.settings.os in ("Linux", "FreeBSD"):
            self.cpp_info.system_libs = ["pthread"]  # Options::threads starts a std::jthread
