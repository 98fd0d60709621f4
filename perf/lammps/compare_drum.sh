#!/usr/bin/env bash
# Side-by-side speed of the base drum (physics.md base case, 2D, ~20 % fill, 3 rpm, ~1800 discs)
# in LAMMPS (shared/reference/lammps-drum2d.in) and in hikiln (`hikiln dem` on
# cases/drum-base.yaml set to the same contact law, time step, skin and particle count).
# Only the rotation phase is timed on both sides: LAMMPS's second "Loop time", hikiln's
# rotate_wall_time_s. Prints particle-steps/s of each run, the medians and hikiln / LAMMPS.
set -euo pipefail

usage() {
  cat <<'TEXT'
Usage: perf/lammps/compare_drum.sh [options]
  --ranks N         LAMMPS MPI ranks and hikiln OpenMP threads (default 2)
  --repeat N        alternate the two runs N times, report medians (default 3)
  --tspin S         simulated rotation time per run in s (default 1.0)
  --nsettle N       LAMMPS settling steps (default 20000; hikiln settles 0.5 s + trims)
  --quick           --repeat 1 --tspin 0.25 --nsettle 5000
  --build-dir DIR   hikiln build directory (default build-perf/ under the repository root)
  --input FILE      LAMMPS input (default ../shared/reference/lammps-drum2d.in next to the repo)
  --json FILE       also write the results as JSON
  --hikiln-set K=V  one more hikiln case setting, after the shared ones (repeatable), e.g.
                    --hikiln-set neighbor.pair_once=true
  -h, --help        this text
Needs lmp and mpirun (Debian: apt-get install lammps; installed here when missing and root),
CMake and python3. Runs in a temporary directory; nothing is written to the repository.
TEXT
}

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
ranks=2
repeat=3
tspin=1.0
nsettle=20000
build_dir="$repo/build-perf"
input=""
json=""
extra_sets=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --ranks) ranks="${2:?}"; shift 2 ;;
    --repeat) repeat="${2:?}"; shift 2 ;;
    --tspin) tspin="${2:?}"; shift 2 ;;
    --nsettle) nsettle="${2:?}"; shift 2 ;;
    --quick) repeat=1; tspin=0.25; nsettle=5000; shift ;;
    --build-dir) build_dir="${2:?}"; shift 2 ;;
    --input) input="${2:?}"; shift 2 ;;
    --json) json="${2:?}"; shift 2 ;;
    --hikiln-set) extra_sets+=(--set "${2:?}"); shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "compare_drum.sh: unknown option '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
if [[ -z "$input" ]]; then
  for candidate in "$repo/../shared/reference/lammps-drum2d.in" "$repo/shared/reference/lammps-drum2d.in"; do
    [[ -f "$candidate" ]] && input="$(cd "$(dirname "$candidate")" && pwd)/$(basename "$candidate")" && break
  done
fi
[[ -f "$input" ]] || { echo "compare_drum.sh: LAMMPS input not found (use --input)" >&2; exit 1; }

if ! command -v lmp >/dev/null || ! command -v mpirun >/dev/null; then
  if [[ $(id -u) -eq 0 ]] && command -v apt-get >/dev/null; then
    echo "compare_drum.sh: installing lammps (apt-get)" >&2
    DEBIAN_FRONTEND=noninteractive apt-get install -y lammps >&2 ||
      { apt-get update >&2 && DEBIAN_FRONTEND=noninteractive apt-get install -y lammps >&2; }
  fi
fi
command -v lmp >/dev/null || { echo "compare_drum.sh: lmp not found (apt-get install lammps)" >&2; exit 1; }

# hikiln: configure like perf/run.sh if needed, build the CLI.
cache="$build_dir/CMakeCache.txt"
if [[ ! -f "$cache" ]]; then
  generator=()
  command -v ninja >/dev/null && generator=(-G Ninja)
  cmake -S "$repo" -B "$build_dir" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release \
    -DHIKILN_ENABLE_TESTS=OFF -DHIKILN_ENABLE_BENCHMARKS=ON >&2
fi
cmake --build "$build_dir" --target hikiln >&2
hikiln="$build_dir/drivers/app/hikiln"
[[ -x "$hikiln" ]] || { echo "compare_drum.sh: $hikiln was not built" >&2; exit 1; }

# The LAMMPS input: 19-21 mm discs, 4 mm skin, dt 2.5e-5 s, gran/hooke/history with
# gamma_n = 1813/s, gamma_t = 906/s (times m_eff), no limit_damping, ~1806 atoms. hikiln gets
# the same law and a fill that gives about as many particles (1806 vs 1725 at 20 %).
skin_fraction=$(python3 -c 'print(0.004 / (0.020 * 1.05))')
hikiln_sets=(
  --set time.step=2.5e-5 --set contact.damping=rate --set contact.normal_damping_rate=1813
  --set contact.tangential_damping_rate=906 --set contact.limit_damping=false
  --set neighbor.skin="$skin_fraction" --set drum.fill=0.21 --set time.settle=0.5
  --set time.duration="$tspin" --set time.spin_up=0 --set output.snapshot_interval=1000
  --set output.checkpoint_interval=1000 --set output.average_interval=1000
  ${extra_sets[@]+"${extra_sets[@]}"}
)

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
results="$work/results.txt"
: > "$results"
load() { cut -d' ' -f1 /proc/loadavg; }

for ((r = 1; r <= repeat; r++)); do
  echo "compare_drum.sh: run $r/$repeat: LAMMPS ($ranks ranks)" >&2
  lw="$work/lammps-$r"
  mkdir -p "$lw"
  cp "$input" "$lw/in.drum"
  l0=$(load)
  (cd "$lw" && mpirun --allow-run-as-root --oversubscribe -np "$ranks" lmp -in in.drum \
      -var nsettle "$nsettle" -var tspin "$tspin" -log log.lammps -screen none)
  python3 - "$lw/log.lammps" "$l0" "$(load)" >>"$results" <<'PY'
import re, sys
loops = re.findall(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms",
                   open(sys.argv[1]).read())
seconds, procs, steps, atoms = loops[-1]  # the rotation run
rate = int(steps) * int(atoms) / float(seconds)
print(f"lammps {rate:.6g} {atoms} {steps} {seconds} {sys.argv[2]} {sys.argv[3]}")
PY
  echo "compare_drum.sh: run $r/$repeat: hikiln ($ranks threads)" >&2
  hw="$work/hikiln-$r"
  l0=$(load)
  # OMP_NUM_THREADS in the environment: the OpenMP runtime reads it when the program loads
  OMP_NUM_THREADS="$ranks" "$hikiln" -q --threads "$ranks" dem "$repo/cases/drum-base.yaml" \
    -o "$hw" "${hikiln_sets[@]}" >&2
  python3 - "$hw/summary.json" "$l0" "$(load)" >>"$results" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
steps = s["rotation_steps"]
print(f"hikiln ran with {s['threads']} threads", file=sys.stderr)
print(f"hikiln {s['particle_steps_per_s']:.6g} {s['particles']} {steps} "
      f"{s['rotate_wall_time_s']:.6g} {sys.argv[2]} {sys.argv[3]}")
PY
done

python3 - "$results" "$ranks" "$json" "${extra_sets[*]+${extra_sets[*]}}" <<'PY'
import json, statistics, sys
rows = [line.split() for line in open(sys.argv[1]) if line.strip()]
ranks, out, extra = sys.argv[2], sys.argv[3], sys.argv[4]
print(f"| run | code | particles | rotation steps | rotation wall s | particle-steps/s | load before/after |")
print("|---:|:---|---:|---:|---:|---:|:---|")
runs = {"lammps": [], "hikiln": []}
for k, (code, rate, atoms, steps, secs, l0, l1) in enumerate(rows):
    runs[code].append(float(rate))
    print(f"| {k // 2 + 1} | {code} | {atoms} | {steps} | {float(secs):.2f} | {float(rate):.3g} | {l0} / {l1} |")
med = {code: statistics.median(v) for code, v in runs.items()}
ratio = med["hikiln"] / med["lammps"]
print()
print(f"median particle-steps/s with {ranks} ranks/threads: LAMMPS {med['lammps']:.3g}, "
      f"hikiln {med['hikiln']:.3g}; hikiln / LAMMPS = {ratio:.2f}"
      + (f" (hikiln also given: {extra})" if extra else ""))
if out:
    json.dump({"ranks": int(ranks), "hikiln_extra_settings": extra, "runs": rows, "median": med,
               "ratio": ratio}, open(out, "w"), indent=2)
PY
