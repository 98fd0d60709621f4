#!/usr/bin/python3
"""Maps of the averaged fields of `hikiln dem` (averages.h5, Cartesian grid), one PNG each.

Fields: shear stress, strain rate, viscosity, velocity (magnitude and arrows), volume fraction,
pressure and the Drucker-Prager friction m. Cells where `valid` is 0 are masked (volume fraction
is shown wherever particles were seen); the drum outline is drawn.

Colour scales follow fixed conventions so that maps of different runs read alike: volume fraction
0..0.9 and friction m 0..1 always; pressure, shear stress and speed from 0 to the 99th percentile
of the bed rounded up to 1, 2, 2.5 or 5 x 10^k; strain rate and viscosity on a log scale over the
whole decades spanning their 1st..99th percentiles. `--limits name=lo:hi` fixes any of them, e.g.
for a series of runs. Written for Debian's python3 with python3-matplotlib, -numpy and -h5py:

    /usr/bin/python3 plot_fields.py --h5 RUN/averages.h5 --out RUN/plots
"""
import argparse
import math
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.colors as mcolors  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# name -> (title, units, colour map, scale kind); kinds: fixed (lo, hi), "linear", "log"
FIELDS = {
    "shear_stress": ("shear stress q", "Pa", "magma", "linear"),
    "strain_rate": ("strain rate", "1/s", "plasma", "log"),
    "viscosity": ("viscosity q / strain rate", "Pa s", "cividis", "log"),
    "velocity": ("velocity", "m/s", "viridis", "linear"),
    "volume_fraction": ("solids area fraction", "1", "Greys", (0.0, 0.9)),
    "pressure": ("pressure p", "Pa", "inferno", "linear"),
    "friction_m": ("friction m = q / p", "1", "coolwarm", (0.0, 1.0)),
}


def nice_ceiling(value):
    """Smallest of 1, 2, 2.5, 5 x 10^k that is >= value."""
    if not np.isfinite(value) or value <= 0:
        return 1.0
    power = 10.0 ** math.floor(math.log10(value))
    for step in (1.0, 2.0, 2.5, 5.0, 10.0):
        if step * power >= value * (1 - 1e-12):
            return step * power
    return 10.0 * power


def read(path):
    """Cartesian fields, cell edges and run attributes of an averages.h5."""
    with h5py.File(path, "r") as f:
        g = f["cartesian"]
        x0, y0 = g.attrs["origin"]
        dx, dy = g.attrs["spacing"]
        fields = {k: g[k][()] for k in g if isinstance(g[k], h5py.Dataset) and g[k].ndim == 2}
        nx, ny = len(g["x_centres"]), len(g["y_centres"])
        attrs = {k: f.attrs[k] for k in ("drum_radius", "omega", "samples", "average_end")}
        attrs["mu_wall"] = f["wall"].attrs["mu_wall"]
        attrs["slip_percent"] = f["wall"].attrs["slip_percent"]
    x_edges = x0 + dx * np.arange(nx + 1)
    y_edges = y0 + dy * np.arange(ny + 1)
    fields["velocity"] = np.hypot(fields["velocity_x"], fields["velocity_y"])
    return fields, x_edges, y_edges, attrs


def norm_for(name, values, limits):
    """The colour normalisation of one field (see the module docstring)."""
    kind = FIELDS[name][3]
    finite = values.compressed() if np.ma.isMaskedArray(values) else values.ravel()
    finite = finite[np.isfinite(finite)]
    if name in limits:
        lo, hi = limits[name]
    elif isinstance(kind, tuple):
        lo, hi = kind
    elif kind == "linear":
        lo, hi = 0.0, nice_ceiling(np.percentile(finite, 99) if finite.size else 1.0)
    else:
        positive = finite[finite > 0]
        if positive.size == 0:
            lo, hi = 1e-2, 1.0
        else:
            lo = 10.0 ** math.floor(math.log10(np.percentile(positive, 1)))
            hi = 10.0 ** math.ceil(math.log10(np.percentile(positive, 99)))
            hi = max(hi, 10 * lo)
    if kind == "log":
        return mcolors.LogNorm(vmin=lo, vmax=hi)
    return mcolors.Normalize(vmin=lo, vmax=hi)


def draw(name, fields, x_edges, y_edges, attrs, limits, out):
    title, units, cmap, kind = FIELDS[name]
    valid = fields["valid"] != 0
    seen = fields["particles_per_sample"] > 0
    mask = ~seen if name == "volume_fraction" else ~valid
    values = np.ma.masked_where(mask | ~np.isfinite(fields[name]), fields[name])
    if kind == "log":
        values = np.ma.masked_where(values <= 0, values)
    fig, ax = plt.subplots(figsize=(6.2, 5.2))
    mesh = ax.pcolormesh(x_edges, y_edges, values, cmap=cmap,
                         norm=norm_for(name, values, limits), shading="flat")
    fig.colorbar(mesh, ax=ax, label=f"{title} ({units})")
    if name == "velocity":
        xc = 0.5 * (x_edges[1:] + x_edges[:-1])
        yc = 0.5 * (y_edges[1:] + y_edges[:-1])
        xx, yy = np.meshgrid(xc, yc)
        ux = np.ma.masked_where(~valid, fields["velocity_x"])
        uy = np.ma.masked_where(~valid, fields["velocity_y"])
        ax.quiver(xx, yy, ux, uy, color="white", pivot="middle", scale_units="xy",
                  angles="xy", width=0.004)
    radius = float(attrs["drum_radius"])
    ax.add_patch(plt.Circle((0, 0), radius, fill=False, color="black", lw=1.2))
    ax.set_xlim(-1.05 * radius, 1.05 * radius)
    ax.set_ylim(-1.05 * radius, 1.05 * radius)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    rpm = float(attrs["omega"]) * 60 / (2 * math.pi)
    ax.set_title(f"{title}\n{rpm:.2f} rpm, {int(attrs['samples'])} samples to "
                 f"{float(attrs['average_end']):.1f} s, mu_wall {float(attrs['mu_wall']):.3f}",
                 fontsize="medium")
    path = os.path.join(out, f"fields_{name}.png")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    print(f"wrote {path}")


def parse_limits(items):
    limits = {}
    for item in items:
        try:
            name, span = item.split("=", 1)
            lo, hi = (float(v) for v in span.split(":", 1))
        except ValueError:
            sys.exit(f"plot_fields: --limits wants name=lo:hi, got '{item}'")
        if name not in FIELDS:
            sys.exit(f"plot_fields: unknown field '{name}' (known: {', '.join(FIELDS)})")
        limits[name] = (lo, hi)
    return limits


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--h5", required=True, help="averages.h5 of a `hikiln dem` run")
    parser.add_argument("--out", required=True, help="directory for the PNG files")
    parser.add_argument("--limits", nargs="*", default=[], help="fixed scales: name=lo:hi")
    args = parser.parse_args()
    fields, x_edges, y_edges, attrs = read(args.h5)
    os.makedirs(args.out, exist_ok=True)
    limits = parse_limits(args.limits)
    for name in FIELDS:
        draw(name, fields, x_edges, y_edges, attrs, limits, args.out)


if __name__ == "__main__":
    main()
