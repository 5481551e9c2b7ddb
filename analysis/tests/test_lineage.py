"""Tests of analysis/lineage.py: the walk back to generation 0 on the fixture run's history, a
hand-made table with a missing parent, and the command line (PNG, TSV, exit codes)."""

import csv

import numpy as np
import pytest

import cambrian_history as ch
import lineage

PNG = b"\x89PNG\r\n\x1a\n"


@pytest.fixture(scope="module")
def loaded(run_history):
    with ch.History(run_history) as h:
        t = h.individuals()
        return t, ch.operator_labels(h, t)


# the main line of the best creature starts at generation 0 and follows parent_a
def test_best_lineage_reaches_generation_zero(loaded):
    t, labels = loaded
    start = lineage.best_id(t)
    assert t["fitness"][t["id"] == start].max() == t["fitness"].max()
    line, ancestors = lineage.trace(t, labels, start)
    table = lineage.lineage_table(t, labels, line)
    assert table[0]["generation"] == 0 and table[0]["parent_a"] == ""
    assert table[-1]["id"] == start
    assert [r["generation"] for r in table] == sorted(r["generation"] for r in table)
    for previous, row in zip(table, table[1:]):
        assert row["parent_a"] == previous["id"]
        assert row["generation"] > previous["generation"]
        assert row["change"] == pytest.approx(row["fitness"] - previous["fitness"])
    # every ancestor, through either parent, is a creature of the history
    ids = set(t["id"].tolist())
    assert ancestors <= ids and {r["id"] for r in table[:-1]} <= ancestors


# a two-parent operator puts parent_b into the ancestors too
def test_ancestors_include_second_parents(loaded):
    t, labels = loaded
    two = np.nonzero((t["parent_b"] != ch.NO_ID) & (t["parent_b"] != t["parent_a"]))[0]
    assert len(two) > 0
    row = two[-1]
    _, ancestors = lineage.trace(t, labels, int(t["id"][row]))
    assert int(t["parent_a"][row]) in ancestors and int(t["parent_b"][row]) in ancestors


# a parent that is not in the table is an input error naming it
def test_missing_parent_is_an_error():
    table = {"id": np.array([0, 1], np.uint64), "parent_a": np.array([ch.NO_ID, 7], np.uint64),
             "parent_b": np.array([ch.NO_ID, ch.NO_ID], np.uint64), "generation": np.array([0, 1], np.uint64),
             "fitness": np.array([1.0, 2.0])}
    with pytest.raises(ch.InputFileError, match="parent 7"):
        lineage.trace(table, np.array(["random", "mutation"]), 1)
    line, ancestors = lineage.trace(table, np.array(["random", "mutation"]), 0)
    assert line == [0] and ancestors == set()


# the command line writes the PNG and a TSV whose last row is the best creature
def test_command_line_writes_png_and_table(sweep_dir, run_history, tmp_path, loaded, capsys):
    t, _ = loaded
    assert lineage.main([run_history, "--output", str(tmp_path / "l.png"), "--table", str(tmp_path / "l.tsv")]) == 0
    assert (tmp_path / "l.png").read_bytes()[:8] == PNG
    rows = list(csv.DictReader(open(tmp_path / "l.tsv"), delimiter="\t"))
    assert rows[0]["generation"] == "0" and int(rows[-1]["id"]) == lineage.best_id(t)
    assert "ancestors in all" in capsys.readouterr().out


# as a script, headless (only with the sweep fixture: starting Python is slow on a busy machine)
def test_runs_as_a_script(sweep_dir, run_script):
    result = run_script("lineage", "--help")
    assert result.returncode == 0 and "--output" in result.stdout


# --id follows another creature; an unknown id, a missing file and bad options fail cleanly
def test_ids_and_errors(run_history, tmp_path, capsys):
    assert lineage.main([run_history, "--id", "0", "--output", str(tmp_path / "a.png")]) == 0
    assert capsys.readouterr().out.splitlines()[1].split("\t")[2] == "0"
    assert lineage.main([run_history, "--id", str(10**9), "--output", str(tmp_path / "b.png")]) == 4
    error = capsys.readouterr().err
    assert "history.h5" in error and str(10**9) in error
    with pytest.raises(SystemExit) as exit_:
        lineage.main([str(tmp_path / "missing.h5"), "--output", str(tmp_path / "c.png")])
    assert exit_.value.code == 4 and "missing.h5" in capsys.readouterr().err
    for arguments, code in ((["--help"], 0), ([run_history, "--id", "x"], 2)):
        with pytest.raises(SystemExit) as exit_:
            lineage.main(arguments)
        assert exit_.value.code == code
