#!/usr/bin/python3
"""Plots of `hikiln fit-diffusivity` from its output directory (fit.csv, mixing_layer.csv, maps.h5):

- fit_misfit.png: both misfits against the candidate alpha_eff (log axis), the best marked;
- mixing_layer.png: the mixed fraction (bed share with 0.1 < theta < 0.9) against rotation time,
  DEM and every candidate, the best one bold;
- temperature_maps.png: DEM (top) and continuum at the best alpha_eff (bottom) on the comparison
  blocks at each snapshot time, one colour scale (the initial cold..hot), non-bed blocks blank.

Written for Debian's python3 with python3-matplotlib, -numpy and -h5py:

    /usr/bin/python3 plot_fit_diffusivity.py --run FIT_DIR
"""
import argparse
import csv
import json
import os

import h5py
import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def plot_misfit(run, fit, best):
    fig, ax = plt.subplots(figsize=(5.5, 4))
    a = fit["alpha_eff"]
    ax.semilogx(a, fit["misfit_mixed_fraction"], "o-", label="mixed fraction (fitted)")
    ax.semilogx(a, fit["misfit_theta_rms"], "s--", label="theta rms (maps)")
    ax.axvline(best, color="k", lw=0.8, ls=":", label=f"best {best:.3g} m$^2$/s")
    ax.set_xlabel("alpha_eff (m$^2$/s)")
    ax.set_ylabel("misfit")
    ax.legend(fontsize=8)
    ax.set_title("continuum vs DEM thermal mixing")
    fig.tight_layout()
    fig.savefig(os.path.join(run, "fit_misfit.png"), dpi=120)
    plt.close(fig)


def plot_layer(run, layer, best_index):
    fig, ax = plt.subplots(figsize=(5.5, 4))
    t = layer["time"]
    columns = [k for k in layer if k.startswith("alpha_")]
    for i, k in enumerate(columns):
        bold = i == best_index
        ax.plot(t, layer[k], lw=2.2 if bold else 0.8, alpha=1.0 if bold else 0.6,
                label=k.replace("alpha_", "alpha ") if bold or i in (0, len(columns) - 1) else None)
    ax.plot(t, layer["dem"], "ko-", lw=1.5, label="DEM")
    ax.set_xlabel("rotation time (s)")
    ax.set_ylabel("mixed fraction of the bed")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(run, "mixing_layer.png"), dpi=120)
    plt.close(fig)


def plot_maps(run, best_index):
    with h5py.File(os.path.join(run, "maps.h5"), "r") as f:
        x, y, times = f["x_centres"][()], f["y_centres"][()], f["times"][()]
        dem_t, dem_bed = f["dem_temperature"][()], f["dem_bed_fraction"][()]
        con_t = f["continuum_temperature"][best_index]
        con_bed = f["continuum_bed_fraction"][best_index]
        cold, hot = f.attrs["cold_K"], f.attrs["hot_K"]
        dem_thr, con_thr = f.attrs["dem_bed_threshold"], f.attrs["continuum_bed_threshold"]
        radius = f.attrs["drum_radius"]
        alpha = f["alpha_eff"][best_index]
    n = len(times)
    fig, axes = plt.subplots(2, n, figsize=(2.2 * n + 1, 4.8), squeeze=False)
    extent = [x[0] - 0.5 * (x[1] - x[0]), x[-1] + 0.5 * (x[1] - x[0]),
              y[0] - 0.5 * (y[1] - y[0]), y[-1] + 0.5 * (y[1] - y[0])]
    image = None
    for k in range(n):
        for row, (T, bed, thr, name) in enumerate([(dem_t[k], dem_bed[k], dem_thr, "DEM"),
                                                    (con_t[k], con_bed[k], con_thr,
                                                     f"continuum {alpha:.2g}")]):
            ax = axes[row][k]
            shown = np.where(bed >= thr, T, np.nan)
            image = ax.imshow(shown, origin="lower", extent=extent, cmap="coolwarm",
                              vmin=min(cold, hot), vmax=max(cold, hot))
            ax.add_patch(plt.Circle((0, 0), radius, fill=False, color="k", lw=0.8))
            ax.set_xlim(-radius, radius)
            ax.set_ylim(-radius, 0.3 * radius)
            ax.set_aspect("equal")
            ax.set_xticks([])
            ax.set_yticks([])
            if row == 0:
                ax.set_title(f"t = {times[k]:.0f} s", fontsize=9)
            if k == 0:
                ax.set_ylabel(name, fontsize=9)
    fig.colorbar(image, ax=axes, shrink=0.8, label="T (K)")
    fig.savefig(os.path.join(run, "temperature_maps.png"), dpi=110)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--run", required=True, help="output directory of hikiln fit-diffusivity")
    args = parser.parse_args()
    fit = read_csv(os.path.join(args.run, "fit.csv"))
    layer = read_csv(os.path.join(args.run, "mixing_layer.csv"))
    with open(os.path.join(args.run, "fit.json")) as f:
        summary = json.load(f)
    best = summary["best_alpha_eff"]
    best_index = int(np.argmin(np.abs(np.log(fit["alpha_eff"] / best))))
    plot_misfit(args.run, fit, best)
    plot_layer(args.run, layer, best_index)
    plot_maps(args.run, best_index)


if __name__ == "__main__":
    main()
