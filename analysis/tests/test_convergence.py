"""Tests of analysis/convergence.py: the comparison measures on made-up data, and, when CTest
names the binary in CAMBRIAN_BINARY, a tiny study (two hand-written creatures, three variants,
two nudges, 1 s measured) run and reported end to end."""

import os
import subprocess
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import convergence  # noqa: E402

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "convergence.py")
CREATURES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "jobs", "creatures")


def straight(speed, seconds=4.0, rate=20.0, start=(0.0, 0.0)):
    """A path along x at `speed` m/s from `start`."""
    time = np.arange(0.0, seconds + 1e-9, 1.0 / rate)
    com = np.stack([start[0] + speed * time, np.full_like(time, start[1])], axis=1)
    return time, com


def test_a_path_stays_with_the_reference_until_it_is_5_cm_off():
    # 0.12 m/s apart: 5 cm after 0.417 s, so first seen at 0.45 s on the 0.05 s grid
    seconds = convergence.time_with_reference(straight(1.12), straight(1.0))
    assert seconds == pytest.approx(0.45, abs=1e-9)
    # the same path, started elsewhere: paths are compared from their own start
    assert convergence.time_with_reference(straight(1.0, start=(3, 4)), straight(1.0)) == pytest.approx(4.0)


def test_relative_error_has_a_floor_for_creatures_that_do_not_walk():
    assert convergence.relative_error(2.2, 2.0) == pytest.approx(0.1)
    assert convergence.relative_error(0.05, 0.0) == pytest.approx(0.5)  # 5 cm against the 0.1 m floor


def test_agreement_allows_for_the_runs_own_chaos():
    assert convergence.agrees([2.05, 2.05], [2.0, 2.0])  # within 10 %
    assert not convergence.agrees([3.0, 3.0], [2.0, 2.0])  # 50 % off, no spread
    # a chaotic walker: 1 m or 3 m by chance; a mean 40 % off is within two standard errors
    assert convergence.agrees([1.0, 3.0, 1.0, 3.0], [3.0, 1.0, 3.0, 3.0])


def test_variants_build_on_the_reference_and_nudges_are_tiny():
    assert convergence.VARIANTS["torque: reference"]["physics.actuation"] == "torque"
    assert convergence.VARIANTS["torque: reference"]["physics.time_step"] == "0.001"
    assert convergence.nudges(3) == [0, 1, 2]
    assert float(convergence.nudged_gravity(2)) == pytest.approx(9.81 * (1 + 2e-6), rel=1e-15)


def test_summary_and_table_from_results_without_trajectories():
    rows = []
    for creature, distances in (("a", {"reference": [1.0, 1.2], "default": [1.1, 1.1]}),
                                ("b", {"reference": [2.0, 2.0], "default": [3.0, 3.0]})):
        for variant, values in distances.items():
            for nudge, value in enumerate(values):
                rows.append({"creature": creature, "variant": variant, "nudge": str(nudge), "status": "ok",
                             "fitness": repr(value), "steps": "100",
                             "wall_seconds": "2" if variant == "reference" else "1", "trajectory": "-"})
    summary, reference = convergence.summarise(rows, ".", load_paths=False)
    by_name = {s["variant"]: s for s in summary}
    assert by_name["default"]["within"] == pytest.approx(0.5)  # a agrees, b is 50 % off
    assert by_name["default"]["cost"] == pytest.approx(1.0)
    assert by_name["reference"]["cost"] == pytest.approx(2.0)
    assert reference["a"]["mean"] == pytest.approx(1.1)
    table = convergence.markdown(summary)
    assert table.splitlines()[0].startswith("| variant | creatures | median error")
    assert "| default | 2 |" in table


def test_any_variant_can_be_the_reference():
    # against "reference" the default is 50 % off for b; against a reference at the default's
    # controller rate it agrees for both creatures
    rows = []
    for creature, distances in (("a", {"reference": [1.0, 1.0], "default": [1.0, 1.0],
                                       "reference, 240 Hz controller": [1.02, 1.02]}),
                                ("b", {"reference": [2.0, 2.0], "default": [3.0, 3.0],
                                       "reference, 240 Hz controller": [2.9, 2.9]})):
        for variant, values in distances.items():
            for nudge, value in enumerate(values):
                rows.append({"creature": creature, "variant": variant, "nudge": str(nudge), "status": "ok",
                             "fitness": repr(value), "steps": "100", "wall_seconds": "1", "trajectory": "-"})
    plain = {s["variant"]: s for s in convergence.summarise(rows, ".", load_paths=False)[0]}
    assert plain["default"]["agree"] == pytest.approx(0.5)
    summary, reference = convergence.summarise(rows, ".", load_paths=False,
                                               reference_name="reference, 240 Hz controller")
    by_name = {s["variant"]: s for s in summary}
    assert by_name["default"]["agree"] == pytest.approx(1.0)
    assert by_name["reference, 240 Hz controller"]["median_error"] == 0
    assert reference["b"]["mean"] == pytest.approx(2.9)
    assert convergence.VARIANTS["reference, 240 Hz controller"]["physics.substeps"] == "5"


def test_the_bootstrap_spreads_a_marginal_agreement_and_not_a_clear_one():
    rows = []
    for creature, (reference, variant) in {"clear": ([1.0, 1.0, 1.0, 1.0], [1.0, 1.0, 1.0, 1.0]),
                                           "marginal": ([1.0, 1.4, 1.0, 1.4], [1.1, 1.5, 1.3, 1.6])}.items():
        for name, values in (("reference", reference), ("default", variant)):
            for nudge, value in enumerate(values):
                rows.append({"creature": creature, "variant": name, "nudge": str(nudge), "status": "ok",
                             "fitness": repr(value), "steps": "100", "wall_seconds": "1", "trajectory": "-"})
    low, middle, high = convergence.bootstrap_agreement(rows, "default", "reference", 200)
    assert 0.5 <= low <= middle <= high <= 1.0
    assert low == 0.5 and high == 1.0  # "clear" always agrees, "marginal" only sometimes
    assert convergence.bootstrap_agreement(rows, "reference", "reference", 50)[2] == 1.0
    assert convergence.bootstrap_agreement(rows, "warp drive", "reference", 10) is None


def test_bad_inputs_name_what_is_wrong(tmp_path):
    done = subprocess.run([sys.executable, SCRIPT, "report", "--out", str(tmp_path)], capture_output=True, text=True)
    assert done.returncode == 4
    assert "results.tsv" in done.stderr
    done = subprocess.run([sys.executable, SCRIPT, "run", "--cambrian", "x", "--creatures", str(tmp_path / "none"),
                           "--out", str(tmp_path)], capture_output=True, text=True)
    assert done.returncode == 4
    assert "not a directory" in done.stderr
    done = subprocess.run([sys.executable, SCRIPT, "run", "--cambrian", "x", "--creatures", CREATURES,
                           "--out", str(tmp_path), "--variant", "warp drive"], capture_output=True, text=True)
    assert done.returncode == 4
    assert "warp drive" in done.stderr
    (tmp_path / "results.tsv").write_text(
        "creature\tvariant\tnudge\tstatus\tfitness\tsteps\twall_seconds\ttrajectory\n"
        "a\tdefault\t0\tok\t1.0\t100\t1\t-\n")
    done = subprocess.run([sys.executable, SCRIPT, "report", "--out", str(tmp_path), "--no-paths",
                           "--reference", "warp drive"], capture_output=True, text=True)
    assert done.returncode == 4
    assert "--reference 'warp drive'" in done.stderr
    done = subprocess.run([sys.executable, SCRIPT, "report", "--out", str(tmp_path), "--no-paths"],
                          capture_output=True, text=True)
    assert done.returncode == 4
    assert "no runs of the reference 'reference'" in done.stderr


@pytest.mark.skipif("CAMBRIAN_BINARY" not in os.environ, reason="CTest names the binary")
def test_a_tiny_study_end_to_end(tmp_path):
    creatures = tmp_path / "creatures"
    creatures.mkdir()
    for name in ("walker4", "single_block"):
        (creatures / f"{name}.genome").write_text(open(os.path.join(CREATURES, f"{name}.genome")).read())
    out = tmp_path / "out"
    command = [sys.executable, SCRIPT, "run", "--cambrian", os.environ["CAMBRIAN_BINARY"], "--creatures",
               str(creatures), "--out", str(out), "--perturbations", "2", "--jobs", "2", "--quiet",
               "--variant", "reference", "--variant", "default", "--variant", "240Hz x1, 10 it",
               "--set", "task.evaluation_time=1"]
    subprocess.run(command, check=True)
    rows = convergence.read_results(str(out / "results.tsv"))
    assert len(rows) == 2 * 3 * 2
    # run again: nothing new to evaluate
    subprocess.run(command, check=True)
    assert len(convergence.read_results(str(out / "results.tsv"))) == 12
    done = subprocess.run([sys.executable, SCRIPT, "report", "--out", str(out), "--figure", str(tmp_path / "c.png")],
                          capture_output=True, text=True, check=True)
    assert "| reference | 2 | 0.0 % |" in done.stdout
    assert "| walker4 |" in done.stdout
    assert (tmp_path / "c.png").stat().st_size > 1000
