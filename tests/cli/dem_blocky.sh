#!/usr/bin/env bash
# `hikiln dem` with superquadric (blocky) particles, a small drum (0.3 m, 12 mm particles, N from the
# case file): (1) the run completes and summary.json describes the shape; (2) the snapshots carry
# orientation, semi-axes and blockiness, the semi-axes give the requested equal-area diameters and
# the bounding radius the summary's ratio, and the particles turned during the rotation; (3) the fill
# is measured with the true superquadric areas (not the bounding circles') and lands within 6 % of
# the requested one; (4) a run stopped half way and continued with --restart ends bitwise identical
# (positions, orientations, velocities, pair directions, time series); (5) with a rough shell the
# glued particles stay circles of the bump size on their ring.
# Usage: dem_blocky.sh HIKILN CASE WORKDIR
set -euo pipefail
hikiln=$1 case=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
# ~120 particles; softer springs and a larger step fraction keep it at ~10 s a run on one core
common=(--set drum.diameter=0.3 --set particles.diameter=0.012 --set drum.rpm=10
        --set contact.normal_stiffness=2e4 --set contact.tangential_stiffness=1e4
        --set time.step_safety=0.1 --set time.settle=0.2 --set time.spin_up=0.1
        --set output.snapshot_interval=0.2 --set output.checkpoint_interval=0.2
        --set output.average_interval=0.3)
"$hikiln" -q --threads 1 dem "$case" -o "$work/full" --set time.duration=0.6 "${common[@]}"
"$hikiln" -q --threads 1 dem "$case" -o "$work/split" --set time.duration=0.3 "${common[@]}"
"$hikiln" -q --threads 1 dem "$case" -o "$work/split" --set time.duration=0.6 "${common[@]}" --restart
diff "$work/full/timeseries.csv" "$work/split/timeseries.csv"
# a rough shell: circles glued to it next to the blocky bed
"$hikiln" -q --threads 1 dem "$case" -o "$work/rough" --set time.duration=0.2 "${common[@]}" \
  --set walls.roughness=glued
/usr/bin/python3 - "$work" <<'PY'
import glob, json, math, sys, h5py, numpy as np
work = sys.argv[1]
summary = json.load(open(f"{work}/full/summary.json"))
shape = summary["particle_shape"]
if shape["shape"] != "superquadric" or shape["aspect_ratio"] != 1:
    sys.exit(f"summary.json particle_shape: {shape}")
N = shape["blockiness"]

def snapshot(path):
    with h5py.File(path, "r") as f:
        g = f[next(iter(f.keys()))]
        return {k: g[k][()] for k in g.keys()}

def by_id(s):
    order = np.argsort(s["id"])
    return {k: v[order] for k, v in s.items()}

paths = sorted(glob.glob(f"{work}/full/snapshots/particles_*.h5"))
first, last = by_id(snapshot(paths[0])), by_id(snapshot(paths[-1]))
free = last["kind"] == 0
a, b, n = last["semi_axis_a"][free], last["semi_axis_b"][free], last["blockiness"][free]
if not (np.all(n == N) and np.array_equal(a, b)):
    sys.exit(f"snapshot shapes are not N = {N} with a = b")
area = 4 * a * b * math.gamma(1 + 1 / N) ** 2 / math.gamma(1 + 2 / N)
d = np.sqrt(4 * area / math.pi)  # equal-area diameters: 12 mm +-5 % (the case's size_range)
if not (d.min() > 0.0114 * (1 - 1e-12) and d.max() < 0.0126 * (1 + 1e-12) and d.std() > 1e-4):
    sys.exit(f"equal-area diameters {d.min()}..{d.max()} not spread over 11.4..12.6 mm")
ratio = last["radius"][free] / (0.5 * d)
if np.max(np.abs(ratio / shape["bounding_over_equal_area_radius"] - 1)) > 1e-9:
    sys.exit(f"bounding radius / equal-area radius {ratio.min()}..{ratio.max()} differs from "
             f"summary {shape['bounding_over_equal_area_radius']}")
if not ratio.min() > 1.05:
    sys.exit("bounding circles would equal the true areas: the area check below cannot fail")
turned = np.abs(last["orientation"][free] - first["orientation"][free]) > 1e-2
if turned.mean() < 0.5:
    sys.exit(f"only {100 * turned.mean():.0f} % of the particles turned by > 0.01 rad")
# fill_measured = solid area / (bulk fraction pi R^2) with the true areas (the particles are the
# same since the fill was measured)
R = 0.15
solid = summary["fill_measured"] * summary["bulk_solid_fraction"] * math.pi * R * R
if abs(solid / area.sum() - 1) > 1e-9:
    sys.exit(f"measured solid area {solid} is not the superquadric areas' sum {area.sum()} "
             f"(bounding circles: {np.sum(math.pi * last['radius'][free] ** 2)})")
if abs(summary["fill_measured"] / summary["fill_requested"] - 1) > 0.06:
    sys.exit(f"fill {summary['fill_measured']} vs requested {summary['fill_requested']}")
xmf = open(f"{work}/full/particles.xmf").read()
if not all(f'Name="{k}"' in xmf for k in ["orientation", "semi_axis_a", "semi_axis_b", "blockiness"]):
    sys.exit("particles.xmf lacks the shape attributes")
print(f"blocky run: {free.sum()} particles N = {N}, fill {summary['fill_measured']:.4f}, "
      f"{100 * turned.mean():.0f} % turned, bounding/equal-area radius {ratio.mean():.4f}")

# restart identity: last snapshot and checkpoint
split = by_id(snapshot(sorted(glob.glob(f"{work}/split/snapshots/particles_*.h5"))[-1]))
bad = [k for k in ["position", "velocity", "angular_velocity", "orientation"]
       if not np.array_equal(last[k], split[k])]
def checkpoint(run):
    f = h5py.File(f"{work}/{run}/checkpoint.h5", "r")
    order = np.argsort(f["integers/id"][()])
    out = {k: f["reals/" + k][()].reshape(len(order), -1)[order]
           for k in ["position", "velocity", "angular_velocity", "orientation", "force", "torque"]}
    ci, cn = f["integers/contact_id"][()], f["integers/contact_neighbor_id"][()]
    o = np.lexsort((cn, ci))  # pair history keyed by (id, neighbour id)
    out["contact_pairs"] = np.stack([ci[o], cn[o]])
    out["contact_angle"] = f["reals/contact_angle"][()][o]
    return out
cf, cs = checkpoint("full"), checkpoint("split")
bad += ["checkpoint " + k for k in cf if not np.array_equal(cf[k], cs[k])]
if bad:
    sys.exit(f"the restarted run differs from the uninterrupted one in {bad}")
print("blocky restart identity: bitwise equal")

rough = by_id(snapshot(sorted(glob.glob(f"{work}/rough/snapshots/particles_*.h5"))[-1]))
shell = rough["kind"] == 2
ring = np.hypot(rough["position"][shell, 0], rough["position"][shell, 1])
if not (shell.sum() > 50 and np.all(rough["blockiness"][shell] == 2)
        and np.array_equal(rough["semi_axis_a"][shell], rough["radius"][shell])
        and np.array_equal(rough["semi_axis_b"][shell], rough["radius"][shell])
        and np.max(np.abs(ring - (R - 0.006))) < 1e-9 and np.all(rough["blockiness"][~shell] == N)):
    sys.exit("rough shell: the glued particles are not circles of the bump size on the ring")
print(f"rough shell: {shell.sum()} glued circles on the ring next to {(~shell).sum()} blocks")
PY
