#!/usr/bin/env bash
# The main job: the hierarchy's stages that exist today, on a quick default case.
#   1. DEM slice of the base drum (cases/drum-quick.yaml: 1700 discs, 20 % fill, 3 rpm, 12 s)
#   2. calibration of the rheology from its averaged fields
# Usage: main-job.sh HIKILN OUTPUT_DIR
set -euo pipefail
hikiln=$1 out=$2
root=$(cd "$(dirname "$0")/.." && pwd)
say() { printf '[main-job] %s\n' "$*"; }

say "stage 1: DEM slice -> $out/dem"
"$hikiln" dem "$root/cases/drum-quick.yaml" -o "$out/dem" ${HIKILN_MAIN_SET:-}
if [ -f "$out/dem/averages.h5" ]; then
  say "stage 2: calibration -> $out/calibration"
  mkdir -p "$out/calibration"
  "$hikiln" calibrate "$out/dem" -o "$out/calibration/rheology.yaml" --plots "$out/calibration"
fi
say "summary of the DEM slice ($out/dem/summary.json):"
python3 -c "import json,sys; d=json.load(open(sys.argv[1])); [print(f'  {k}: {d[k]}') for k in ('particles','fill_measured','wall_slip_percent','surface_angle_deg','particle_steps_per_s','wall_time_s')]" "$out/dem/summary.json"
