"""Tests of analysis/improvements.py: outcome classes and points of improvement on a hand-made
table with known answers, consistency with the fixture run's history, and the command line."""

import numpy as np
import pytest

import cambrian_history as ch
import improvements

PNG = b"\x89PNG\r\n\x1a\n"
NO = ch.NO_ID


def hand_made():
    """Generation 0: ids 0 (fitness 1) and 1 (2). Generation 1: 2 = mutation of 0 (1.5, better),
    3 = crossover of 0 and 1 (1.8, worse than the better parent), 4 = crossover of 1 with itself
    (3.0: better, new champion), 5 = graft of 0 and 1 (2.0, same), 6 = mutation failed."""
    table = {
        "id": np.arange(7, dtype=np.uint64),
        "generation": np.array([0, 0, 1, 1, 1, 1, 1], np.uint64),
        "parent_a": np.array([NO, NO, 0, 0, 1, 0, 1], np.uint64),
        "parent_b": np.array([NO, NO, NO, 1, 1, 1, NO], np.uint64),
        "fitness": np.array([1.0, 2.0, 1.5, 1.8, 3.0, 2.0, 0.0]),
        "status": np.array([0, 0, 0, 0, 0, 0, 3], np.uint8),
    }
    labels = np.array(["random", "random", "mutation", "crossover", "crossover", "graft", "mutation"])
    return table, labels


# each offspring is classed against its better parent; identical parents are labelled
def test_classes_of_a_hand_made_table():
    table, labels = hand_made()
    classes = improvements.classify(table, labels, ["ok", "invalid_body", "x", "exploded"])
    got = {row: (label, outcome, reference) for row, label, outcome, reference in classes}
    assert got == {2: ("mutation", "improved", 1.0), 3: ("crossover", "worse", 2.0),
                   4: ("crossover (same parents)", "improved", 2.0), 5: ("graft", "same", 2.0),
                   6: ("mutation", "failed", 2.0)}
    points = improvements.points_of_improvement(table, labels)
    assert points == [{"generation": 1, "id": 4, "operator": "crossover", "fitness": 3.0,
                       "previous": 2.0, "gain": 1.0}]
    points = improvements.points_of_improvement(table, labels, classes)
    assert points[0]["operator"] == "crossover (same parents)"
    summary = improvements.summarise(classes, points, table)
    assert summary["mutation"]["offspring"] == 2 and summary["mutation"]["improved"] == 1
    assert summary["mutation"]["failed"] == 1 and improvements.rate(summary["mutation"]) == 0.5
    assert summary["crossover (same parents)"]["points"] == 1 and summary["graft"]["same"] == 1


# Krčah's mutant classes: zero fitness or failed, the same fitness as the (better) parent, another
# non-zero fitness
def test_mutant_classes_of_a_hand_made_table():
    table, labels = hand_made()
    # two more mutants of 0: one with its parent's fitness, one with fitness 0 and status ok
    for name in table:
        extra = {"id": [7, 8], "generation": [1, 1], "parent_a": [0, 0], "parent_b": [NO, NO],
                 "fitness": [1.0, 0.0], "status": [0, 0]}[name]
        table[name] = np.concatenate([table[name], np.array(extra, dtype=table[name].dtype)])
    labels = np.concatenate([labels, ["mutation", "mutation"]])
    classes = improvements.classify(table, labels, ["ok", "invalid_body", "x", "exploded"])
    counts = improvements.mutant_classes(table, classes)
    assert counts["mutation"] == {"offspring": 4, "zero": 2, "same": 1, "different": 1}
    assert counts["graft"] == {"offspring": 1, "zero": 0, "same": 1, "different": 0}
    assert counts["crossover"] == {"offspring": 1, "zero": 0, "same": 0, "different": 1}
    rows = improvements.mutant_rows(counts)
    assert rows[0].startswith("operator\toffspring\tzero\tsame\tdifferent")
    assert "mutation\t4\t2\t1\t1\t0.5000\t0.2500\t0.2500" in rows


# identical genome bytes count as identical parents even with different ids
def test_identical_genomes_count_as_same_parents():
    table, labels = hand_made()
    classes = improvements.classify(table, labels, ["ok"], genomes=lambda row: b"CMBG")
    assert {label for _, label, _, _ in classes if label.startswith("crossover")} == {"crossover (same parents)"}


# on the fixture run: every bred offspring is classed once; points follow the generation bests
def test_fixture_counts_agree_with_the_history(run_history):
    with ch.History(run_history) as h:
        t, g = h.individuals(), h.generations()
        labels = ch.operator_labels(h, t)
        statuses = h.status_names()
    classes = improvements.classify(t, labels, statuses)
    bred = np.isin(labels, ["mutation", "crossover", "graft"]) & (t["generation"] > 0)
    assert len(classes) == int(bred.sum()) > 0
    points = improvements.points_of_improvement(t, labels)
    expected = [int(gen) for i, gen in enumerate(g["generation"]) if i > 0 and g["best"][i] > g["best"][:i].max()]
    assert [p["generation"] for p in points] == expected
    assert all(p["gain"] > 0 for p in points)
    assert all(int(g["best_id"][list(g["generation"]).index(p["generation"])]) == p["id"] for p in points)
    summary = improvements.summarise(classes, points, t)
    assert sum(e["offspring"] for e in summary.values()) == len(classes)
    assert sum(e["points"] for e in summary.values()) == len(points)
    for e in summary.values():
        assert e["improved"] + e["same"] + e["worse"] + e["failed"] == e["offspring"]


# the command line: a PNG, the tables, windows; errors give 4 and 2
def test_command_line(sweep_dir, run_history, tmp_path, capsys):
    assert improvements.main([run_history, "--output", str(tmp_path / "i.png"), "--window", "2",
                              "--table", str(tmp_path / "ops.tsv"), "--windows-table", str(tmp_path / "win.tsv")]) == 0
    assert (tmp_path / "i.png").read_bytes()[:8] == PNG
    assert "points of improvement" in capsys.readouterr().out
    header = (tmp_path / "ops.tsv").read_text().splitlines()[0]
    assert header.startswith("operator\toffspring\timproved")
    firsts = {line.split("\t")[0] for line in (tmp_path / "win.tsv").read_text().splitlines()[1:]}
    assert firsts <= {"0", "2", "4", "6", "8"} and "0" in firsts
    assert improvements.main([run_history, "--output", str(tmp_path / "i.png"),
                              "--mutants-table", str(tmp_path / "mutants.tsv")]) == 0
    assert "mutant classes" in capsys.readouterr().out
    mutants = (tmp_path / "mutants.tsv").read_text().splitlines()
    assert mutants[0].startswith("operator\toffspring\tzero") and len(mutants) > 1


def test_runs_as_a_script(sweep_dir, run_script):
    result = run_script("improvements", "--help")
    assert result.returncode == 0 and "--window" in result.stdout


def test_errors(tmp_path, capsys):
    with pytest.raises(SystemExit) as exit_:
        improvements.main([str(tmp_path / "none.h5")])
    assert exit_.value.code == 4 and "none.h5" in capsys.readouterr().err
    with pytest.raises(SystemExit) as exit_:
        improvements.main(["x.h5", "--window", "-1"])
    assert exit_.value.code == 2
