#!/usr/bin/env bash
# `hikiln sweep --batch`: the cases of a study rotated together as one batch end bitwise where
# each case run alone ends (particles by id, contact history, bed statistics), their averaged
# fields agree to round-off (summation order), and a heated case, which cannot join the batch,
# runs alone. Usage: sweep_batch_identity.sh HIKILN BASE_CASE WORKDIR
set -euo pipefail
hikiln=$1 base=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
export HIKILN_PLOT_SCRIPTS="$work/no-plots" # plots are not what this checks (and take most of the time)
cat > "$work/study.yaml" <<YAML
base: $base
cases:
  rpm-3: {drum.rpm: 3.0}
  rpm-6-mu-0.3: {drum.rpm: 6.0, contact.friction: 0.3}
  fill-30: {drum.fill: 0.30}
  heated: {heat.enabled: true}
YAML
common=(--set drum.diameter=0.6 --set time.duration=0.5 --set time.spin_up=0.1
        --set time.settle=0.3 --set output.checkpoint_interval=0.25 --set output.snapshot_interval=0.25
        --set output.average_interval=0.25)
"$hikiln" -q --threads 1 sweep "$work/study.yaml" -o "$work/alone" "${common[@]}"
"$hikiln" --threads 2 sweep "$work/study.yaml" -o "$work/batch" --batch "${common[@]}" \
  2>&1 | tee "$work/batch.log"
grep -q "batch: 3 slices" "$work/batch.log"
grep -q "heated runs alone (heat transfer is on)" "$work/batch.log"
/usr/bin/python3 - "$work" "$(dirname "$0")" <<'PY'
import sys, json, h5py, numpy as np
work = sys.argv[1]
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, sys.argv[2])
from checkpoint_state import particle_state
def state(run):
    path = f"{work}/{run}/checkpoint.h5"
    f = h5py.File(path, "r")
    history = set(zip(f["integers/contact_id"][()], f["integers/contact_neighbor_id"][()],
                      f["reals/contact_shear"][()]))
    fields = {k: f["reals/" + k][()] for k in ["averages_cartesian", "averages_polar", "averages_wall"]}
    return particle_state(path), history, fields
for case in ["rpm-3", "rpm-6-mu-0.3", "fill-30", "heated"]:
    a, ha, fa = state(f"alone/{case}")
    b, hb, fb = state(f"batch/{case}")
    bad = [k for k in a if not np.array_equal(a[k], b[k])]
    if bad or ha != hb or len(ha) < 50:
        sys.exit(f"{case}: batched run differs from the run alone in {bad}, history equal "
                 f"{ha == hb} ({len(ha)} entries)")
    for k in fa:
        err = np.max(np.abs(fa[k] - fb[k])) / np.max(np.abs(fa[k]))
        if not err < 1e-12:
            sys.exit(f"{case}: averaged {k} differs by {err:.2e} (relative to its largest value)")
    summary = json.load(open(f"{work}/batch/{case}/summary.json"))
    if (summary["batch"] is None) != (case == "heated"):
        sys.exit(f"{case}: summary.json batch entry {summary['batch']}")
print("batched sweep: every case bitwise equal to its run alone")
PY
