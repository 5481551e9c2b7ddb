"""Tests of analysis/diversity.py: the shingle distance on made-up genomes, the per-generation
table against the fixture run's history, and the command line."""

import numpy as np
import pytest

import cambrian_history as ch
import diversity

PNG = b"\x89PNG\r\n\x1a\n"


# identical genomes are at distance 0, genomes without a common shingle at 1
def test_jaccard_distance_bounds():
    a = diversity.shingles(b"CMBG" + bytes(range(200)))
    assert diversity.jaccard_distance(a, a) == 0.0
    b = diversity.shingles(bytes([255]) * 50)
    assert diversity.jaccard_distance(a, b) == 1.0
    assert len(diversity.shingles(b"ab")) == 1  # a genome shorter than a shingle


# one changed byte in a long genome changes at most 4 of its shingles
def test_small_change_gives_small_distance():
    genome = bytes(range(256)) * 2
    changed = bytearray(genome)
    changed[300] ^= 0xFF
    d = diversity.jaccard_distance(diversity.shingles(genome), diversity.shingles(bytes(changed)))
    assert 0.0 < d <= 8 / 256


# all pairs when few, sampled pairs when many; the mean is exact for a known set
def test_mean_distance_all_pairs_and_sampled():
    rng = np.random.default_rng(1)
    same = [b"CMBGabcdefgh"] * 5
    assert diversity.mean_distance(same, 100, rng) == 0.0
    apart = [bytes([k]) * 40 for k in range(30)]
    assert diversity.mean_distance(apart, 10, rng) == 1.0  # 435 pairs > 10: sampled, never self-pairs
    assert diversity.mean_distance([b"CMBGx"], 10, rng) == 0.0


# the node count is read from the genome header
def test_genome_node_count():
    assert ch.genome_node_count(b"CMBG" + (1).to_bytes(4, "little") + (3).to_bytes(4, "little")) == 3
    assert ch.genome_node_count(b"XXXX12345678") == -1


# Krčah's groups of equal fitness: the largest first, and the share in groups of at most 5
def test_groups_of_equal_fitness():
    fitness = [1.0] * 6 + [2.0] * 2 + [3.0] + [0.5] * 2
    genomes = [b"a"] * 5 + [b"b"] + [b"c", b"c"] + [b"d"] + [b"e", b"f"]
    groups = diversity.largest_groups(fitness, genomes, 3)
    assert groups == [{"size": 6, "share": 6 / 11, "fitness": 1.0, "distinct_genomes": 2},
                      {"size": 2, "share": 2 / 11, "fitness": 2.0, "distinct_genomes": 1},
                      {"size": 2, "share": 2 / 11, "fitness": 0.5, "distinct_genomes": 2}]
    assert diversity.small_group_share(fitness) == pytest.approx(5 / 11)
    assert diversity.small_group_share([1.0] * 6) == 0.0


# per generation, the table agrees with the history's own columns
def test_fixture_table_agrees_with_history(run_history):
    with ch.History(run_history) as h:
        t, g = h.individuals(), h.generations()
        stream = ch.genome_stream(h)
    rows = diversity.diversity(t, stream, pairs=50)
    assert [r["generation"] for r in rows] == list(g["generation"])
    for row, distinct, count in zip(rows, g["distinct_genomes"], g["count"]):
        assert row["distinct_genomes"] == distinct and row["count"] == count
        parts = t["parts"][t["generation"] == row["generation"]]
        assert row["parts_min"] == parts.min() and row["parts_max"] == parts.max()
        assert row["parts_mean"] == pytest.approx(parts.mean())
        assert 1 <= row["distinct_fitness"] <= count and 0 < row["largest_group_share"] <= 1
        assert 0 <= row["small_group_share"] <= 1
        assert row["nodes_mean"] >= 1 and row["genome_bytes_mean"] > 12
        assert 0.0 <= row["genotype_distance"] <= 1.0
    # generation 0 is random: its genomes differ
    assert rows[0]["genotype_distance"] > 0.1


def test_command_line(sweep_dir, run_history, tmp_path, capsys):
    assert diversity.main([run_history, "--output", str(tmp_path / "d.png"), "--table", str(tmp_path / "d.tsv")]) == 0
    assert (tmp_path / "d.png").read_bytes()[:8] == PNG
    lines = (tmp_path / "d.tsv").read_text().splitlines()
    assert lines[0].split("\t") == diversity.COLUMNS and len(lines) > 2
    capsys.readouterr()
    # the largest groups of the last generation, then of generation 0; a generation not there
    assert diversity.main([run_history, "--output", str(tmp_path / "d.png"), "--groups", "2"]) == 0
    out = capsys.readouterr().out
    assert "largest groups of equal fitness in generation" in out and "size\tshare\tfitness" in out
    assert diversity.main([run_history, "--output", str(tmp_path / "d.png"), "--groups", "2",
                           "--groups-generation", "0"]) == 0
    assert "in generation 0 " in capsys.readouterr().out
    assert diversity.main([run_history, "--output", str(tmp_path / "d.png"), "--groups", "2",
                           "--groups-generation", "999"]) == 2
    assert "no generation 999" in capsys.readouterr().err


def test_runs_as_a_script(sweep_dir, run_script):
    result = run_script("diversity", "--help")
    assert result.returncode == 0 and "--pairs" in result.stdout


def test_errors(tmp_path, capsys):
    bad = tmp_path / "bad.h5"
    bad.write_text("not hdf5")
    with pytest.raises(SystemExit) as exit_:
        diversity.main([str(bad)])
    assert exit_.value.code == 4 and "bad.h5" in capsys.readouterr().err
    with pytest.raises(SystemExit) as exit_:
        diversity.main([str(bad), "--pairs", "0"])
    assert exit_.value.code == 2
