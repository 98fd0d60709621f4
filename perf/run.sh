#!/usr/bin/env bash
# Builds hikiln_bench if needed, runs it for Serial once and for OpenMP at 1 and 2 threads, merges
# the runs into one JSON file (each result tagged with backend and thread count), writes a
# Markdown table next to it and prints the table. Needs only bash, CMake and python3.
set -euo pipefail

usage() {
  cat <<'TEXT'
Usage: perf/run.sh [options]
  --filter REGEX      run only benchmarks whose name matches REGEX (Google Benchmark syntax)
  --quick             smoke run: arrays up to 8 MiB (HIKILN_BENCH_MAX_MIB) and short min_time
  -o, --output PATH   merged JSON file (default perf/results/<UTC-date>-<hostname>.json);
                      the Markdown table goes to the same path with .md
  --build-dir DIR     build directory (default build-perf/ under the repository root)
  --threads "1 2"     OpenMP thread counts to run (default "1 2")
  --repetitions N     repeat each benchmark N times and report the median (default 1)
  --lammps            also run perf/lammps/compare_drum.sh (LAMMPS vs hikiln base drum, rotation
                      phase only; installs the Debian lammps package if missing) and write its
                      table and JSON next to the results (<output>-lammps.{md,json})
  -h, --help          this text
Environment: HIKILN_BENCH_MAX_MIB caps the largest array (MiB, default 512);
HIKILN_BENCH_MAX_PARTICLES caps the DEM benchmarks (default 1000000; --quick: 10000).
TEXT
}

original_args="$*"
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="$repo/build-perf"
filter=""
quick=0
output=""
threads_list="1 2"
repetitions=1
lammps=0
while [[ $# -gt 0 ]]; do
  case "$1" in
    --filter) filter="${2:?--filter needs a REGEX}"; shift 2 ;;
    --filter=*) filter="${1#*=}"; shift ;;
    --quick) quick=1; shift ;;
    -o|--output) output="${2:?$1 needs a PATH}"; shift 2 ;;
    --output=*) output="${1#*=}"; shift ;;
    --build-dir) build_dir="${2:?--build-dir needs a DIR}"; shift 2 ;;
    --build-dir=*) build_dir="${1#*=}"; shift ;;
    --threads) threads_list="${2:?--threads needs a list}"; shift 2 ;;
    --threads=*) threads_list="${1#*=}"; shift ;;
    --repetitions) repetitions="${2:?--repetitions needs N}"; shift 2 ;;
    --repetitions=*) repetitions="${1#*=}"; shift ;;
    --lammps) lammps=1; shift ;;
    -h|--help) usage; exit 0 ;;
    *) echo "perf/run.sh: unknown option '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
command -v python3 >/dev/null || { echo "perf/run.sh: python3 not found" >&2; exit 1; }
command -v cmake >/dev/null || { echo "perf/run.sh: cmake not found" >&2; exit 1; }

# (a) Configure once (benchmarks on, tests off), then let the build tool decide what is stale.
cache="$build_dir/CMakeCache.txt"
if [[ ! -f "$cache" ]] || grep -q '^HIKILN_ENABLE_BENCHMARKS:BOOL=OFF' "$cache"; then
  generator=()
  if [[ ! -f "$cache" ]] && command -v ninja >/dev/null; then
    generator=(-G Ninja)
  fi
  echo "perf/run.sh: configuring $build_dir" >&2
  cmake -S "$repo" -B "$build_dir" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release \
    -DHIKILN_ENABLE_TESTS=OFF -DHIKILN_ENABLE_BENCHMARKS=ON >&2
fi
cmake --build "$build_dir" --target hikiln_bench >&2
exe="$build_dir/perf/hikiln_bench"
[[ -x "$exe" ]] || { echo "perf/run.sh: $exe was not built" >&2; exit 1; }

# (b) Run each backend separately so each run has its own thread count in its context.
export OMP_PROC_BIND=spread OMP_PLACES=threads
extra=()
if [[ $quick -eq 1 ]]; then
  export HIKILN_BENCH_MAX_MIB="${HIKILN_BENCH_MAX_MIB:-8}"
  export HIKILN_BENCH_MAX_PARTICLES="${HIKILN_BENCH_MAX_PARTICLES:-10000}"
  extra+=(--benchmark_min_time=0.01)
fi
if [[ $repetitions -gt 1 ]]; then
  extra+=("--benchmark_repetitions=$repetitions" --benchmark_report_aggregates_only=true)
fi

# Benchmark names depend on HIKILN_BENCH_MAX_MIB (sizes), so list them with the same environment.
mapfile -t names < <(OMP_NUM_THREADS=1 "$exe" --benchmark_list_tests=true \
  ${filter:+"--benchmark_filter=$filter"} 2>/dev/null | grep '/' || true)
if [[ ${#names[@]} -eq 0 ]]; then
  echo "perf/run.sh: no benchmark matches '${filter}'" >&2
  exit 1
fi

# An anchored alternation of the exact names of one backend's benchmarks (ERE-escaped).
backend_regex() {
  local backend="$1" name escaped alternatives=""
  for name in "${names[@]}"; do
    if [[ "/$name/" == */"$backend"/* ]]; then
      escaped="$(printf '%s' "$name" | sed 's/[][\.*^$+?(){}|]/\\&/g')"
      alternatives+="${alternatives:+|}$escaped"
    fi
  done
  [[ -n "$alternatives" ]] && printf '^(%s)$' "$alternatives"
}

workdir="$(mktemp -d)"
trap 'rm -rf "$workdir"' EXIT
run_args=()
run_backend() {
  local backend="$1" threads="$2" regex file
  regex="$(backend_regex "$backend")" || return 0
  file="$workdir/$backend-$threads.json"
  echo "perf/run.sh: $backend, OMP_NUM_THREADS=$threads" >&2
  OMP_NUM_THREADS="$threads" "$exe" "--benchmark_filter=$regex" "--benchmark_out=$file" \
    --benchmark_out_format=json "${extra[@]}" >&2
  run_args+=(--run "$backend" "$threads" "$file")
}
run_backend Serial 1
for threads in $threads_list; do
  run_backend OpenMP "$threads"
done
run_backend Cuda 1
if [[ ${#run_args[@]} -eq 0 ]]; then
  echo "perf/run.sh: nothing ran (no Serial, OpenMP or Cuda benchmark matched)" >&2
  exit 1
fi

# (c) + (d) Merge, write JSON and Markdown, print the table.
if [[ -z "$output" ]]; then
  stem="$repo/perf/results/$(date -u +%Y-%m-%d)-$(uname -n)"
  output="$stem.json"
  suffix=2
  while [[ -e "$output" ]]; do
    output="$stem-$suffix.json"
    suffix=$((suffix + 1))
  done
fi
markdown="${output%.json}.md"
python3 "$repo/perf/scripts/merge_runs.py" --output "$output" --markdown "$markdown" \
  --command "perf/run.sh $original_args" "${run_args[@]}"
echo >&2
echo "perf/run.sh: wrote $output and $markdown" >&2

# (e) Optional: LAMMPS side by side on the base drum (2 ranks vs 2 threads by default).
if [[ $lammps -eq 1 ]]; then
  lammps_args=(--build-dir "$build_dir" --json "${output%.json}-lammps.json")
  [[ $quick -eq 1 ]] && lammps_args+=(--quick)
  "$repo/perf/lammps/compare_drum.sh" "${lammps_args[@]}" | tee "${output%.json}-lammps.md"
  echo "perf/run.sh: wrote ${output%.json}-lammps.{json,md}" >&2
fi
