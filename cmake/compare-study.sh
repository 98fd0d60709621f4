#!/usr/bin/env bash
# The physics.md section 5 study, DEM vs continuum on the five 2D drum cases (cases/compare/):
#   1. five DEM slices (hikiln sweep cases/compare/dem.yaml; 60 s of rotation each)
#   2. calibration of the rheology from all five (hikiln calibrate)
#   3. five continuum runs with the calibrated rheology (cases/compare/continuum-CASE.yaml)
#   4. hikiln compare of the five pairs: per-case maps and one table + plot (OUT/compare/cases.*)
# Finished stages are kept: re-running resumes (delete a stage's folder to redo it).
# Usage: compare-study.sh HIKILN OUT [--quick]
#   --quick: a shortened setting that checks the pipeline in minutes (a 1 m drum, 3 s of DEM
#            rotation, continuum 32 x 32 cells for 4 s); its numbers mean nothing.
set -euo pipefail
hikiln=$1 out=$2 quick=${3:-}
root=$(cd "$(dirname "$0")/.." && pwd)
cases=(fill-10-rpm-3 fill-20-rpm-3 fill-30-rpm-3 fill-20-rpm-1.5 fill-20-rpm-6)
say() { printf '[compare-study] %s\n' "$*"; }
dem_set=() cont_set=()
if [ "$quick" = "--quick" ]; then
  dem_set=(--set drum.diameter=1.0 --set time.spin_up=1 --set time.duration=3
           --set output.average_interval=1 --set output.snapshot_interval=1)
  cont_set=(--set drum.diameter=1.0 --set grid.cells=32 --set time.duration=4
            --set time.slip_after=2)
elif [ -n "$quick" ]; then
  echo "usage: compare-study.sh HIKILN OUT [--quick]" >&2
  exit 2
fi

say "stage 1: DEM slices -> $out/dem"
"$hikiln" sweep "$root/cases/compare/dem.yaml" -o "$out/dem" "${dem_set[@]}"

rheology=$out/calibration/rheology.yaml
if [ ! -f "$rheology" ]; then
  say "stage 2: calibration -> $out/calibration"
  mkdir -p "$out/calibration"
  "$hikiln" calibrate "${cases[@]/#/$out/dem/}" -o "$rheology" --plots "$out/calibration"
fi

say "stage 3: continuum runs with $rheology -> $out/continuum"
for c in "${cases[@]}"; do
  if [ -f "$out/continuum/$c/summary.json" ]; then
    say "  $c: done before, kept"
    continue
  fi
  "$hikiln" continuum "$root/cases/compare/continuum-$c.yaml" -o "$out/continuum/$c" \
    --set rheology.file="$(cd "$(dirname "$rheology")" && pwd)/rheology.yaml" "${cont_set[@]}"
done

say "stage 4: comparison -> $out/compare"
pairs=()
for c in "${cases[@]}"; do pairs+=("$out/dem/$c" "$out/continuum/$c"); done
labels=$(IFS=,; echo "${cases[*]}")
"$hikiln" compare "${pairs[@]}" -o "$out/compare" --labels "$labels"
say "done: $out/compare/cases.md"
cat "$out/compare/cases.md"
