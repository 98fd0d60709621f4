# Code generation for the host compiler, for every target of the project.
#
# Floating-point contraction stays off (no a * b + c fused into one FMA): GCC contracts C++ by
# default wherever the instruction set has an FMA (AArch64, -march=x86-64-v3, most -march=native),
# and a fused result differs from the separate product and sum in the last bits.
add_compile_options($<$<COMPILE_LANG_AND_ID:CXX,GNU,Clang>:-ffp-contract=off>)

# HIKILN_HOST_ARCH: empty (the compiler's default: binaries run on any machine of the
# architecture), or a -march value such as native or x86-64-v3: wider vectors for the grid
# stencils, and binaries that need a CPU with that instruction set (README.md, "Host instruction
# set"). On x86-64 the results stay bitwise those of the default build:
# - -mno-fma -mno-avx512f: GCC 12 fuses some vectorised complex-multiply-like patterns
#   (vfmaddsub) even with -ffp-contract=off, so no instruction set with an FMA may be enabled
#   (AVX-512 has its own; GCC's tunings for x86 CPUs use 256-bit vectors anyway);
# - the sources that use Eigen keep the default -march (hikiln_eigen_baseline below): Eigen's
#   vectorised products add in an order that depends on the vector width.
set(HIKILN_HOST_ARCH "" CACHE STRING
    "Host instruction set (-march value, e.g. native or x86-64-v3); empty: the compiler's default")
set(_hikiln_x86 FALSE)
if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$")
  set(_hikiln_x86 TRUE)
endif()
if(HIKILN_HOST_ARCH)
  add_compile_options($<$<COMPILE_LANG_AND_ID:CXX,GNU,Clang>:-march=${HIKILN_HOST_ARCH}>)
  if(_hikiln_x86)
    add_compile_options($<$<COMPILE_LANG_AND_ID:CXX,GNU,Clang>:-mno-fma$<SEMICOLON>-mno-avx512f>)
  endif()
  message(STATUS "hikiln: host code compiled with -march=${HIKILN_HOST_ARCH}")
endif()

# hikiln_eigen_baseline(SOURCES...): compile these sources (those that include Eigen) for the
# architecture's baseline even when HIKILN_HOST_ARCH is set (a later -march wins).
function(hikiln_eigen_baseline)
  if(HIKILN_HOST_ARCH AND _hikiln_x86)
    set_property(SOURCE ${ARGN} APPEND PROPERTY COMPILE_OPTIONS
                 $<$<COMPILE_LANG_AND_ID:CXX,GNU,Clang>:-march=x86-64>)
  endif()
endfunction()
