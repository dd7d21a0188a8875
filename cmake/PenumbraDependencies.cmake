# Every dependency comes from Debian packages (scripts/setup installs them).

find_package(CGAL 5.4 REQUIRED)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(TBB REQUIRED)
find_package(PNG REQUIRED)
find_package(embree 3 REQUIRED)
# ERFA (liberfa-dev), the IAU SOFA models for the sun layer; Debian ships a pkg-config
# file and no CMake package.
find_package(PkgConfig REQUIRED)
pkg_check_modules(erfa REQUIRED IMPORTED_TARGET erfa)
find_package(assimp 5 REQUIRED)
if(PENUMBRA_BUILD_CLI)
  find_package(CLI11 REQUIRED)
endif()
if(PENUMBRA_BUILD_TESTS)
  find_package(Boost 1.74 REQUIRED COMPONENTS unit_test_framework)
  find_package(ZLIB REQUIRED)  # gzip-compressed fixtures (tests/support/fixtures.h)
endif()
if(PENUMBRA_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()
