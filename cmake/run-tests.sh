#!/usr/bin/env bash
# Sets up everything (Debian packages, cached Kokkos) on a fresh Debian bookworm machine, builds hikiln
# with warnings as errors and runs the test suite (all labels but `long`).
#
#   cmake/run-tests.sh                 default: unit + verification tests, Serial and OpenMP (1, 2 threads)
#   cmake/run-tests.sh --long          also the long validation tests
#   cmake/run-tests.sh --cuda-compile  also compile the whole project against a CUDA Kokkos (no GPU needed)
#   cmake/run-tests.sh --cuda          build against the CUDA Kokkos and run the tests (needs a GPU)
# Environment: HIKILN_BUILD_DIR (default build/), HIKILN_JOBS, HIKILN_DEPS_DIR (see setup-deps.sh).
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
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    *) echo "run-tests: unknown option '$arg' (try --help)" >&2; exit 2 ;;
  esac
done
jobs=${HIKILN_JOBS:-$(nproc)}
say() { printf '[run-tests] %s\n' "$*"; }

build_and_test() {  # build_dir, extra cmake args...
  local dir=$1; shift
  say "configuring $dir"
  cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DHIKILN_WARNINGS_AS_ERRORS=ON "$@" >"$dir.configure.log" 2>&1 \
    || { cat "$dir.configure.log"; exit 1; }
  say "building ($jobs jobs)"
  cmake --build "$dir" -j "$jobs"
}

if [ "$cuda_run" = 1 ]; then
  bash "$root/cmake/setup-deps.sh" --cuda
  dir=${HIKILN_BUILD_DIR:-$root/build-cuda}
  mkdir -p "$dir"
  build_and_test "$dir" -DHIKILN_ENABLE_CUDA=ON
else
  bash "$root/cmake/setup-deps.sh"
  dir=${HIKILN_BUILD_DIR:-$root/build}
  mkdir -p "$dir"
  build_and_test "$dir"
fi

say "running tests (excluding labels: ${labels_exclude:-none})"
ctest_args=(--test-dir "$dir" --output-on-failure -j "$jobs")
[ -n "$labels_exclude" ] && ctest_args+=(-LE "$labels_exclude")
status=0
ctest "${ctest_args[@]}" || status=$?

if [ "$cuda_compile" = 1 ]; then
  say "CUDA compile check: building the project against the CUDA Kokkos (no GPU needed)"
  bash "$root/cmake/setup-deps.sh" --cuda
  cdir=$root/build-cuda-compile
  mkdir -p "$cdir"
  build_and_test "$cdir" -DHIKILN_ENABLE_CUDA=ON
  say "CUDA compile check passed"
fi
exit $status
