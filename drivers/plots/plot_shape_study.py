"""Table and plot of the particle-shape study (cmake/shape-study.sh): for each blockiness N, the
DEM bed measures (summary.json of OUT/dem/blockiness-N) and the fitted rheology (summary.json of
OUT/calibration/blockiness-N). Writes OUT/shape-table.md, OUT/shape-table.csv, OUT/shape-study.png.
Usage: plot_shape_study.py OUT"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLUMNS = [  # (header, source, key, format)
    ("N", "dem", None, "{:g}"),
    ("particles", "dem", "particles", "{:d}"),
    ("fill %", "dem", "fill_measured", "{:.1%}"),
    ("surface angle (deg)", "dem", "surface_angle_deg", "{:.1f}"),
    ("wall slip %", "dem", "wall_slip_percent", "{:.1f}"),
    ("mu_wall", "cal", "mu_wall", "{:.3f}"),
    ("m0", "cal", "m0", "{:.3f}"),
    ("m1", "cal", "m1", "{:.3g}"),
    ("mu_fr (Coulomb)", "cal", "mu_fr", "{:.3f}"),
    ("cells fitted", "cal", "cells", "{:d}"),
    ("rotation (s)", "dem", "simulated_rotation_s", "{:g}"),
    ("particle-steps/s", "dem", "particle_steps_per_s", "{:.3g}"),
]


def load(path):
    with open(path) as f:
        return json.load(f)


def main(out):
    rows = []
    for n in (2, 3, 4, 6):
        dem_path = os.path.join(out, "dem", f"blockiness-{n}", "summary.json")
        cal_path = os.path.join(out, "calibration", f"blockiness-{n}", "summary.json")
        if not os.path.exists(dem_path):
            print(f"plot_shape_study: {dem_path} missing, blockiness {n} left out", file=sys.stderr)
            continue
        dem = load(dem_path)
        cal = load(cal_path) if os.path.exists(cal_path) else {}
        shape = dem.get("particle_shape", {})
        row = {"N": shape.get("blockiness", n), "dem": dem, "cal": cal}
        rows.append(row)
    if not rows:
        sys.exit(f"plot_shape_study: no runs under {out}/dem")

    def value(row, source, key):
        if key is None:
            return row["N"]
        return row[source].get(key)

    def text(v, fmt):
        if v is None:
            return "n/a"
        try:
            return fmt.format(v)
        except (ValueError, TypeError):
            return str(v)

    with open(os.path.join(out, "shape-table.md"), "w") as f:
        f.write("| " + " | ".join(c[0] for c in COLUMNS) + " |\n")
        f.write("|" + "---|" * len(COLUMNS) + "\n")
        for row in rows:
            cells = [text(value(row, s, k), fmt) for _, s, k, fmt in COLUMNS]
            f.write("| " + " | ".join(cells) + " |\n")
    with open(os.path.join(out, "shape-table.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow([c[0] for c in COLUMNS])
        for row in rows:
            w.writerow([value(row, s, k) for _, s, k, _ in COLUMNS])

    n = [r["N"] for r in rows]
    panels = [("surface angle (deg)", "dem", "surface_angle_deg"),
              ("wall slip %", "dem", "wall_slip_percent"),
              ("mu_wall", "cal", "mu_wall"),
              ("m0 (friction at zero strain rate)", "cal", "m0")]
    fig, axes = plt.subplots(1, len(panels), figsize=(4 * len(panels), 3.4))
    for ax, (label, source, key) in zip(axes, panels):
        ys = [value(r, source, key) for r in rows]
        xs = [x for x, y in zip(n, ys) if y is not None]
        ax.plot(xs, [y for y in ys if y is not None], "o-")
        ax.set_xlabel("blockiness N")
        ax.set_title(label, fontsize=10)
        ax.set_xticks([2, 3, 4, 6])
        ax.grid(alpha=0.3)
    fig.suptitle("particle-shape study (DEM, cases/studies/shape.yaml)", fontsize=11)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "shape-study.png"), dpi=120)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
