#!/bin/bash
# Timed restart segments of the shape study's 2 m drum, taken in turn: the way hikiln compares
# two builds, or a shape against circles or discs, on a shared machine whose speed drifts slowly
# (whole runs spread by 25 % and more there; docs/blocky-particles.md, Performance).
#
# usage: perf/scripts/drum_segments.sh REPS ENTRY...
#   ENTRY = BINARY:N[:disc]  the hikiln binary, the case cases/shape/blockiness-N.yaml, and
#                            "disc" for the disc engine on that case (particles.shape=disc)
# Each distinct (N, disc) first gets a checkpoint from a whole run with the first entry's
# binary (settle 0.5 s, spin-up 0.2 s, 0.5 s of rotation), kept in $SEGMENTS_DIR (default
# /tmp/hikiln-segments). Then, REPS times, every entry restarts from its checkpoint and runs
# 0.3 s more (blocky) or 1.0 s more (circles, discs) on core 0 (taskset), one at a time. Prints
# each segment's particle_steps_per_s and, per entry, the median rate and the median of its
# per-turn ratio to the first entry's rate (first / entry: a cost when the first is the faster).
# SEGMENT_THREADS=2 runs every segment on two threads pinned to cores 0 and 1 instead (the
# checkpoints are the same).
set -euo pipefail
reps=$1; shift
root=$(cd "$(dirname "$0")/../.." && pwd)
dir=${SEGMENTS_DIR:-/tmp/hikiln-segments}
mkdir -p "$dir"
sets=(--set time.settle=0.5 --set time.spin_up=0.2 --set output.snapshot_interval=0.5
      --set output.checkpoint_interval=1 --set output.average_interval=0.5)
first_binary=${1%%:*}
threads=${SEGMENT_THREADS:-1}
cores=0-$((threads - 1))
log="$dir/segments.log"
: > "$log"
run() { # binary N disc output duration [--restart]
  local extra=()
  [ "$3" = disc ] && extra=(--set particles.shape=disc)
  taskset -c "$cores" "$1" -q --threads "$threads" dem "$root/cases/shape/blockiness-$2.yaml" -o "$4" \
    "${sets[@]}" "${extra[@]}" --set "time.duration=$5" "${@:6}" > /dev/null
}
for entry in "$@"; do
  IFS=: read -r binary n disc <<< "$entry"
  base="$dir/base-$n-${disc:-blocky}"
  [ -f "$base/checkpoint.h5" ] || run "$first_binary" "$n" "${disc:-}" "$base" 0.5
done
for r in $(seq 1 "$reps"); do
  for entry in "$@"; do
    IFS=: read -r binary n disc <<< "$entry"
    more=0.3
    { [ "$n" = 2 ] || [ "${disc:-}" = disc ]; } && more=1.0
    rm -rf "$dir/segment" && cp -r "$dir/base-$n-${disc:-blocky}" "$dir/segment"
    run "$binary" "$n" "${disc:-}" "$dir/segment" "$(python3 -c "print(0.5 + $more)")" --restart
    rate=$(python3 -c "import json; print(json.load(open('$dir/segment/summary.json'))['particle_steps_per_s'])")
    echo "$r $entry $rate" | tee -a "$log"
  done
done
python3 - "$log" "$@" <<'PY'
import statistics, sys
log, entries = sys.argv[1], sys.argv[2:]
rates = {}
for line in open(log):
    r, entry, rate = line.split()
    rates.setdefault(entry, {})[int(r)] = float(rate)
first = rates[entries[0]]
for entry in dict.fromkeys(entries):
    mine = rates[entry]
    ratios = [first[r] / mine[r] for r in sorted(mine)]
    print(f"{entry}: median {statistics.median(mine.values()) / 1e6:.3f} M particle-steps/s, "
          f"first / this median {statistics.median(ratios):.2f} "
          f"(range {min(ratios):.2f}-{max(ratios):.2f})")
PY
