"""Read a cambrian history file (history.h5), complete or still being written.

The layout is documented in docs/hdf5-schema.md. Every table is a group of one-dimensional
columns (``/individuals/measures`` is two-dimensional); this module returns them as numpy arrays
cut to the rows every column holds, so a file read while ``cambrian evolve`` appends to it is
always consistent.

    import cambrian_history as ch
    with ch.History("run/history.h5") as h:
        gens = h.generations()           # dict: column name -> numpy array
        inds = h.individuals()           # dict, plus "measure:<name>" columns
        genome = h.genome_bytes(42)      # bytes of individual 42 (serializeGenome)
        print(h.attributes["config_text"])
        frame = h.individuals_frame()    # pandas DataFrame, measures as named columns
        print(h.decode_genomes([42])[42])  # the genome's text and body, as cambrian inspect
"""

import configparser
import os
import signal
import time

import h5py
import numpy as np

FORMAT_NAME = "cambrian-history"
FORMAT_VERSION = 1
NO_ID = np.iinfo(np.uint64).max  # parent_a / parent_b when there is no parent


# /generations columns added after format version 1 was frozen (older files lack them)
GENERATION_COLUMNS_ADDED_LATER = ("rank0_cpu_seconds", "rank0_dispatch_seconds", "epoch")


class HistoryError(Exception):
    """The file is missing, not HDF5, or not a cambrian history (message names the file)."""


def _text(value):
    """An attribute value as str (h5py may hand back bytes)."""
    if isinstance(value, bytes):
        return value.decode("utf-8")
    if isinstance(value, np.ndarray) and value.shape == ():
        return _text(value[()])
    return value


def _names(values):
    """A names attribute as a list of str."""
    return [_text(v) for v in values]


# metadata read attempts of a SWMR reader: the sleeps between them double from a microsecond,
# so 20 wait about a second in all (HDF5's default, 100, can wait for minutes on a damaged file)
SWMR_READ_ATTEMPTS = 20


def _bound_read_attempts(fapl):
    """Sets the file access list's metadata read attempts (h5py has no call for it: HDF5's own,
    from the library h5py loaded); leaves HDF5's default when that library cannot be found."""
    try:
        import ctypes
        with open("/proc/self/maps") as maps:
            paths = {line.split()[-1] for line in maps if "libhdf5" in line and "_hl" not in line}
        for path in sorted(paths):
            lib = ctypes.CDLL(path)
            lib.H5Pset_metadata_read_attempts.argtypes = [ctypes.c_int64, ctypes.c_uint]
            if lib.H5Pset_metadata_read_attempts(fapl.id, SWMR_READ_ATTEMPTS) >= 0:
                return
    except (OSError, AttributeError):
        pass


def _seconds_to_read_header():
    """The bound on the probe's time (CAMBRIAN_READ_SECONDS, as the C++ readers)."""
    try:
        return max(1, int(os.environ.get("CAMBRIAN_READ_SECONDS", "20")))
    except ValueError:
        return 20


def _probe(path):
    """None when the header of `path` (its attributes and those of every group and dataset) may
    be read in this process, else what went wrong. It is read first in a child process (a fresh
    interpreter): a damaged file can send HDF5 1.10 into an endless loop there (found by fuzzing:
    H5HG_read on a string attribute) or crash it, which no exception catches; how the child ends
    tells. Known and open: on some damaged files HDF5 crashes later, reading data, in whichever
    process reads it (the C++ readers refuse those files cleanly)."""
    import subprocess
    import sys

    seconds = _seconds_to_read_header()
    code = ("import sys; sys.path.insert(0, sys.argv[1]); import cambrian_history; "
            "cambrian_history._read_header(sys.argv[2])")
    here = os.path.dirname(os.path.abspath(__file__))
    try:
        done = subprocess.run([sys.executable, "-c", code, here, path], timeout=seconds,
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        return (f"reading the file's header did not end in {seconds} s: a damaged file that "
                "sends HDF5 into an endless loop")
    if done.returncode < 0:
        name = signal.Signals(-done.returncode).name
        return f"reading the file's header crashed HDF5 ({name}): a damaged file"
    return None


def _read_header(path):
    """The probe's child: every attribute the readers may touch, each failure passed over (the
    parent raises it properly), so that only a crash or a hang ends it differently."""

    def attempt(read):
        try:
            return read()
        except Exception:
            return None

    f = attempt(lambda: _open_hdf5_here(path))
    if f is None:
        return
    attempt(lambda: dict(f.attrs.items()))
    for group_name in attempt(lambda: list(f)) or []:
        group = attempt(lambda: f[group_name])
        attempt(lambda: dict(group.attrs.items()))
        for name in attempt(lambda: list(group)) or []:
            attempt(lambda: dict(group[name].attrs.items()))


def open_hdf5(path):
    """An HDF5 file for reading. The file is probed in a child process first (_probe): one that
    crashes HDF5 or sends it into an endless loop is an OSError naming it. A finished file opens
    plainly: a damaged one then fails at its first bad checksum (OSError). Only a file a writer
    holds (a run going on, or one a crash left so) is opened for SWMR reading, with a bounded
    number of metadata read attempts."""
    path = str(path)
    if not os.path.exists(path):
        raise FileNotFoundError(f"{path}: no such file")
    problem = _probe(path)
    if problem:
        raise OSError(problem)
    return _open_hdf5_here(path)


# opens of a file shorter than its header says, made again: a writer extending it between
# generations has not written its end yet (a file truncated for good still fails, 2.75 s later)
TRUNCATED_RETRIES = 10


def _open_hdf5_here(path):
    """open_hdf5 without the probe."""
    for attempt in range(TRUNCATED_RETRIES + 1):
        try:
            return _open_hdf5_once(path)
        except FileNotFoundError:
            raise
        except OSError as error:
            if "truncated file" not in str(error) or attempt == TRUNCATED_RETRIES:
                raise
            time.sleep(0.05 * (attempt + 1))


def _open_hdf5_once(path):
    """The file opened plainly, else for SWMR reading (a writer holds it)."""
    try:
        return h5py.File(path, "r")
    except FileNotFoundError:
        raise
    except OSError:
        fapl = h5py.h5p.create(h5py.h5p.FILE_ACCESS)
        fapl.set_fclose_degree(h5py.h5f.CLOSE_STRONG)
        _bound_read_attempts(fapl)
        fid = h5py.h5f.open(path.encode(), h5py.h5f.ACC_RDONLY | h5py.h5f.ACC_SWMR_READ, fapl=fapl)
        return h5py.File(fid)


class _FileSide:
    """The child's side of a History: the open file and the reads the parent asks for."""

    # reopenings of a file opened plainly that a writer took up meanwhile
    REOPENINGS = 5

    def __init__(self, path):
        self.path = path
        self.file = _open_hdf5_here(path)

    def _read(self, how):
        """how(file)'s value. The writer closes the file between generations, so a reader may
        open it plainly and then see the writer take it up again: the plain view then points
        past the file's end ("addr overflow"). Such a read is made again on the file opened anew
        (for SWMR reading while the writer holds it)."""
        for attempt in range(self.REOPENINGS + 1):
            try:
                if self.file is None:
                    raise OSError(f"{self.path}: cannot be opened again while its writer takes it up")
                return how(self.file)
            except OSError:
                if (self.file is not None and self.file.swmr_mode) or attempt == self.REOPENINGS:
                    raise
                if self.file is not None:
                    self.file.close()
                    self.file = None
                time.sleep(0.05 * (attempt + 1))
                try:  # the writer may be between opening and taking the file up: both opens fail
                    self.file = _open_hdf5_here(self.path)
                except OSError:
                    pass

    def attributes(self):
        return self._read(lambda file: {key: value for key, value in file.attrs.items()})

    def table(self, group_name, skip):
        """Every column of a group, refreshed and cut to the rows all columns hold."""
        def read(file):
            group = file[group_name]
            datasets = {name: group[name] for name in group if name not in skip}
            for dataset in datasets.values():
                dataset.refresh()
            rows = min((d.shape[0] for d in datasets.values()), default=0)
            return {name: d[:rows] for name, d in datasets.items()}
        return self._read(read)

    def length(self, name):
        def read(file):
            dataset = file[name]
            dataset.refresh()
            return dataset.shape[0]
        return self._read(read)

    def rows(self, name, start, stop):
        def read(file):
            dataset = file[name]
            dataset.refresh()
            return dataset[start:stop]
        return self._read(read)

    def attribute(self, name, key):
        return self._read(lambda file: file[name].attrs[key])


def _serve(path):
    """The child process of a History: reads requests (method name and arguments, pickled) from
    stdin and answers each with (True, value) or (False, (kind, message)) on stdout."""
    import pickle
    import sys

    requests, answers = sys.stdin.buffer, sys.stdout.buffer
    sys.stdout = sys.stderr  # nothing else may write to the answers
    side = None
    while True:
        try:
            method, arguments = pickle.load(requests)
        except EOFError:
            return
        try:
            if method == "open":
                side = _FileSide(*arguments)
                value = None
            else:
                value = getattr(side, method)(*arguments)
            answer = (True, value)
        except FileNotFoundError as error:
            answer = (False, ("missing", str(error)))
        except KeyError as error:
            answer = (False, ("key", str(error)))
        except Exception as error:  # an HDF5 error of a damaged file, told to the parent
            answer = (False, ("os", f"{type(error).__name__}: {error}"))
        pickle.dump(answer, answers, protocol=pickle.HIGHEST_PROTOCOL)
        answers.flush()


class History:
    """An open history file; use as a context manager or call close().

    HDF5 is called in a child process that this object starts and talks to: on some damaged
    files HDF5 1.10 crashes (SIGSEGV, SIGABRT) or loops without end instead of reporting an
    error, and that must end the child, never the analysis. Such a file is a HistoryError naming
    it; the header's reading is bounded (CAMBRIAN_READ_SECONDS, default 20 s)."""

    def __init__(self, path):
        import subprocess
        import sys

        self.path = str(path)
        if not os.path.exists(self.path):
            raise HistoryError(f"{self.path}: no such history file")
        here = os.path.dirname(os.path.abspath(__file__))
        code = ("import sys; sys.path.insert(0, sys.argv[1]); import cambrian_history; "
                "cambrian_history._serve(sys.argv[2])")
        self._child = subprocess.Popen([sys.executable, "-c", code, here, self.path],
                                       stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                       stderr=subprocess.DEVNULL)
        try:
            self._call("open", self.path, bound=_seconds_to_read_header())
            raw = self._call("attributes", bound=_seconds_to_read_header())
        except HistoryError:
            self.close()
            raise
        except OSError as error:
            self.close()
            raise HistoryError(f"{self.path}: not a readable HDF5 file ({error})") from error
        fmt = _text(raw.get("format", ""))
        if fmt != FORMAT_NAME:
            self.close()
            raise HistoryError(f"{self.path}: not a cambrian history (format '{fmt}')")
        version = int(raw["format_version"])
        if version > FORMAT_VERSION:
            self.close()
            raise HistoryError(f"{self.path}: format_version {version} is newer than {FORMAT_VERSION}")
        self.attributes = {key: _text(value) for key, value in raw.items()}

    def _call(self, method, *arguments, bound=None):
        """The child's answer to one request; HistoryError when the child crashed or did not
        answer within `bound` seconds, KeyError / OSError as the child raised them."""
        import pickle
        import select

        child = self._child
        try:
            pickle.dump((method, arguments), child.stdin, protocol=pickle.HIGHEST_PROTOCOL)
            child.stdin.flush()
            if bound is not None and not select.select([child.stdout], [], [], bound)[0]:
                child.kill()
                child.wait()
                raise HistoryError(f"{self.path}: reading the file's header did not end in {bound} s: "
                                   "a damaged file that sends HDF5 into an endless loop")
            ok, value = pickle.load(child.stdout)
        except (EOFError, BrokenPipeError, pickle.UnpicklingError):
            code = child.wait()
            how = signal.Signals(-code).name if code < 0 else f"exit {code}"
            raise HistoryError(f"{self.path}: reading the file crashed HDF5 ({how}): a damaged file")
        if ok:
            return value
        kind, message = value
        if kind == "key":
            raise KeyError(f"{self.path}: {message}")
        raise OSError(f"{self.path}: {message}")

    def close(self):
        child, self._child = getattr(self, "_child", None), None
        if child is None:
            return
        try:
            child.stdin.close()
        except OSError:
            pass
        try:
            child.wait(timeout=10)
        except Exception:
            child.kill()
            child.wait()
        child.stdout.close()

    def __del__(self):
        self.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def _table(self, group_name, skip=()):
        """Every column of a group, refreshed and cut to the rows all columns hold."""
        return self._call("table", group_name, tuple(skip))

    def generations(self):
        """The /generations table: dict of column name -> numpy array, one entry per generation.

        Rows end at the first that was never filled in (row i must hold generation i and a write
        time): an append cut short by a kill or a full disk leaves such rows behind."""
        table = self._table("generations")
        # columns added after format version 1 was frozen read as zeros from older files
        for name in GENERATION_COLUMNS_ADDED_LATER:
            if name not in table:
                kind = np.uint64 if name == "epoch" else np.float64
                table[name] = np.zeros(len(table["generation"]), dtype=kind)
        complete = (table["generation"] == np.arange(len(table["generation"]))) & (
            table["unix_time"] > 0
        )
        rows = int(np.argmin(complete)) if not complete.all() else len(complete)
        return {name: column[:rows] for name, column in table.items()}

    def individuals(self):
        """The /individuals table without genome bytes, plus "measure:<name>" 1-D columns: the
        rows of the generations in generations() (a generation's individuals come first)."""
        table = self._table("individuals", skip=("genome_bytes",))
        size = self._call("length", "individuals/genome_bytes")
        complete = table["genome_offset"] + table["genome_size"] <= size
        rows = int(np.argmin(complete)) if not complete.all() else len(complete)
        rows = min(rows, int(self.generations()["count"].sum()))
        table = {name: column[:rows] for name, column in table.items()}
        for index, name in enumerate(self.measure_names()):
            table["measure:" + name] = table["measures"][:, index]
        return table

    def genome_stream(self):
        """The whole concatenated genome byte stream as a numpy uint8 array (one read)."""
        return self._call("rows", "individuals/genome_bytes", None, None)

    def measure_names(self):
        return _names(self._call("attribute", "individuals/measures", "names"))

    def measure_units(self):
        return _names(self._call("attribute", "individuals/measures", "units"))

    def operator_names(self):
        return _names(self._call("attribute", "individuals/operator", "names"))

    def status_names(self):
        return _names(self._call("attribute", "individuals/status", "names"))

    def units(self, group_name, column):
        """The units attribute of a column ("s", "m", "1", ...)."""
        return _text(self._call("attribute", f"{group_name}/{column}", "units"))

    def genome_bytes(self, individual_id):
        """The serialized genome of an individual, as bytes; KeyError when absent."""
        table = self.individuals()
        where = np.nonzero(table["id"] == np.uint64(individual_id))[0]
        if len(where) == 0:
            raise KeyError(f"{self.path}: no individual with id {individual_id}")
        i = where[0]
        offset, size = int(table["genome_offset"][i]), int(table["genome_size"][i])
        return bytes(self._call("rows", "individuals/genome_bytes", offset, offset + size))


    # --- the tables as pandas DataFrames (Debian's python3-pandas, imported on first use) ---

    def generations_frame(self):
        """The /generations table as a DataFrame indexed by generation (0-based)."""
        import pandas as pd

        frame = pd.DataFrame(self.generations())
        return frame.set_index("generation", drop=False).rename_axis(None)

    def individuals_frame(self, genomes=False):
        """The /individuals table as a DataFrame, one row per row of the file (elites repeat
        their id in later generations). Measures are named columns (``distance``, ...), status
        and operator categorical names, parents nullable (<NA> for a random creature).
        genomes=True adds ``genome``: each row's serialized genome as bytes (decode them with
        decode_genomes)."""
        import pandas as pd

        table = self.individuals()
        columns = {}
        for name, column in table.items():
            if name == "measures" or name.startswith("measure:"):
                continue
            columns[name] = column
        frame = pd.DataFrame(columns)
        for name in ("parent_a", "parent_b"):
            values = pd.array(table[name], dtype="UInt64")
            values[table[name] == NO_ID] = pd.NA
            frame[name] = values
        frame["status"] = pd.Categorical.from_codes(table["status"].astype(np.int64),
                                                    self.status_names())
        frame["operator"] = pd.Categorical.from_codes(table["operator"].astype(np.int64),
                                                      self.operator_names())
        for name in self.measure_names():
            frame[name] = table["measure:" + name]
        if genomes:
            stream = self.genome_stream()
            frame["genome"] = [bytes(stream[o : o + n]) for o, n in
                               zip(table["genome_offset"].astype(np.int64),
                                   table["genome_size"].astype(np.int64))]
        return frame

    def decode_genomes(self, ids, cambrian=None, body=True):
        """dict id -> the genome's text (docs/genome.md), followed by its body statistics when
        body=True: what ``cambrian inspect`` prints, for many genomes in one run of the binary
        (``cambrian`` is its path; default: $CAMBRIAN_BINARY, the build tree, then PATH)."""
        import subprocess
        import tempfile

        ids = [int(i) for i in ids]
        if not ids:
            return {}
        binary = find_cambrian(cambrian)
        table = self.individuals()
        stream = self.genome_stream()
        rows = first_rows(table)
        with tempfile.TemporaryDirectory(prefix="cambrian-decode-") as folder:
            config = os.path.join(folder, "config.ini")
            with open(config, "w") as out:
                out.write(str(self.attributes.get("config_text", "")))
            paths = []
            for individual in ids:
                if individual not in rows:
                    raise KeyError(f"{self.path}: no individual with id {individual}")
                path = os.path.join(folder, f"{individual}.genome")
                with open(path, "wb") as out:
                    out.write(genome_of(stream, table, rows[individual]))
                paths.append(path)
            command = [binary, "inspect", "--config", config, *paths]
            done = subprocess.run(command, capture_output=True, text=True)
            if done.returncode != 0:
                raise RuntimeError(f"{' '.join(command[:2])} failed (exit {done.returncode}): "
                                   f"{done.stderr.strip()}")
        texts = _split_inspected(done.stdout, paths)
        if not body:
            texts = [text.split("\n\n# body:")[0] + "\n" for text in texts]
        return dict(zip(ids, texts))


INSPECT_SEPARATOR = "==> "  # cambrian inspect's header line before each of several genomes


def _split_inspected(output, paths):
    """The texts of several genomes from one `cambrian inspect` output (one per path, in order;
    each after a line "==> PATH <==")."""
    if len(paths) == 1:
        return [output]
    texts, current = [], None
    for line in output.splitlines(keepends=True):
        if line.startswith(INSPECT_SEPARATOR) and line.rstrip().endswith(" <=="):
            if current is not None:
                texts.append("".join(current).rstrip("\n") + "\n")
            current = []
        elif current is not None:
            current.append(line)
    if current is not None:
        texts.append("".join(current).rstrip("\n") + "\n")
    if len(texts) != len(paths):
        raise RuntimeError(f"cambrian inspect printed {len(texts)} genomes for {len(paths)} files")
    return texts


def find_cambrian(path=None):
    """The cambrian binary: `path` (which must be one), else $CAMBRIAN_BINARY, else the release or CI build of this
    source tree, else `cambrian` on PATH; FileNotFoundError naming what was tried."""
    import shutil

    if path:
        if os.path.isfile(path) and os.access(path, os.X_OK):
            return path
        raise FileNotFoundError(f"{path}: no such cambrian binary")
    tried = []
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    for candidate in (os.environ.get("CAMBRIAN_BINARY"),
                      os.path.join(root, "build", "release", "src", "app", "cambrian"),
                      os.path.join(root, "build", "ci", "src", "app", "cambrian"),
                      shutil.which("cambrian")):
        if not candidate:
            continue
        tried.append(candidate)
        if os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return candidate
    raise FileNotFoundError("no cambrian binary found (tried " + ", ".join(tried) +
                            "); pass its path or set CAMBRIAN_BINARY")


def load(path):
    """(attributes, individuals, generations) of a history file, read in one go."""
    with History(path) as history:
        return history.attributes, history.individuals(), history.generations()


# --- helpers shared by the analysis scripts (lineage, improvements, diversity, load balance,
# scaling); additions only, the reader above is unchanged ---

EXIT_OK = 0  # success
EXIT_USAGE = 2  # bad command line (argparse's own code)
EXIT_INPUT = 4  # a history file is missing, not HDF5, foreign or empty (docs/exit-codes.md)


class InputFileError(Exception):
    """A history opened fine but cannot be analysed (no rows, a missing parent, ...)."""


def worker_count(attributes, generations=None):
    """Evaluating ranks of a run: the `workers` column when present, else rank_count - 1
    (a one-rank run evaluates in process: one worker)."""
    if generations is not None and len(generations.get("workers", [])) > 0:
        return int(generations["workers"][0])
    ranks = int(attributes.get("rank_count", 1))
    return max(ranks - 1, 1)


def island_histories(directory):
    """The histories of a run's output directory as [(island, path)]: for an island run (its
    index DIR/archipelago.ini, docs/parallel.md) each island's DIR/<directory>/history.h5 in
    island order, else [(0, DIR/history.h5)]. Raises InputFileError naming the index when it
    cannot be read."""
    index = os.path.join(directory, "archipelago.ini")
    if not os.path.exists(index):
        return [(0, os.path.join(directory, "history.h5"))]
    parser = configparser.ConfigParser(interpolation=None)
    try:
        with open(index) as handle:
            parser.read_file(handle)
        count = parser.getint("islands", "count")
        return [(k, os.path.join(directory, parser.get(f"island_{k}", "directory"), "history.h5"))
                for k in range(count)]
    except (OSError, ValueError, configparser.Error) as error:
        raise InputFileError(f"{index}: {error}") from error


def config_value(attributes, section, key, default=None):
    """A value from the root attribute config_text (INI text), as str; default when absent."""
    current = None
    for line in str(attributes.get("config_text", "")).splitlines():
        line = line.strip()
        if line.startswith("[") and line.endswith("]"):
            current = line[1:-1].strip()
        elif current == section and "=" in line:
            name, value = line.split("=", 1)
            if name.strip() == key:
                return value.strip()
    return default


def operator_labels(history, table):
    """The operator of every row of an individuals table, as a numpy array of str."""
    names = np.array(history.operator_names(), dtype=object)
    return names[table["operator"].astype(np.int64)]


def first_rows(table):
    """dict id -> row index of the first row holding that id (the row where it was evaluated:
    elite copies that repeat an id come later)."""
    ids = table["id"]
    unique, first = np.unique(ids, return_index=True)
    return dict(zip(unique.tolist(), first.tolist()))


def genome_stream(history):
    """The whole concatenated genome byte stream as a numpy uint8 array (one read)."""
    return history.genome_stream()


def genome_of(stream, table, row):
    """The genome bytes of one row, cut from a stream read by genome_stream()."""
    offset, size = int(table["genome_offset"][row]), int(table["genome_size"][row])
    return bytes(stream[offset : offset + size])


def genome_node_count(genome):
    """Node count of a serialized genome (u32 after the magic and the version); -1 if too short."""
    if len(genome) < 12 or genome[:4] != b"CMBG":
        return -1
    return int.from_bytes(genome[8:12], "little")


def open_or_exit(path, program):
    """(attributes, individuals, generations, operator labels, status names) of a history, or
    the script's exit with EXIT_INPUT and an error naming the file."""
    import sys

    try:
        with History(path) as history:
            individuals = history.individuals()
            generations = history.generations()
            labels = operator_labels(history, individuals)
            statuses = history.status_names()
            attributes = history.attributes
    except (HistoryError, KeyError, OSError, AttributeError, ValueError, RuntimeError) as error:
        print(f"{program}: error: {path}: {error}" if str(path) not in str(error)
              else f"{program}: error: {error}", file=sys.stderr)
        raise SystemExit(EXIT_INPUT)
    if len(individuals["id"]) == 0 or len(generations["generation"]) == 0:
        print(f"{program}: error: {path}: no generations written yet", file=sys.stderr)
        raise SystemExit(EXIT_INPUT)
    return attributes, individuals, generations, labels, statuses


def tsv_lines(rows, columns):
    """Lines of a TSV table of dict rows: the header, then one line per row (floats as %.6g)."""
    lines = ["\t".join(columns)]
    for row in rows:
        lines.append("\t".join(f"{row[c]:.6g}" if isinstance(row[c], float) else str(row[c]) for c in columns))
    return lines


def save_figure(figure, title, output, dpi):
    """Gives a matplotlib figure its title and layout, writes it to `output` and closes it."""
    import matplotlib.pyplot as plt

    figure.suptitle(title)
    figure.tight_layout()
    figure.savefig(output, dpi=dpi)
    plt.close(figure)
