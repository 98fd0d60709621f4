#!/usr/bin/env bash
# `hikiln compare` end to end on two tiny runs of the same small drum (0.6 m, 20 % fill, 3 rpm):
# (1) one pair: comparison.json has finite spot values (DEM and continuum), wall slips, surface
#     measures and map differences; comparison.csv has one row per DEM cell; the PNG maps exist;
# (2) two pairs: one table (cases.csv, cases.md) and one plot (cases.png) over the cases;
# (3) bad input stops with a message naming the file and the reason: a DEM run without
#     averages.h5, a continuum run without outputs, two different drums, an odd number of runs.
# Usage: compare_runs.sh HIKILN DEM_CASE CONTINUUM_CASE WORKDIR
set -euo pipefail
hikiln=$1 dem_case=$2 cont_case=$3 work=$4
export OMP_WAIT_POLICY=passive
rm -rf "$work" && mkdir -p "$work"
"$hikiln" -q --threads 1 dem "$dem_case" -o "$work/dem" --set drum.diameter=0.6 \
  --set time.settle=0.4 --set time.spin_up=0.2 --set time.duration=1.0 \
  --set output.sample_interval=0.01 --set output.snapshot_interval=1.0
cont=(--set drum.diameter=0.6 --set grid.cells=32 --set time.output_interval=0.1)
"$hikiln" -q --threads 1 continuum "$cont_case" -o "$work/cont" "${cont[@]}" \
  --set time.duration=0.6 --set time.slip_after=0.3
"$hikiln" -q --threads 1 continuum "$cont_case" -o "$work/cont-6rpm" "${cont[@]}" \
  --set time.duration=0.1 --set drum.rpm=6

"$hikiln" --threads 1 compare "$work/dem" "$work/cont" -o "$work/one" 2>&1 | tee "$work/one.log"
"$hikiln" -q --threads 1 compare "$work/dem" "$work/cont" "$work/dem" "$work/cont" \
  -o "$work/two" --labels first,second

/usr/bin/python3 - "$work" <<'PY'
import json, math, os, sys
work = sys.argv[1]
j = json.load(open(f"{work}/one/comparison.json"))
def finite(path, value):
    if not isinstance(value, (int, float)) or not math.isfinite(value):
        sys.exit(f"comparison.json {path} = {value!r} is not a finite number")
for name in ("pressure", "shear_stress", "viscosity", "strain_rate", "velocity_x"):
    for who in ("dem", "continuum"):
        finite(f"spot.values.{name}.{who}", j["spot"]["values"][name][who])
if j["spot"]["cells_valid_in_both"] < 1:
    sys.exit("no spot cell is valid in both runs")
for who in ("dem", "continuum"):
    finite(f"wall_slip_percent.{who}", j["wall_slip_percent"][who])
    finite(f"surface.angle_deg.{who}", j["surface"]["angle_deg"][who])
    finite(f"bed_volume_fraction.{who}", j["bed_volume_fraction"][who])
for key in ("rms_difference", "max_abs_difference"):
    finite(f"surface.{key}", j["surface"][key])
for name in ("pressure", "shear_stress", "velocity_x", "velocity_y", "volume_fraction_normalised"):
    finite(f"maps.{name}.relative_l2", j["maps"][name]["relative_l2"])
    if j["maps"][name]["cells"] < 5:
        sys.exit(f"maps.{name}: only {j['maps'][name]['cells']} cells in the comparison")
avg = j["continuum_average"]
if avg["outputs"] != 3 or abs(avg["from_s"] - 0.4) > 1e-6 or abs(avg["to_s"] - 0.6) > 1e-6:
    sys.exit(f"continuum average should take the 3 outputs after 0.3 s: {avg}")
# the surface in the middle of a 20 % bed lies between the shell bottom and the axis
mid = [h for x, h in zip(j["surface"]["x"], j["surface"]["dem"]) if h is not None and abs(x) < 0.05]
if not mid or not all(-0.3 < h < 0.0 for h in mid):
    sys.exit(f"DEM surface near the axis not within the drum's lower half: {mid}")
rows = open(f"{work}/one/comparison.csv").read().splitlines()
if len(rows) != 1 + j["grid"]["nx"] * j["grid"]["ny"]:
    sys.exit(f"comparison.csv has {len(rows)} lines for {j['grid']['nx']} x {j['grid']['ny']} cells")
pngs = ["compare_" + n + ".png" for n in ("volume_fraction", "pressure", "shear_stress",
        "viscosity", "strain_rate", "velocity_x", "velocity_y", "maps", "surface")]
for png in pngs:
    path = f"{work}/one/{png}"
    if not os.path.exists(path) or os.path.getsize(path) < 10000:
        sys.exit(f"plot_compare.py did not draw {path}")
table = open(f"{work}/two/cases.csv").read().splitlines()
if len(table) != 3 or not table[1].startswith("first,") or not table[2].startswith("second,"):
    sys.exit(f"cases.csv should have a header and rows first, second: {table}")
if table[1].split(",")[1:] != table[2].split(",")[1:]:
    sys.exit("the same pair compared twice gave different rows")
for f in ("cases.md", "cases.png", "first/comparison.json", "second/compare_maps.png"):
    if not os.path.exists(f"{work}/two/{f}"):
        sys.exit(f"missing {work}/two/{f}")
print("comparison: finite spot values, slips, surfaces, map differences; tables and plots: ok")
PY
grep -q "spot (.* cells" "$work/one.log" || { echo "compare printed no spot line"; exit 1; }

# expect_error NAME REGEX ARGS...: compare must fail and say REGEX.
expect_error() {
  local name=$1 regex=$2
  shift 2
  if "$hikiln" --threads 1 compare "$@" -o "$work/bad-$name" >"$work/bad-$name.log" 2>&1; then
    echo "compare $name: succeeded on bad input"; exit 1
  fi
  grep -Eq "$regex" "$work/bad-$name.log" || {
    echo "compare $name: message does not match '$regex':"; cat "$work/bad-$name.log"; exit 1; }
  [ ! -e "$work/bad-$name/comparison.json" ] || { echo "compare $name: wrote output"; exit 1; }
}
mkdir -p "$work/empty"
expect_error no-averages "DEM run directory '.*/cont' has no averages.h5" "$work/cont" "$work/cont"
expect_error no-outputs "continuum run directory '.*/empty' has no fields_NNNN.h5" \
  "$work/dem" "$work/empty"
expect_error swapped "holds averages.h5, a DEM run: the order is DEM_RUN CONTINUUM_RUN" \
  "$work/dem" "$work/dem"
expect_error other-drum \
  "are not the same drum: drum.rpm 3 rpm \(DEM\) vs 6 rpm \(continuum\)" "$work/dem" "$work/cont-6rpm"
expect_error odd "give DEM_RUN CONTINUUM_RUN pairs, got 3 paths" "$work/dem" "$work/cont" "$work/dem"
echo "bad input: clear errors: ok"
