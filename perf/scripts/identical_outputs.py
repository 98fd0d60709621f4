#!/usr/bin/python3
"""Whether two hikiln runs wrote bitwise the same HDF5 outputs: every dataset of every .h5 file
under RUN_A against the same path under RUN_B (NaN equal to NaN).

    perf/scripts/identical_outputs.py RUN_A RUN_B

Prints "K/N datasets identical" and the first differing or missing ones; exits 1 unless all are
identical. Used to check that a change leaves a run's output bitwise as it was (perf/README.md,
e.g. "The pair-once option made cheaper"). Needs h5py (Debian: python3-h5py).
"""
import sys
from pathlib import Path

import h5py
import numpy as np


def same(a, b):
    """Bitwise equality of two dataset values (NaN equal to NaN for floats)."""
    if a.shape != b.shape or a.dtype != b.dtype:
        return False
    if a.dtype.kind == "f":
        return bool(np.array_equal(a, b, equal_nan=True))
    return bool(np.array_equal(a, b))


def compare(run_a, run_b):
    """Returns (datasets compared, identical, list of differences)."""
    total, identical, differences = 0, 0, []
    files = sorted(run_a.rglob("*.h5"))
    if not files:
        differences.append(f"no .h5 files under {run_a}")
    for path_a in files:
        path_b = run_b / path_a.relative_to(run_a)
        if not path_b.exists():
            differences.append(f"missing {path_b}")
            continue
        with h5py.File(path_a, "r") as fa, h5py.File(path_b, "r") as fb:
            names = []
            fa.visititems(lambda name, obj: names.append(name)
                          if isinstance(obj, h5py.Dataset) else None)
            for name in names:
                total += 1
                if name not in fb:
                    differences.append(f"missing {path_b}:{name}")
                elif same(fa[name][()], fb[name][()]):
                    identical += 1
                else:
                    differences.append(f"differs {path_a.relative_to(run_a)}:{name}")
    return total, identical, differences


def main(argv):
    if len(argv) != 3:
        print("usage: perf/scripts/identical_outputs.py RUN_A RUN_B", file=sys.stderr)
        return 2
    run_a, run_b = Path(argv[1]), Path(argv[2])
    for run in (run_a, run_b):
        if not run.is_dir():
            print(f"identical_outputs.py: {run} is not a run folder", file=sys.stderr)
            return 2
    total, identical, differences = compare(run_a, run_b)
    print(f"{identical}/{total} datasets identical")
    for line in differences[:50]:
        print("  " + line)
    return 0 if identical == total and not differences else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
