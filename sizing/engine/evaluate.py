"""What every evaluation of one design file shares (each technology
evaluates its own in its folder, reached through ``Technology.evaluate``):
catalog look-ups, figures for results, the worst load case."""
from __future__ import annotations

import math

from ..errors import InputError
from ..io.catalog import Catalog
from .loads import load_cases  # noqa: F401  (the load cases every evaluation runs, read from here)


def lookup(catalog: Catalog, group: dict, entry_id: str | None, file: str, field: str):
    if entry_id is None:
        return None
    if entry_id not in group:
        known = ", ".join(sorted(group)) or "none"
        raise InputError(file, field, f"unknown catalog id {entry_id!r} (known: {known})")
    return group[entry_id]


def finite_or_none(value):
    """A figure for results: None where it is not finite."""
    value = float(value)
    return value if math.isfinite(value) else None


def worst_case(cases: list[dict]) -> dict:
    """The case with the largest load: what the contracts' 'simulated' means."""
    if not cases:
        return {}
    return max(cases, key=lambda case: case["load_N"])
