#!/usr/bin/env python3
"""Checks perf/scripts/merge_runs.py and perf/compare.py on synthetic Google Benchmark JSON:
tagging by backend and thread count, the median choice for repetitions, the Markdown table and
the +-5 % flags. Run by ctest as perf_scripts (standard library only)."""

import json
import os
import subprocess
import sys
import tempfile
import unittest

PERF = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MERGE = os.path.join(PERF, "scripts", "merge_runs.py")
COMPARE = os.path.join(PERF, "compare.py")


def entry(name, gbs, real_time_ms=1.0, run_type="iteration", aggregate=None):
    """One Google Benchmark result entry as hikiln_bench writes it."""
    result = {"name": name + ("_" + aggregate if aggregate else ""), "run_name": name,
              "run_type": run_type, "iterations": 10, "real_time": real_time_ms,
              "cpu_time": real_time_ms, "time_unit": "ms", "bytes_per_second": gbs * 1e9,
              "GB/s": gbs, "label": "8 MiB"}
    if aggregate:
        result["aggregate_name"] = aggregate
    return result


def write_run(directory, filename, threads, entries):
    """A benchmark JSON file with a minimal context; returns its path."""
    path = os.path.join(directory, filename)
    context = {"num_cpus": 2, "kokkos_version": "3.4.1", "hikiln_version": "0.1.0",
               "cpu_model": "Test CPU", "openmp_threads": str(threads)}
    with open(path, "w", encoding="utf-8") as handle:
        json.dump({"context": context, "benchmarks": entries}, handle)
    return path


def run(*args):
    """Runs a script with python3 and returns (exit code, stdout)."""
    done = subprocess.run([sys.executable, *args], capture_output=True, text=True, check=False)
    return done.returncode, done.stdout + done.stderr


class MergeAndCompare(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def merged(self, name, copy_gbs):
        """Merges a Serial run and OpenMP runs at 1 and 2 threads into NAME.json."""
        serial = write_run(self.dir, name + "-s.json", 1,
                           [entry("copy/Serial/8388608/manual_time", copy_gbs[0])])
        omp1 = write_run(self.dir, name + "-o1.json", 1,
                         [entry("copy/OpenMP/8388608/manual_time", copy_gbs[1])])
        omp2 = write_run(self.dir, name + "-o2.json", 2,
                         [entry("copy/OpenMP/8388608/manual_time", copy_gbs[2])])
        out = os.path.join(self.dir, name + ".json")
        code, text = run(MERGE, "--output", out, "--markdown", out[:-5] + ".md",
                         "--run", "Serial", "1", serial, "--run", "OpenMP", "1", omp1,
                         "--run", "OpenMP", "2", omp2)
        self.assertEqual(code, 0, text)
        return out, text

    def test_merge_tags_entries_and_writes_table(self):
        out, text = self.merged("base", (10.0, 11.0, 18.0))
        with open(out, encoding="utf-8") as handle:
            document = json.load(handle)
        tags = [(e["benchmark"], e["backend"], e["host_threads"], e["size"])
                for e in document["benchmarks"]]
        self.assertEqual(tags, [("copy", "Serial", 1, "8388608"), ("copy", "OpenMP", 1, "8388608"),
                                ("copy", "OpenMP", 2, "8388608")])
        self.assertEqual(len(document["runs"]), 3)
        self.assertIn("| copy | OpenMP | 2 | 8 MiB | 1 ms | 18 GB/s |", text)
        with open(out[:-5] + ".md", encoding="utf-8") as handle:
            self.assertIn("| copy | Serial | 1 | 8 MiB | 1 ms | 10 GB/s |", handle.read())

    def test_compare_flags_changes_beyond_five_percent(self):
        base, _ = self.merged("base", (10.0, 10.0, 10.0))
        new, _ = self.merged("new", (11.0, 10.2, 9.0))  # +10 %, +2 %, -10 %
        code, text = run(COMPARE, base, new)
        self.assertEqual(code, 0, text)
        self.assertIn("| copy | Serial | 1 | 8 MiB | 10 GB/s | 11 GB/s | 1.100 | faster |", text)
        self.assertIn("| copy | OpenMP | 1 | 8 MiB | 10 GB/s | 10.2 GB/s | 1.020 |  |", text)
        self.assertIn("| copy | OpenMP | 2 | 8 MiB | 10 GB/s | 9 GB/s | 0.900 | **SLOWER** |", text)
        self.assertIn("3 compared, 1 faster and 1 slower", text)
        code, _ = run(COMPARE, base, new, "--fail-on-slower")
        self.assertEqual(code, 1)
        code, _ = run(COMPARE, base, new, "--fail-on-slower", "--threshold", "15")
        self.assertEqual(code, 0)

    def test_compare_uses_median_of_repetitions_in_raw_files(self):
        name = "triad/OpenMP/8388608/manual_time"
        base = write_run(self.dir, "raw-base.json", 2, [entry(name, 20.0)])
        new = write_run(self.dir, "raw-new.json", 2, [
            entry(name, 30.0, aggregate="mean", run_type="aggregate"),
            entry(name, 25.0, aggregate="median", run_type="aggregate"),
            entry(name, 1.0, aggregate="stddev", run_type="aggregate")])
        code, text = run(COMPARE, base, new)
        self.assertEqual(code, 0, text)
        self.assertIn("| triad | OpenMP | 2 | 8 MiB | 20 GB/s | 25 GB/s | 1.250 | faster |", text)

    def test_results_missing_on_one_side_are_listed(self):
        base = write_run(self.dir, "a.json", 1, [entry("copy/Serial/1048576/manual_time", 5.0)])
        new = write_run(self.dir, "b.json", 1, [entry("triad/Serial/1048576/manual_time", 5.0)])
        code, text = run(COMPARE, base, new)
        self.assertEqual(code, 0, text)
        self.assertIn("only in baseline", text)
        self.assertIn("only in new", text)
        self.assertIn("0 compared", text)


if __name__ == "__main__":
    unittest.main()
