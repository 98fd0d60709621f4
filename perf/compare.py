#!/usr/bin/env python3
"""Compares two hikiln benchmark result files (merged files from perf/run.sh, or raw
hikiln_bench --benchmark_out JSON) and prints a Markdown table of throughput ratios new/baseline
per benchmark, backend, thread count and size, flagging changes beyond the threshold (5 %).

  perf/compare.py BASELINE.json NEW.json [--threshold 5] [--fail-on-slower]

Ratios above 1 mean the new run is faster. Standard library only.
"""

import argparse
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "scripts"))
import perfresults  # noqa: E402


def load(path):
    """The representative result per key of a merged or raw benchmark JSON file."""
    with open(path, encoding="utf-8") as handle:
        document = json.load(handle)
    if "hikiln_perf" in document:
        entries = document["benchmarks"]
    else:
        # Raw output of one run: OpenMP ran with the thread count recorded in the context.
        openmp_threads = int(document.get("context", {}).get("openmp_threads", 1))
        entries = []
        for entry in document.get("benchmarks", []):
            backend = perfresults.parse_name(entry.get("run_name", entry["name"]))[1]
            entries.append(perfresults.tag_entry(entry, openmp_threads if backend == "OpenMP"
                                                 else 1))
    return perfresults.representative_entries(entries)


def compare(baseline, new, threshold):
    """(rows, counts) of the comparison table; threshold is a fraction (0.05)."""
    rows = []
    counts = {"compared": 0, "faster": 0, "slower": 0, "missing": 0}
    keys = sorted(set(baseline) | set(new),
                  key=lambda key: perfresults.sort_key((new.get(key) or baseline.get(key))))
    for key in keys:
        old_entry, new_entry = baseline.get(key), new.get(key)
        benchmark, backend, threads, _ = key
        size = perfresults.display_size(new_entry or old_entry)
        if old_entry is None or new_entry is None:
            counts["missing"] += 1
            where = "only in new" if old_entry is None else "only in baseline"
            rows.append([benchmark, backend, threads, size, "", "", "", where])
            continue
        if old_entry.get("error_occurred") or new_entry.get("error_occurred"):
            counts["missing"] += 1
            rows.append([benchmark, backend, threads, size, "", "", "", "error"])
            continue
        old_value, unit = perfresults.throughput(old_entry)
        new_value, _ = perfresults.throughput(new_entry)
        ratio = new_value / old_value if old_value > 0 else float("nan")
        counts["compared"] += 1
        flag = ""
        if ratio > 1.0 + threshold:
            flag = "faster"
            counts["faster"] += 1
        elif ratio < 1.0 - threshold:
            flag = "**SLOWER**"
            counts["slower"] += 1
        rows.append([benchmark, backend, threads, size,
                     f"{perfresults.format_number(old_value)} {unit}",
                     f"{perfresults.format_number(new_value)} {unit}",
                     f"{ratio:.3f}", flag])
    return rows, counts


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("baseline", help="baseline results JSON")
    parser.add_argument("new", help="new results JSON")
    parser.add_argument("--threshold", type=float, default=5.0,
                        help="flag ratios beyond +-THRESHOLD percent (default 5)")
    parser.add_argument("--fail-on-slower", action="store_true",
                        help="exit with status 1 when any result is slower beyond the threshold")
    args = parser.parse_args()

    rows, counts = compare(load(args.baseline), load(args.new), args.threshold / 100.0)
    header = ["benchmark", "backend", "threads", "size", "baseline", "new", "new/baseline", "flag"]
    print(f"Baseline: {args.baseline}  \nNew: {args.new}\n")
    print(perfresults.markdown_table(header, rows))
    print(f"\n{counts['compared']} compared, {counts['faster']} faster and {counts['slower']} "
          f"slower beyond +-{args.threshold:g} %, {counts['missing']} not comparable.")
    return 1 if args.fail_on_slower and counts["slower"] else 0


if __name__ == "__main__":
    sys.exit(main())
