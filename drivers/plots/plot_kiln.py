#!/usr/bin/python3
"""Pictures of a `hikiln kiln` run (physics.md 7).

Reads the run directory (fields_NNNN.h5 with 3D cell fields [nz][ny][nx], timeseries.csv,
case.resolved.yaml) and writes:

- kiln_holdup.png: solids hold-up in the kiln, solids fed and discharged (cumulative) against
  time, and the mass balance error (in - out - accumulation - dam) against time;
- kiln_surface_tNNN.png: the bed surface (the iso-surface of solids volume fraction at half
  the packed value, by marching cubes from scikit-image) coloured by axial velocity, one per
  snapshot time (time.snapshots of the case; the output nearest to each), and
  kiln_surfaces.png with all of them on one colour scale;
- kiln_midplane.png: the vertical axial mid-plane (x = 0) of each snapshot, solids fraction as
  colour and the in-plane velocity (axial, vertical) as arrows;
- kiln_bed_depth.csv / .png: the axial bed-depth profile of each snapshot, the depth of a flat
  bed holding each cross-section's solids (phi_max: the largest phi at the start);
- with kramers.average_from set: kiln_kramers.png, the steady-state mean bed depth along the
  kiln against Kramers-Croockewit (kramers_croockewit.csv and summary.json of the run);
- with the energy equation on (heat.enabled): kiln_heat.png, the bed's mean temperature and the
  heat balance error against time, and kiln_bed_temperature.csv / .png, the bed's mean
  temperature per cross-section (solids-weighted) along the kiln at each snapshot.

Written for Debian's python3 with python3-matplotlib, -numpy, -h5py and -skimage:

    /usr/bin/python3 plot_kiln.py --run RUN --out RUN/plots
"""
import argparse
import csv
import glob
import json
import os
import re
import sys

import h5py
import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.colors as mcolors  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402


def read_series(run):
    path = os.path.join(run, "timeseries.csv")
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_kiln: {path} has no rows")
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def snapshot_times(run):
    """time.snapshots of the resolved case (a flow list of numbers), or [] when absent."""
    path = os.path.join(run, "case.resolved.yaml")
    if not os.path.exists(path):
        return []
    text = open(path).read()
    match = re.search(r"snapshots:\s*\[([^\]]*)\]", text)
    if not match:
        return []
    return [float(v) for v in match.group(1).split(",") if v.strip()]


def read_outputs(run):
    """(time, path) of every field output, by time."""
    out = []
    for path in sorted(glob.glob(os.path.join(run, "fields_*.h5"))):
        with h5py.File(path, "r") as f:
            out.append((float(f.attrs["time"]), path))
    if not out:
        sys.exit(f"plot_kiln: no fields_*.h5 in {run}")
    return sorted(out)


def load(path):
    with h5py.File(path, "r") as f:
        fields = {k: f["fields"][k][()] for k in f["fields"]}
    return fields


def geometry(path):
    """Grid origin and cell size (x, y, z) from a field output's root attributes."""
    with h5py.File(path, "r") as f:
        origin = [float(f.attrs[f"origin_{a}"]) for a in "xyz"]
        spacing = [float(f.attrs[f"spacing_{a}"]) for a in "xyz"]
    return np.array(origin), np.array(spacing)


def kiln_radius(run):
    """kiln.diameter / 2 from the resolved case."""
    text = open(os.path.join(run, "case.resolved.yaml")).read()
    match = re.search(r"diameter:\s*([0-9.eE+-]+)", text)
    if not match:
        sys.exit("plot_kiln: no kiln.diameter in case.resolved.yaml")
    return 0.5 * float(match.group(1))


def segment_depth(area, radius):
    """Depth of the circular segment of the given area (bisection)."""
    lo, hi = 0.0, 2.0 * radius
    for _ in range(100):
        h = 0.5 * (lo + hi)
        theta = 2.0 * np.arccos(1.0 - h / radius)
        if radius * radius * (theta - np.sin(theta)) / 2.0 < area:
            lo = h
        else:
            hi = h
    return 0.5 * (lo + hi)


def bed_depth(fields, spacing, phi_max, radius):
    """Per cross-section (along z): the depth of a flat bed of its bed area. The area counts the
    cells' true open volume (fluid_volume; older runs: the capacity, which the shell's cut cells
    raise to half a cell), as hikiln's own bed profile does (drivers/cfd/KilnBedProfile.cpp)."""
    volume = fields.get("fluid_volume", fields["capacity"])
    solids = (fields["volume_fraction"] * volume).sum(axis=(1, 2))
    area = solids * spacing[0] * spacing[1] / phi_max
    return np.array([segment_depth(a, radius) for a in area])


def bed_temperature(fields):
    """Per cross-section (along z): the solids-weighted mean temperature (NaN without solids)."""
    solids = fields["volume_fraction"] * fields["capacity"]
    weight = solids.sum(axis=(1, 2))
    heat = (solids * fields["temperature"]).sum(axis=(1, 2))
    return np.where(weight > 0, heat / np.maximum(weight, 1e-300), np.nan)


def axial_profiles(out, name, z, times, profiles, column, ylabel, title):
    """name.csv (z and one column per snapshot) and name.png of profiles along the kiln."""
    with open(os.path.join(out, f"{name}.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["z_m"] + [f"{column}_t{time:g}" for time in times])
        for k in range(len(z)):
            writer.writerow([f"{z[k]:.6g}"] + [f"{p[k]:.6g}" for p in profiles])
    fig, ax = plt.subplots(figsize=(8, 4))
    for time, p in zip(times, profiles):
        ax.plot(z, p, label=f"t = {time:g} s")
    ax.set_xlabel("z (m), inlet at 0")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, f"{name}.png"), dpi=120)
    plt.close(fig)


def surface(fields, level, origin, spacing):
    """Triangles (N x 3 x 3, x y z in m) of the iso-surface phi = level and the axial velocity
    at their centroids (nearest cell)."""
    from skimage.measure import marching_cubes

    phi = fields["volume_fraction"]  # [nz][ny][nx]
    # pad with empty cells so the surface closes at the ends and the shell
    padded = np.pad(phi, 1, mode="constant", constant_values=0.0)
    verts, faces, _, _ = marching_cubes(padded, level=level)
    verts -= 1.0  # index space of the unpadded cell centres (k, j, i)
    xyz = np.stack([origin[0] + (verts[:, 2] + 0.5) * spacing[0],
                    origin[1] + (verts[:, 1] + 0.5) * spacing[1],
                    origin[2] + (verts[:, 0] + 0.5) * spacing[2]], axis=1)
    tris = xyz[faces]
    centre = verts[faces].mean(axis=1)
    nz, ny, nx = phi.shape
    k = np.clip(np.rint(centre[:, 0]).astype(int), 0, nz - 1)
    j = np.clip(np.rint(centre[:, 1]).astype(int), 0, ny - 1)
    i = np.clip(np.rint(centre[:, 2]).astype(int), 0, nx - 1)
    return tris, fields["axial_velocity"][k, j, i]


def draw_surface(ax, tris, colour, norm, cmap, extent, title):
    # the kiln axis (z) drawn horizontally: plot (z, x, y)
    poly = Poly3DCollection(tris[:, :, [2, 0, 1]], linewidths=0.0)
    poly.set_facecolor(cmap(norm(colour)))
    ax.add_collection3d(poly)
    ax.set_xlim(extent[2])
    ax.set_ylim(extent[0])
    ax.set_zlim(extent[1])
    ax.set_box_aspect((extent[2][1] - extent[2][0], extent[0][1] - extent[0][0],
                       extent[1][1] - extent[1][0]))
    ax.view_init(elev=25, azim=-60)
    ax.set_xlabel("z (m)")
    ax.set_ylabel("x (m)")
    ax.set_zlabel("y (m)")
    ax.set_title(title)


def plot_kramers(run, out):
    """kiln_kramers.png from the run's kramers_croockewit.csv (nothing without one)."""
    path = os.path.join(run, "kramers_croockewit.csv")
    if not os.path.exists(path):
        return
    with open(os.path.join(run, "summary.json")) as f:
        kc = json.load(f).get("kramers_croockewit", {})
    if kc.get("max_rel_deviation") is None:  # a csv left by an earlier run of the directory
        return
    with open(path) as f:
        rows = list(csv.DictReader(f))
    d = np.array([float(r["distance_from_discharge_m"]) for r in rows])
    fig, ax = plt.subplots(figsize=(7, 4), layout="constrained")
    depth = np.array([float(r["depth_m"]) for r in rows])
    counted = np.array([r["compared"] == "1" for r in rows])
    ax.plot(d[counted], depth[counted], "o", color="C0", label="hikiln (steady-state mean)")
    ax.plot(d[~counted], depth[~counted], "o", mfc="none", color="C0",
            label="hikiln, not compared (start, inlet)")
    ax.plot(d, [float(r["depth_kramers_m"]) for r in rows], "-", color="C1",
            label=f"Kramers-Croockewit, beta = {kc['repose_angle_deg']:.1f} deg (measured)")
    if kc.get("uniform_depth_m") is not None:
        ax.axhline(kc["uniform_depth_m"], ls=":", color="grey", label="uniform depth")
    ax.set_xlabel("distance from the discharge end (m)")
    ax.set_ylabel("bed depth (m)")
    ax.set_ylim(bottom=0.0)
    window = kc["window_s"]
    ax.set_title(f"Bed depth at steady state, t = {window[0]:g}-{window[1]:g} s: largest "
                 f"deviation {100 * kc['max_rel_deviation']:.1f} %", fontsize=10)
    ax.legend(fontsize=8)
    fig.savefig(os.path.join(out, "kiln_kramers.png"), dpi=120)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--run", required=True, help="hikiln kiln output directory")
    parser.add_argument("--out", required=True, help="directory for the PNG files")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)

    s = read_series(args.run)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    top.plot(s["time"], s["holdup_m3"], label="hold-up")
    top.plot(s["time"], s["solids_in_m3"], label="fed (cumulative)")
    top.plot(s["time"], s["solids_out_m3"], label="discharged (cumulative)")
    if np.any(s["dam_displaced_m3"] > 0):
        top.plot(s["time"], s["dam_displaced_m3"], label="taken by the dam ring")
    top.set_ylabel("solids volume (m$^3$)")
    top.legend()
    top.set_title("Kiln solids hold-up and mass balance")
    later = s["time"] > 0  # the balance is exactly 0 before the first step
    bottom.semilogy(s["time"][later], np.maximum(np.abs(s["balance_error_m3"][later]), 1e-300))
    bottom.set_ylabel("|in - out - accumulation - dam| (m$^3$)")
    bottom.set_xlabel("time (s)")
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "kiln_holdup.png"), dpi=120)
    plt.close(fig)

    if "heat_J" in s:
        fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
        top.plot(s["time"], s["bed_mean_temperature_K"])
        top.set_ylabel("bed mean temperature (K)")
        top.set_title("Kiln heat: bed temperature and heat balance")
        bottom.semilogy(s["time"][later],
                        np.maximum(np.abs(s["heat_balance_error_J"][later]), 1e-300),
                        label="|in - out + shell - accumulation - dam|")
        for key, label in (("heat_from_shell_J", "from the shell (cumulative)"),
                           ("heat_in_J", "in at the inlet (cumulative)")):
            bottom.semilogy(s["time"][later], np.maximum(s[key][later], 1e-300), label=label)
        bottom.set_ylabel("heat (J)")
        bottom.set_xlabel("time (s)")
        bottom.legend()
        fig.tight_layout()
        fig.savefig(os.path.join(args.out, "kiln_heat.png"), dpi=120)
        plt.close(fig)

    outputs = read_outputs(args.run)
    wanted = snapshot_times(args.run) or [t for t, _ in outputs[:: max(1, len(outputs) // 6)]]
    chosen = []
    for t in wanted:
        time, path = min(outputs, key=lambda o: abs(o[0] - t))
        if (time, path) not in chosen:
            chosen.append((time, path))
    origin, spacing = geometry(outputs[0][1])
    first = load(outputs[0][1])
    phi_max = float(np.max(first["volume_fraction"]))  # the packed bed at rest
    level = 0.5 * phi_max
    nz, ny, nx = first["volume_fraction"].shape
    extent = [(origin[a], origin[a] + n * spacing[a]) for a, n in enumerate((nx, ny, nz))]

    surfaces = []
    for time, path in chosen:
        fields = load(path)
        if np.max(fields["volume_fraction"]) < level:
            continue
        tris, axial = surface(fields, level, origin, spacing)
        surfaces.append((time, fields, tris, axial))
    if not surfaces:
        sys.exit("plot_kiln: no output holds a bed")
    vmax = max(np.max(np.abs(a)) for _, _, _, a in surfaces) or 1.0
    norm = mcolors.Normalize(-vmax, vmax)
    cmap = plt.get_cmap("coolwarm")
    cols = min(3, len(surfaces))
    rows = (len(surfaces) + cols - 1) // cols
    grid = plt.figure(figsize=(6 * cols, 4.5 * rows))
    for n, (time, _, tris, axial) in enumerate(surfaces):
        title = f"bed surface at t = {time:.1f} s"
        one = plt.figure(figsize=(9, 5))
        ax = one.add_subplot(projection="3d")
        draw_surface(ax, tris, axial, norm, cmap, extent, title)
        one.colorbar(plt.cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax, shrink=0.6,
                     label="axial velocity (m/s)")
        one.savefig(os.path.join(args.out, f"kiln_surface_t{time:05.1f}.png"), dpi=120)
        plt.close(one)
        draw_surface(grid.add_subplot(rows, cols, n + 1, projection="3d"), tris, axial, norm, cmap,
                     extent, title)
    grid.colorbar(plt.cm.ScalarMappable(norm=norm, cmap=cmap), ax=grid.axes, shrink=0.5,
                  label="axial velocity (m/s)")
    grid.savefig(os.path.join(args.out, "kiln_surfaces.png"), dpi=110)
    plt.close(grid)

    # equal axes: size the figure to the slice's length over its height
    ratio = (extent[2][1] - extent[2][0]) / (extent[1][1] - extent[1][0])
    radius = kiln_radius(args.run)
    z = origin[2] + (np.arange(nz) + 0.5) * spacing[2]
    times = [time for time, _, _, _ in surfaces]
    depths = [bed_depth(fields, spacing, phi_max, radius) for _, fields, _, _ in surfaces]
    axial_profiles(args.out, "kiln_bed_depth", z, times, depths, "depth_m", "bed depth (m)",
                   "Axial bed-depth profile (flat bed of the same solids per cross-section)")
    if "temperature" in first:
        axial_profiles(args.out, "kiln_bed_temperature", z, times,
                       [bed_temperature(fields) for _, fields, _, _ in surfaces], "bed_T_K",
                       "bed mean temperature (K)",
                       "Bed temperature along the kiln (solids-weighted, per cross-section)")

    plot_kramers(args.run, args.out)

    fig, axes = plt.subplots(len(surfaces), 1, figsize=(1.8 + 1.5 * ratio, 1.9 * len(surfaces)),
                             squeeze=False, layout="constrained")
    i0 = nx // 2
    y = origin[1] + (np.arange(ny) + 0.5) * spacing[1]
    for ax, (time, fields, _, _) in zip(axes[:, 0], surfaces):
        phi = fields["volume_fraction"][:, :, i0].T  # [y][z]
        image = ax.pcolormesh(z, y, phi, shading="nearest", cmap="YlOrBr",
                              vmin=0.0, vmax=2.0 * level)
        vel = fields["velocity"][:, :, i0, :]  # [z][y][3]
        step = max(1, nz // 24)
        ax.quiver(z[::step], y[::step], vel[::step, ::step, 2].T, vel[::step, ::step, 1].T,
                  scale_units="xy", angles="xy", width=0.002)
        ax.set_aspect("equal")
        ax.set_ylabel("y (m)")
        ax.set_title(f"axial mid-plane x = 0, t = {time:.1f} s", fontsize=9)
        fig.colorbar(image, ax=ax, label="solids fraction")
    axes[-1, 0].set_xlabel("z (m), inlet at 0")
    fig.savefig(os.path.join(args.out, "kiln_midplane.png"), dpi=110)
    plt.close(fig)
    print(f"plot_kiln: {len(surfaces)} snapshots rendered in {args.out}")


if __name__ == "__main__":
    main()
