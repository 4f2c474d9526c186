"""How the flips re-solve the DC motor actuator (``registry.Resolving``):
the designs asked about alone, on a catalog of the parts they use (designs
from parts each simulated, catalog actuators re-simulated)."""
from __future__ import annotations

from typing import TYPE_CHECKING

from dataclasses import replace

from ..registry import Resolving

if TYPE_CHECKING:
    from ...engine.candidate import Candidate

# the catalog groups of a DC design's parts, by its components key
PART_GROUPS = {"motor": "motors", "screw": "screws", "gear": "gears", "drive": "drives", "actuator": "dc_actuators"}


def parts_of(catalog, alive: tuple):
    """The catalog with only the DC parts (and catalog actuators) that
    ``alive`` designs use; the other technologies' parts are kept."""
    used = {attr: set() for attr in PART_GROUPS.values()}
    for c in alive:
        for kind, ident in (c.components or {}).items():
            if kind in PART_GROUPS and ident is not None:
                used[PART_GROUPS[kind]].add(ident)
    return replace(catalog, **{attr: {k: v for k, v in getattr(catalog, attr).items() if k in ids}
                               for attr, ids in used.items()})


def units(solve, req, catalog, loads, cs: list[Candidate]) -> list[dict]:
    """Designs ``cs`` re-solved for ``req`` and ``catalog``."""
    rows = {tuple((c.components or {}).get(k) for k in ("motor", "screw", "gear", "drive")) for c in cs}
    return solve(req, parts_of(catalog, tuple(cs)), loads, None, "summary", rows=rows)[0].candidates


RESOLVING = Resolving(units=units)
