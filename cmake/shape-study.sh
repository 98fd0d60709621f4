#!/usr/bin/env bash
# The physics.md section 1 particle-shape study (docs/blocky-particles.md):
#   1. four DEM slices of the base case with superquadric particles of blockiness N = 2 (the disc
#      reference), 3, 4, 6 (hikiln sweep cases/studies/shape.yaml -> OUT/dem/blockiness-N;
#      each holds its averaged fields, viscosity and stress maps in plots/, mu_wall and slip in
#      summary.json);
#   2. each run calibrated on its own (hikiln calibrate -> OUT/calibration/blockiness-N:
#      rheology.yaml, the m(strain rate), Coulomb and viscosity fits and their plots);
#   3. one table OUT/shape-table.md (+ .csv) and plot OUT/shape-study.png of the bed measures
#      and fitted parameters against N.
# Finished runs are kept: re-running resumes. Extra arguments reach every DEM run, e.g.
#   shape-study.sh HIKILN OUT --set drum.diameter=1.0 --set time.duration=20   (a reduced study)
# Usage: shape-study.sh HIKILN OUT [--set KEY=VALUE ...]
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: shape-study.sh HIKILN OUT [--set KEY=VALUE ...]" >&2; exit 2; }
hikiln=$1 out=$2
shift 2
root=$(cd "$(dirname "$0")/.." && pwd)
say() { printf '[shape-study] %s\n' "$*"; }

say "stage 1: DEM slices -> $out/dem"
"$hikiln" sweep "$root/cases/studies/shape.yaml" -o "$out/dem" "$@"

for n in 2 3 4 6; do
  cal=$out/calibration/blockiness-$n
  if [ -f "$cal/rheology.yaml" ]; then
    say "stage 2: blockiness-$n calibrated before, kept"
    continue
  fi
  say "stage 2: calibration of blockiness-$n -> $cal"
  mkdir -p "$cal"
  "$hikiln" calibrate "$out/dem/blockiness-$n" -o "$cal/rheology.yaml" --plots "$cal"
done

say "stage 3: table and plot -> $out/shape-table.md, $out/shape-study.png"
/usr/bin/python3 "$root/drivers/plots/plot_shape_study.py" "$out"
cat "$out/shape-table.md"
