#!/bin/bash
# Two hikiln binaries timed side by side: both run the same `hikiln dem` case at the same time,
# one thread each, OLD on core 0 and NEW on core 1, then the cores swapped; REPS times. On a
# shared VM whose speed drifts by 20 % and more between runs a minute apart, runs taken at the
# same time see the same machine, so their ratio is far steadier than that of runs taken in turn
# (perf/README.md, "Each pair evaluated once").
#
# usage: perf/scripts/side_by_side.sh REPS OLD NEW CASE [hikiln dem options...]
#   e.g. perf/scripts/side_by_side.sh 3 old/hikiln new/hikiln cases/drum-base.yaml \
#          --set time.duration=1 --set time.settle=0.5 --set time.spin_up=0
# FROM=DIR copies DIR (a finished run with its checkpoint.h5) into each output first, for
# restart segments: add --restart and a longer time.duration to the options.
# SIDE_BY_SIDE_DIR (default /tmp/hikiln-side-by-side) keeps the outputs and side_by_side.log.
# Prints each run's particle_steps_per_s, each turn's NEW / OLD ratio and their median.
set -euo pipefail
if [ $# -lt 4 ]; then
  sed -n '2,15p' "$0" >&2
  exit 2
fi
reps=$1 old=$2 new=$3 case=$4
shift 4
for binary in "$old" "$new"; do
  [ -x "$binary" ] || { echo "side_by_side.sh: $binary is not an executable" >&2; exit 2; }
done
[ -f "$case" ] || { echo "side_by_side.sh: case file $case not found" >&2; exit 2; }
if [ -n "${FROM:-}" ] && [ ! -f "$FROM/checkpoint.h5" ]; then
  echo "side_by_side.sh: FROM=$FROM has no checkpoint.h5" >&2
  exit 2
fi
dir=${SIDE_BY_SIDE_DIR:-/tmp/hikiln-side-by-side}
mkdir -p "$dir"
log="$dir/side_by_side.log"
: > "$log"
run() { # binary core output [dem options...]
  local binary=$1 core=$2 out=$3
  shift 3
  rm -rf "$out"
  if [ -n "${FROM:-}" ]; then
    cp -r "$FROM" "$out"
  fi
  OMP_NUM_THREADS=1 taskset -c "$core" "$binary" -q --threads 1 dem "$case" -o "$out" "$@" \
    > "$out.log" 2>&1 || { echo "side_by_side.sh: $binary failed, see $out.log" >&2; return 1; }
}
rate() { python3 -c "import json, sys; print(json.load(open(sys.argv[1]))['particle_steps_per_s'])" "$1/summary.json"; }
options=("$@")
for r in $(seq 1 "$reps"); do
  for swap in 0 1; do
    oldCore=$swap newCore=$((1 - swap))
    run "$old" "$oldCore" "$dir/old" "${options[@]}" &
    oldJob=$!
    run "$new" "$newCore" "$dir/new" "${options[@]}" &
    newJob=$!
    wait "$oldJob"
    wait "$newJob"
    echo "$r.$swap $(rate "$dir/old") $(rate "$dir/new")" | tee -a "$log"
  done
done
python3 - "$log" <<'PY'
import statistics, sys
ratios = []
for line in open(sys.argv[1]):
    turn, old, new = line.split()
    ratios.append(float(new) / float(old))
print("new / old per turn: " + ", ".join(f"{r:.3f}" for r in ratios))
print(f"median {statistics.median(ratios):.3f} (range {min(ratios):.3f}-{max(ratios):.3f}, "
      f"{len(ratios)} turns)")
PY
