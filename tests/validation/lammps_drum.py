#!/usr/bin/env python3
"""Code-to-code check of hikiln's DEM against LAMMPS (../shared/reference/validation.md, table
"Code-to-code: the base drum in LAMMPS"). Reads a finished `hikiln sweep` of
cases/studies/lammps-validation.yaml (three or more seeds per case) and checks, per case, wall slip and
surface angle.

Without --lammps: LAMMPS's values are validation.md's single runs, so LAMMPS's own seed spread is
unknown; a case passes when |hikiln mean - LAMMPS| <= 2 * (hikiln's standard deviation over seeds)
+ a floor (1.5 % slip, 1.5 deg angle) that stands for it.

With --lammps CSV (written by tests/validation/lammps_reference.sh: LAMMPS run with several seeds):
both spreads are measured, and a case passes when |hikiln mean - LAMMPS mean| <= 2 * sqrt(s_h^2 +
s_l^2), the run-to-run spread of the difference of one run of each code. The table also gives z, the
difference of the means over its standard error sqrt(s_h^2 / n_h + s_l^2 / n_l).

Prints a table (and writes it as CSV with --csv FILE); exits 1 if any case is outside.
Usage: lammps_drum.py SWEEP_DIR [--lammps CSV] [--csv FILE]"""
import argparse
import csv
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
    """Mean, sample standard deviation and count."""
    m = sum(values) / len(values)
    s = math.sqrt(sum((v - m) ** 2 for v in values) / (len(values) - 1)) if len(values) > 1 else 0.0
    return m, s, len(values)


def read_lammps_runs(path):
    """case -> list of (particles, slip, angle) from lammps_reference.sh's CSV."""
    runs = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            runs.setdefault(row["case"], []).append(
                (int(row["particles"]), float(row["wall_slip_percent"]), float(row["surface_angle_deg"])))
    return runs


def compare(h, lmp, measured, what):
    """(allowed difference, z of the means, verdict) for hikiln stats h against LAMMPS stats lmp."""
    diff = abs(h[0] - lmp[0])
    if measured:
        allowed = 2.0 * math.sqrt(h[1] ** 2 + lmp[1] ** 2)
        se = math.sqrt(h[1] ** 2 / h[2] + lmp[1] ** 2 / lmp[2])
    else:
        allowed = 2.0 * h[1] + FLOOR[what]
        se = h[1] / math.sqrt(h[2])
    z = diff / se if se > 0 else float("inf")
    return allowed, z, diff <= allowed


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("sweep", help="finished sweep of cases/studies/lammps-validation.yaml")
    parser.add_argument("--lammps", help="lammps-runs.csv of tests/validation/lammps_reference.sh")
    parser.add_argument("--csv", help="also write the table here")
    args = parser.parse_args()

    lammps_runs = read_lammps_runs(args.lammps) if args.lammps else None
    ok = True
    rows = []
    print(f"{'case':16} {'N':>5} {'N_lmp':>5} | {'slip % hikiln':>14} {'LAMMPS':>13} {'allowed':>7} {'z':>5} |"
          f" {'angle deg hikiln':>16} {'LAMMPS':>13} {'allowed':>7} {'z':>5} | verdict")
    for case, (n_ref, slip_ref, angle_ref) in LAMMPS.items():
        runs = sorted(Path(args.sweep).glob(case + "-s*/summary.json"))
        if len(runs) < 2:
            print(f"{case}: fewer than two finished seeds in {args.sweep}")
            ok = False
            continue
        summaries = [json.loads(r.read_text()) for r in runs]
        n = stats([s["particles"] for s in summaries])[0]
        slip = stats([s["wall_slip_percent"] for s in summaries])
        angle = stats([s["surface_angle_deg"] for s in summaries])
        if lammps_runs is not None:
            mine = lammps_runs.get(case, [])
            if len(mine) < 2:
                print(f"{case}: fewer than two LAMMPS seeds in {args.lammps}")
                ok = False
                continue
            n_lmp = stats([r[0] for r in mine])[0]
            slip_lmp = stats([r[1] for r in mine])
            angle_lmp = stats([r[2] for r in mine])
        else:
            n_lmp, slip_lmp, angle_lmp = n_ref, (slip_ref, 0.0, 1), (angle_ref, 0.0, 1)
        measured = lammps_runs is not None
        slip_allowed, slip_z, good_slip = compare(slip, slip_lmp, measured, "slip")
        angle_allowed, angle_z, good_angle = compare(angle, angle_lmp, measured, "angle")
        ok &= good_slip and good_angle
        verdict = "ok" if good_slip and good_angle else "OUTSIDE"
        print(f"{case:16} {n:5.0f} {n_lmp:5.0f} | {slip[0]:6.1f} +-{slip[1]:4.1f}   {slip_lmp[0]:5.1f} +-{slip_lmp[1]:4.1f}"
              f" {slip_allowed:7.1f} {slip_z:5.1f} | {angle[0]:8.1f} +-{angle[1]:4.1f}   {angle_lmp[0]:5.1f} +-"
              f"{angle_lmp[1]:4.1f} {angle_allowed:7.1f} {angle_z:5.1f} | {verdict}")
        rows.append({"case": case, "particles": round(n), "particles_lammps": round(n_lmp),
                     "seeds": slip[2], "seeds_lammps": slip_lmp[2],
                     "slip_mean": slip[0], "slip_sd": slip[1], "slip_lammps_mean": slip_lmp[0],
                     "slip_lammps_sd": slip_lmp[1], "slip_allowed": slip_allowed, "slip_z": slip_z,
                     "angle_mean": angle[0], "angle_sd": angle[1], "angle_lammps_mean": angle_lmp[0],
                     "angle_lammps_sd": angle_lmp[1], "angle_allowed": angle_allowed, "angle_z": angle_z,
                     "verdict": verdict})
    if args.csv and rows:
        with open(args.csv + ".tmp", "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(rows[0]))
            writer.writeheader()
            writer.writerows(rows)
        Path(args.csv + ".tmp").replace(args.csv)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
