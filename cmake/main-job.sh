#!/usr/bin/env bash
# The main job: the hierarchy's stages that exist today, on a quick default case.
#   1. DEM slice of the base drum (cases/drum-quick.yaml: 1700 discs, 20 % fill, 3 rpm, 12 s)
#   2. calibration of the rheology from its averaged fields
#   3. the 2D continuum model of the same drum with that rheology (cases/continuum-drum-quick.yaml:
#      64 x 64 cells, 10 s)
#   4. DEM vs continuum (hikiln compare: spot values, wall slip, bed surface, side-by-side maps)
# The five-case study of physics.md 5 is cmake/compare-study.sh (docs/compare.md).
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
if [ -f "$out/calibration/rheology.yaml" ]; then
  rheology=$(cd "$out/calibration" && pwd)/rheology.yaml
  say "stage 3: continuum drum with $rheology -> $out/continuum"
  "$hikiln" continuum "$root/cases/continuum-drum-quick.yaml" -o "$out/continuum" \
    --set rheology.file="$rheology" ${HIKILN_MAIN_CONTINUUM_SET:-}
  say "stage 4: DEM vs continuum -> $out/compare"
  "$hikiln" compare "$out/dem" "$out/continuum" -o "$out/compare"
fi
say "summary of the DEM slice ($out/dem/summary.json):"
python3 -c "import json,sys; d=json.load(open(sys.argv[1])); [print(f'  {k}: {d[k]}') for k in ('particles','fill_measured','wall_slip_percent','surface_angle_deg','particle_steps_per_s','wall_time_s')]" "$out/dem/summary.json"
if [ -f "$out/compare/comparison.json" ]; then
  say "DEM vs continuum ($out/compare/comparison.json, maps in $out/compare/compare_*.png):"
  python3 - "$out/compare/comparison.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
def f(v): return "n/a" if v is None else f"{v:.4g}"
s = j["spot"]
print(f"  spot {s['depth_above_shell_bottom']:.3g} m above the shell bottom ({s['cells_valid_in_both']} cells), DEM / continuum:")
for name, v in s["values"].items():
    print(f"    {name}: {f(v['dem'])} / {f(v['continuum'])} {v['units']}")
w, a = j["wall_slip_percent"], j["surface"]["angle_deg"]
print(f"  wall slip: {f(w['dem'])} / {f(w['continuum'])} %; surface angle: {f(a['dem'])} / {f(a['continuum'])} deg; rms surface difference {f(j['surface']['rms_difference'])} m")
PY
fi
