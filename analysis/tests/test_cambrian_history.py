"""Tests of the history reader and the fitness plot, on the history.h5 of a small synthetic
`cambrian evolve` run (CTest runs it first and passes its directory in CAMBRIAN_RUN_DIR)."""

import csv
import os
import subprocess
import sys

import numpy as np
import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
import cambrian_history as ch  # noqa: E402

RUN_DIR = os.environ.get("CAMBRIAN_RUN_DIR")
POPULATION = int(os.environ.get("CAMBRIAN_RUN_POPULATION", "0"))
GENERATIONS = int(os.environ.get("CAMBRIAN_RUN_GENERATIONS", "0"))
pytestmark = pytest.mark.skipif(not RUN_DIR, reason="CAMBRIAN_RUN_DIR not set (run through ctest)")


@pytest.fixture(scope="module")
def history_path():
    return os.path.join(RUN_DIR, "history.h5")


@pytest.fixture(scope="module")
def history(history_path):
    with ch.History(history_path) as h:
        yield h


def read_tsv(name):
    with open(os.path.join(RUN_DIR, name), newline="") as handle:
        return list(csv.DictReader(handle, delimiter="\t"))


def test_attributes_name_the_run(history):
    a = history.attributes
    assert a["format"] == "cambrian-history"
    assert int(a["format_version"]) == 1
    assert int(a["seed"]) == 3
    assert int(a["rank_count"]) == 1
    assert a["bullet_precision"] == "float64"
    assert a["start_time"].endswith("Z") and len(a["start_time"]) == 20
    assert "[evolution]" in a["config_text"] and f"population = {POPULATION}" in a["config_text"]
    assert "name = synthetic" in a["config_text"]
    assert len(a["config_hash"]) == 16 and a["cambrian_version"] and a["git_hash"]


def test_generations_match_the_tsv_table(history):
    g = history.generations()
    rows = read_tsv("generations.tsv")
    assert len(g["generation"]) == GENERATIONS == len(rows)
    assert list(g["generation"]) == list(range(GENERATIONS))
    for i, row in enumerate(rows):
        assert g["best"][i] == float(row["best"])
        assert g["median"][i] == float(row["median"])
        assert g["best_id"][i] == int(row["best_id"])
        assert g["epoch"][i] == int(row["epoch"]) == 0
    assert np.all(g["q25"] <= g["median"]) and np.all(g["median"] <= g["q75"])
    assert np.all((g["distinct_genomes"] >= 1) & (g["distinct_genomes"] <= POPULATION))
    # every generation of this run is followed by a checkpoint (run.checkpoint_every = 1)
    assert np.all(g["checkpoint_seconds"] > 0)
    # a generation's wall time holds its evaluation span; its checkpoint is written while the
    # next generation starts (the last one's at its own end)
    assert np.all(g["wall_seconds"] >= g["evaluation_span_seconds"])
    assert g["wall_seconds"][-1] >= g["evaluation_span_seconds"][-1] + g["checkpoint_seconds"][-1]
    assert np.all(g["wall_seconds"][1:] >= g["checkpoint_seconds"][:-1])
    assert history.units("generations", "wall_seconds") == "s"


def test_columns_added_later_read_as_zeros_from_older_files():
    older = os.path.join(HERE, "..", "..", "tests", "store", "data", "v1_run", "history.h5")
    with ch.History(older) as h:
        g = h.generations()
    assert len(g["generation"]) > 0
    assert list(g["epoch"]) == [0] * len(g["generation"])


def test_individuals_match_the_tsv_table(history):
    t = history.individuals()
    rows = read_tsv("individuals.tsv")
    assert len(t["id"]) == POPULATION * GENERATIONS == len(rows)
    assert list(t["id"]) == [int(r["id"]) for r in rows]
    assert [float(r["fitness"]) for r in rows] == list(t["fitness"])
    operators = history.operator_names()
    assert [operators[o] for o in t["operator"]] == [r["operator"] for r in rows]
    statuses = history.status_names()
    assert [statuses[s] for s in t["status"]] == [r["status"] for r in rows]
    # generation 0 has no parents; crossover children have two
    first = t["generation"] == 0
    assert np.all(t["parent_a"][first] == ch.NO_ID)
    crossover = t["operator"] == operators.index("crossover")
    assert crossover.any() and np.all(t["parent_b"][crossover] != ch.NO_ID)
    # the synthetic task's measures are its own columns, named: cost and nodes, no distance
    assert history.measure_names() == ["cost_us", "nodes"]
    assert "measure:distance" not in t
    assert np.all(t["measure:nodes"] >= 1)
    assert np.all(t["measure:cost_us"] >= 0)
    assert history.measure_units()[history.measure_names().index("cost_us")] == "us"


def test_best_of_each_generation_is_in_the_individuals(history):
    t = history.individuals()
    g = history.generations()
    for i, generation in enumerate(g["generation"]):
        mine = t["generation"] == generation
        assert t["fitness"][mine].max() == g["best"][i]


def test_genome_bytes_by_id(history):
    t = history.individuals()
    for individual in t["id"][:5]:
        genome = history.genome_bytes(int(individual))
        assert genome[:4] == b"CMBG"
    with pytest.raises(KeyError):
        history.genome_bytes(10**9)


def test_frames_hold_the_tables(history):
    pd = pytest.importorskip("pandas")
    g, frame = history.generations(), history.generations_frame()
    assert list(frame.index) == list(range(GENERATIONS))
    for name, column in g.items():
        assert np.array_equal(frame[name].to_numpy(), column), name
    t, people = history.individuals(), history.individuals_frame()
    assert len(people) == POPULATION * GENERATIONS
    # measures are named columns, status and operator their names, parents <NA> when absent
    assert np.array_equal(people["cost_us"].to_numpy(), t["measure:cost_us"])
    assert np.array_equal(people["nodes"].to_numpy(), t["measure:nodes"])
    assert "measures" not in people and "measure:nodes" not in people
    assert list(people["operator"]) == list(ch.operator_labels(history, t))
    assert set(people["status"].cat.categories) == set(history.status_names())
    first = people[people["generation"] == 0]
    assert first["parent_a"].isna().all() and first["parent_b"].isna().all()
    crossover = people[people["operator"] == "crossover"]
    assert len(crossover) and crossover["parent_b"].notna().all()
    assert people["parent_a"].dtype == pd.UInt64Dtype()
    # the frame answers the questions a user asks of it, as the arrays do
    best = people.groupby("generation")["fitness"].max()
    assert np.array_equal(best.to_numpy(), g["best"])
    # genomes as bytes on request, the same as genome_bytes
    with_genomes = history.individuals_frame(genomes=True)
    for row in with_genomes.head(5).itertuples():
        assert row.genome == history.genome_bytes(row.id)


def test_genomes_decoded_on_request(history):
    if not os.environ.get("CAMBRIAN_BINARY"):
        pytest.skip("CAMBRIAN_BINARY not set (run through ctest)")
    people = history.individuals_frame()
    last = people[people["generation"] == GENERATIONS - 1]
    ids = [int(i) for i in last["id"].head(3)]
    texts = history.decode_genomes(ids)
    assert list(texts) == ids
    for individual in ids:
        text = texts[individual]
        assert text.startswith("cambrian-genome")
        assert "\n# body: " in text and "\nend\n" in text
        # the synthetic task's `nodes` measure is the genome's gene count
        nodes = int(last[last["id"] == individual]["nodes"].iloc[0])
        assert sum(line.startswith("node ") for line in text.splitlines()) == nodes
    plain = history.decode_genomes(ids[:1], body=False)[ids[0]]
    assert plain.startswith("cambrian-genome") and "# body" not in plain
    assert texts[ids[0]].startswith(plain.rstrip("\n"))
    with pytest.raises(KeyError):
        history.decode_genomes([10**9])
    with pytest.raises(FileNotFoundError, match="no-such-binary"):
        history.decode_genomes(ids, cambrian="/no-such-binary")


def test_load_returns_everything(history_path):
    attributes, individuals, generations = ch.load(history_path)
    assert attributes["format"] == "cambrian-history"
    assert len(individuals["id"]) == POPULATION * GENERATIONS
    assert len(generations["best"]) == GENERATIONS


def test_bad_files_raise_history_error(tmp_path):
    with pytest.raises(ch.HistoryError, match="no such"):
        ch.History(tmp_path / "missing.h5")
    text = tmp_path / "text.h5"
    text.write_text("not hdf5\n")
    with pytest.raises(ch.HistoryError, match="text.h5"):
        ch.History(text)


def run_plot(*arguments):
    script = os.path.join(os.path.dirname(HERE), "plot_fitness.py")
    return subprocess.run([sys.executable, script, *arguments], capture_output=True, text=True)


def test_plot_writes_a_png(history_path, tmp_path):
    output = tmp_path / "fitness.png"
    result = run_plot(history_path, "--output", str(output))
    assert result.returncode == 0, result.stderr
    assert output.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_plot_of_several_runs(history_path, tmp_path):
    output = tmp_path / "runs.png"
    result = run_plot(history_path, history_path, "--output", str(output), "--log")
    assert result.returncode == 0, result.stderr
    assert output.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    # one bad file among them: nothing written, the file named
    missing = str(tmp_path / "missing.h5")
    result = run_plot(history_path, missing, "--output", str(tmp_path / "y.png"))
    assert result.returncode == 4 and "missing.h5" in result.stderr
    assert not (tmp_path / "y.png").exists()


def test_plot_of_a_sequence(history_path, tmp_path):
    output = tmp_path / "sequence.png"
    result = run_plot(
        history_path, history_path, "--sequence", "--label", "step 1", "--label", "step 2", "--output", str(output)
    )
    assert result.returncode == 0, result.stderr
    assert output.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    # a label for each history or none: a clear usage error, nothing written
    result = run_plot(history_path, history_path, "--sequence", "--label", "one", "--output", str(tmp_path / "z.png"))
    assert result.returncode == 2 and "--label given 1 times for 2 histories" in result.stderr
    assert not (tmp_path / "z.png").exists()


def test_a_sequence_numbers_each_step_on_from_the_one_before(tmp_path):
    sys.path.insert(0, os.path.dirname(HERE))
    import plot_fitness

    step = {"generation": [0, 1, 2], "best": [1, 2, 3], "mean": [1, 1, 1], "median": [1, 1, 1]}
    step.update(q25=[0, 0, 0], q75=[2, 2, 2])
    drawn = []
    original = plot_fitness.plt.Axes.plot

    def record(axes, x, *rest, **options):
        drawn.append(list(x))
        return original(axes, x, *rest, **options)

    plot_fitness.plt.Axes.plot = record
    try:
        plot_fitness.plot_sequence([("a", step), ("b", step)], "t", str(tmp_path / "s.png"))
    finally:
        plot_fitness.plt.Axes.plot = original
    assert drawn[0] == [0, 1, 2] and drawn[-1] == [3, 4, 5]


def test_run_labels_are_seeds_unless_shared():
    sys.path.insert(0, os.path.dirname(HERE))
    import plot_fitness

    assert plot_fitness.run_label("a/s1/history.h5", 1, [1, 2]) == "seed 1"
    assert plot_fitness.run_label("a/s1/history.h5", 1, [1, 1]) == "s1"


def test_plot_help_and_bad_file(tmp_path):
    result = run_plot("--help")
    assert result.returncode == 0 and "--output" in result.stdout
    result = run_plot(str(tmp_path / "missing.h5"), "--output", str(tmp_path / "x.png"))
    assert result.returncode == 4 and "missing.h5" in result.stderr


def test_rows_of_an_append_cut_short_are_not_read(history_path, tmp_path):
    """A kill or a full disk during an append leaves rows that were extended but never filled
    (zeros): the reader stops at the last generation whose row is in, and reads only its
    individuals."""
    import shutil

    import h5py

    torn = str(tmp_path / "torn.h5")
    shutil.copy(history_path, torn)
    with h5py.File(torn, "r+") as f:
        for group, more in (("individuals", POPULATION), ("generations", 1)):
            for name, dataset in f[group].items():
                shape = list(dataset.shape)
                shape[0] += more * (100 if name == "genome_bytes" else 1)
                dataset.resize(shape)
    with ch.History(torn) as h:
        g = h.generations()
        assert list(g["generation"]) == list(range(GENERATIONS))
        table = h.individuals()
        assert len(table["id"]) == POPULATION * GENERATIONS
        assert int(table["generation"].max()) == GENERATIONS - 1


WRITER = """
import sys, h5py
path = sys.argv[1]
sys.stdin.readline()
with h5py.File(path, "r+", libver="latest", locking=False) as f:  # as the run's writer
    f.swmr_mode = True
    for group in ("generations", "individuals"):
        for dataset in f[group].values():
            rows = dataset.shape[0]
            dataset.resize(rows + 4000, axis=0)
            dataset[rows:] = dataset[rows - 1]
    f.flush()
    print("appended", flush=True)
    sys.stdin.readline()
"""


def test_a_reader_that_opened_it_between_generations_reads_on_when_the_writer_goes_on(
        history_path, tmp_path):
    # the run's writer closes the file between generations: a reader opens it plainly then, and
    # must go on reading when the writer takes it up again and appends
    path = tmp_path / "between.h5"
    path.write_bytes(open(history_path, "rb").read())
    writer = subprocess.Popen(["/usr/bin/python3", "-c", WRITER, str(path)], stdin=subprocess.PIPE,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        with ch.History(str(path)) as h:
            writer.stdin.write("go\n")
            writer.stdin.flush()
            assert writer.stdout.readline() == "appended\n", writer.stderr.read()
            generations = h.generations()
            individuals = h.individuals()
        assert len(generations["generation"]) >= GENERATIONS
        assert len(individuals["id"]) >= POPULATION * GENERATIONS
    finally:
        writer.stdin.close()
        writer.wait(timeout=60)


# an island run's directory names each island's history (DIR/archipelago.ini); a plain run's
# its own; a damaged index is an input error naming it
def test_island_histories(tmp_path):
    assert ch.island_histories(str(tmp_path)) == [(0, str(tmp_path / "history.h5"))]
    (tmp_path / "archipelago.ini").write_text(
        "[islands]\ncount = 2\ninterval = 1\n\n[island_0]\ndirectory = island_0\n\n"
        "[island_1]\ndirectory = island_1\n")
    assert ch.island_histories(str(tmp_path)) == [
        (0, str(tmp_path / "island_0" / "history.h5")), (1, str(tmp_path / "island_1" / "history.h5"))]
    (tmp_path / "archipelago.ini").write_text("[islands]\ncount = 3\n")
    with pytest.raises(ch.InputFileError, match="archipelago.ini"):
        ch.island_histories(str(tmp_path))
