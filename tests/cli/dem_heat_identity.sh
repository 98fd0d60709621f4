#!/usr/bin/env bash
# `hikiln dem` with heat (docs/heat.md) end to end on a small drum (0.6 m, ~150 discs), with every
# conserving mechanism on (internal conduction, contact conduction, radiation; no environment) and
# the heat stepped every 7 mechanical steps (not a divisor of the sample interval):
# (1) the heat energy drift in summary.json stays at round-off (< 1e-10 relative) while the
#     mixing measure (std of the particle temperatures over its initial value) falls below 1;
# (2) a run stopped at a checkpoint and restarted ends with bitwise the same shell temperatures,
#     contact layers and heat time series as an uninterrupted run;
# (3) 1 and 2 threads give bitwise the same temperatures and heat time series;
# (4) snapshots carry the temperatures (HDF5 datasets and XDMF attributes), the same in the
#     restarted run as in the uninterrupted one; the temperature maps are drawn.
# Usage: dem_heat_identity.sh HIKILN CASE WORKDIR
set -euo pipefail
hikiln=$1 case=$2 work=$3
export OMP_WAIT_POLICY=passive # 2 threads on a busy machine: sleep at barriers, do not spin
rm -rf "$work" && mkdir -p "$work"
common=(--set drum.diameter=0.6 --set drum.fill=0.2 --set time.spin_up=0.1 --set time.settle=0.4
        --set output.checkpoint_interval=0.2 --set output.snapshot_interval=0.2
        --set heat.enabled=true --set heat.contact_conduction=true --set heat.step_every=7
        --set heat.shells=4 --set heat.initial=left_right)
"$hikiln" -q --threads 2 dem "$case" -o "$work/full" --set time.duration=0.4 "${common[@]}"
"$hikiln" -q --threads 2 dem "$case" -o "$work/split" --set time.duration=0.2 "${common[@]}"
"$hikiln" -q --threads 2 dem "$case" -o "$work/split" --set time.duration=0.4 "${common[@]}" --restart
"$hikiln" -q --threads 1 dem "$case" -o "$work/one" --set time.duration=0.4 "${common[@]}"
for run in split one; do
  diff "$work/full/heat_timeseries.csv" "$work/$run/heat_timeseries.csv"
  diff "$work/full/timeseries.csv" "$work/$run/timeseries.csv"
done
/usr/bin/python3 - "$work" <<'PY'
import glob, json, os, sys, h5py, numpy as np
work = sys.argv[1]
def state(run):
    f = h5py.File(f"{work}/{run}/checkpoint.h5", "r")
    ids = f["integers/heat_id"][()]
    order = np.argsort(ids)
    out = {"shells": f["reals/heat_temperature"][()].reshape(len(ids), -1)[order]}
    pairs = np.stack([f["integers/heat_contact_id"][()], f["integers/heat_contact_neighbor_id"][()]])
    layers = np.lexsort(pairs[::-1])
    for k in ["area", "layer", "layer_other"]:
        out[k] = f["reals/heat_contact_" + k][()][layers]
    out["pairs"] = pairs[:, layers]
    for k in ["heat_time", "heat_sub_steps", "heat_last_step", "heat_max_drift"]:
        out[k] = f["scalars/" + k][()]
    return out
full = state("full")
if full["pairs"].shape[1] < 50:
    sys.exit(f"only {full['pairs'].shape[1]} contact layers in the checkpoint: contacts not exercised")
for other in ["split", "one"]:
    s = state(other)
    bad = [k for k in full if not np.array_equal(full[k], s[k])]
    if bad:
        sys.exit(f"{other} differs from the uninterrupted 2-thread run in {bad}")
print("heat restart and thread-count identity: bitwise equal")
for run in ["full", "split", "one"]:
    heat = json.load(open(f"{work}/{run}/summary.json"))["heat"]
    drift = heat["heat_energy_drift_max_relative"]
    if not drift < 1e-10:
        sys.exit(f"{run}: heat energy drift {drift} is not at round-off")
    if not 0.0 < heat["mixing_measure"] < 1.0:
        sys.exit(f"{run}: mixing measure {heat['mixing_measure']} did not fall below 1")
print(f"drift {drift:.2e}, mixing {heat['mixing_measure']:.6f}: ok")
def snapshots(run):
    xmf = open(f"{work}/{run}/particles.xmf").read()
    if xmf.count('Name="temperature"') < 2 or 'Name="surface_temperature"' not in xmf:
        sys.exit(f"{run}/particles.xmf lacks the temperature attributes")
    out = []
    for path in sorted(glob.glob(f"{work}/{run}/snapshots/particles_*.h5")):
        with h5py.File(path, "r") as f:
            g = next(f[k] for k in f if k.startswith("step_"))
            order = np.argsort(g["id"][()])
            out.append(np.stack([g["temperature"][()][order], g["surface_temperature"][()][order]]))
    return out
full, split = snapshots("full"), snapshots("split")
if len(full) < 2 or len(full) != len(split) or any(not np.array_equal(a, b) for a, b in zip(full, split)):
    sys.exit(f"snapshot temperatures differ after the restart ({len(full)} vs {len(split)} snapshots)")
if np.array_equal(full[0], full[-1]):
    sys.exit("the snapshot temperatures did not change")
print(f"{len(full)} snapshots carry the same temperatures after a restart: ok")
for name in ("heat_mixing.png", "temperature_maps.png"):
    path = f"{work}/full/plots/{name}"
    if not os.path.exists(path) or os.path.getsize(path) < 10000:
        sys.exit(f"plot_temperature.py did not draw {path}")
print("temperature maps drawn: ok")
PY
