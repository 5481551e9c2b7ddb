"""Tests of analysis/scaling.py: Amdahl, Gustafson and Karp–Flatt on synthetic curves with a
known serial fraction, the grouping of repeats, and the fixture sweep (1 and 2 workers)."""

import os

import numpy as np
import pytest

import scaling

PNG = b"\x89PNG\r\n\x1a\n"
P = np.array([1, 2, 4, 8, 16, 64, 1024])


# Karp–Flatt of an exact Amdahl curve is its serial fraction at every p > 1
@pytest.mark.parametrize("s", [0.0, 0.01, 0.05, 0.3])
def test_karp_flatt_recovers_amdahl_serial_fraction(s):
    e = scaling.karp_flatt(scaling.amdahl_speedup(s, P), P)
    assert np.isnan(e[0])
    assert np.allclose(e[1:], s, atol=1e-12)


# the least-squares fits recover the serial fraction of exact curves
@pytest.mark.parametrize("s", [0.0, 0.002, 0.05, 0.5, 1.0])
def test_fits_recover_serial_fraction(s):
    assert scaling.fit_amdahl(P, scaling.amdahl_speedup(s, P)) == pytest.approx(s, abs=1e-6)
    assert scaling.fit_gustafson(P, scaling.gustafson_speedup(s, P)) == pytest.approx(s, abs=1e-12)


def fake_runs(times, population=lambda p: 300):
    """Run dicts as read_run makes them: {workers: [median generation times of repeats]}."""
    return [{"path": f"w{p}/r{i}", "workers": p, "population": population(p), "generations": 4, "time": t,
             "times": np.array([t]), "rank0_share": 0.01, "evaluations": 240.0, "rank0_serial": 0.001}
            for p, repeats in times.items() for i, t in enumerate(repeats)]


# repeats are grouped per worker count; strong speedup, efficiency and spread follow
def test_strong_points_from_repeats():
    s = 0.1
    times = {p: [10 * (s + (1 - s) / p) * f for f in (0.9, 1.0, 1.3)] for p in (1, 2, 4, 8)}
    rows, fitted, base = scaling.points(fake_runs(times), "strong")
    assert base == 1 and [r["workers"] for r in rows] == [1, 2, 4, 8]
    assert all(r["repeats"] == 3 for r in rows)
    assert rows[0]["speedup"] == 1.0 and rows[0]["efficiency"] == 1.0
    for r in rows:
        assert r["speedup"] == pytest.approx(1 / (s + (1 - s) / r["workers"]))
        assert r["efficiency"] == pytest.approx(r["speedup"] / r["workers"])
        assert r["speedup_min"] < r["speedup"] < r["speedup_max"]
        assert r["time_min"] <= r["time_median"] <= r["time_max"]
    assert all(r["serial_fraction"] == pytest.approx(s) for r in rows[1:])
    assert fitted == pytest.approx(s, abs=1e-6)


# weak scaling: the scaled speedup of a Gustafson sweep recovers its serial fraction
def test_weak_points_recover_gustafson():
    s = 0.2
    # scaled speedup p - s (p - 1) means T(p) = p T(1) / (p - s (p - 1))
    times = {p: [5.0 * p / (p - s * (p - 1))] for p in (1, 2, 4, 8)}
    runs = fake_runs(times, population=lambda p: 30 * p)
    assert scaling.check_sweep(runs, "weak") == []
    assert scaling.check_sweep(runs, "strong")  # populations differ: a warning
    rows, fitted, _ = scaling.points(runs, "weak")
    assert fitted == pytest.approx(s, abs=1e-9)
    assert rows[0]["speedup"] == 1.0
    for r in rows[1:]:
        assert r["speedup"] == pytest.approx(r["workers"] - s * (r["workers"] - 1))
        assert r["serial_fraction"] == pytest.approx(s)


# a sweep that starts at 2 workers gives speedups relative to 2
def test_relative_speedup_without_one_worker():
    rows, _, base = scaling.points(fake_runs({2: [4.0], 4: [2.0]}), "strong")
    assert base == 2 and rows[0]["speedup"] == 2.0 and rows[1]["speedup"] == 4.0


# the fixture sweep: one point per worker count, measured from the histories
def test_fixture_sweep(sweep_dir):
    runs = scaling.load_sweep([sweep_dir], 1)
    assert sorted({r["workers"] for r in runs}) == [1, 2]
    rows, fitted, base = scaling.points(runs, "strong")
    assert base == 1 and rows[0]["speedup"] == 1.0 and 0.0 <= fitted <= 1.0
    for r in rows:
        assert r["time_median"] > 0 and 0.0 <= r["rank0_share"] < 1.0 and r["population"] > 0
        # rank 0 waits asleep while the workers evaluate: CPU well under its wall time
        # (a property of the optimised build: under the sanitizers their own work is most of it)
        if os.environ.get("CAMBRIAN_SANITIZED", "OFF") in ("", "0", "OFF"):
            assert 0.0 < r["rank0_cpu_share"] < 0.5
        assert r["generations"] == r["repeats"] * (runs[0]["generations"])


def test_command_line_on_the_sweep(sweep_dir, run_script, tmp_path):
    result = run_script("scaling", sweep_dir, "--output", tmp_path / "s.png", "--table", tmp_path / "s.tsv",
                        "--markdown", tmp_path / "s.md")
    assert result.returncode == 0, result.stderr
    assert (tmp_path / "s.png").read_bytes()[:8] == PNG
    assert "# amdahl_serial_fraction" in result.stdout
    lines = (tmp_path / "s.tsv").read_text().splitlines()
    assert lines[0].split("\t") == scaling.COLUMNS and len(lines) == 3
    assert "Karp–Flatt" in (tmp_path / "s.md").read_text()


def test_errors(tmp_path, capsys):
    assert scaling.main([str(tmp_path)]) == 4  # an empty directory
    assert "no history.h5" in capsys.readouterr().err
    bad = tmp_path / "w1" / "history.h5"
    bad.parent.mkdir()
    bad.write_text("x")
    assert scaling.main([str(tmp_path)]) == 4
    assert str(bad) in capsys.readouterr().err
    with pytest.raises(SystemExit) as exit_:
        scaling.main([str(tmp_path), "--mode", "sideways"])
    assert exit_.value.code == 2
