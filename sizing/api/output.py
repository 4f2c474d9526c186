"""Writing a command's result: the one step every command shares.

A command first computes its result (``api.solution``, ``api.studies``, ...),
a frozen dataclass that declares its ``layout``, the ``inputs`` it must
never overwrite and the files it stands for (``files()``); ``write`` then
hands them to the atomic writer (``io.atomic``), so every command's outputs
are complete or untouched. ``check`` runs before any work, so a bad
``--out`` costs nothing.

Two layouts:

- ``"folder"`` (solve, robust, sweep, diagnose): ``files()`` maps names
  inside the output folder to their contents, swapped in at once;
- ``"files"`` (fit, catalog add, catalog import-mgdb): ``files()`` maps
  paths to contents, each renamed over its path together.

A content is text, bytes, or a callable giving them, so a large page or the
plotly bundle is made only while it is written.
"""
from __future__ import annotations

import gc
import threading
from collections.abc import Mapping
from contextlib import contextmanager
from pathlib import Path

from ..io.atomic import check_files, check_folder, write_files, write_folder
from ..report.bundle import PLOTLY_FILE       # a constant; the bundle itself loads only when written


class Payload(Mapping):
    """A result read as the mapping it carries (``_payload()``), so callers
    that index a command's return value (``result["static"]``) keep working."""

    def _payload(self) -> Mapping:
        raise NotImplementedError

    def __getitem__(self, key):
        return self._payload()[key]

    def __iter__(self):
        return iter(self._payload())

    def __len__(self) -> int:
        return len(self._payload())


def plotly_js() -> str:
    """The folder's plotly bundle (report/bundle.py), made only when written."""
    from ..report.bundle import plotly_js as bundle
    return bundle()


def check(dest, names, inputs=(), layout: str = "folder", option: str = "--out") -> None:
    """Before any work: ``dest`` can take the outputs ``names`` (a folder),
    or each of ``names`` can be written as a file (``layout="files"``)."""
    if layout == "folder":
        check_folder(dest, names, inputs=inputs, option=option)
    else:
        check_files(names, inputs=inputs, option=option)


def write(result, dest: str | Path | None = None, option: str = "--out") -> list[str]:
    """Write ``result.files()`` (never over one of ``result.inputs``); returns
    the paths written. ``dest``: the output folder of a folder result."""
    files = result.files()
    if result.layout == "files":
        return [str(p) for p in write_files(files, inputs=result.inputs, option=option)]
    write_folder(dest, files, inputs=result.inputs, option=option)
    return [str(Path(dest) / name) for name in files]


# Gen-1 collections before the collector's full pass while a command runs
# (Python's default is 10). The full passes traverse every object the
# imports made (numba, scipy, plotly: a few million) to free almost
# nothing: on the seed's ``solve --fast`` four of them took 0.3 s of CPU of
# 4.9 s and freed 60 objects, while the young generations, still collected
# as often, free thousands. 1000 leaves long commands (robust, diagnose)
# a full pass every few million allocations.
FULL_COLLECTION_EVERY = 1000


_COLLECTIONS = {"running": 0, "was": None}
_COLLECTIONS_LOCK = threading.Lock()


@contextmanager
def few_full_collections():
    """The garbage collector's full passes made rare while a command
    computes and writes; its thresholds as they were once the last of the
    commands running at once (threads) returns."""
    with _COLLECTIONS_LOCK:
        if not _COLLECTIONS["running"]:
            was = _COLLECTIONS["was"] = gc.get_threshold()
            gc.set_threshold(was[0], was[1], max(was[2], FULL_COLLECTION_EVERY))
        _COLLECTIONS["running"] += 1
    try:
        yield
    finally:
        with _COLLECTIONS_LOCK:
            _COLLECTIONS["running"] -= 1
            if not _COLLECTIONS["running"]:
                gc.set_threshold(*_COLLECTIONS["was"])


def produce(names, dest, inputs, compute):
    """Every folder command's shape: check ``dest`` before any work (when
    given), ``compute()`` the result, write it into ``dest``; returns it."""
    if dest is not None:
        check(dest, names, inputs)
    with few_full_collections():
        result = compute()
        if dest is not None:
            write(result, dest)
    return result


__all__ = ["PLOTLY_FILE", "Payload", "check", "few_full_collections", "plotly_js", "produce", "write"]
