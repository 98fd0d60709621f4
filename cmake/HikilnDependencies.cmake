# Finds every dependency. Kokkos comes from -DKokkos_ROOT (a user's own, 3.4 or newer) or from the
# prefix that cmake/setup-deps.sh built; that prefix is searched first so that Debian's broken
# libtrilinos-kokkos CMake files are never picked up by accident.
set(HIKILN_KOKKOS_MIN_VERSION 3.4)
if(NOT Kokkos_ROOT AND NOT DEFINED ENV{Kokkos_ROOT})
  set(_hikiln_variant "")
  if(HIKILN_ENABLE_CUDA)
    set(_hikiln_variant "--cuda")
  endif()
  execute_process(COMMAND bash ${PROJECT_SOURCE_DIR}/cmake/setup-deps.sh --print-prefix ${_hikiln_variant}
                  OUTPUT_VARIABLE _hikiln_recipe_prefix OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(EXISTS "${_hikiln_recipe_prefix}")
    list(PREPEND CMAKE_PREFIX_PATH "${_hikiln_recipe_prefix}")
  endif()
endif()

find_package(Kokkos REQUIRED)
if(Kokkos_VERSION VERSION_LESS HIKILN_KOKKOS_MIN_VERSION)
  message(FATAL_ERROR "hikiln needs Kokkos >= ${HIKILN_KOKKOS_MIN_VERSION}; found ${Kokkos_VERSION} at ${Kokkos_DIR}")
endif()
message(STATUS "hikiln: Kokkos ${Kokkos_VERSION} from ${Kokkos_DIR} (devices: ${Kokkos_DEVICES})")
if(HIKILN_ENABLE_CUDA AND NOT Kokkos_ENABLE_CUDA)
  message(FATAL_ERROR "HIKILN_ENABLE_CUDA=ON but the Kokkos at ${Kokkos_DIR} has no CUDA backend "
                      "(build one with: cmake/setup-deps.sh --cuda)")
endif()
find_package(KokkosKernels REQUIRED)

find_package(Eigen3 3.3 REQUIRED NO_MODULE)
# hikiln calls Eigen from host code only. EIGEN_NO_CUDA keeps nvcc from compiling Eigen's
# __host__ __device__ paths, which emit front-end warnings from Eigen's own headers (#20012,
# #20014, #20015 with Eigen 3.4 and CUDA 13). Set on the imported target of this build only.
set_property(TARGET Eigen3::Eigen APPEND PROPERTY INTERFACE_COMPILE_DEFINITIONS EIGEN_NO_CUDA)
find_package(HDF5 REQUIRED COMPONENTS C)
find_package(yaml-cpp REQUIRED)
find_package(CLI11 REQUIRED)
find_package(fmt REQUIRED)
find_package(spdlog REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(Threads REQUIRED)
