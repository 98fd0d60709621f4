#!/usr/bin/python3
"""Particle temperature maps and the thermal mixing curve of a heated `hikiln dem` run.

Reads the particle snapshots (snapshots/particles_*.h5, dataset `temperature`: the mean
temperature of each particle) and heat_timeseries.csv of a run directory and writes:

- temperature_NNNN.png: every snapshot's particles as discs coloured by temperature (one PNG per
  snapshot, NNNN counting snapshots), on one colour scale: the initial minimum..maximum;
- temperature_maps.png: up to six snapshots side by side, evenly spread over the run;
- heat_mixing.png: the mixing measure std(T_i) / std(T_i at the start) against rotation time (log
  scale, with the equilibrium threshold of summary.json) and the min / mean / max temperature.

Written for Debian's python3 with python3-matplotlib, -numpy and -h5py:

    /usr/bin/python3 plot_temperature.py --run RUN --out RUN/plots --drum-radius 1.0
"""
import argparse
import csv
import glob
import json
import math
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.colors as mcolors  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import EllipseCollection  # noqa: E402


def read_series(run):
    """Columns of heat_timeseries.csv as arrays."""
    path = os.path.join(run, "heat_timeseries.csv")
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_temperature: {path} has no rows")
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def read_snapshots(run):
    """(time, positions, radii, temperatures) of every snapshot holding temperatures."""
    out = []
    for path in sorted(glob.glob(os.path.join(run, "snapshots", "particles_*.h5"))):
        with h5py.File(path, "r") as f:
            groups = [f[k] for k in f if k.startswith("step_")]
            if not groups or "temperature" not in groups[0]:
                continue
            group = groups[0]
            out.append((float(f.attrs["time"]), group["position"][()], group["radius"][()],
                        group["temperature"][()]))
    return out


def draw_particles(ax, position, radius, temperature, norm, cmap, drum_radius, ylim):
    """Discs at their true size, coloured by temperature, inside the drum outline."""
    d = 2 * radius
    discs = EllipseCollection(d, d, np.zeros_like(d), units="xy", offsets=position,
                              offset_transform=ax.transData, cmap=cmap, norm=norm)
    discs.set_array(temperature)
    ax.add_collection(discs)
    ax.add_patch(plt.Circle((0, 0), drum_radius, fill=False, color="black", lw=1.0))
    ax.set_xlim(-1.02 * drum_radius, 1.02 * drum_radius)
    ax.set_ylim(*ylim)
    ax.set_aspect("equal")
    return discs


def rotation_time(series, time):
    """Rotation time of a snapshot at run time `time` (the series gives the offset)."""
    return max(0.0, time - (series["time"][0] - series["rotation_time"][0]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--run", required=True, help="output directory of a heated `hikiln dem`")
    parser.add_argument("--out", required=True, help="directory for the PNG files")
    parser.add_argument("--drum-radius", type=float, required=True, help="drum radius (m)")
    args = parser.parse_args()
    series = read_series(args.run)
    snapshots = read_snapshots(args.run)
    os.makedirs(args.out, exist_ok=True)
    threshold = None
    summary_path = os.path.join(args.run, "summary.json")
    if os.path.exists(summary_path):
        with open(summary_path) as f:
            threshold = json.load(f).get("heat", {}).get("equilibrium_threshold")
    R = args.drum_radius

    if snapshots:
        t0 = snapshots[0][3]
        lo, hi = float(np.min(t0)), float(np.max(t0))
        if hi - lo < 1e-9 * max(1.0, abs(hi)):
            lo, hi = lo - 1.0, hi + 1.0
        norm = mcolors.Normalize(vmin=lo, vmax=hi)
        cmap = "coolwarm"
        top = max(float(np.max(p[:, 1] + r)) for _, p, r, _ in snapshots)
        ylim = (-1.02 * R, min(1.02 * R, top + 0.08 * R))
        for n, (time, position, radius, temperature) in enumerate(snapshots):
            fig, ax = plt.subplots(figsize=(7.0, 2.0 + 5.0 * (ylim[1] - ylim[0]) / (2 * R)))
            discs = draw_particles(ax, position, radius, temperature, norm, cmap, R, ylim)
            fig.colorbar(discs, ax=ax, label="particle mean temperature (K)")
            ax.set_xlabel("x (m)")
            ax.set_ylabel("y (m)")
            ax.set_title(f"rotation time {rotation_time(series, time):.1f} s, "
                         f"std {np.std(temperature):.1f} K", fontsize="medium")
            path = os.path.join(args.out, f"temperature_{n:04d}.png")
            fig.tight_layout()
            fig.savefig(path, dpi=110)
            plt.close(fig)
        print(f"wrote {len(snapshots)} temperature maps to {args.out}")

        chosen = sorted(set(np.linspace(0, len(snapshots) - 1, min(6, len(snapshots)))
                            .round().astype(int)))
        cols = min(3, len(chosen))
        rows = math.ceil(len(chosen) / cols)
        height = 0.6 + 3.6 * (ylim[1] - ylim[0]) / (2 * R)
        fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, height * rows + 0.8),
                                 squeeze=False)
        for ax in axes.ravel()[len(chosen):]:
            ax.axis("off")
        for ax, n in zip(axes.ravel(), chosen):
            time, position, radius, temperature = snapshots[n]
            discs = draw_particles(ax, position, radius, temperature, norm, cmap, R, ylim)
            ax.set_title(f"{rotation_time(series, time):.1f} s", fontsize="medium")
            ax.set_xticks([])
            ax.set_yticks([])
        fig.colorbar(discs, ax=axes.ravel().tolist(), label="temperature (K)", shrink=0.8)
        path = os.path.join(args.out, "temperature_maps.png")
        fig.savefig(path, dpi=110)
        plt.close(fig)
        print(f"wrote {path}")

    fig, (top_ax, bottom_ax) = plt.subplots(2, 1, figsize=(6.4, 6.4), sharex=True)
    t = series["rotation_time"]
    mixing = series["mixing"]
    shown = np.isfinite(mixing) & (mixing > 0)
    top_ax.semilogy(t[shown], mixing[shown], color="C0")
    if threshold:
        top_ax.axhline(threshold, color="grey", ls="--", lw=1, label=f"threshold {threshold}")
        top_ax.legend()
    top_ax.set_ylabel("mixing: std(T) / std(T) at start")
    top_ax.grid(True, which="both", alpha=0.3)
    bottom_ax.plot(t, series["max_temperature_K"], color="C3", label="max")
    bottom_ax.plot(t, series["mean_temperature_K"], color="k", label="mean (heat content)")
    bottom_ax.plot(t, series["min_temperature_K"], color="C0", label="min")
    bottom_ax.set_xlabel("rotation time (s)")
    bottom_ax.set_ylabel("particle temperature (K)")
    bottom_ax.legend()
    bottom_ax.grid(True, alpha=0.3)
    path = os.path.join(args.out, "heat_mixing.png")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
