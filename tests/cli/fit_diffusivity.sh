#!/usr/bin/env bash
# `hikiln fit-diffusivity` end to end on a small heated DEM drum (0.6 m, ~150 discs, 2 s of
# rotation, snapshots every 0.5 s) and a 32^2 continuum with three candidate diffusivities:
# (1) both models start with the same bed (bed blocks within 25 %), fit.json has a finite
#     misfit per candidate, the best is one of them, both models start
#     unmixed (mixed fraction 0 at t = 0, the split lies on a block edge);
# (2) the continuum's mixed fraction at the last time grows with alpha_eff (the fit can see it);
# (3) maps.h5 holds both models' maps, and the plots are drawn;
# (4) bad input: a DEM run without heat and a negative candidate fail with a clear message.
# Usage: fit_diffusivity.sh HIKILN CASE WORKDIR
set -euo pipefail
hikiln=$1 case=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
dem=(--set drum.diameter=0.6 --set drum.fill=0.2 --set drum.rpm=6 --set time.spin_up=0.1
     --set time.settle=0.4 --set time.duration=2 --set output.snapshot_interval=0.5
     --set heat.shells=4)
"$hikiln" -q --threads 1 dem "$case" -o "$work/dem" "${dem[@]}" --set heat.enabled=true \
  --set heat.initial=left_right
"$hikiln" -q --threads 1 fit-diffusivity "$work/dem" -o "$work/fit" --alphas 1e-6,1e-4,1e-2 \
  --duration 2 --set grid.cells=32
/usr/bin/python3 - "$work/fit" <<'PY'
import csv, json, math, os, sys, h5py
fit = sys.argv[1]
j = json.load(open(f"{fit}/fit.json"))
misfits = j["misfit_mixed_fraction"]
if len(misfits) != 3 or not all(m is not None and math.isfinite(m) for m in misfits):
    sys.exit(f"misfits {misfits}: expected three finite values")
if j["best_alpha_eff"] not in j["alpha_eff_candidates"]:
    sys.exit("best alpha_eff is not a candidate")
rows = list(csv.DictReader(open(f"{fit}/mixing_layer.csv")))
first, last = rows[0], rows[-1]
if abs(float(first["time"])) > 1e-6 or any(float(v) != 0.0 for k, v in first.items() if k != "time"):
    sys.exit(f"the first row should be t = 0 with nothing mixed: {first}")
layer = [float(last[k]) for k in last if k.startswith("alpha_")]
if not (layer[0] <= layer[1] <= layer[2] and layer[2] > layer[0]):
    sys.exit(f"mixed fraction at t = {last['time']} does not grow with alpha_eff: {layer}")
with h5py.File(f"{fit}/maps.h5", "r") as f:
    n = len(f["x_centres"])
    # both models start with the same flat bed: bed fractions in range, similar bed areas
    cont_bed, dem_bed = f["continuum_bed_fraction"][0, 0], f["dem_bed_fraction"][0]
    if not cont_bed.max() <= 1.0 + 1e-9:
        sys.exit(f"continuum bed fraction {cont_bed.max()} above 1")
    nc = (cont_bed >= f.attrs["continuum_bed_threshold"]).sum()
    nd = (dem_bed >= f.attrs["dem_bed_threshold"]).sum()
    if not (nd > 0 and abs(nc - nd) <= 0.25 * nd):
        sys.exit(f"bed blocks at t = 0: continuum {nc}, DEM {nd}")
    if f["continuum_temperature"].shape != (3, len(rows), n, n):
        sys.exit(f"continuum maps shape {f['continuum_temperature'].shape}")
    if f["dem_temperature"].shape != (len(rows), n, n):
        sys.exit(f"DEM maps shape {f['dem_temperature'].shape}")
for png in ["fit_misfit.png", "mixing_layer.png", "temperature_maps.png"]:
    if not os.path.getsize(f"{fit}/{png}") > 1000:
        sys.exit(f"{png} missing or empty")
print(f"fit: misfits {[round(m, 4) for m in misfits]}, best {j['best_alpha_eff']}, mixed "
      f"fraction at t = {last['time']}: DEM {last['dem']}, continuum {layer}")
PY
# a DEM run without heat has no temperatures to fit
"$hikiln" -q --threads 1 dem "$case" -o "$work/cold" "${dem[@]}" --set time.duration=0.5
if "$hikiln" -q fit-diffusivity "$work/cold" -o "$work/x" > "$work/cold.log" 2>&1; then
  echo "fit-diffusivity accepted a run without heat"; exit 1
fi
grep -q "case.resolved.yaml: heat.enabled is false" "$work/cold.log" || { cat "$work/cold.log"; exit 1; }
if "$hikiln" -q fit-diffusivity "$work/dem" -o "$work/x" --alphas 1e-5,-1 > "$work/neg.log" 2>&1
then
  echo "fit-diffusivity accepted a negative alpha_eff"; exit 1
fi
grep -q "alphas" "$work/neg.log" || { cat "$work/neg.log"; exit 1; }
echo "bad input rejected with clear messages"
