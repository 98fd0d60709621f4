#!/usr/bin/env bash
# Sets up everything (Debian packages, cached Kokkos) on a fresh Debian bookworm machine, builds hikiln
# with warnings as errors and runs the test suite (all labels but `long`).
#
#   cmake/run-tests.sh                 default: unit + verification tests, Serial and OpenMP (1, 2 threads)
#   cmake/run-tests.sh --long          also the long validation tests
#   cmake/run-tests.sh --cuda-compile  also compile every target with nvcc against a CUDA Kokkos
#                                      (no GPU needed; builds that Kokkos once, ~20 min on 2 cores)
#   cmake/run-tests.sh --cuda          build with nvcc against the CUDA Kokkos and run the tests on
#                                      Serial, OpenMP and CUDA (needs an NVIDIA GPU)
# Environment: HIKILN_BUILD_DIR (default build/, build-cuda/ with --cuda), HIKILN_CUDA_BUILD_DIR
# (--cuda-compile, default build-cuda-compile/), HIKILN_JOBS, HIKILN_DEPS_DIR (see setup-deps.sh),
# HIKILN_HOST_ARCH (a -march value such as native; default: the compiler's, see README.md).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
labels_exclude="long"
cuda_compile=0
cuda_run=0
for arg in "$@"; do
  case "$arg" in
    --long) labels_exclude="" ;;
    --cuda-compile) cuda_compile=1 ;;
    --cuda) cuda_run=1 ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    *) echo "run-tests: unknown option '$arg' (try --help)" >&2; exit 2 ;;
  esac
done
jobs=${HIKILN_JOBS:-$(nproc)}
say() { printf '[run-tests] %s\n' "$*"; }

configure() {  # build_dir, extra cmake args...: configure (quietly, log next to the build dir)
  local dir=$1; shift
  mkdir -p "$dir"
  say "configuring $dir"
  cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DHIKILN_WARNINGS_AS_ERRORS=ON \
    "-DHIKILN_HOST_ARCH=${HIKILN_HOST_ARCH:-}" "$@" >"$dir.configure.log" 2>&1 \
    || { cat "$dir.configure.log"; return 1; }
}

# The CUDA Kokkos must be compiled with its own nvcc_wrapper (it passes host flags on to g++).
cuda_configure_args() {
  local prefix
  prefix=$(bash "$root/cmake/setup-deps.sh" --print-prefix --cuda)
  printf '%s\n' -DHIKILN_ENABLE_CUDA=ON "-DCMAKE_CXX_COMPILER=$prefix/bin/nvcc_wrapper"
}

if [ "$cuda_run" = 1 ]; then
  command -v nvidia-smi >/dev/null && nvidia-smi -L >/dev/null 2>&1 \
    || { echo "run-tests: --cuda needs an NVIDIA GPU (nvidia-smi found none); use --cuda-compile" >&2; exit 1; }
  bash "$root/cmake/setup-deps.sh" --cuda
  dir=${HIKILN_BUILD_DIR:-$root/build-cuda}
  mapfile -t cuda_args < <(cuda_configure_args)
  configure "$dir" "${cuda_args[@]}"
else
  bash "$root/cmake/setup-deps.sh"
  dir=${HIKILN_BUILD_DIR:-$root/build}
  configure "$dir"
fi
say "building ($jobs jobs)"
cmake --build "$dir" -j "$jobs" || { say "FAILED: build in $dir"; exit 1; }

say "running tests (excluding labels: ${labels_exclude:-none})"
ctest_args=(--test-dir "$dir" --output-on-failure -j "$jobs")
[ -n "$labels_exclude" ] && ctest_args+=(-LE "$labels_exclude")
status=0
ctest "${ctest_args[@]}" || status=$?
if [ "$status" = 0 ]; then say "tests passed"; else say "FAILED: tests (ctest exit $status)"; fi

if [ "$cuda_compile" = 1 ]; then
  # Every target (library, CLI, tests, benchmarks) through nvcc; -k 0 reports all failures at once.
  say "CUDA compile check: building everything against the CUDA Kokkos (no GPU needed)"
  bash "$root/cmake/setup-deps.sh" --cuda
  cdir=${HIKILN_CUDA_BUILD_DIR:-$root/build-cuda-compile}
  mapfile -t cuda_args < <(cuda_configure_args)
  t0=$(date +%s)
  if configure "$cdir" "${cuda_args[@]}" && cmake --build "$cdir" -j "$jobs" -- -k 0; then
    say "CUDA compile check passed ($(( $(date +%s) - t0 )) s, build dir $cdir)"
  else
    say "FAILED: CUDA compile check (errors above; build dir $cdir)"
    status=1
  fi
fi
exit $status
