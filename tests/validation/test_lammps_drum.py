#!/usr/bin/env python3
"""Checks lammps_drum.py's pass rule on synthetic sweeps: hikiln seeds as summary.json files and
LAMMPS seeds as lammps_reference.sh's CSV. Run by ctest as validation_lammps_drum_rule (standard
library only)."""

import csv
import json
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "lammps_drum.py")
sys.path.insert(0, HERE)
from lammps_drum import LAMMPS as CASES  # noqa: E402  validation.md's table: particles, slip %, angle deg


def write_sweep(directory, offsets):
    """Three hikiln seeds per case at the table's values + offset + (-1, 0, +1) x 0.5 (sd 0.5)."""
    for case, (particles, slip, angle) in CASES.items():
        for k, spread in enumerate((-0.5, 0.0, 0.5), start=1):
            run = os.path.join(directory, f"{case}-s{k}")
            os.makedirs(run)
            d_slip, d_angle = offsets.get(case, (0.0, 0.0))
            with open(os.path.join(run, "summary.json"), "w", encoding="utf-8") as handle:
                json.dump({"particles": particles, "wall_slip_percent": slip + d_slip + spread,
                           "surface_angle_deg": angle + d_angle + spread}, handle)


def write_lammps(path, spread):
    """Three LAMMPS seeds per case at the table's values +- spread (sd = spread)."""
    with open(path, "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(["case", "seed", "particles", "wall_slip_percent", "surface_angle_deg",
                         "rotate_wall_time_s"])
        for case, (particles, slip, angle) in CASES.items():
            for seed, d in ((1, -spread), (2, 0.0), (3, spread)):
                writer.writerow([case, seed, particles, slip + d, angle + d, 10.0])


def run(*args):
    done = subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True,
                          check=False)
    return done.returncode, done.stdout + done.stderr


class PassRule(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def test_table_mode_floor_and_spread(self):
        # sd 0.5 -> allowed 2 * 0.5 + 1.5 = 2.5 (slip) and 2.5 (angle)
        write_sweep(os.path.join(self.dir, "ok"), {"fill-20-rpm-3": (2.4, -2.4)})
        code, out = run(os.path.join(self.dir, "ok"))
        self.assertEqual(code, 0, out)
        write_sweep(os.path.join(self.dir, "off"), {"fill-30-rpm-3": (2.6, 0.0)})
        code, out = run(os.path.join(self.dir, "off"))
        self.assertEqual(code, 1, out)
        self.assertIn("OUTSIDE", out)

    def test_measured_mode_uses_both_spreads(self):
        lammps = os.path.join(self.dir, "lammps.csv")
        write_lammps(lammps, 1.5)  # sd 1.5 -> allowed 2 * sqrt(0.5^2 + 1.5^2) = 3.16
        write_sweep(os.path.join(self.dir, "ok"), {"fill-10-rpm-6": (3.1, 0.0)})
        table = os.path.join(self.dir, "table.csv")
        code, out = run(os.path.join(self.dir, "ok"), "--lammps", lammps, "--csv", table)
        self.assertEqual(code, 0, out)
        with open(table, newline="", encoding="utf-8") as handle:
            rows = {row["case"]: row for row in csv.DictReader(handle)}
        self.assertEqual(len(rows), 5)
        self.assertAlmostEqual(float(rows["fill-10-rpm-6"]["slip_allowed"]), 2 * (0.25 + 2.25) ** 0.5)
        self.assertAlmostEqual(float(rows["fill-10-rpm-6"]["slip_lammps_sd"]), 1.5)
        write_sweep(os.path.join(self.dir, "off"), {"fill-10-rpm-6": (0.0, -3.3)})
        code, out = run(os.path.join(self.dir, "off"), "--lammps", lammps)
        self.assertEqual(code, 1, out)
        # with a tight LAMMPS spread the measured rule is stricter than the table rule's floor
        write_lammps(lammps, 0.1)
        write_sweep(os.path.join(self.dir, "tight"), {"fill-20-rpm-1.5": (2.0, 0.0)})
        self.assertEqual(run(os.path.join(self.dir, "tight"))[0], 0)
        self.assertEqual(run(os.path.join(self.dir, "tight"), "--lammps", lammps)[0], 1)

    def test_missing_seeds_fail(self):
        write_sweep(os.path.join(self.dir, "ok"), {})
        lammps = os.path.join(self.dir, "lammps.csv")
        with open(lammps, "w", encoding="utf-8") as handle:
            handle.write("case,seed,particles,wall_slip_percent,surface_angle_deg,rotate_wall_time_s\n")
            handle.write("fill-10-rpm-3,1,821,54.9,10.2,1.0\n")
        code, out = run(os.path.join(self.dir, "ok"), "--lammps", lammps)
        self.assertEqual(code, 1, out)
        self.assertIn("fewer than two LAMMPS seeds", out)


if __name__ == "__main__":
    unittest.main()
