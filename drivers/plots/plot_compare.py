#!/usr/bin/python3
"""Side-by-side maps of `hikiln compare` (DEM vs continuum on the common grid), one PNG per field.

Each compare_FIELD.png has three panels: the DEM map, the continuum map on the SAME colour scale,
and their difference (continuum - DEM; for strain rate and viscosity log10 of their ratio), with
the drum outline, the spot window and both bed surfaces drawn on every panel. Each map shows its
own valid cells; the difference the cells valid in both. Volume fraction is shown divided by each
run's bed value (the DEM's is an area fraction of discs, the continuum's a volume fraction), on
all cells. compare_surface.png overlays the two surface shapes; compare_maps.png is an overview
of all fields (DEM top row, continuum bottom row). Colour scales: linear fields from the 1st to
the 99th percentile of both maps together (velocities symmetric about 0), strain rate and
viscosity logarithmic over the same percentiles. Written for Debian's python3 with
python3-matplotlib and -numpy:

    /usr/bin/python3 plot_compare.py --dir COMPARE_OUTPUT
"""
import argparse
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.colors as mcolors  # noqa: E402
import matplotlib.patches as mpatches  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# name -> (title, units, colour map, scale kind)
FIELDS = {
    "volume_fraction": ("volume fraction / bed value", "1", "Greys", "fraction"),
    "pressure": ("pressure", "Pa", "inferno", "positive"),
    "shear_stress": ("shear stress", "Pa", "magma", "positive"),
    "viscosity": ("viscosity", "Pa s", "cividis", "log"),
    "strain_rate": ("strain rate", "1/s", "plasma", "log"),
    "velocity_x": ("velocity x", "m/s", "RdBu_r", "symmetric"),
    "velocity_y": ("velocity y", "m/s", "RdBu_r", "symmetric"),
}


def load(directory):
    """comparison.json and the per-cell columns of comparison.csv as [ny][nx] arrays."""
    with open(os.path.join(directory, "comparison.json")) as f:
        meta = json.load(f)
    table = np.genfromtxt(os.path.join(directory, "comparison.csv"), delimiter=",", names=True)
    nx, ny = meta["grid"]["nx"], meta["grid"]["ny"]
    maps = {name: table[name].reshape(ny, nx) for name in table.dtype.names}
    return meta, maps


def limits(kind, values):
    """Colour normalisation shared by the DEM and continuum maps of one field."""
    finite = values[np.isfinite(values)]
    if kind == "fraction":
        return mcolors.Normalize(0.0, 1.1)
    if kind == "log":
        positive = finite[finite > 0]
        if positive.size == 0:
            return mcolors.LogNorm(1e-3, 1.0)
        lo, hi = np.percentile(positive, [1, 99])
        return mcolors.LogNorm(lo, max(hi, lo * 10))
    if finite.size == 0:
        return mcolors.Normalize(0.0, 1.0)
    if kind == "symmetric":
        reach = np.percentile(np.abs(finite), 99) or 1.0
        return mcolors.Normalize(-reach, reach)
    hi = np.percentile(finite, 99)
    return mcolors.Normalize(min(0.0, finite.min()), hi if hi > 0 else 1.0)


def field_maps(meta, maps, name):
    """DEM map, continuum map (masked outside their valid cells) and their difference."""
    dem, cont = maps["dem_" + name].copy(), maps["continuum_" + name].copy()
    dem_valid, cont_valid = maps["dem_valid"] > 0, maps["continuum_valid"] > 0
    if name == "volume_fraction":
        dem /= meta["bed_volume_fraction"]["dem"]
        cont /= meta["bed_volume_fraction"]["continuum"]
        shown = np.isfinite(dem) & np.isfinite(cont) & ((dem > 0.01) | (cont > 0.01))
        return dem, cont, np.where(shown, cont - dem, np.nan)
    dem[~dem_valid] = np.nan
    cont[~cont_valid] = np.nan
    if FIELDS[name][3] == "log":
        with np.errstate(divide="ignore", invalid="ignore"):
            difference = np.log10(cont / dem)
    else:
        difference = cont - dem
    difference[~(dem_valid & cont_valid)] = np.nan
    return dem, cont, difference


def decorate(ax, meta):
    """Drum outline, spot window and both surfaces."""
    cx, cy = meta["grid"]["axis"]
    radius = 0.5 * meta["drum"]["diameter"]
    ax.add_patch(mpatches.Circle((cx, cy), radius, fill=False, color="0.4", lw=0.8))
    spot = meta["spot"]
    w = spot["half_width"]
    ax.add_patch(mpatches.Rectangle((spot["x"] - w, spot["y"] - w), 2 * w, 2 * w, fill=False,
                                    color="lime", lw=1.0))
    surface = meta["surface"]
    x = np.array(surface["x"], dtype=float)
    ax.plot(x, np.array(surface["dem"], dtype=float), "--", color="cyan", lw=1.2, label="DEM")
    ax.plot(x, np.array(surface["continuum"], dtype=float), "-", color="orange", lw=1.2,
            label="continuum")
    ax.set_aspect("equal")
    ax.set_xlim(cx - radius * 1.02, cx + radius * 1.02)
    ax.set_ylim(cy - radius * 1.02, cy + radius * 1.02)
    ax.set_xticks([])
    ax.set_yticks([])


def edges(meta):
    g = meta["grid"]
    return (g["x0"] + g["dx"] * np.arange(g["nx"] + 1), g["y0"] + g["dy"] * np.arange(g["ny"] + 1))


def draw_field(meta, maps, name, out):
    title, units, cmap, kind = FIELDS[name]
    dem, cont, difference = field_maps(meta, maps, name)
    norm = limits(kind, np.concatenate([dem.ravel(), cont.ravel()]))
    xe, ye = edges(meta)
    fig, axes = plt.subplots(1, 3, figsize=(13.5, 4.6), constrained_layout=True)
    for ax, values, who in ((axes[0], dem, "DEM"), (axes[1], cont, "continuum")):
        mesh = ax.pcolormesh(xe, ye, np.ma.masked_invalid(values), cmap=cmap, norm=norm)
        ax.set_title(f"{who}: {title}")
        decorate(ax, meta)
    fig.colorbar(mesh, ax=axes[:2], shrink=0.85, label=f"{title} [{units}]")
    finite = difference[np.isfinite(difference)]
    reach = np.percentile(np.abs(finite), 99) if finite.size else 1.0
    mesh = axes[2].pcolormesh(xe, ye, np.ma.masked_invalid(difference), cmap="coolwarm",
                              norm=mcolors.Normalize(-(reach or 1.0), reach or 1.0))
    label = "log10(continuum / DEM)" if kind == "log" else f"continuum - DEM [{units}]"
    axes[2].set_title(label)
    decorate(axes[2], meta)
    axes[2].legend(loc="upper left", fontsize=7)
    fig.colorbar(mesh, ax=axes[2], shrink=0.85, label=label)
    drum = meta["drum"]
    fig.suptitle(f"{meta['label']}: D = {drum['diameter']:g} m, {drum['rpm']:g} rpm, "
                 f"fill {drum['fill']:g}")
    fig.savefig(os.path.join(out, f"compare_{name}.png"), dpi=110)
    plt.close(fig)


def draw_overview(meta, maps, out):
    fig, axes = plt.subplots(2, len(FIELDS), figsize=(3.2 * len(FIELDS), 6.4),
                             constrained_layout=True)
    xe, ye = edges(meta)
    for col, name in enumerate(FIELDS):
        title, units, cmap, kind = FIELDS[name]
        dem, cont, _ = field_maps(meta, maps, name)
        norm = limits(kind, np.concatenate([dem.ravel(), cont.ravel()]))
        for row, values in enumerate((dem, cont)):
            mesh = axes[row, col].pcolormesh(xe, ye, np.ma.masked_invalid(values), cmap=cmap,
                                             norm=norm)
            decorate(axes[row, col], meta)
        axes[0, col].set_title(title)
        fig.colorbar(mesh, ax=axes[:, col], orientation="horizontal", shrink=0.9,
                     label=units)
    axes[0, 0].set_ylabel("DEM")
    axes[1, 0].set_ylabel("continuum")
    fig.savefig(os.path.join(out, "compare_maps.png"), dpi=90)
    plt.close(fig)


def draw_surface(meta, out):
    surface = meta["surface"]
    x = np.array(surface["x"], dtype=float)
    cx, cy = meta["grid"]["axis"]
    radius = 0.5 * meta["drum"]["diameter"]
    fig, ax = plt.subplots(figsize=(6.5, 4.2), constrained_layout=True)
    arc = np.linspace(-radius, radius, 200)
    ax.plot(cx + arc, cy - np.sqrt(radius**2 - arc**2), color="0.5", lw=1, label="shell")
    angles = surface["angle_deg"]
    ax.plot(x, np.array(surface["dem"], dtype=float), "o--", ms=3,
            label=f"DEM ({angles['dem'] or float('nan'):.1f} deg)")
    ax.plot(x, np.array(surface["continuum"], dtype=float), "s-", ms=3,
            label=f"continuum ({angles['continuum'] or float('nan'):.1f} deg)")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("bed surface height y [m]")
    rms = surface["rms_difference"]
    ax.set_title(f"{meta['label']}: bed surface (rms difference "
                 f"{rms if rms is not None else float('nan'):.3f} m)")
    ax.set_aspect("equal")
    ax.legend(fontsize=8)
    fig.savefig(os.path.join(out, "compare_surface.png"), dpi=110)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--dir", required=True, help="hikiln compare output directory")
    parser.add_argument("--out", help="where the PNGs go (default: --dir)")
    args = parser.parse_args()
    out = args.out or args.dir
    os.makedirs(out, exist_ok=True)
    meta, maps = load(args.dir)
    for name in FIELDS:
        draw_field(meta, maps, name, out)
    draw_overview(meta, maps, out)
    draw_surface(meta, out)
    print(f"wrote {len(FIELDS) + 2} PNGs to {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
