#!/usr/bin/env bash
# `hikiln dem` with heat in a rough drum (discs glued to the shell, cases/drum-base-rough.yaml shrunk
# to 0.6 m): the glued discs exchange heat with the bed and count in the conserved heat energy, but
# the bed's temperature statistics (mean, std, mixing measure) are over the free particles only.
# Checked against the particle snapshots, which carry each particle's kind:
# (1) the initial std in summary.json is the std of the free particles' temperatures in the first
#     snapshot, and differs from the std over all particles (so the check can tell them apart);
# (2) the bed mean temperature in heat_timeseries.csv at each snapshot time is the heat-capacity
#     (r^3) weighted mean over the free particles of that snapshot;
# (3) summary.json counts the particles by kind as the snapshots do;
# (4) the heat energy drift stays at round-off (< 1e-10) with the glued discs exchanging heat.
# Usage: dem_heat_rough_bed.sh HIKILN CASE WORKDIR
set -euo pipefail
hikiln=$1 case=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
"$hikiln" -q --threads 1 dem "$case" -o "$work/run" --set drum.diameter=0.6 --set drum.fill=0.2 \
  --set time.spin_up=0.1 --set time.settle=0.4 --set time.duration=0.2 \
  --set output.snapshot_interval=0.1 --set heat.enabled=true --set heat.initial=left_right \
  --set heat.shells=4
/usr/bin/python3 - "$work/run" <<'PY'
import csv, glob, json, sys, h5py, numpy as np
run = sys.argv[1]
summary = json.load(open(f"{run}/summary.json"))
heat = summary["heat"]
rows = list(csv.DictReader(open(f"{run}/heat_timeseries.csv")))
snaps = []
for path in sorted(glob.glob(f"{run}/snapshots/particles_*.h5")):
    with h5py.File(path, "r") as f:
        g = f[next(iter(f.keys()))]
        snaps.append((float(f.attrs["time"]), g["kind"][()], g["temperature"][()], g["radius"][()]))
if len(snaps) < 2:
    sys.exit(f"expected at least 2 snapshots, found {len(snaps)}")
time, kind, T, r = snaps[0]
counts = np.bincount(kind, minlength=3)
if counts[0] < 50 or counts[2] < 20:
    sys.exit(f"kinds {counts.tolist()}: expected free particles and glued shell discs")
by_kind = summary["particles_by_kind"]
if [by_kind["free"], by_kind["fixed"], by_kind["shell"]] != counts.tolist():
    sys.exit(f"summary particles_by_kind {by_kind} differs from the snapshot's kinds {counts.tolist()}")
free_std, all_std = T[kind == 0].std(), T.std()
if abs(free_std - all_std) < 1e-3 * free_std:
    sys.exit("free and all-particle std coincide: the case cannot test the bed statistics")
if abs(heat["std_temperature_initial_K"] - free_std) > 1e-10 * free_std:
    sys.exit(f"initial std {heat['std_temperature_initial_K']} is not the free particles' {free_std}"
             f" (all particles: {all_std})")
for time, kind, T, r in snaps:
    row = min(rows, key=lambda row: abs(float(row["time"]) - time))
    if abs(float(row["time"]) - time) > 1e-6:
        sys.exit(f"no heat_timeseries row at snapshot time {time}")
    bed = kind == 0
    mean = (r[bed] ** 3 * T[bed]).sum() / (r[bed] ** 3).sum()
    if abs(float(row["mean_temperature_K"]) - mean) > 1e-8 * mean:
        sys.exit(f"t = {time}: bed mean {row['mean_temperature_K']} K, free particles {mean} K")
if not heat["heat_energy_drift_max_relative"] < 1e-10:
    sys.exit(f"heat energy drift {heat['heat_energy_drift_max_relative']} is not at round-off")
print(f"bed statistics over {counts[0]} free particles ({counts[2]} glued discs excluded): "
      f"initial std {free_std:.6g} K (all particles {all_std:.6g} K); drift "
      f"{heat['heat_energy_drift_max_relative']:.2g}")
PY
