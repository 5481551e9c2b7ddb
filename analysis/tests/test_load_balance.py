"""Tests of analysis/load_balance.py on the fixture run's history: per-worker sums agree with
the generations table, utilisation is a share, and the command line."""

import numpy as np
import pytest

import cambrian_history as ch
import load_balance

PNG = b"\x89PNG\r\n\x1a\n"


@pytest.fixture(scope="module")
def tables(run_history):
    with ch.History(run_history) as h:
        return h.attributes, h.individuals(), h.generations()


# evaluations and busy seconds per worker add up to the generations table's totals
def test_per_worker_sums(tables):
    attributes, t, g = tables
    workers = load_balance.per_worker(t)
    assert sum(w[0] for w in workers.values()) == int(np.sum(g["evaluations"]))
    assert sum(w[1] for w in workers.values()) == pytest.approx(float(np.sum(g["worker_busy_seconds"])), rel=1e-3, abs=1e-5)
    expected = set(range(1, int(attributes["rank_count"]))) if int(attributes["rank_count"]) > 1 else {0}
    assert set(workers) == expected  # every worker rank took part, copies (-1) left out
    for n, busy, mean, peak in workers.values():
        assert mean == pytest.approx(busy / n) and peak >= mean


# utilisation is busy / (workers * span), a share; imbalance is at least 1
def test_per_generation_utilisation(tables):
    _, t, g = tables
    rows = load_balance.per_generation(t, g)
    assert len(rows) == len(g["generation"])
    for row, i in zip(rows, range(len(rows))):
        expected = g["worker_busy_seconds"][i] / (g["workers"][i] * g["evaluation_span_seconds"][i])
        assert row["utilisation"] == pytest.approx(expected)
        assert 0 < row["utilisation"] <= 1.0 + 1e-9
        assert row["imbalance"] >= 1.0
        assert row["busy_seconds"] + row["idle_seconds"] == pytest.approx(row["workers"] * row["span_seconds"], rel=1e-3, abs=1e-5)


# a generation where one of two workers did everything has imbalance 2
def test_imbalance_of_a_lopsided_generation():
    t = {"generation": np.array([0, 0, 0], np.uint64), "worker_rank": np.array([1, 1, -1], np.int32),
         "eval_seconds": np.array([1.0, 2.0, 0.0])}
    g = {"generation": np.array([0], np.uint64), "workers": np.array([2], np.int32), "evaluations": np.array([2], np.uint64),
         "evaluation_span_seconds": np.array([3.0]), "worker_busy_seconds": np.array([3.0]),
         "worker_idle_seconds": np.array([3.0])}
    row = load_balance.per_generation(t, g)[0]
    assert row["imbalance"] == 2.0 and row["utilisation"] == 0.5
    assert load_balance.per_worker(t) == {1: (2, 3.0, 1.5, 2.0)}


def test_command_line(sweep_dir, run_history, tmp_path, capsys):
    assert load_balance.main([run_history, "--output", str(tmp_path / "lb.png"), "--table", str(tmp_path / "lb.tsv")]) == 0
    assert (tmp_path / "lb.png").read_bytes()[:8] == PNG
    assert "worker_rank\tevaluations\tbusy_seconds" in capsys.readouterr().out
    assert (tmp_path / "lb.tsv").read_text().startswith("generation\tworkers")


def test_runs_as_a_script(sweep_dir, run_script):
    result = run_script("load_balance", "--help")
    assert result.returncode == 0 and "--bins" in result.stdout


def test_errors(tmp_path, capsys):
    with pytest.raises(SystemExit) as exit_:
        load_balance.main([str(tmp_path / "gone.h5")])
    assert exit_.value.code == 4 and "gone.h5" in capsys.readouterr().err
    with pytest.raises(SystemExit) as exit_:
        load_balance.main(["x.h5", "--bins", "0"])
    assert exit_.value.code == 2
