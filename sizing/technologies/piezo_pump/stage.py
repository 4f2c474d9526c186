"""The piezo pump's stage of ``sizing solve``: its designs (``designs``)
and their results.json records (``record``)."""
from __future__ import annotations

from collections import Counter

from ...engine.records import Outcome
from .designs import pump_designs
from .record import pump_candidate


def solve(req, catalog, loads, progress, detail="summary") -> tuple[Outcome, tuple]:
    """The frequency-rectified piezo pump (``designs.py``) and its records."""
    out = pump_designs(req, catalog, loads, progress)
    return Outcome("piezo_pump", [pump_candidate(req, d) for d in out.designs], Counter(out.ruled_out),
                   out.records, dict(out.counts)), out.designs
