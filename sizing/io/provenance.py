"""Provenance of catalog values, for reports: which results rest on values
whose status is ``"assumed: <reason>"`` rather than a datasheet, the seed
(ARL-TR-10251) or a measurement (``sizing fit``)."""
from __future__ import annotations

from collections.abc import Iterable, Mapping

from .catalog import Catalog

STATUSES = ("datasheet", "seed", "measured", "assumed")


def status_kind(text: str) -> str:
    """``"assumed: k_s x stroke"`` -> ``"assumed"``; ``"seed"`` -> ``"seed"``."""
    return text.split(":", 1)[0].strip()


def assumed_values(catalog: Catalog, component_ids) -> dict[str, dict[str, str]]:
    """{entry id: {field: reason}} for every assumed value of the given parts.

    ``component_ids`` is an iterable of catalog ids, or a candidate's
    ``components`` dict (non-string values such as ``n_stacks`` and ids not
    in the catalog are skipped). Entries without assumed values are left out.
    """
    if isinstance(component_ids, str):
        component_ids = [component_ids]
    elif isinstance(component_ids, Mapping):
        component_ids = component_ids.values()
    out: dict[str, dict[str, str]] = {}
    for entry_id in _unique(component_ids):
        try:
            _, entry = catalog.get(entry_id)
        except KeyError:
            continue
        assumed = entry.assumed()
        if assumed:
            out[entry_id] = assumed
    return out


def status_counts(catalog: Catalog, component_ids: Iterable[str]) -> dict[str, int]:
    """How many values of the given parts have each status."""
    counts = dict.fromkeys(STATUSES, 0)
    for entry_id in _unique(component_ids):
        try:
            _, entry = catalog.get(entry_id)
        except KeyError:
            continue
        for text in entry.status.values():
            kind = status_kind(text)
            counts[kind] = counts.get(kind, 0) + 1
    return counts


def _unique(ids) -> list[str]:
    found: list[str] = []
    for value in ids:
        if isinstance(value, str) and value not in found:
            found.append(value)
    return found
