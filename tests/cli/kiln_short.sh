#!/usr/bin/env bash
# `hikiln kiln` end to end on a coarse copy of the shipped 15 m kiln (12 x 12 x 6 cells, 0.6 s,
# the dam ring put in at 0.3 s):
# (1) summary.json: the solids balance (in - out - accumulation - dam) closes to 1e-8 of the
#     throughput, solids came in and went out, the dam took some, phi stayed in [0, phi_max];
# (2) timeseries.csv has the initial row and one per output, its hold-up matches the balance;
# (3) the 3D fields are in the HDF5 outputs and fields.xmf, with the shape [nz][ny][nx];
# (4) bad input: overlapping inlet patches are refused naming the rule;
# (5) the hot-shell case beside CASE (kiln-15m-hot-shell.yaml), as coarse, 0.4 s, a 0.1 s tracer
#     pulse: the heat balance (in - out + shell - accumulation) closes to 1e-10 of the heat
#     exchanged, the shell heated the bed, the tracer taken in is the solids fed during the pulse,
#     the temperature and tracer fields are in the HDF5 outputs;
# (6) the Kramers-Croockewit comparison on kramers-inclined.yaml beside CASE, 1 s on 12 x 12 x 10
#     cells averaged from 0.4 s (not steady: this checks the plumbing; the long test asserts the
#     physics): four outputs averaged, a repose angle and a profile for every section upstream
#     of the start, the window's feed as timeseries.csv has it, a tracer pulse conserved; an average_from past the end is refused.
# Usage: kiln_short.sh HIKILN CASE WORKDIR
set -euo pipefail
hikiln=$1 case=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
"$hikiln" -q --threads 1 kiln "$case" -o "$work/run" --set grid.cells_across=12 \
  --set grid.cells_along=6 --set time.duration=0.6 --set time.output_interval=0.2 \
  --set dam.on_at=0.3 --set "time.snapshots=[0.1]"
/usr/bin/python3 - "$work/run" <<'PY'
import csv, json, sys, h5py
run = sys.argv[1]
s = json.load(open(f"{run}/summary.json"))
def check(ok, what):
    if not ok:
        sys.exit(f"kiln_short: {what} (summary: {json.dumps(s, indent=1)})")
check(s["balance_error_of_throughput"] < 1e-8, "solids balance does not close to 1e-8")
check(s["balance_error_worst_step_of_throughput"] < 1e-8, "a step's balance is off")
check(s["solids_in_m3"] > 0 and s["solids_out_m3"] > 0, "no solids came in or went out")
check(s["dam_displaced_m3"] > 0, "the dam ring took no solids")
check(s["phi_min"] >= -1e-12 and s["phi_max"] <= 0.57 + 1e-12, "phi left [0, phi_max]")
rows = list(csv.DictReader(open(f"{run}/timeseries.csv")))
times = [float(r["time"]) for r in rows]
check(len(rows) == 5 and abs(times[-1] - 0.6) < 1e-9, f"timeseries times {times}")
first, last = rows[0], rows[-1]
change = float(last["holdup_m3"]) - float(first["holdup_m3"])
budget = (float(last["solids_in_m3"]) - float(last["solids_out_m3"])
          - float(last["dam_displaced_m3"]))
# the CSV holds about 10 significant digits: compare to that of the hold-up
check(abs(change - budget) <= 1e-8 * float(first["holdup_m3"]),
      f"hold-up change {change} vs in - out - dam {budget}")
with h5py.File(f"{run}/fields_0004.h5", "r") as f:
    phi = f["fields/volume_fraction"][()]
    vel = f["fields/velocity"][()]
    check(phi.shape == (6, 12, 12) and vel.shape == (6, 12, 12, 3), f"shapes {phi.shape} {vel.shape}")
xmf = open(f"{run}/fields.xmf").read()
check(xmf.count('GridType="Uniform"') == 5 and "axial_velocity" in xmf,
      "fields.xmf lacks the outputs")
print("kiln_short: balance", s["balance_error_of_throughput"], "of the throughput; in",
      s["solids_in_m3"], "out", s["solids_out_m3"], "dam", s["dam_displaced_m3"], "m3")
PY
if "$hikiln" -q kiln "$case" -o "$work/bad" --set feed.area_fraction=0.7 2> "$work/bad.err"; then
  echo "kiln_short: overlapping patches were accepted"; exit 1
fi
grep -q "feed and air patches not overlapping" "$work/bad.err" || { cat "$work/bad.err"; exit 1; }
hot="$(dirname "$case")/kiln-15m-hot-shell.yaml"
"$hikiln" -q --threads 1 kiln "$hot" -o "$work/hot" --set grid.cells_across=12 \
  --set grid.cells_along=6 --set time.duration=0.4 --set time.output_interval=0.2 \
  --set "time.snapshots=[]" --set tracer.pulse_duration=0.1
/usr/bin/python3 - "$work/hot" <<'PY'
import csv, json, sys, h5py
run = sys.argv[1]
s = json.load(open(f"{run}/summary.json"))
h, t = s["heat"], s["tracer"]
def check(ok, what):
    if not ok:
        sys.exit(f"kiln_short (hot shell): {what} (summary: {json.dumps(s, indent=1)})")
check(h["balance_error_of_exchanged"] < 1e-10, "the heat balance does not close to 1e-10")
check(h["balance_error_worst_step_of_exchanged"] < 1e-8, "a step's heat balance is off")
check(h["from_shell_J"] > 0 and h["in_J"] > 0 and h["out_J"] > 0, "no heat from the shell / ends")
check(300 < h["bed_mean_temperature_K"] < 1000, "the bed was not heated, or overheated")
rows = list(csv.DictReader(open(f"{run}/timeseries.csv")))
fed = [float(r["solids_in_m3"]) for r in rows]  # at 0, 0.2, 0.4 s; the feed is steady
check(abs(t["injected_m3"] - fed[1] / 2) <= 1e-6 * fed[1], f"tracer in {t['injected_m3']} vs fed {fed}")
with h5py.File(f"{run}/fields_0002.h5", "r") as f:
    T = f["fields/temperature"][()]
    check(T.shape == (6, 12, 12) and T.min() >= 300 - 1e-9 and T.max() <= 1000 + 1e-9,
          f"temperature field {T.shape} [{T.min()}, {T.max()}]")
    check("tracer" in f["fields"], "no tracer field")
print("kiln_short (hot shell): heat balance", h["balance_error_of_exchanged"], "of the exchanged;",
      "from the shell", h["from_shell_J"], "J; bed mean", h["bed_mean_temperature_K"], "K")
PY
kc="$(dirname "$case")/kramers-inclined.yaml"
"$hikiln" -q --threads 1 kiln "$kc" -o "$work/kramers" --set grid.cells_across=12 \
  --set grid.cells_along=10 --set time.duration=1.0 --set time.output_interval=0.2 \
  --set kramers.average_from=0.4 --set tracer.pulse_start=0.2 --set tracer.pulse_duration=0.2
/usr/bin/python3 - "$work/kramers" <<'PY'
import csv, json, math, sys
run = sys.argv[1]
k = json.load(open(f"{run}/summary.json"))["kramers_croockewit"]
def check(ok, what):
    if not ok:
        sys.exit(f"kiln_short (Kramers-Croockewit): {what} ({json.dumps(k, indent=1)})")
check(k["samples"] == 4 and k["window_s"] == [0.4, 1.0], "the window is not the four outputs")
check(5 < k["repose_angle_deg"] < 60, "no plausible repose angle")
# the window's feed (bulk) is the solids fed between its ends over phi_max
series = {round(float(r["time"]), 6): r for r in csv.DictReader(open(f"{run}/timeseries.csv"))}
fed = float(series[1.0]["solids_in_m3"]) - float(series[0.4]["solids_in_m3"])
feed = fed / 0.6 / 0.57
check(abs(k["feed_bulk_m3_per_s"] / feed - 1) < 1e-6, f"feed {k['feed_bulk_m3_per_s']} vs {feed}")
rows = list(csv.DictReader(open(f"{run}/kramers_croockewit.csv")))
check(len(rows) == 10 and sum(int(r["compared"]) for r in rows) == 8,
      "the profile does not cover the ten sections (eight compared)")
check(all(0 < float(r["depth_kramers_m"]) < 0.4 for r in rows), "a Kramers depth out of the kiln")
check(k["max_rel_deviation"] >= 0 and k["uniform_depth_m"] > 0, "no deviation or uniform depth")
# the theory's own rise is about 0 in this short kiln (its start depth is within 2 % of the
# uniform depth: +0.6 mm before the settling sub-steps of 2026-12-03, -0.4 mm after), so only
# that it is a number is checked here; the long tests validation_kiln_kramers_* check it
check(k["rise_m"] > 0, "the depth does not rise from the start")
check(math.isfinite(k["rise_kramers_m"]) and abs(k["rise_kramers_m"]) < k["uniform_depth_m"],
      "no Kramers rise")
# the tracer pulse (0.2-0.4 s) is conserved: tagged content = fed - discharged (the bed leaves
# cells empty here, which once tagged solids from nothing)
t = json.load(open(f"{run}/summary.json"))["tracer"]
check(t["injected_m3"] > 0 and t["balance_error_of_injected"] < 1e-8, f"tracer balance {t}")
print("kiln_short (Kramers-Croockewit): angle", k["repose_angle_deg"], "deg, deviation",
      k["max_rel_deviation"])
PY
if "$hikiln" -q kiln "$kc" -o "$work/bad" --set kramers.average_from=200 2> "$work/bad.err"; then
  echo "kiln_short: kramers.average_from past the end was accepted"; exit 1
fi
grep -q "average_from < duration" "$work/bad.err" || { cat "$work/bad.err"; exit 1; }
echo "kiln_short: passed"
