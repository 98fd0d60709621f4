#!/usr/bin/python3
"""Spot values near the bottom of the drum, wall slip and surface angle per case, DEM vs
continuum, from the cases.csv of `hikiln compare` with several DEM/continuum pairs (physics.md 5:
1.5 / 3 / 6 rpm at 20 % fill and 10 / 20 / 30 % fill at 3 rpm). Written for Debian's python3 with
python3-matplotlib and -numpy:

    /usr/bin/python3 plot_compare_cases.py --csv OUT/cases.csv --out OUT/cases.png
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

PANELS = [
    ("spot_pressure", "pressure [Pa]"),
    ("spot_shear_stress", "shear stress [Pa]"),
    ("spot_viscosity", "viscosity [Pa s]"),
    ("spot_strain_rate", "strain rate [1/s]"),
    ("spot_velocity_x", "x-velocity [m/s]"),
    ("wall_slip_percent", "wall slip [%]"),
    ("surface_angle_deg", "surface angle [deg]"),
]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--csv", required=True, help="cases.csv of hikiln compare")
    parser.add_argument("--out", required=True, help="PNG to write")
    args = parser.parse_args()
    table = np.genfromtxt(args.csv, delimiter=",", names=True, dtype=None, encoding="utf-8")
    table = np.atleast_1d(table)
    labels = [str(c) for c in table["case"]]
    x = np.arange(len(labels))
    fig, axes = plt.subplots(2, 4, figsize=(16, 7), constrained_layout=True)
    for ax, (column, title) in zip(axes.ravel(), PANELS):
        ax.bar(x - 0.2, table[column + "_dem"].astype(float), 0.4, label="DEM")
        ax.bar(x + 0.2, table[column + "_continuum"].astype(float), 0.4, label="continuum")
        ax.set_xticks(x)
        ax.set_xticklabels(labels, rotation=30, ha="right", fontsize=8)
        ax.set_title(title)
        if column == "spot_viscosity":
            ax.set_yscale("log")
    axes[0, 0].legend()
    last = axes.ravel()[-1]
    for column, marker in (("relative_l2_pressure", "o"), ("relative_l2_shear_stress", "s"),
                           ("relative_l2_velocity_x", "^"), ("relative_l2_velocity_y", "v")):
        last.plot(x, table[column].astype(float), marker, label=column.replace("relative_l2_", ""))
    last.set_xticks(x)
    last.set_xticklabels(labels, rotation=30, ha="right", fontsize=8)
    last.set_title("map relative L2 difference")
    last.legend(fontsize=7)
    fig.suptitle("DEM vs continuum: spot values near the bottom of the drum, wall slip, surface")
    fig.savefig(args.out, dpi=100)
    plt.close(fig)
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
