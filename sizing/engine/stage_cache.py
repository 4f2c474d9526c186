"""What the re-solves behind the flips (``flip.py``) share: each
sized geometric program, simulation and enumeration, kept by its
whole input while ``reuse()`` is open.

A search that moves one value re-solves the same part combinations at the
same value several times (a combination's own bisection step, then the
other combinations there, then the whole technology to confirm the flip):
the second time, a program or a simulation with the same input gives the
same answer, so it is read back instead of run again. The key is the
input itself (every field of the program's input, every array of a
simulated design and its load cases), never the value moved, so nothing
that depends on that value can be read at another one. Outside
``reuse()`` nothing is kept: a plain solve runs every stage.
"""
from __future__ import annotations

from contextlib import contextmanager
from dataclasses import astuple, fields
from typing import Callable

import numpy as np

_store: dict | None = None


@contextmanager
def reuse():
    """Keep each stage's results by input until the block ends."""
    global _store
    outer, _store = _store, ({} if _store is None else _store)
    try:
        yield
    finally:
        _store = outer


def active() -> bool:
    return _store is not None


def cached(key: tuple, compute: Callable):
    """``compute()``, or what it gave for ``key`` earlier inside ``reuse()``."""
    if _store is None:
        return compute()
    if key not in _store:
        _store[key] = compute()
    return _store[key]


def gp_key(objectives: tuple, s) -> tuple:
    """A geometric program's key: its objectives and every input field."""
    return ("gp", objectives, astuple(s))


def simulation_key(design, loads, stroke: float) -> tuple:
    """A sized design's simulation key: every array of its
    candidate row, its ramp, the load cases and the target stroke."""
    cand = design.cand
    rows = tuple(np.asarray(getattr(cand, f.name)).tobytes() for f in fields(cand))
    return ("sim", rows, float(design.ramp), tuple(float(x) for x in loads), float(stroke))


def lookup(key: tuple):
    """What was kept for ``key`` inside ``reuse()``; None when nothing was."""
    return None if _store is None else _store.get(key)


def remember(key: tuple, value) -> None:
    """Keep ``value`` for ``key`` (only inside ``reuse()``)."""
    if _store is not None:
        _store[key] = value
