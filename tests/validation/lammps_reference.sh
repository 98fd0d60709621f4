#!/usr/bin/env bash
# The LAMMPS side of the code-to-code check (../shared/reference/validation.md, "Code-to-code"):
# the five tabulated drum cases, each with several seeds of the particle diameters, run with the
# shared reference input and measured with the shared analysis script. Writes OUT/lammps-runs.csv
# (case, seed, particles, wall slip %, surface angle deg), which `lammps_drum.py SWEEP --lammps
# OUT/lammps-runs.csv` compares with hikiln's seeds, using both codes' measured spreads.
set -euo pipefail

usage() {
  cat <<'TEXT'
Usage: tests/validation/lammps_reference.sh OUT [options]
  --seeds "S1 S2 ..."   LAMMPS seeds of the diameters (default "12345 23456 34567")
  --jobs N              runs at once, one MPI rank each (default 2)
  --tspin S             rotation time per run in s (default 15, as validation.md)
  --cases "C1 C2 ..."   a subset of fill-10-rpm-3 fill-20-rpm-3 fill-30-rpm-3 fill-20-rpm-1.5
                        fill-10-rpm-6 (default: all five)
Needs lmp (Debian: apt-get install lammps) and python3. Resumable: a run whose result line
exists is not run again. About 25-30 min for all 15 runs on 2 cores.
TEXT
}

[[ $# -ge 1 && "$1" != -* ]] || { usage >&2; exit 2; }
out="$1"
shift
seeds="12345 23456 34567"
jobs=2
tspin=15
cases="fill-10-rpm-3 fill-20-rpm-3 fill-30-rpm-3 fill-20-rpm-1.5 fill-10-rpm-6"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --seeds) seeds="${2:?}"; shift 2 ;;
    --jobs) jobs="${2:?}"; shift 2 ;;
    --tspin) tspin="${2:?}"; shift 2 ;;
    --cases) cases="${2:?}"; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "lammps_reference.sh: unknown option '$1'" >&2; usage >&2; exit 2 ;;
  esac
done

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
reference=""
for candidate in "$repo/../shared/reference" "$repo/shared/reference"; do
  [[ -f "$candidate/lammps-drum2d.in" ]] && reference="$(cd "$candidate" && pwd)" && break
done
[[ -n "$reference" ]] || { echo "lammps_reference.sh: shared/reference/lammps-drum2d.in not found" >&2; exit 1; }
command -v lmp >/dev/null || { echo "lammps_reference.sh: lmp not found (apt-get install lammps)" >&2; exit 1; }

# validation.md: the lattice cut height sets the fill (10 / 20 / 30 %).
ycut_of() {
  case "$1" in
    10) echo -0.6436 ;;
    20) echo -0.4389 ;;
    30) echo -0.2573 ;;
    *) echo "lammps_reference.sh: no lattice cut for fill $1 %" >&2; return 1 ;;
  esac
}

mkdir -p "$out"
out="$(cd "$out" && pwd)"
runs=()
for case in $cases; do
  [[ "$case" =~ ^fill-([0-9]+)-rpm-([0-9.]+)$ ]] || { echo "lammps_reference.sh: bad case '$case'" >&2; exit 2; }
  ycut_of "${BASH_REMATCH[1]}" >/dev/null
  for seed in $seeds; do
    runs+=("$case $seed")
  done
done

# One run: its own folder, dumps every 0.25 s, then the shared analysis over the last 10 s;
# the result line is written last (write-then-rename), so an interrupted run is redone.
run_one() {
  local case="$1" seed="$2"
  [[ "$case" =~ ^fill-([0-9]+)-rpm-([0-9.]+)$ ]]
  local fill="${BASH_REMATCH[1]}" rpm="${BASH_REMATCH[2]}"
  local dir="$out/$case-s$seed"
  [[ -f "$dir/result.csv" ]] && return 0
  rm -rf "$dir" && mkdir -p "$dir"
  (cd "$dir" && lmp -in "$reference/lammps-drum2d.in" -log lammps.log -screen none \
    -var rpm "$rpm" -var seed "$seed" -var ycut "$(ycut_of "$fill")" -var nsettle 40000 \
    -var tspin "$tspin" -var dumpevery 10000)
  local line
  line="$(python3 "$reference/lammps-drum2d-analyse.py" "$dir" "$rpm")"
  # "DIR: particles N, dumps D, slip S %, surface angle A deg"
  [[ "$line" =~ particles\ ([0-9]+),\ dumps\ ([0-9]+),\ slip\ ([-0-9.]+)\ %,\ surface\ angle\ ([-0-9.]+)\ deg ]] ||
    { echo "lammps_reference.sh: unexpected analysis output: $line" >&2; return 1; }
  local particles="${BASH_REMATCH[1]}" dumps="${BASH_REMATCH[2]}" slip="${BASH_REMATCH[3]}"
  local angle="${BASH_REMATCH[4]}"
  [[ "$dumps" -gt 0 && "$particles" -gt 0 ]] ||
    { echo "lammps_reference.sh: $dir: no dumps after the first 5 s of rotation (tspin $tspin)" >&2; return 1; }
  local loop
  loop="$(grep -m2 '^Loop time' "$dir/lammps.log" | tail -1 | awk '{print $4}')"
  echo "$case,$seed,$particles,$slip,$angle,$loop" > "$dir/result.tmp"
  mv "$dir/result.tmp" "$dir/result.csv"
  rm -f "$dir"/drum2d.*.dump
  echo "$case seed $seed: $particles particles, slip $slip %, angle $angle deg (${loop} s rotating)" >&2
}
export -f run_one ycut_of
export out reference tspin

printf '%s\n' "${runs[@]}" | xargs -P "$jobs" -L 1 bash -c 'run_one "$0" "$1"'

{
  echo "case,seed,particles,wall_slip_percent,surface_angle_deg,rotate_wall_time_s"
  for entry in "${runs[@]}"; do
    read -r case seed <<<"$entry"
    cat "$out/$case-s$seed/result.csv"
  done
} > "$out/lammps-runs.csv.tmp"
mv "$out/lammps-runs.csv.tmp" "$out/lammps-runs.csv"
echo "lammps_reference.sh: wrote $out/lammps-runs.csv" >&2
