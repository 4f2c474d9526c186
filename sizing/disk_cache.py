"""Results of slow, deterministic computations kept on disk between runs,
as numba keeps its compiled kernels: ``memo`` wraps a function of
hashable arguments that returns a float (a plate's finite-element solve,
a quantity's text in SI units).

One JSON file per function in the cache folder (``SIZING_CACHE_DIR``, else
``~/.cache/sizing``, as the parsed catalogs), under ``computed/``, named by
a hash of the function's module source and the versions of the packages
it rests on, so that any change to the code that computes the values
starts a new file. New values are written when the process exits (or at
``flush()``), each file whole by ``io.atomic.store_cache`` and then
renamed; one that cannot be written only means the values are computed
again next run, one that cannot be read is ignored. What only one process
asks for twice (a treated voltage log, ``diagnose.inputs``) is kept in its
memory by ``functools.lru_cache`` instead: it is not worth a file.
"""
from __future__ import annotations

import atexit
import functools
import hashlib
import inspect
import json
import os
from importlib import metadata
from pathlib import Path

KEEP = 16       # files kept in the folder (older versions of the code are dropped)


def root() -> Path:
    """The project's cache folder: SIZING_CACHE_DIR, else ~/.cache/sizing."""
    return Path(os.environ.get("SIZING_CACHE_DIR") or Path.home() / ".cache" / "sizing")


def folder() -> Path:
    return root() / "computed"


def memo(*packages: str):
    """Keep ``func``'s float results on disk, keyed by its arguments' repr;
    ``packages``: the distributions whose versions the results depend on."""
    def wrap(func):
        state: dict = {"known": {}}          # path -> the values read or computed

        def path() -> Path:
            if "tag" not in state:
                source = inspect.getsource(inspect.getmodule(func))
                versions = [f"{p} {metadata.version(p)}" for p in packages]
                state["tag"] = hashlib.sha256("\n".join((source, *versions)).encode()).hexdigest()[:16]
            return folder() / f"{func.__module__}.{func.__qualname__}-{state['tag']}.json"

        @functools.wraps(func)
        def cached(*args):
            where = path()
            if where not in state["known"]:
                state["known"][where] = _read(where)
            known, key = state["known"][where], repr(args)
            if key not in known:
                known[key] = float(func(*args))
                _pending[where] = known
            return known[key]
        cached.forget = state["known"].clear     # what was read: as a new process starts
        return cached
    return wrap


_pending: dict[Path, dict] = {}       # files with values not yet written


@atexit.register
def flush() -> None:
    """Write the values computed since the last flush (at exit, or when called)."""
    while _pending:
        path, values = _pending.popitem()
        values.update({k: v for k, v in _read(path).items() if k not in values})     # another run's
        _store(path, values)


def _store(path: Path, values: dict) -> None:
    from .io.atomic import store_cache
    store_cache(path, json.dumps(values).encode(), KEEP)


def _read(path: Path) -> dict:
    try:
        values = json.loads(path.read_text())
    except (OSError, ValueError):
        return {}
    return values if isinstance(values, dict) else {}
