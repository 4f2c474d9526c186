"""``sizing fit hysteresis --catalog-entry ID``: a catalog stack entry
(catalogs/README.md, ``[[stack]]``) carrying the fitted Bouc-Wen parameters
under status ``measured``.

A fit measures only the hysteresis; every other field of a stack entry
(stiffness, capacitance, mass, ...) comes from the base entry: the stack
named with ``--prior-stack`` (its statuses kept), or, when none is named, the
seed's Table 1 stack with every copied value marked ``assumed`` so that
``sizing catalog list`` counts them and nobody mistakes them for the
measured stack's datasheet. Pure: raw dicts in, raw dict / text out; the
command (``api.fitting``) reads the base entry, validates it and writes ID.toml
(a ``[[stack]]`` block for a catalog file) and ID.csv (a one-row sheet for
``sizing catalog add stack ID.csv``).
"""
from __future__ import annotations

import copy
import csv
import datetime as dt
import io

from ..fit.bouc_wen import PARAM_NAMES


def stack_entry(base: dict, entry_id: str, params, sources: list[str], base_named: bool, prior_note: str,
                today: dt.date | None = None) -> dict:
    """Raw ``[[stack]]`` entry: ``base`` (a raw catalog entry) with id,
    provenance and ``bouc_wen`` replaced by the fit's values (SI)."""
    today = today or dt.date.today()
    raw = copy.deepcopy(base)
    runs = ", ".join(sources)
    raw["id"] = entry_id
    raw["name"] = f"{base['name']} (Bouc-Wen measured: {entry_id})"
    raw["source"] = (f"sizing fit hysteresis on {runs} ({today.isoformat()}); other values from catalog entry "
                     f"{base['id']}: {base['source']}")
    raw["retrieved"] = today
    raw["bouc_wen"] = {name: float(v) for name, v in zip(PARAM_NAMES, params)}
    status = dict(base.get("status", {}))
    if not base_named:
        reason = (f"assumed: copied from {base['id']} (no --prior-stack named the measured stack); "
                  "replace with the measured stack's datasheet value")
        status = {key: reason for key in status}
    status["bouc_wen"] = f"measured: sizing fit hysteresis on {runs}, {prior_note}"
    raw["status"] = status
    note = (f"Bouc-Wen parameters fitted with sizing fit hysteresis ({today.isoformat()}) on {runs}. "
            + ("" if base_named else f"Every other value is copied from {base['id']} and marked assumed. "))
    raw["notes"] = note + (base.get("notes") or "")
    return raw


def stack_sheet(raw: dict) -> str:
    """The entry as a one-row sheet for ``sizing catalog add`` (catalog_import:
    quantities keep their units in the cells, nested tables are
    ``bouc_wen.NAME`` columns, statuses ``status.FIELD`` columns; the sheet
    reader takes one line per row, so line breaks in notes become spaces)."""
    columns, cells = [], []
    for key, value in raw.items():
        if key == "status":
            continue
        if isinstance(value, dict):
            for sub, v in value.items():
                columns.append(f"{key}.{sub}")
                cells.append(repr(float(v)) if isinstance(v, float) else str(v))
        else:
            columns.append(key)
            text = value.isoformat() if isinstance(value, dt.date) else str(value)
            cells.append(" ".join(text.split()) if key == "notes" else text)
    for key, value in raw.get("status", {}).items():
        columns.append(f"status.{key}")
        cells.append(value)
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(columns)
    writer.writerow(cells)
    return buffer.getvalue()
