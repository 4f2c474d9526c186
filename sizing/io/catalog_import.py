"""``sizing catalog add KIND FILE.csv``: new parts from a vendor sheet.

The CSV has a header line and one part per row. Columns are the fields of
the kind (catalogs/README.md); a unit may sit in the header, as vendor
sheets do (``stiffness [N/um]`` or ``stiffness (N/um)``), or in the cell
(``"100 N/um"``); a bare number under a header without unit is SI.
Nested tables are columns ``bouc_wen.d33`` or ``pid.kp``. Provenance: a
``status`` column gives the status of every value of the row (default
``datasheet``), ``status.FIELD`` columns override it per field. ``retrieved``
defaults to today. Empty cells are absent values.

Every row is validated like a catalog entry (schema, units, plausibility,
an id new to the catalog and to the sheet); the first bad row is an
InputError naming the CSV line and column. Only when every row is good are
the entries appended to the kind's file, atomically.
"""
from __future__ import annotations

import csv
import datetime as dt
import re
from dataclasses import dataclass
from pathlib import Path

from ..errors import InputError
from .catalog import DEFAULT_CATALOG, KINDS, Entry, load_catalog
from . import toml_text
from .schema import parse_model

# "name [unit]" or "name (unit)"; the unit may hold parentheses itself, as the
# catalog's own units do ("friction_pressure_coefficient [N/(m*Pa)]")
_HEADER = re.compile(r"^\s*([A-Za-z0-9_.]+)\s*(?:\[\s*([^\]]*?)\s*\]|\(\s*(.*?)\s*\))?\s*$")
PROVENANCE = ("id", "name", "manufacturer", "source", "retrieved", "notes")
TEXT_FIELDS = ("material", "type", "section", "derivative_on")


@dataclass
class ImportResult:
    file: Path            # the catalog file to write
    kind: str             # "stack", ...
    ids: list[str]        # entries added, in sheet order
    text: str = ""        # the catalog file with them appended


def resolve_kind(kind: str) -> tuple[str, str, type[Entry]]:
    """'stack', 'stacks' or 'stacks.toml' -> (file name, array name, model)."""
    key = kind.strip().lower().removesuffix(".toml").replace("-", "_")
    for file_name, (array, model) in KINDS.items():
        if key in (array, file_name.removesuffix(".toml")):
            return file_name, array, model
    known = ", ".join(array for array, _ in KINDS.values())
    raise InputError(None, "KIND", f"expected one of {known}, got {kind!r}")


def _columns(header: list[str], csv_path: Path, model: type[Entry]) -> list[tuple[str, str | None]]:
    known = set(model.model_fields) - {"status"}
    nested = {name for name in ("bouc_wen", "pid") if name in model.model_fields}
    columns = []
    for index, text in enumerate(header, start=1):
        match = _HEADER.match(text or "")
        name, unit = (match.group(1), match.group(2) or match.group(3) or None) if match else (text, None)
        head, _, tail = name.partition(".")
        ok = (name in known and name not in nested) or name == "status" \
            or (head == "status" and tail in model.quantity_fields() + sorted(nested)) \
            or (head in nested and tail in _sub_fields(model, head))
        if not ok:
            raise InputError(str(csv_path), f"line 1, column {index} ({text!r})",
                             f"unknown column; expected fields of a {model.__name__.lower()} "
                             f"(catalogs/README.md), 'status' or 'status.FIELD'")
        if any(c[0] == name for c in columns):
            raise InputError(str(csv_path), f"line 1, column {index} ({text!r})", "duplicate column")
        columns.append((name, unit))
    if "id" not in [c[0] for c in columns]:
        raise InputError(str(csv_path), "line 1", "expected an 'id' column")
    return columns


def _sub_fields(model: type[Entry], name: str) -> list[str]:
    from .catalog_diff import _sub_model
    sub = _sub_model(model, name)
    return list(sub.model_fields) if sub is not None else []


def _cell(value: str, unit: str | None):
    value = value.strip()
    try:
        number = float(value)
    except ValueError:
        return value
    if unit:
        return f"{value} {unit}"
    return int(value) if re.fullmatch(r"[-+]?\d+", value) else number


def _row_to_raw(row: list[str], columns, model: type[Entry], csv_path: Path, line: int) -> tuple[dict, dict]:
    """Raw TOML-like dict of one row, and {field: column label} for messages."""
    raw: dict = {}
    where: dict[str, str] = {}
    statuses: dict[str, str] = {}
    default_status = "datasheet"
    for index, ((name, unit), value) in enumerate(zip(columns, row), start=1):
        if value is None or not value.strip():
            continue
        label = f"column {index} ({name})"
        if name == "status":
            default_status = value.strip()
            where["status"] = label
            continue
        head, _, tail = name.partition(".")
        if head == "status":
            statuses[tail] = value.strip()
            where[f"status.{tail}"] = label
        elif tail:
            raw.setdefault(head, {})[tail] = _cell(value, unit)
            where[f"{head}.{tail}"] = label
        elif name in PROVENANCE or name in TEXT_FIELDS:
            raw[name] = value.strip()
            where[name] = label
        else:
            raw[name] = _cell(value, unit)
            where[name] = label
    if len(row) > len(columns) and any(v.strip() for v in row[len(columns):]):
        raise InputError(str(csv_path), f"line {line}", f"expected {len(columns)} cells (as in the header), got {len(row)}")
    if "retrieved" in raw:
        try:
            raw["retrieved"] = dt.date.fromisoformat(raw["retrieved"])
        except ValueError:
            raise InputError(str(csv_path), f"line {line}, {where['retrieved']}",
                             f"expected a date YYYY-MM-DD, got {raw['retrieved']!r}") from None
    else:
        raw["retrieved"] = dt.date.today()
    status = {name: statuses.get(name, default_status) for name in model.quantity_fields() if name in raw}
    for name in ("bouc_wen", "pid"):
        if name in raw and name in statuses:
            status[name] = statuses[name]
        elif name == "bouc_wen" and name in raw:
            status[name] = default_status
    status.update({k: v for k, v in statuses.items() if k not in status})
    raw["status"] = status
    return raw, where


def _column_of(field: str, where: dict[str, str]) -> str:
    """Pydantic's '[bouc_wen].d33' or 'status' -> the CSV column label."""
    path = field.replace("[", "").replace("]", "")
    if path in where:
        return where[path]
    head = path.split(".")[0].split(":")[0]
    if head == "status":
        for key, label in where.items():
            if key.startswith("status"):
                return label
        return "column status"
    return where.get(head, f"column {head}")


def parse_sheet(csv_path: str | Path, model: type[Entry], array: str) -> list[tuple[int, Entry, dict]]:
    """(CSV line, validated entry, raw dict) of every row of the sheet."""
    csv_path = Path(csv_path)
    try:
        text = csv_path.read_text(encoding="utf-8-sig")
    except FileNotFoundError:
        raise InputError(str(csv_path), None, "file not found") from None
    except (IsADirectoryError, UnicodeDecodeError):
        raise InputError(str(csv_path), None, "expected a UTF-8 CSV file") from None
    except OSError as exc:      # symlink loop, permission denied
        raise InputError(str(csv_path), None, f"cannot read the CSV file: {exc.strerror or exc}") from None
    rows = list(csv.reader(text.splitlines()))
    if not rows:
        raise InputError(str(csv_path), "line 1", "expected a header line, got an empty file")
    columns = _columns(rows[0], csv_path, model)
    from .validate import _entry_problems
    parsed = []
    ids: dict[str, int] = {}
    for line, row in enumerate(rows[1:], start=2):
        if not any(cell.strip() for cell in row):
            continue
        raw, where = _row_to_raw(row, columns, model, csv_path, line)
        try:
            entry = parse_model(model, raw, csv_path)
        except InputError as exc:
            raise InputError(str(csv_path), f"line {line}, {_column_of(exc.field or '', where)}",
                             f"{exc.field}: {exc.message}" if exc.field else exc.message) from None
        if entry.id in ids:
            raise InputError(str(csv_path), f"line {line}, {where['id']}", f"duplicate id {entry.id!r}, already on line {ids[entry.id]}")
        ids[entry.id] = line
        for field_name, message in _entry_problems(array, entry, dt.date.today()):
            if message.startswith("warning: "):
                continue
            raise InputError(str(csv_path), f"line {line}, {_column_of(field_name, where)}", f"{field_name}: {message}")
        parsed.append((line, entry, raw))
    if not parsed:
        raise InputError(str(csv_path), "line 2", "expected at least one part after the header")
    return parsed


# --- TOML -----------------------------------------------------------------

def entry_toml(array: str, raw: dict) -> str:
    """One ``[[array]]`` entry as written in the catalog files."""
    lines = [f"[[{toml_text.table_name(array)}]]"]
    tables = {k: v for k, v in raw.items() if isinstance(v, dict)}
    first = [k for k in PROVENANCE[:5] if k in raw]
    rest = [k for k in raw if k not in first and k not in tables and k != "notes"]
    for key in first + rest + (["notes"] if "notes" in raw else []):
        lines.append(toml_text.line(key, raw[key]))
    for name, table in tables.items():
        if name == "status":
            continue
        lines += ["", f"[{toml_text.table_name(array, name)}]"] + [toml_text.line(k, v) for k, v in table.items()]
    if raw.get("status"):
        lines += ["", f"[{toml_text.table_name(array, 'status')}]"] + [toml_text.line(k, v) for k, v in raw["status"].items()]
    return "\n".join(lines) + "\n"


def plan_parts(kind: str, csv_path: str | Path, catalog_dir: str | Path | None = None) -> ImportResult:
    """Validate the sheet and give the kind's catalog file with its parts
    appended (``ImportResult.text``); ``api.catalogs`` reads the catalog
    back with it and writes it."""
    file_name, array, model = resolve_kind(kind)
    folder = Path(catalog_dir) if catalog_dir is not None else DEFAULT_CATALOG
    catalog = load_catalog(folder)
    parsed = parse_sheet(csv_path, model, array)
    for line, entry, _ in parsed:
        if any(entry.id in group for group in catalog.groups().values()):
            raise InputError(str(csv_path), f"line {line}, column id",
                             f"id {entry.id!r} is already in the catalog ({folder})")
    target = folder / file_name
    old = target.read_text(encoding="utf-8") if target.exists() else \
        f"# {array} entries; schema: catalogs/README.md ([[{array}]]).\n"
    stamp = dt.date.today().isoformat()
    block = f"\n# Added by `sizing catalog add {array} {Path(csv_path).name}` on {stamp}.\n" + \
        "\n".join(entry_toml(array, raw) for _, _, raw in parsed)
    new = old.rstrip("\n") + "\n" + block
    return ImportResult(file=target, kind=array, ids=[entry.id for _, entry, _ in parsed], text=new)
