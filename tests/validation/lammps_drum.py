#!/usr/bin/env python3
"""Code-to-code check of hikiln's DEM against LAMMPS (../shared/reference/validation.md, table
"Code-to-code: the base drum in LAMMPS"). Reads a finished `hikiln sweep` of
cases/studies/lammps-validation.yaml (three seeds per case) and checks, per case, that LAMMPS's wall
slip and surface angle lie within the run-to-run spread hikiln shows: |mean - LAMMPS| <= 2 * (standard
deviation over seeds) + a floor (1.5 % slip, 1.5 deg angle) that stands for LAMMPS's own unmeasured
seed spread. Prints a table; exits 1 if any case is outside. Usage: lammps_drum.py SWEEP_DIR"""
import json
import math
import sys
from pathlib import Path

# validation.md: fill, rpm -> (particles, wall slip %, surface angle deg), LAMMPS 2022 on these machines.
LAMMPS = {
    "fill-10-rpm-3": (821, 54.9, 10.2),
    "fill-20-rpm-3": (1645, 53.5, 13.7),
    "fill-30-rpm-3": (2484, 51.3, 19.3),
    "fill-20-rpm-1.5": (1645, 54.0, 13.1),
    "fill-10-rpm-6": (821, 56.2, 12.4),
}
FLOOR = {"slip": 1.5, "angle": 1.5}


def stats(values):
    m = sum(values) / len(values)
    s = math.sqrt(sum((v - m) ** 2 for v in values) / (len(values) - 1)) if len(values) > 1 else 0.0
    return m, s


def main(sweep):
    ok = True
    print(f"{'case':18} {'N':>5} {'N_lmp':>5} | {'slip %':>13} {'lmp':>5} | {'angle deg':>13} {'lmp':>5} | verdict")
    for case, (n_ref, slip_ref, angle_ref) in LAMMPS.items():
        runs = sorted(Path(sweep).glob(case + "-s*/summary.json"))
        if len(runs) < 2:
            print(f"{case}: fewer than two finished seeds in {sweep}")
            ok = False
            continue
        summaries = [json.loads(r.read_text()) for r in runs]
        n = stats([s["particles"] for s in summaries])[0]
        slip = stats([s["wall_slip_percent"] for s in summaries])
        angle = stats([s["surface_angle_deg"] for s in summaries])
        good_slip = abs(slip[0] - slip_ref) <= 2 * slip[1] + FLOOR["slip"]
        good_angle = abs(angle[0] - angle_ref) <= 2 * angle[1] + FLOOR["angle"]
        ok &= good_slip and good_angle
        print(f"{case:18} {n:5.0f} {n_ref:5d} | {slip[0]:6.1f} +-{slip[1]:4.1f} {slip_ref:5.1f} | "
              f"{angle[0]:6.1f} +-{angle[1]:4.1f} {angle_ref:5.1f} | "
              f"{'ok' if good_slip and good_angle else 'OUTSIDE'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
