#!/usr/bin/python3
"""How far `hikiln continuum` drum runs of one case lie from a reference run, in the flow averaged
over the outputs after slip_after.

Used to choose the momentum tolerance of the 2D drums (perf/README.md, "The momentum tolerance of
the 2D drums"): run the case once per tolerance (`--set numerics.momentum_tolerance=T`, same
duration and outputs), then

    perf/scripts/drum_run_difference.py REF_RUN RUN...

prints per run the mean momentum iterations and seconds per step (summary.json), the wall slip
(summary.json) and the surface angle (mean over the averaged outputs, as
tests/validation/drum_surface_angle.py measures it), and for the velocity, bed pressure, strain
rate and viscosity the relative L2 difference of the time-averaged field against the
reference's, over the reference's bed (averaged volume fraction above phi_max / 2).
"""
import argparse
import json
import sys
from pathlib import Path

import h5py
import numpy as np
import yaml

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tests" / "validation"))
from drum_surface_angle import surface_angle  # noqa: E402

FIELDS = ("velocity", "bed_pressure", "strain_rate", "viscosity", "volume_fraction")


def averaged(run):
    """Time-averaged fields, surface angle and summary of a run, over its outputs after slip_after."""
    case = yaml.safe_load((Path(run) / "case.resolved.yaml").read_text())
    summary = json.loads((Path(run) / "summary.json").read_text())
    interval = case["time"]["output_interval"]
    first = int(np.ceil(case["time"]["slip_after"] / interval - 1e-9))
    files = sorted(Path(run).glob("fields_*.h5"))[first:]
    if not files:
        raise SystemExit(f"drum_run_difference: {run}: no outputs after slip_after")
    sums = {}
    for path in files:
        with h5py.File(path, "r") as f:
            for name in FIELDS:
                sums[name] = sums.get(name, 0.0) + np.nan_to_num(np.array(f["fields"][name]))
    mean = {name: total / len(files) for name, total in sums.items()}
    angle = np.mean([surface_angle(str(p), case["drum"]["diameter"]) for p in files])
    return mean, angle, summary, case["material"]["phi_max"]


def relative_l2(field, reference, mask):
    return np.linalg.norm((field - reference)[mask]) / np.linalg.norm(reference[mask])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("reference")
    parser.add_argument("runs", nargs="+")
    args = parser.parse_args()
    ref, _, _, phi_max = averaged(args.reference)
    bed = ref["volume_fraction"] > 0.5 * phi_max
    print("run, iterations, s/step, wall slip %, surface angle deg, rel. L2 on the bed of the "
          "averaged velocity, bed pressure, strain rate, viscosity")
    for run in [args.reference] + args.runs:
        mean, angle, s, _ = averaged(run)
        diffs = ", ".join(f"{relative_l2(mean[n], ref[n], bed):.2e}" for n in FIELDS[:4])
        print(f"{run}, {s['mean_viscous_iterations']:.1f}, {s['seconds_per_step']:.4f}, "
              f"{s['wall_slip_percent']:.3f}, {angle:.2f}, {diffs}")


if __name__ == "__main__":
    main()
