#!/usr/bin/env python3
"""How far `hikiln kiln` runs of one case lie from a reference run, at one output.

Used to choose a solver tolerance (docs/kiln-3d.md, "Momentum tolerance"): run the case once per
tolerance (`--set numerics.momentum_tolerance=T`, same duration and outputs), then

    perf/scripts/kiln_run_difference.py REF_RUN RUN... [--output 2]

prints per run the mean momentum iterations and seconds per step (summary.json), the relative
hold-up difference, the largest velocity difference over the reference's largest speed, and the
largest volume-fraction and relative pressure differences in fields_NNNN.h5.
"""
import argparse
import json
from pathlib import Path

import h5py
import numpy as np

FIELDS = ("velocity", "volume_fraction", "pressure")


def load(run, output):
    with h5py.File(Path(run) / f"fields_{output:04d}.h5", "r") as f:
        fields = {name: np.array(f["fields"][name]) for name in FIELDS}
    summary = json.loads((Path(run) / "summary.json").read_text())
    return fields, summary


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("reference")
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--output", type=int, default=2, help="output number (default 2)")
    args = parser.parse_args()
    ref, ref_summary = load(args.reference, args.output)
    vmax = np.abs(ref["velocity"]).max()
    pmax = np.abs(ref["pressure"]).max()
    print("run, iterations, s/step, holdup rel diff, max du/max u, max dphi, max dp/max p")
    for run in [args.reference] + args.runs:
        fields, s = load(run, args.output)
        holdup = (s["holdup_final_m3"] - ref_summary["holdup_final_m3"]) / ref_summary["holdup_final_m3"]
        print(f"{run}, {s['mean_viscous_iterations']:.1f}, {s['seconds_per_step']:.3f}, {holdup:.2e}, "
              f"{np.abs(fields['velocity'] - ref['velocity']).max() / vmax:.2e}, "
              f"{np.abs(fields['volume_fraction'] - ref['volume_fraction']).max():.2e}, "
              f"{np.abs(fields['pressure'] - ref['pressure']).max() / pmax:.2e}")


if __name__ == "__main__":
    main()
