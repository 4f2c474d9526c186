"""Render fit results as TOML (docs/formats.md, "Fit output"): tables that paste
straight into a rig file ([stack], [stack.bouc_wen], [motor]) plus [fit]."""
from __future__ import annotations

import math


def _value(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(float(f"{v:.6g}"))
    if isinstance(v, str):
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if hasattr(v, "item"):
        return _value(v.item())
    raise TypeError(f"cannot write {type(v).__name__} to TOML")


def _key(k: str) -> str:
    return k if k and all(c.isalnum() or c in "_-" for c in k) else _value(str(k))


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
                subs.append((f"{name}.{_key(key)}", val))
            elif val is not None:
                body.append(f"{_key(key)} = {_value(val)}")
        if body or not subs:
            lines.append(f"[{name}]" + (f"  # {comments[name]}" if name in comments else ""))
            lines.extend(body + [""])
        for sub_name, sub in subs:
            emit(sub_name, sub)

    for name, table in tables.items():
        emit(name, table)
    return "\n".join(lines)
