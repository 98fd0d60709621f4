#!/usr/bin/env bash
# Sets up everything on a fresh Debian bookworm machine, builds hikiln (Release, OpenMP) and runs the
# main job. Outputs go to runs/main/ (override with HIKILN_RUN_DIR). HIKILN_HOST_ARCH=native compiles
# for this machine's CPU (README.md, "Host instruction set").
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=${HIKILN_JOBS:-$(nproc)}
dir=${HIKILN_BUILD_DIR:-$root/build}
out=${HIKILN_RUN_DIR:-$root/runs/main}
say() { printf '[run-main] %s\n' "$*"; }

bash "$root/cmake/setup-deps.sh"
mkdir -p "$dir" "$out"
say "configuring and building hikiln in $dir"
cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release "-DHIKILN_HOST_ARCH=${HIKILN_HOST_ARCH:-}" \
  >"$dir.configure.log" 2>&1 \
  || { cat "$dir.configure.log"; exit 1; }
cmake --build "$dir" -j "$jobs" --target hikiln
hikiln=$dir/drivers/app/hikiln

"$hikiln" info
"$root/cmake/main-job.sh" "$hikiln" "$out"
say "done: outputs in $out"
