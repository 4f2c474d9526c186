"""The one TOML writer of every file the tool writes (fit results, catalog
entries, imported tables).

Keys and values are formatted by tomlkit, which follows the TOML spec's
quoting (a bare key is ASCII letters, digits, ``_`` and ``-`` only; any
other key is a quoted string) and escaping (quotes, backslashes and every
control character). The layout - table order, ``[[array]]`` entries, a
comment after a table's header - stays the caller's, so the files read the
same as they always have. Everything written here reads back with
``tomllib`` to the same values (tests/io/test_toml_text.py).
"""
from __future__ import annotations

import datetime as dt
import math
import unicodedata

import tomlkit


def key(name) -> str:
    """``name`` as a TOML key: bare when the spec allows, quoted otherwise."""
    return tomlkit.key(str(name)).as_string()


def table_name(*parts) -> str:
    """A dotted table name from its parts, each quoted as a key needs."""
    return ".".join(key(p) for p in parts)


def value(v) -> str:
    """One TOML value: booleans, integers, floats (nan and inf included),
    strings, dates and lists of them; numpy scalars by their Python value."""
    if hasattr(v, "item") and not isinstance(v, (str, bytes)):
        v = v.item()
    if isinstance(v, float) and not math.isfinite(v):
        return "nan" if math.isnan(v) else ("inf" if v > 0 else "-inf")
    if isinstance(v, tuple):
        v = list(v)
    if isinstance(v, list):
        return "[" + ", ".join(value(x) for x in v) + "]"
    if not isinstance(v, (bool, int, float, str, dt.date)):
        raise TypeError(f"cannot write {type(v).__name__} to TOML")
    return tomlkit.item(v).as_string()


def line(name, v) -> str:
    """``key = value``."""
    return f"{key(name)} = {value(v)}"


def comment(text: str) -> str:
    """``# text`` on one line: control characters (a newline would end the
    comment and start invalid TOML) become spaces."""
    clean = "".join(" " if unicodedata.category(c) == "Cc" else c for c in str(text))
    return f"# {clean}"
