#!/usr/bin/env python3
"""Merges several hikiln_bench JSON outputs (one per backend / thread count) into one file whose
benchmark entries are tagged with backend, host_threads, benchmark and size, writes a Markdown
table next to it and prints the table. Used by perf/run.sh; standard library only.

  merge_runs.py --output OUT.json --markdown OUT.md [--command "..."] \\
                --run Serial 1 serial.json --run OpenMP 2 openmp-2.json ...
"""

import argparse
import datetime
import json
import os
import socket
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import perfresults  # noqa: E402


def merge(runs, command):
    """The merged document for runs given as (backend, threads, path) triples."""
    merged = {
        "hikiln_perf": {
            "format": 1,
            "created_utc": datetime.datetime.now(datetime.timezone.utc)
                                           .strftime("%Y-%m-%dT%H:%M:%SZ"),
            "hostname": socket.gethostname(),
            "command": command,
        },
        "context": {},
        "runs": [],
        "benchmarks": [],
    }
    for backend, threads, path in runs:
        with open(path, encoding="utf-8") as handle:
            document = json.load(handle)
        context = document.get("context", {})
        if not merged["context"]:
            merged["context"] = context
        merged["runs"].append({"backend": backend, "host_threads": threads,
                               "file": os.path.basename(path), "context": context})
        for entry in document.get("benchmarks", []):
            tagged = perfresults.tag_entry(entry, threads)
            if tagged["backend"] not in ("", backend):
                raise SystemExit(f"{path}: {entry['name']} is not a {backend} benchmark")
            tagged["backend"] = backend
            merged["benchmarks"].append(tagged)
    return merged


def table(merged):
    """The Markdown results table of a merged document."""
    rows = []
    chosen = perfresults.representative_entries(merged["benchmarks"])
    for entry in sorted(chosen.values(), key=perfresults.sort_key):
        if entry.get("error_occurred"):
            time_text, rate_text = "error", entry.get("error_message", "")
        else:
            value, unit = perfresults.throughput(entry)
            time_text = perfresults.format_time(perfresults.time_seconds(entry))
            rate_text = f"{perfresults.format_number(value)} {unit}"
        rows.append([entry["benchmark"], entry["backend"], entry["host_threads"],
                     perfresults.display_size(entry), time_text, rate_text])
    header = ["benchmark", "backend", "threads", "size", "time", "throughput"]
    return perfresults.markdown_table(header, rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--output", required=True, help="merged JSON file to write")
    parser.add_argument("--markdown", help="Markdown table file to write")
    parser.add_argument("--command", default="", help="command line recorded in the JSON")
    parser.add_argument("--run", nargs=3, action="append", required=True,
                        metavar=("BACKEND", "THREADS", "FILE"),
                        help="one benchmark JSON file and the backend/threads it ran with")
    args = parser.parse_args()

    runs = [(backend, int(threads), path) for backend, threads, path in args.run]
    merged = merge(runs, args.command)
    text = table(merged)
    context = merged["context"]
    heading = (f"hikiln {context.get('hikiln_version', '?')}, Kokkos "
               f"{context.get('kokkos_version', '?')}, {context.get('cpu_model', '?')} "
               f"({context.get('num_cpus', '?')} CPUs), host {merged['hikiln_perf']['hostname']}, "
               f"{merged['hikiln_perf']['created_utc']}")
    # The machine may be shared: the 1-minute load average when each run started says how busy.
    loads = [run["context"].get("load_avg", [None])[0] for run in merged["runs"]]
    if all(load is not None for load in loads):
        heading += ("; 1-min load average at the start of each run: "
                    + ", ".join(f"{run['backend']}/{run['host_threads']}: {load:.2f}"
                                for run, load in zip(merged["runs"], loads)))

    perfresults.write_atomically(args.output, json.dumps(merged, indent=1) + "\n")
    if args.markdown:
        perfresults.write_atomically(args.markdown, f"{heading}\n\n{text}\n")
    print(heading)
    print()
    print(text)


if __name__ == "__main__":
    main()
