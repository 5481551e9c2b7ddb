"""Tests of analysis/report.py: every section of the page on the fixture run (synthetic, finished),
on a walk run while it is still going (history read as SWMR, creatures replayed into the
viewer), and bad input named with its exit code."""

import os
import re
import signal
import subprocess
import sys
import time

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
import cambrian_history as ch  # noqa: E402

RUN_DIR = os.environ.get("CAMBRIAN_RUN_DIR")
BINARY = os.environ.get("CAMBRIAN_BINARY")
SECTIONS = ("run", "fitness", "lineage", "operators", "diversity", "load", "creatures")


def run_report(*arguments):
    env = dict(os.environ, MPLBACKEND="Agg")
    return subprocess.run([sys.executable, os.path.join(ROOT, "analysis", "report.py"), *map(str, arguments)],
                          capture_output=True, text=True, env=env)


def sections(text):
    """section id -> its HTML."""
    found = dict(re.findall(r'<section id="(\w+)">(.*?)</section>', text, re.S))
    assert set(found) == set(SECTIONS), sorted(found)
    return found


@pytest.mark.skipif(not RUN_DIR, reason="CAMBRIAN_RUN_DIR not set (run through ctest)")
def test_every_section_of_a_finished_run(tmp_path):
    page = tmp_path / "report.html"
    done = run_report(RUN_DIR, "-o", page)
    assert done.returncode == 0, done.stderr
    text = page.read_text()
    found = sections(text)
    for name in ("fitness", "lineage", "operators", "diversity", "load"):
        assert 'src="data:image/png;base64,' in found[name], name
        assert "could not make this section" not in found[name], found[name]
    with ch.History(os.path.join(RUN_DIR, "history.h5")) as history:
        attributes, generations = history.attributes, history.generations()
    assert f"<th>seed</th><td>{attributes['seed']}</td>" in found["run"]
    assert f"{len(generations['generation'])} of {len(generations['generation'])}" in found["run"]
    assert "finished or stopped" in found["run"] and attributes["config_hash"] in found["run"]
    assert "synthetic task has no bodies" in found["creatures"]
    # the per-operator table is there, as a table, not as text
    assert re.search(r"<th>operator</th>", found["operators"])
    # nothing outside the page
    assert not re.search(r'<(script|link|img)[^>]+(src|href)="(http|/|file)', text)


@pytest.mark.skipif(not BINARY, reason="CAMBRIAN_BINARY not set (run through ctest)")
def test_a_run_still_going_on_with_its_creatures(tmp_path):
    run = tmp_path / "live"
    evolve = subprocess.Popen([BINARY, "evolve", "--evolution.population", "6", "--evolution.generations", "400",
                               "--task.evaluation_time", "1", "--seed", "4", "--quiet", "--out", str(run)],
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    try:
        history = run / "history.h5"
        deadline = time.time() + 120
        while True:
            assert evolve.poll() is None, evolve.stderr.read().decode()
            if history.exists():
                try:
                    with ch.History(str(history)) as h:
                        if len(h.generations()["generation"]) >= 3:
                            break
                except ch.HistoryError:
                    pass
            assert time.time() < deadline, "the run wrote no 3 generations in 120 s"
            time.sleep(0.5)
        page = tmp_path / "live.html"
        done = run_report(run, "-o", page, "--generation", 0, 1, "--cambrian", BINARY)
        assert evolve.poll() is None, "the run ended before the report was written: not a live test"
    finally:
        evolve.send_signal(signal.SIGTERM)
        evolve.wait(timeout=60)
    assert done.returncode == 0, done.stderr
    found = sections(page.read_text())
    assert "going on (run.lock held)" in found["run"]
    assert '<iframe class="viewer"' in found["creatures"]
    assert "generation 0" in found["creatures"] and "generation 1" in found["creatures"]
    assert "could not make this section" not in page.read_text()


def test_bad_input_is_named_with_its_exit_code(tmp_path):
    missing = run_report(tmp_path / "none")
    assert missing.returncode == ch.EXIT_INPUT and "none" in missing.stderr
    empty = tmp_path / "empty"
    empty.mkdir()
    no_history = run_report(empty)
    assert no_history.returncode == ch.EXIT_INPUT and "history.h5" in no_history.stderr
    assert not (empty / "report.html").exists()
    assert run_report(empty, "--generation", "-1").returncode == ch.EXIT_USAGE
