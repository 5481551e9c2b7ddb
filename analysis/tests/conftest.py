"""Shared fixtures of the analysis tests: the history of a small synthetic run
(CAMBRIAN_RUN_DIR, set by CTest) and, for the scaling tests, a small sweep of runs
(CAMBRIAN_SWEEP_DIR, set by tests/analysis/CMakeLists.txt); tests needing one skip without it."""

import os
import subprocess
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
ANALYSIS = os.path.dirname(HERE)
sys.path.insert(0, ANALYSIS)


@pytest.fixture(scope="session")
def run_history():
    """Path of the fixture run's history.h5 (skips when CTest did not provide it)."""
    run_dir = os.environ.get("CAMBRIAN_RUN_DIR")
    if not run_dir:
        pytest.skip("CAMBRIAN_RUN_DIR not set (run through ctest)")
    return os.path.join(run_dir, "history.h5")


@pytest.fixture(scope="session")
def sweep_dir():
    """Directory of the fixture sweep (runs at 1 and 2 workers; skips without it). Tests that
    draw PNGs or start Python ask for it too, so that the store label's pytest over this folder
    (on a one-rank run, no sweep) stays quick."""
    sweep = os.environ.get("CAMBRIAN_SWEEP_DIR")
    if not sweep:
        pytest.skip("CAMBRIAN_SWEEP_DIR not set (run through ctest -L analysis)")
    return sweep


@pytest.fixture(scope="session")
def run_script():
    """Runs analysis/<name>.py with arguments; returns the CompletedProcess (text)."""

    def run(name, *arguments):
        script = os.path.join(ANALYSIS, name + ".py")
        env = dict(os.environ, MPLBACKEND="Agg")
        return subprocess.run([sys.executable, script, *map(str, arguments)], capture_output=True, text=True, env=env)

    return run


PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
