"""Tests of compare_histories.py on small history files written here with h5py (and, when CTest
passes CAMBRIAN_RUN_DIR, on the history of a real run compared with itself)."""

import os
import subprocess
import sys

import h5py
import numpy as np
import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(os.path.dirname(HERE), "compare_histories.py")
sys.path.insert(0, os.path.dirname(HERE))
import compare_histories as cmp  # noqa: E402

CONFIG = "[evolution]\ngenerations = 3\npopulation = 4\n\n[run]\nout = {out}\nseed = 5\n"


def write_history(path, out="a", rank_count=1, fitness=None, eval_seconds=None, seed=5,
                  extra=None, run_only=None):
    """A miniature history: root attributes, /individuals and /generations columns."""
    fitness = np.array([1.0, 2.0, np.nan, 0.5]) if fitness is None else np.asarray(fitness)
    eval_seconds = np.array([0.1, 0.2, 0.3, 0.4]) if eval_seconds is None else eval_seconds
    with h5py.File(path, "w") as f:
        f.attrs["format"] = "cambrian-history"
        f.attrs["config_text"] = CONFIG.format(out=out)
        f.attrs["seed"] = np.uint64(seed)
        f.attrs["start_time"] = f"2024-01-0{rank_count}T00:00:00Z"
        f.attrs["rank_count"] = np.int32(rank_count)
        if run_only is not None:
            f.attrs["run_only_settings"] = np.array(run_only, dtype=h5py.string_dtype())
        ind = f.create_group("individuals")
        ind.create_dataset("id", data=np.arange(4, dtype=np.uint64))
        d = ind.create_dataset("fitness", data=fitness)
        d.attrs["units"] = "task"
        ind.create_dataset("eval_seconds", data=eval_seconds)
        ind.create_dataset("worker_rank", data=np.array([1, 2, 1, 2], dtype=np.int32) * rank_count)
        ind.create_dataset("measures", data=np.zeros((4, 2)))
        gen = f.create_group("generations")
        gen.create_dataset("best", data=np.array([2.0]))
        gen.create_dataset("wall_seconds", data=np.array([rank_count * 1.5]))
        if extra:
            gen.create_dataset(extra, data=np.array([1]))


@pytest.fixture
def pair(tmp_path):
    a, b = tmp_path / "a.h5", tmp_path / "b.h5"
    write_history(a)
    return a, b


def run(*args):
    return subprocess.run([sys.executable, SCRIPT, *map(str, args)], capture_output=True,
                          text=True, env=dict(os.environ, MPLBACKEND="Agg"))


def test_help():
    result = run("--help")
    assert result.returncode == 0
    assert "timing" in result.stdout


def test_identical_except_timing_and_run_only_settings(pair):
    a, b = pair
    write_history(b, out="elsewhere", rank_count=2, eval_seconds=np.array([9.0, 8.0, 7.0, 6.0]))
    result = run(a, b)
    assert result.returncode == 0, result.stdout
    assert "identical" in result.stdout
    assert cmp.compare(str(a), str(b)) == []


def test_run_only_keys_come_from_the_files(pair):
    # files that list their run-only keys: a listed key is not compared, run.out (not listed
    # here) is
    a, b = pair
    write_history(a, run_only=["evolution.population"])
    write_history(b, out="elsewhere", run_only=["evolution.population"])
    with h5py.File(b, "a") as f:
        f.attrs["config_text"] = CONFIG.format(out="elsewhere").replace("population = 4",
                                                                       "population = 9")
    differences = cmp.compare(str(a), str(b))
    assert any("run.out" in line for line in differences), differences
    assert not any("population" in line for line in differences), differences
    # files without the attribute fall back to the keys that were run-only before it existed
    write_history(a)
    with h5py.File(a, "r") as f:
        assert "run.out" in cmp.run_only_settings(f)
        assert "evolution.population" not in cmp.run_only_settings(f)


def test_changed_fitness_is_reported_with_row(pair):
    a, b = pair
    write_history(b, fitness=[1.0, 2.0, np.nan, 0.5000000000000001])
    result = run(a, b)
    assert result.returncode == 1
    assert "/individuals/fitness: 1 row(s) differ" in result.stdout
    assert "row 3" in result.stdout


def test_nan_equals_nan_bitwise(pair):
    a, b = pair
    write_history(b)
    assert cmp.compare(str(a), str(b)) == []


def test_changed_result_setting_is_reported(pair):
    a, b = pair
    write_history(b, seed=6)
    differences = cmp.compare(str(a), str(b))
    assert any("attribute seed" in line for line in differences)


def test_missing_dataset_and_shape(pair, tmp_path):
    a, b = pair
    write_history(b, extra="distinct_genomes")
    differences = cmp.compare(str(a), str(b))
    assert any("/generations/distinct_genomes: only in B" in line for line in differences)
    c = tmp_path / "c.h5"
    write_history(c, fitness=[1.0, 2.0, np.nan], eval_seconds=np.array([0.1, 0.2, 0.3]))
    differences = cmp.compare(str(a), str(c))
    assert any("shape" in line for line in differences)


def test_ignore_option(pair):
    a, b = pair
    write_history(b, fitness=[5.0, 2.0, np.nan, 0.5])
    assert run(a, b, "--ignore", "individuals/fitness").returncode == 0


def test_unreadable_file_exits_2(pair, tmp_path):
    a, _ = pair
    bad = tmp_path / "bad.h5"
    bad.write_bytes(b"not hdf5")
    result = run(a, bad)
    assert result.returncode == 2
    assert "cannot read" in result.stderr


@pytest.mark.skipif(not os.environ.get("CAMBRIAN_RUN_DIR"), reason="CAMBRIAN_RUN_DIR not set")
def test_real_history_equals_itself():
    path = os.path.join(os.environ["CAMBRIAN_RUN_DIR"], "history.h5")
    result = run(path, path)
    assert result.returncode == 0, result.stdout
