#!/usr/bin/python3
"""Plots of `hikiln calibrate`: the DEM scatter data and the fitted laws, one PNG each.

Reads calibration.csv (one row per selected cell), calibration.json (the fits) and, when it is
beside calibration.csv, wall_profile.csv (one row per shell bin), all written by
`hikiln calibrate`. Written for Debian's python3 with python3-matplotlib and python3-numpy:

    /usr/bin/python3 plot_calibration.py --csv OUT/calibration.csv \
        --json OUT/calibration.json --out DIR
"""
import argparse
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_cells(path):
    """Columns of calibration.csv as numpy arrays, plus the run label of every row."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_calibration: {path} has no cells")
    runs = [r["run"] for r in rows]
    columns = {k: np.array([float(r[k]) for r in rows]) for k in rows[0] if k != "run"}
    return runs, columns


def run_order(runs):
    """Run labels in the order they first appear."""
    return list(dict.fromkeys(runs))


def scatter_by_run(ax, runs, x, y):
    labels = np.array(runs)
    for label in run_order(runs):
        mask = labels == label
        ax.scatter(x[mask], y[mask], s=8, alpha=0.6, label=label)


def finish(fig, ax, path, title):
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    print(f"wrote {path}")


def shear_vs_strain_rate(runs, c, fits, out):
    fig, ax = plt.subplots(figsize=(6, 4.5))
    scatter_by_run(ax, runs, c["strain_rate"], c["shear_stress"])
    law = fits["newtonian"]
    rate = np.geomspace(c["strain_rate"].min(), c["strain_rate"].max(), 100)
    ax.plot(rate, law["coefficient"] * rate ** law["exponent"], "k-",
            label=f"fit: tau = {law['coefficient']:.3g} gamma_dot^{law['exponent']:.3f}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("strain rate gamma_dot [1/s]")
    ax.set_ylabel("shear stress q [Pa]")
    verdict = "Newtonian" if law["newtonian"] else "not Newtonian (n = 1 would be)"
    finish(fig, ax, os.path.join(out, "shear_stress_vs_strain_rate.png"),
           f"Shear stress vs strain rate: {verdict}")


def shear_vs_pressure(runs, c, fits, out):
    fig, ax = plt.subplots(figsize=(6, 4.5))
    scatter_by_run(ax, runs, c["pressure"], c["shear_stress"])
    coulomb = fits["coulomb"]
    p = np.linspace(0.0, c["pressure"].max(), 100)
    ax.plot(p, coulomb["cohesion"] + coulomb["mu_fr"] * p, "k-",
            label=(f"Coulomb: mu_fr = {coulomb['mu_fr']:.3f} (phi = {coulomb['phi_deg']:.1f} deg), "
                   f"c = {coulomb['cohesion']:.3g} Pa"))
    ax.set_xlabel("pressure p [Pa]")
    ax.set_ylabel("shear stress q [Pa]")
    finish(fig, ax, os.path.join(out, "shear_stress_vs_pressure.png"), "Coulomb line")


def viscosity_vs_pressure(runs, c, fits, out):
    fig, ax = plt.subplots(figsize=(6, 4.5))
    labels = np.array(runs)
    lines = {r["label"]: r["viscosity_vs_pressure"] for r in fits["runs"]}
    for label in run_order(runs):
        mask = labels == label
        points = ax.scatter(c["pressure"][mask], c["viscosity"][mask], s=8, alpha=0.6, label=label)
        if label in lines:
            p = np.linspace(c["pressure"][mask].min(), c["pressure"][mask].max(), 50)
            line = lines[label]
            ax.plot(p, line["intercept"] + line["slope"] * p, "-", color=points.get_facecolor()[0],
                    alpha=1.0, label=f"{label}: R^2 = {line['quality']['r_squared']:.2f}")
    ax.set_xlabel("pressure p [Pa]")
    ax.set_ylabel("shear viscosity q / gamma_dot [Pa s]")
    finish(fig, ax, os.path.join(out, "viscosity_vs_pressure.png"), "Viscosity vs pressure per run")


def friction_vs_strain_rate(runs, c, fits, out):
    fig, ax = plt.subplots(figsize=(6, 4.5))
    scatter_by_run(ax, runs, c["strain_rate"], c["m"])
    line = fits["m_line"]
    rate = np.linspace(0.0, c["strain_rate"].max(), 100)
    ax.plot(rate, line["intercept"] + line["slope"] * rate, "k-",
            label=(f"m = {line['intercept']:.3f} + {line['slope']:.3g} gamma_dot "
                   f"(R^2 = {line['quality']['r_squared']:.2f})"))
    mu_i = fits.get("mu_i", {})
    if "m_s" in mu_i:
        ms, m2, i0 = mu_i["m_s"], mu_i["m_2"], mu_i["I0"]
        predicted = ms + (m2 - ms) * c["inertial_number"] / (c["inertial_number"] + i0)
        ax.scatter(c["strain_rate"], predicted, s=6, marker="x", color="0.3",
                   label=f"mu(I) fit at each cell: m_s {ms:.3f}, m_2 {m2:.3f}, I0 {i0:.3g}")
    ax.set_xlabel("strain rate gamma_dot [1/s]")
    ax.set_ylabel("Drucker-Prager m = q / p [-]")
    finish(fig, ax, os.path.join(out, "m_vs_strain_rate.png"), "Friction coefficient m(gamma_dot)")


def friction_vs_inertial_number(runs, c, fits, out):
    mu_i = fits.get("mu_i", {})
    if "m_s" not in mu_i:
        return
    fig, ax = plt.subplots(figsize=(6, 4.5))
    scatter_by_run(ax, runs, c["inertial_number"], c["m"])
    ms, m2, i0 = mu_i["m_s"], mu_i["m_2"], mu_i["I0"]
    inertial = np.geomspace(c["inertial_number"].min(), c["inertial_number"].max(), 100)
    ax.plot(inertial, ms + (m2 - ms) * inertial / (inertial + i0), "k-",
            label=f"mu(I): m_s {ms:.3f}, m_2 {m2:.3f}, I0 {i0:.3g}")
    ax.set_xscale("log")
    ax.set_xlabel("inertial number I = gamma_dot d / sqrt(p / rho_p) [-]")
    ax.set_ylabel("Drucker-Prager m = q / p [-]")
    finish(fig, ax, os.path.join(out, "m_vs_inertial_number.png"), "mu(I) form")


def wall_profile(csv_path, fits, out):
    """Friction ratio and slip along the shell per run (wall_profile.csv beside calibration.csv)."""
    path = os.path.join(os.path.dirname(os.path.abspath(csv_path)), "wall_profile.csv")
    if not os.path.exists(path):
        return
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        return
    runs = np.array([r["run"] for r in rows])
    col = {k: np.array([float(r[k]) for r in rows]) for k in rows[0] if k != "run"}
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(6.5, 7), sharex=True)
    for label in run_order(list(runs)):
        # bins with at least 5 % of the run's largest normal stress: the rest is a few grazing
        # contacts whose ratio is noise
        mask = (runs == label) & (col["normal_stress"] >= 0.05 * col["normal_stress"][runs == label].max())
        top.plot(col["theta_deg"][mask], col["friction_ratio"][mask], "o-", ms=3, label=label)
        bottom.plot(col["theta_deg"][mask], col["slip_percent"][mask], "o-", ms=3, label=label)
    mu_wall = fits.get("wall", {}).get("mu_wall")
    if mu_wall is not None:
        top.axhline(mu_wall, color="k", ls="--", label=f"mu_wall (shell average) {mu_wall:.3f}")
    top.set_ylabel("shear / normal wall stress [-]")
    bottom.set_ylabel("wall slip [%]")
    bottom.set_xlabel("angle of the shell bin [deg]")
    top.grid(True, alpha=0.3)
    top.legend(fontsize="small")
    top.set_title("Wall friction and slip along the shell\n(bins with >= 5 % of the run's largest "
                  "normal stress)", fontsize="medium")
    finish(fig, bottom, os.path.join(out, "wall_profile.png"), "")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--csv", required=True, help="calibration.csv")
    parser.add_argument("--json", required=True, help="calibration.json")
    parser.add_argument("--out", required=True, help="directory for the PNG files")
    args = parser.parse_args()
    runs, cells = read_cells(args.csv)
    with open(args.json) as f:
        fits = json.load(f)
    os.makedirs(args.out, exist_ok=True)
    shear_vs_strain_rate(runs, cells, fits, args.out)
    shear_vs_pressure(runs, cells, fits, args.out)
    viscosity_vs_pressure(runs, cells, fits, args.out)
    friction_vs_strain_rate(runs, cells, fits, args.out)
    friction_vs_inertial_number(runs, cells, fits, args.out)
    wall_profile(args.csv, fits, args.out)


if __name__ == "__main__":
    main()
