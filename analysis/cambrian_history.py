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
"""

import h5py
import numpy as np

FORMAT_NAME = "cambrian-history"
FORMAT_VERSION = 1
NO_ID = np.iinfo(np.uint64).max  # parent_a / parent_b when there is no parent


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


class History:
    """An open history file; use as a context manager or call close()."""

    def __init__(self, path):
        self.path = str(path)
        try:
            self.file = h5py.File(self.path, "r", swmr=True)
        except FileNotFoundError as error:
            raise HistoryError(f"{self.path}: no such history file") from error
        except OSError:
            try:
                self.file = h5py.File(self.path, "r")
            except OSError as error:
                raise HistoryError(f"{self.path}: not a readable HDF5 file ({error})") from error
        fmt = _text(self.file.attrs.get("format", ""))
        if fmt != FORMAT_NAME:
            self.file.close()
            raise HistoryError(f"{self.path}: not a cambrian history (format '{fmt}')")
        version = int(self.file.attrs["format_version"])
        if version > FORMAT_VERSION:
            self.file.close()
            raise HistoryError(f"{self.path}: format_version {version} is newer than {FORMAT_VERSION}")
        self.attributes = {key: _text(value) for key, value in self.file.attrs.items()}

    def close(self):
        self.file.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def _table(self, group_name, skip=()):
        """Every column of a group, refreshed and cut to the rows all columns hold."""
        group = self.file[group_name]
        datasets = {name: group[name] for name in group if name not in skip}
        for dataset in datasets.values():
            dataset.refresh()
        rows = min((d.shape[0] for d in datasets.values()), default=0)
        return {name: d[:rows] for name, d in datasets.items()}

    def generations(self):
        """The /generations table: dict of column name -> numpy array, one entry per generation."""
        return self._table("generations")

    def individuals(self):
        """The /individuals table without genome bytes, plus "measure:<name>" 1-D columns."""
        table = self._table("individuals", skip=("genome_bytes",))
        stream = self.file["individuals/genome_bytes"]
        stream.refresh()
        size = stream.shape[0]
        complete = table["genome_offset"] + table["genome_size"] <= size
        rows = int(np.argmin(complete)) if not complete.all() else len(complete)
        table = {name: column[:rows] for name, column in table.items()}
        for index, name in enumerate(self.measure_names()):
            table["measure:" + name] = table["measures"][:, index]
        return table

    def measure_names(self):
        return _names(self.file["individuals/measures"].attrs["names"])

    def measure_units(self):
        return _names(self.file["individuals/measures"].attrs["units"])

    def operator_names(self):
        return _names(self.file["individuals/operator"].attrs["names"])

    def status_names(self):
        return _names(self.file["individuals/status"].attrs["names"])

    def units(self, group_name, column):
        """The units attribute of a column ("s", "m", "1", ...)."""
        return _text(self.file[group_name][column].attrs["units"])

    def genome_bytes(self, individual_id):
        """The serialized genome of an individual, as bytes; KeyError when absent."""
        table = self.individuals()
        where = np.nonzero(table["id"] == np.uint64(individual_id))[0]
        if len(where) == 0:
            raise KeyError(f"{self.path}: no individual with id {individual_id}")
        i = where[0]
        offset, size = int(table["genome_offset"][i]), int(table["genome_size"][i])
        stream = self.file["individuals/genome_bytes"]
        return bytes(stream[offset : offset + size])


def load(path):
    """(attributes, individuals, generations) of a history file, read in one go."""
    with History(path) as history:
        return history.attributes, history.individuals(), history.generations()
