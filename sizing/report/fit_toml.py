"""Render fit results as TOML (docs/formats.md, "Fit output"): tables that paste
straight into a rig file ([stack], [stack.bouc_wen], [motor]) plus [fit]."""
from __future__ import annotations

import math

from ..io import toml_text


def _value(v) -> str:
    """A value as written in a fit file: floats to six significant digits."""
    if hasattr(v, "item") and not isinstance(v, str):
        v = v.item()
    if isinstance(v, float) and math.isfinite(v):
        v = float(f"{v:.6g}")
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    return toml_text.value(v)


def render_toml(tables: dict, comments: dict | None = None) -> str:
    """tables: {"stack": {...}, "stack.bouc_wen": {...}, "fit": {...}, ...},
    each a flat dict of scalars/lists, written in the given order. A value
    that is itself a dict is written as a sub-table after its parent."""
    comments = comments or {}
    lines: list[str] = []

    def emit(name, table):
        subs, body = [], []
        for key, val in table.items():
            if isinstance(val, dict):
                subs.append((f"{name}.{toml_text.key(key)}", val))
            elif val is not None:
                body.append(f"{toml_text.key(key)} = {_value(val)}")
        if body or not subs:
            lines.append(f"[{name}]" + (f"  {toml_text.comment(comments[name])}" if name in comments else ""))
            lines.extend(body + [""])
        for sub_name, sub in subs:
            emit(sub_name, sub)

    for name, table in tables.items():
        emit(name, table)
    return "\n".join(lines)
