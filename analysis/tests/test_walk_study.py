"""Tests of walk_study.py: steadiness of motion from trajectories, and the whole script on the
test suite's run (CAMBRIAN_RUN_DIR)."""

import os
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
import walk_study  # noqa: E402


def trajectory(positions_x, rate=10.0):
    """A measured-phase-only trajectory whose centre of mass moves along x as given."""
    x = np.asarray(positions_x, dtype=float)
    com = np.zeros((len(x), 3))
    com[:, 0] = x
    return {
        "time": np.arange(len(x)) / rate,
        "phase": np.full(len(x), walk_study.MEASURE_PHASE),
        "center_of_mass": com,
    }


def test_steady_walker_moves_every_second():
    walker = trajectory(np.linspace(0, 5, 101))  # 10 s at 0.5 m/s
    progress = walk_study.per_second_progress(walker)
    assert len(progress) == 10
    assert np.allclose(progress, 0.5)
    assert walk_study.steadiness(progress) == 1.0


def test_creature_that_falls_over_moves_in_one_second():
    x = np.concatenate([np.linspace(0, 2, 11), np.full(90, 2.0)])  # all in the first second
    progress = walk_study.per_second_progress(trajectory(x))
    assert progress[0] == pytest.approx(2.0)
    assert walk_study.steadiness(progress) == pytest.approx(0.1)


def test_direction_is_the_net_displacement():
    walker = trajectory(np.linspace(0, -3, 101))  # walking backwards counts as travel
    assert walk_study.steadiness(walk_study.per_second_progress(walker)) == 1.0


def test_only_the_measured_phase_counts():
    walker = trajectory(np.linspace(0, 5, 101))
    walker["phase"][:50] = 0  # settle
    assert len(walk_study.per_second_progress(walker)) == 5


@pytest.mark.skipif("CAMBRIAN_RUN_DIR" not in os.environ, reason="needs the test suite's run")
def test_script_on_a_run(tmp_path, capsys):
    output = tmp_path / "study.png"
    code = walk_study.main(["--run", "run=" + os.environ["CAMBRIAN_RUN_DIR"], "--output", str(output)])
    assert code == 0
    assert output.stat().st_size > 0
    assert "| run |" in capsys.readouterr().out


def test_missing_run_is_exit_4(tmp_path):
    assert walk_study.main(["--run", "x=" + str(tmp_path / "absent"), "--output", str(tmp_path / "a.png")]) == 4
