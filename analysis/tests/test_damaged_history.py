"""A damaged history.h5 makes every Python reader fail within seconds, naming the file: a
finished file is opened plainly (a bad checksum fails at once), only a file a writer holds is
read as SWMR, and then with a bounded number of metadata read attempts (HDF5's default retries a
bad checksum for minutes)."""

import os
import random
import subprocess
import sys

import pytest

import cambrian_history as ch

HERE = os.path.dirname(os.path.abspath(__file__))
ANALYSIS = os.path.dirname(HERE)
LIMIT = 60  # seconds; each reader should need well under one


def damaged_header(source, target, which=3):
    """A copy of `source` with one byte flipped inside its `which`-th object header ("OHDR",
    checksummed): reading that object fails its metadata checksum."""
    data = bytearray(open(source, "rb").read())
    starts, at = [], data.find(b"OHDR")
    while at >= 0:
        starts.append(at)
        at = data.find(b"OHDR", at + 1)
    assert len(starts) > which, "a history has object headers for its groups and datasets"
    data[starts[which] + 8] ^= 0x40
    open(target, "wb").write(data)
    return target


def flipped(source, target, seed, count=50):
    """A copy of `source` with `count` random bits flipped (seeded)."""
    data = bytearray(open(source, "rb").read())
    rng = random.Random(seed)
    for _ in range(count):
        data[rng.randrange(len(data))] ^= 1 << rng.randrange(8)
    open(target, "wb").write(data)
    return target


def run(script, *arguments):
    env = dict(os.environ, MPLBACKEND="Agg")
    return subprocess.run([sys.executable, os.path.join(ANALYSIS, script), *map(str, arguments)],
                          capture_output=True, text=True, env=env, timeout=LIMIT)


def test_a_bad_object_header_fails_at_once_naming_the_file(run_history, tmp_path):
    for which in (3, 6, 9):
        bad = damaged_header(run_history, tmp_path / f"header{which}.h5", which)
        done = run("lineage.py", bad, "--output", tmp_path / "lineage.png")
        assert done.returncode == ch.EXIT_INPUT, done.stderr
        assert str(bad) in done.stderr
        compared = run("compare_histories.py", run_history, bad)
        assert compared.returncode == 2, compared.stderr
        assert f"{bad}: cannot read" in compared.stderr


def test_random_damage_never_hangs_a_reader(run_history, tmp_path):
    # every reader ends within the limit (subprocess.run raises TimeoutExpired otherwise), and
    # never by a signal: HDF5 1.10 crashes (SIGSEGV, SIGABRT) on some of these files, in the
    # child process that does the reading, and the reader says so naming the file
    for seed in range(1, 9):
        bad = flipped(run_history, tmp_path / f"flipped{seed}.h5", seed)
        done = run("lineage.py", bad, "--output", tmp_path / "lineage.png")
        assert done.returncode in (0, ch.EXIT_INPUT), (seed, done.returncode, done.stderr)
        if done.returncode == ch.EXIT_INPUT:
            assert str(bad) in done.stderr
        compared = run("compare_histories.py", run_history, bad, "--quiet")
        assert compared.returncode in (1, 2), (seed, compared.returncode, compared.stderr)
        if compared.returncode == 2:
            assert str(bad) in compared.stderr


def test_a_file_that_sends_hdf5_into_an_endless_loop_ends_within_the_bound(tmp_path):
    # found by fuzzing: HDF5 1.10 loops in H5HG_read on one of this file's string attributes;
    # the header is read first in a child process with a time bound
    looping = os.path.join(os.path.dirname(ANALYSIS), "tests", "store", "data",
                           "history_hdf5_endless_loop.h5")
    env = dict(os.environ, MPLBACKEND="Agg", CAMBRIAN_READ_SECONDS="2")
    for script, arguments in (("lineage.py", [looping, "--output", tmp_path / "l.png"]),
                              ("compare_histories.py", [looping, looping])):
        done = subprocess.run([sys.executable, os.path.join(ANALYSIS, script), *map(str, arguments)],
                              capture_output=True, text=True, env=env, timeout=LIMIT)
        assert done.returncode in (ch.EXIT_INPUT, 2), done.stderr
        assert looping in done.stderr
        assert "did not end in 2 s" in done.stderr, done.stderr
