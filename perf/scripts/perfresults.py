"""Shared helpers for hikiln benchmark results (Google Benchmark JSON): name parsing, choosing
one entry per benchmark, throughput and Markdown formatting. Standard library only."""

import math
import os
import tempfile

# Kokkos backends as they appear in benchmark names ("copy/OpenMP/1048576/manual_time").
KNOWN_BACKENDS = ("Serial", "OpenMP", "Threads", "Cuda", "HIP", "SYCL")
BACKEND_ORDER = {name: rank for rank, name in enumerate(KNOWN_BACKENDS)}
# Name components Google Benchmark appends that are not part of the benchmark's identity.
TIME_SUFFIXES = ("manual_time", "real_time", "process_time")
TIME_UNIT_SECONDS = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}


def parse_name(run_name):
    """Splits "copy/OpenMP/8388608/manual_time" into ("copy", "OpenMP", "8388608").

    The backend is the first component that names a Kokkos backend; everything before it is the
    benchmark, everything after it (minus timing suffixes and "key:value" options such as
    "repeats:3") is the size/arguments. Names without a backend get backend "".
    """
    parts = [p for p in run_name.split("/")
             if p not in TIME_SUFFIXES and ":" not in p]
    for i, part in enumerate(parts):
        if part in KNOWN_BACKENDS and i > 0:
            return "/".join(parts[:i]), part, "/".join(parts[i + 1:])
    return "/".join(parts), "", ""


def _size_sort_key(size):
    """Numeric sizes sort numerically, anything else after them alphabetically."""
    try:
        return (0, float(size), "")
    except ValueError:
        return (1, 0.0, size)


def sort_key(entry):
    """Groups rows by benchmark and size, then backend and thread count (scaling reads down)."""
    return (entry["benchmark"], _size_sort_key(entry["size"]),
            BACKEND_ORDER.get(entry["backend"], len(BACKEND_ORDER)), entry["host_threads"])


def tag_entry(entry, host_threads):
    """A copy of a Google Benchmark entry with benchmark, backend, size and host_threads added."""
    tagged = dict(entry)
    benchmark, backend, size = parse_name(entry.get("run_name", entry["name"]))
    tagged.update(benchmark=benchmark, backend=backend, size=size, host_threads=host_threads)
    return tagged


def representative_entries(entries):
    """One entry per (benchmark, backend, host_threads, size): the median aggregate when the run
    had repetitions, else the first iteration entry. Errored entries are kept so they show."""
    chosen, medians = {}, set()
    for entry in entries:
        key = result_key(entry)
        if entry.get("run_type") == "aggregate":
            if entry.get("aggregate_name") == "median":
                chosen[key] = entry
                medians.add(key)
        elif key not in chosen and key not in medians:
            chosen[key] = entry
    return chosen


def result_key(entry):
    """The identity of a result across files: (benchmark, backend, host_threads, size)."""
    return (entry["benchmark"], entry["backend"], entry["host_threads"], entry["size"])


def time_seconds(entry):
    """The entry's real (here: manual) time per iteration in seconds."""
    return entry["real_time"] * TIME_UNIT_SECONDS.get(entry.get("time_unit", "ns"), 1e-9)


def throughput(entry):
    """(value, unit) where larger is better: the "GB/s" counter, else items/s, else bytes/s in
    GB/s, else iterations per second."""
    if "GB/s" in entry:
        return float(entry["GB/s"]), "GB/s"
    if "items_per_second" in entry:
        return float(entry["items_per_second"]), "items/s"
    if "bytes_per_second" in entry:
        return float(entry["bytes_per_second"]) / 1e9, "GB/s"
    seconds = time_seconds(entry)
    return (1.0 / seconds if seconds > 0 else math.nan), "1/s"


def format_number(value):
    """Three significant digits; whole numbers from 1000 up, exponent from a million up."""
    if value is None or math.isnan(value):
        return "n/a"
    if 1000 <= abs(value) < 1e6:
        return f"{value:.0f}"
    return f"{value:.3g}"


def format_time(seconds):
    """A time with a unit that keeps three significant digits readable."""
    for unit, scale in (("s", 1.0), ("ms", 1e-3), ("us", 1e-6)):
        if seconds >= scale:
            return f"{format_number(seconds / scale)} {unit}"
    return f"{format_number(seconds / 1e-9)} ns"


def display_size(entry):
    """The benchmark's own label (e.g. "8 MiB") when it set one, else the raw argument."""
    return entry.get("label") or entry["size"]


def markdown_table(header, rows, left_columns=2):
    """A GitHub-flavoured Markdown table; columns after the first left_columns are right aligned."""
    align = [":---" if i < left_columns else "---:" for i in range(len(header))]
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join(align) + "|"]
    lines += ["| " + " | ".join(str(cell) for cell in row) + " |" for row in rows]
    return "\n".join(lines)


def write_atomically(path, text):
    """Writes text to path through a temporary sibling and a rename, so a reader never sees a
    half-written file."""
    directory = os.path.dirname(os.path.abspath(path))
    os.makedirs(directory, exist_ok=True)
    handle, temporary = tempfile.mkstemp(dir=directory, prefix=".tmp-")
    try:
        with os.fdopen(handle, "w", encoding="utf-8") as stream:
            stream.write(text)
        os.chmod(temporary, 0o644)  # mkstemp makes 0600; results are meant to be shared
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise
