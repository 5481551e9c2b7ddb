#!/usr/bin/python3
"""Compare two cambrian history files, ignoring what legitimately varies between runs.

Exit 0 when the histories A and B are identical except timing and placement columns (wall
times, unix_time, eval_seconds, worker_rank, workers, busy/idle, checkpoint_seconds) and
run-only provenance (start_time, rank_count, and the keys of config_text that the histories list
as run-only in their run_only_settings attribute, such as run.out);
exit 1 with a readable list of differences otherwise; exit 2 when a file cannot be read.

Values are compared bit for bit (NaN equals NaN only with the same bits). Used by the
checkpoint/resume tests: a run killed and resumed must give the history of a straight run.
"""

import argparse
import sys

import numpy as np

try:
    import h5py
except ImportError:  # pragma: no cover - Debian's python3-h5py is a dependency
    sys.exit("compare_histories.py: python3-h5py is missing (apt-get install python3-h5py)")

from cambrian_history import open_hdf5  # noqa: E402 (the same directory)

# columns whose values depend on timing or on which rank evaluated what
TIMING_DATASETS = {
    "individuals/eval_seconds",
    "individuals/worker_rank",
    "generations/workers",
    "generations/rank0_serial_seconds",
    "generations/rank0_cpu_seconds",
    "generations/rank0_dispatch_seconds",
    "generations/evaluation_span_seconds",
    "generations/worker_busy_seconds",
    "generations/worker_idle_seconds",
    "generations/checkpoint_seconds",
    "generations/wall_seconds",
    "generations/unix_time",
}

# root attributes that describe the run, not its results
RUN_ATTRIBUTES = {"start_time", "rank_count"}

# root attributes compared through their meaning rather than their text
READ_APART = {"config_text", "run_only_settings"}

# the run-only keys of histories written before each history listed its own (in the attribute
# run_only_settings, from the settings' declarations): frozen, never extended
RUN_ONLY_BEFORE_THE_ATTRIBUTE = frozenset({
    "evolution.generations",
    "run.out",
    "run.quiet",
    "run.verbose",
    "run.max_hours",
    "run.checkpoint_every",
    "run.checkpoint_minutes",
    "run.test_kill_at",
    "run.test_worker_abort_at",
    "run.dispatch_order",
    "run.dispatch_seed",
})


def run_only_settings(file):
    """The run-only keys a history lists (run_only_settings), or the frozen older set."""
    if "run_only_settings" in file.attrs:
        return {text(v) for v in np.atleast_1d(file.attrs["run_only_settings"])}
    return set(RUN_ONLY_BEFORE_THE_ATTRIBUTE)


def result_settings(config_text, run_only):
    """The `section.key -> value` settings of INI text, the keys of `run_only` left out."""
    settings, section = {}, ""
    for line in config_text.splitlines():
        if line.startswith("[") and line.endswith("]"):
            section = line[1:-1]
        elif " = " in line:
            key, value = line.split(" = ", 1)
            name = section + "." + key
            if name not in run_only:
                settings[name] = value
    return settings


def text(value):
    """An attribute value as text (bytes decoded)."""
    if isinstance(value, bytes):
        return value.decode("utf-8", "replace")
    if isinstance(value, np.ndarray):
        return repr([text(v) for v in value.tolist()])
    return repr(value) if not isinstance(value, str) else value


def datasets(group, prefix=""):
    """path -> dataset for every dataset below `group`."""
    found = {}
    for name, item in group.items():
        path = prefix + name
        if isinstance(item, h5py.Dataset):
            found[path] = item
        else:
            found.update(datasets(item, path + "/"))
    return found


def compare_settings(a, b, differences):
    """Appends a line per result-changing setting that differs between the files a and b (the
    keys either file declares run-only are left out)."""
    run_only = run_only_settings(a) | run_only_settings(b)
    sa = result_settings(text(a.attrs["config_text"]), run_only)
    sb = result_settings(text(b.attrs["config_text"]), run_only)
    for key in sorted(set(sa) | set(sb)):
        if sa.get(key) != sb.get(key):
            differences.append(f"/: config_text setting {key}: {sa.get(key)!r} != {sb.get(key)!r}")


def compare_attributes(where, a, b, skip, differences):
    """Appends a line per attribute that differs between the objects a and b."""
    for name in sorted(set(a.attrs) | set(b.attrs)):
        if name in skip:
            continue
        if name not in a.attrs or name not in b.attrs:
            side = "A" if name in a.attrs else "B"
            differences.append(f"{where}: attribute {name} only in {side}")
            continue
        va, vb = a.attrs[name], b.attrs[name]
        if text(va) != text(vb):
            differences.append(f"{where}: attribute {name}: {text(va)!r} != {text(vb)!r}")


def same_bits(x, y):
    """Element-wise bit equality of two equally shaped arrays (rows of 2-D arrays)."""
    if x.dtype.kind == "f":
        x, y = x.view(f"u{x.dtype.itemsize}"), y.view(f"u{y.dtype.itemsize}")
    equal = x == y
    return equal.all(axis=tuple(range(1, equal.ndim))) if equal.ndim > 1 else equal


def compare_dataset(path, a, b, differences, limit=5):
    """Appends lines describing how datasets a and b differ (shape, type, values)."""
    if a.dtype != b.dtype:
        differences.append(f"/{path}: type {a.dtype} != {b.dtype}")
        return
    x, y = a[()], b[()]
    if x.shape != y.shape:
        differences.append(f"/{path}: shape {x.shape} != {y.shape}")
        n = min(len(x), len(y)) if x.ndim and y.ndim else 0
        x, y = x[:n], y[:n]
    if x.ndim == 0:
        if not same_bits(np.atleast_1d(x), np.atleast_1d(y)).all():
            differences.append(f"/{path}: {x!r} != {y!r}")
        return
    rows = np.flatnonzero(~same_bits(x, y))
    if len(rows):
        shown = ", ".join(f"row {r}: {x[r]!r} != {y[r]!r}" for r in rows[:limit])
        more = f" (and {len(rows) - limit} more)" if len(rows) > limit else ""
        differences.append(f"/{path}: {len(rows)} row(s) differ: {shown}{more}")


def compare(path_a, path_b, ignore=()):
    """The list of differences between two history files (empty: identical)."""
    differences = []
    skip = TIMING_DATASETS | set(ignore)
    with open_hdf5(path_a) as a, open_hdf5(path_b) as b:
        compare_attributes("/", a, b, RUN_ATTRIBUTES | READ_APART, differences)
        compare_settings(a, b, differences)
        da, db = datasets(a), datasets(b)
        for path in sorted(set(da) | set(db)):
            if path not in da or path not in db:
                side = "A" if path in da else "B"
                differences.append(f"/{path}: only in {side}")
                continue
            compare_attributes("/" + path, da[path], db[path], set(), differences)
            if path not in skip:
                compare_dataset(path, da[path], db[path], differences)
    return differences


def unreadable(path):
    """Why the file at `path` cannot be read whole (its first bad object), or None."""
    try:
        with open_hdf5(path) as file:
            dict(file.attrs)
            for dataset in datasets(file).values():
                dict(dataset.attrs)
                dataset[()]
    except Exception as error:  # whatever h5py raises on damaged bytes
        return str(error) or type(error).__name__
    return None


def main(argv=None):
    """Compares in a child process: on some damaged files HDF5 1.10 crashes (SIGSEGV, SIGABRT)
    instead of reporting an error, and that must be exit 2 naming the file, never a crash."""
    import os
    import signal
    import subprocess

    argv = sys.argv[1:] if argv is None else list(argv)
    if os.environ.get("CAMBRIAN_COMPARE_CHILD") == "1" or "-h" in argv or "--help" in argv:
        return compare_main(argv)
    env = dict(os.environ, CAMBRIAN_COMPARE_CHILD="1")
    code = subprocess.run([sys.executable, os.path.abspath(__file__), *argv], env=env).returncode
    if code >= 0:
        return code
    # the child crashed: find which file does it, each in a child of its own
    crash = signal.Signals(-code).name
    paths = [a for a in argv if not a.startswith("-")][:2]
    for path in paths:
        probe = subprocess.run([sys.executable, "-c",
                                "import sys; sys.path.insert(0, sys.argv[1]); import compare_histories as c; "
                                "sys.exit(1 if c.unreadable(sys.argv[2]) else 0)",
                                os.path.dirname(os.path.abspath(__file__)), path],
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        if probe.returncode != 0:
            print(f"compare_histories.py: {path}: cannot read (reading it crashed HDF5, {crash}: "
                  "a damaged file)", file=sys.stderr)
            return 2
    print(f"compare_histories.py: cannot read {' or '.join(paths)}: reading crashed HDF5 ({crash})",
          file=sys.stderr)
    return 2


def compare_main(argv):
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("a", help="first history.h5")
    parser.add_argument("b", help="second history.h5")
    parser.add_argument("--ignore", action="append", default=[], metavar="DATASET",
                        help="another dataset to leave out, e.g. individuals/steps (repeatable)")
    parser.add_argument("--quiet", "-q", action="store_true", help="no output, only the exit code")
    args = parser.parse_args(argv)
    try:
        differences = compare(args.a, args.b, args.ignore)
    except Exception as error:  # a damaged file: say which
        for path in (args.a, args.b):
            why = unreadable(path)
            if why:
                print(f"compare_histories.py: {path}: cannot read ({why})", file=sys.stderr)
                return 2
        print(f"compare_histories.py: cannot read {args.a} or {args.b}: {error}", file=sys.stderr)
        return 2
    if not args.quiet:
        if differences:
            print(f"{args.a} and {args.b} differ:")
            for line in differences:
                print("  " + line)
        else:
            print(f"{args.a} and {args.b} are identical (timing columns not compared)")
    return 1 if differences else 0


if __name__ == "__main__":
    sys.exit(main())
