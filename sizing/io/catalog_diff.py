"""``sizing catalog diff OLD NEW``: what changed between two catalogs.

OLD and NEW are catalog folders or git revisions of the repository
(``HEAD~3``, a tag, a commit; ``REV:path/to/catalogs`` for another folder
than ``catalogs/``). A revision is materialised from
``git show REV:catalogs/FILE`` into a scratch folder (``io.atomic``) and read like any
other folder.

Entries are compared by id. Quantities are compared in SI, so
``"100 N/um"`` and ``"1e8 N/m"`` are the same value; each changed field
carries the old and new value in SI with the SI unit, and the text as
written in the file. Provenance (``source``, ``retrieved``, ``status.*``)
and nested tables (``bouc_wen.*``, ``pid.*``) are compared too. A file
that the current schema rejects (an old revision, say) is still compared,
field by field, from its raw values.
"""
from __future__ import annotations

import contextlib
import datetime as dt
import math
import subprocess
import typing
from dataclasses import asdict, dataclass, field
from pathlib import Path

from pydantic import BaseModel, BeforeValidator

from ..errors import InputError
from ..units import KINDS as UNIT_KINDS, UnitError, parse_quantity, to_si
from .atomic import scratch_folder
from .catalog import DEFAULT_CATALOG, KINDS, load_catalog
from .schema import load_toml, read_input_bytes

REL_TOL = 1e-9          # quantities closer than this (relative) are equal


@dataclass
class FieldChange:
    field: str                    # "stiffness", "bouc_wen.d33", "status.stiffness", "source"
    old: object                   # SI float for quantities, else the value as read (None: absent)
    new: object
    unit: str | None = None       # SI unit of old and new ("N/m"), None for text
    old_text: str | None = None   # as written in the file, e.g. "4.33e8 N/m"
    new_text: str | None = None
    relative_change: float | None = None   # new / old - 1 for quantities


@dataclass
class EntryRef:
    kind: str                     # "stack", "fluid", ...
    id: str
    file: str                     # "stacks.toml"


@dataclass
class EntryChange(EntryRef):
    fields: list[FieldChange] = field(default_factory=list)


@dataclass
class CatalogDiff:
    """Result of ``diff_catalogs``. ``changed_fields()`` indexes it by id."""

    old: str
    new: str
    added: list[EntryRef] = field(default_factory=list)
    removed: list[EntryRef] = field(default_factory=list)
    changed: list[EntryChange] = field(default_factory=list)
    old_sha256: str | None = None
    new_sha256: str | None = None

    @property
    def empty(self) -> bool:
        return not (self.added or self.removed or self.changed)

    def changed_fields(self) -> dict[str, list[FieldChange]]:
        return {c.id: c.fields for c in self.changed}

    def to_dict(self) -> dict:
        return asdict(self)

    @classmethod
    def from_dict(cls, data: dict) -> "CatalogDiff":
        """Inverse of ``to_dict`` (e.g. a ``diff --json`` output read back)."""
        return cls(old=data.get("old", ""), new=data.get("new", ""),
                   added=[EntryRef(**e) for e in data.get("added", [])],
                   removed=[EntryRef(**e) for e in data.get("removed", [])],
                   changed=[EntryChange(kind=c["kind"], id=c["id"], file=c["file"],
                                        fields=[FieldChange(**f) for f in c.get("fields", [])])
                            for c in data.get("changed", [])],
                   old_sha256=data.get("old_sha256"), new_sha256=data.get("new_sha256"))


# --- where a catalog comes from -------------------------------------------

def _git(args: list[str], cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run(["git", *args], cwd=cwd, capture_output=True, text=True)


def _repository(start: Path) -> Path | None:
    try:
        out = _git(["rev-parse", "--show-toplevel"], start)
    except (FileNotFoundError, NotADirectoryError):
        return None
    return Path(out.stdout.strip()) if out.returncode == 0 else None


def _repositories() -> list[Path]:
    """The repository of the working directory, then the one sizing ships in."""
    found = []
    for start in (Path.cwd(), DEFAULT_CATALOG.parent):
        repo = _repository(start) if start.is_dir() else None
        if repo is not None and repo not in found:
            found.append(repo)
    return found


def revision_files(spec: str, repo: Path | None = None) -> dict[str, bytes]:
    """{file name: content} of the catalog files of git revision ``spec``
    (``REV`` or ``REV:folder``). InputError when no repository knows the
    revision or it holds no catalog files."""
    rev, _, sub = spec.partition(":")
    sub = (sub or "catalogs").strip("/")
    repos = [repo] if repo is not None else _repositories()
    if not repos:
        raise InputError(spec, None, "expected a catalog folder or a git revision, and no git repository was found")
    for root in repos:
        if _git(["rev-parse", "--verify", "--quiet", f"{rev}^{{commit}}"], root).returncode != 0:
            continue
        listing = _git(["ls-tree", "--name-only", f"{rev}:{sub}"], root)
        names = [n for n in listing.stdout.split() if n in KINDS] if listing.returncode == 0 else []
        if not names:
            raise InputError(spec, None, f"revision {rev} of {root} has no catalog files in {sub}/ ({', '.join(KINDS)})")
        files = {}
        for name in names:
            shown = subprocess.run(["git", "show", f"{rev}:{sub}/{name}"], cwd=root, capture_output=True)
            if shown.returncode != 0:
                raise InputError(spec, name, f"git show failed: {shown.stderr.decode(errors='replace').strip()}")
            files[name] = shown.stdout
        return files
    raise InputError(spec, None, "expected a catalog folder or a git revision (no such folder, "
                                 f"and no revision {rev!r} in {', '.join(map(str, repos))})")


# --- reading entries ---------------------------------------------------------

def quantity_kind(model: type[BaseModel], name: str) -> str | None:
    """The unit kind (``units.KINDS`` key) of a Qty field of ``model``, or None."""
    info = model.model_fields.get(name)
    if info is None:
        return None
    for meta in info.metadata:
        kind = _kind_of_validator(meta)
        if kind:
            return kind
    return _kind_in_annotation(info.annotation)


def _kind_of_validator(meta) -> str | None:
    if not isinstance(meta, BeforeValidator):
        return None
    func = meta.func
    if getattr(func, "kind", None):
        return func.kind
    names = getattr(func.__code__, "co_freevars", ())
    for var, cell in zip(names, func.__closure__ or ()):
        if var == "kind" and cell.cell_contents in UNIT_KINDS:
            return cell.cell_contents
    return None


def _kind_in_annotation(annotation) -> str | None:
    for meta in getattr(annotation, "__metadata__", ()):
        kind = _kind_of_validator(meta)
        if kind:
            return kind
    for arg in typing.get_args(annotation):
        kind = _kind_in_annotation(arg)
        if kind:
            return kind
    return None


def field_unit(model: type[BaseModel], name: str) -> str | None:
    """SI unit of a quantity field of a catalog model ("N/m"), or None."""
    return _unit(quantity_kind(model, name))


def _unit(kind: str | None) -> str | None:
    if kind is None:
        return None
    unit = UNIT_KINDS[kind][0].replace("**", "^").replace("*", " ")
    return unit or "1"


def _flatten(raw: dict, model: type[BaseModel] | None) -> dict[str, tuple[object, str | None, str | None]]:
    """{field path: (value, unit, text)} of one raw TOML entry. Quantities
    become SI floats when they convert, else stay as written."""
    flat: dict[str, tuple[object, str | None, str | None]] = {}
    for key, value in raw.items():
        if isinstance(value, dict):
            sub_model = _sub_model(model, key)
            for sub_key, sub_value in value.items():
                kind = quantity_kind(sub_model, sub_key) if sub_model is not None else None
                flat[f"{key}.{sub_key}"] = _value(sub_value, kind, f"{key}.{sub_key}")
            continue
        kind = quantity_kind(model, key) if model is not None else None
        flat[key] = _value(value, kind, key)
    return flat


def _sub_model(model: type[BaseModel] | None, key: str) -> type[BaseModel] | None:
    if model is None or key not in model.model_fields:
        return None
    for arg in (model.model_fields[key].annotation, *typing.get_args(model.model_fields[key].annotation)):
        if isinstance(arg, type) and issubclass(arg, BaseModel):
            return arg
    return None


TEXT_FIELDS = {"id", "name", "manufacturer", "source", "notes", "material", "type", "section", "derivative_on"}


def _value(value, kind: str | None, key: str = ""):
    text = value if isinstance(value, str) else None
    if isinstance(value, (dt.date, dt.datetime)):
        return value.isoformat(), None, None
    if kind is None:
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            return float(value), None, None
        if text is not None and len(text) < 60 and key not in TEXT_FIELDS and not key.startswith("status"):
            return _base_units(value)
        return value, None, text
    try:
        return to_si(value, kind), _unit(kind), text if text is not None else repr(value)
    except (UnitError, TypeError, ValueError):
        return value, None, text


def _base_units(text: str):
    """A quantity in a field without a declared unit ("-25.5552 1/s"):
    its magnitude in SI base units, so that a bare number compares equal."""
    try:
        quantity = parse_quantity(text).to_base_units()
    except (UnitError, Exception):   # pint raises several types on odd input
        return text, None, text
    unit = f"{quantity.units:~}".replace(" ", "").replace("**", "^") or None
    return float(quantity.magnitude), unit, text


def read_raw(folder: Path) -> dict[str, tuple[str, str, dict]]:
    """{id: (kind, file name, flat fields)} of every entry in ``folder``."""
    entries: dict[str, tuple[str, str, dict]] = {}
    for file_name, (array, model) in KINDS.items():
        path = folder / file_name
        if not path.exists():
            continue
        for index, raw in enumerate(load_toml(path).get(array, [])):
            if not isinstance(raw, dict):
                raise InputError(str(path), f"[[{array}]] #{index + 1}", "expected a table")
            entry_id = raw.get("id")
            if not isinstance(entry_id, str):
                raise InputError(str(path), f"[[{array}]] #{index + 1}: id", "required field is missing")
            entries[entry_id] = (array, file_name, _flatten(raw, model))
    return entries


def _read_labelled(folder: Path, spec) -> dict:
    """read_raw, with errors in a materialised revision named REV:catalogs/FILE."""
    try:
        return read_raw(folder)
    except InputError as exc:
        if Path(spec).is_dir() or exc.file is None:
            raise
        rev, _, sub = str(spec).partition(":")
        name = Path(exc.file).name
        raise InputError(f"{rev}:{(sub or 'catalogs').strip('/')}/{name}", exc.field, exc.message) from None


# --- baselines ---------------------------------------------------------------

SNAPSHOT_DIR = "catalog"     # folder beside results.json holding the catalog it was computed with


def snapshot_files(catalog_folder: str | Path) -> dict[str, bytes]:
    """{``catalog/FILE``: content} of the catalog files: what ``sizing solve``
    writes beside results.json so that a later ``--baseline
    out_dir/results.json`` can diff against them."""
    folder = Path(catalog_folder)
    return {f"{SNAPSHOT_DIR}/{name}": read_input_bytes(folder / name) for name in KINDS if (folder / name).exists()}


def baseline_catalog(results_path: str | Path, results: dict | None = None) -> Path | None:
    """The catalog a baseline results.json was computed with: the snapshot
    beside it, else its ``catalog_dir`` when that folder still has the same
    ``catalog_sha256``; None when neither is available."""
    results_path = Path(results_path)
    snapshot = results_path.parent / SNAPSHOT_DIR
    if snapshot.is_dir() and any((snapshot / name).exists() for name in KINDS):
        return snapshot
    results = results or {}
    folder = results.get("catalog_dir")
    if folder and Path(folder).is_dir():
        if results.get("catalog_sha256") in (None, _sha(Path(folder))):
            return Path(folder)
    return None


# --- comparing -------------------------------------------------------------

def _same(a, b) -> bool:
    if isinstance(a, float) and isinstance(b, float):
        return a == b or math.isclose(a, b, rel_tol=REL_TOL, abs_tol=0.0)
    if isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool) and not isinstance(b, bool):
        return math.isclose(float(a), float(b), rel_tol=REL_TOL)
    return a == b


def _compare(old: dict, new: dict) -> list[FieldChange]:
    changes = []
    order = list(old) + [k for k in new if k not in old]
    for key in order:
        o_val, o_unit, o_text = old.get(key, (None, None, None))
        n_val, n_unit, n_text = new.get(key, (None, None, None))
        if key in old and key in new and _same(o_val, n_val):
            continue
        unit = n_unit or o_unit
        rel = None
        if (isinstance(o_val, (int, float)) and isinstance(n_val, (int, float)) and o_val
                and not isinstance(o_val, bool) and not isinstance(n_val, bool)):
            rel = n_val / o_val - 1
        changes.append(FieldChange(key, o_val, n_val, unit, o_text, n_text, rel))
    # quantities first, then notes and provenance
    rank = lambda c: (c.field.startswith("status.") or c.field in ("source", "retrieved", "notes", "name"), )
    return sorted(changes, key=rank)


def _sha(folder: Path) -> str | None:
    try:
        return load_catalog(folder).sha256
    except InputError:
        return None


def diff_catalogs(old: str | Path, new: str | Path) -> CatalogDiff:
    """Compare two catalogs (folders or git revisions, see module doc)."""
    with contextlib.ExitStack() as stack:
        folders = [Path(spec) if Path(spec).is_dir() else
                   stack.enter_context(scratch_folder(revision_files(str(spec)), prefix="sizing-diff-"))
                   for spec in (old, new)]
        a, b = (_read_labelled(f, spec) for f, spec in zip(folders, (old, new)))
        diff = CatalogDiff(old=str(old), new=str(new), old_sha256=_sha(folders[0]), new_sha256=_sha(folders[1]))
    for entry_id, (kind, file_name, _) in b.items():
        if entry_id not in a:
            diff.added.append(EntryRef(kind, entry_id, file_name))
    for entry_id, (kind, file_name, old_fields) in a.items():
        if entry_id not in b:
            diff.removed.append(EntryRef(kind, entry_id, file_name))
            continue
        changes = _compare(old_fields, b[entry_id][2])
        if changes:
            diff.changed.append(EntryChange(kind, entry_id, b[entry_id][1], changes))
    return diff


# --- text --------------------------------------------------------------------

def _show(value, unit, text) -> str:
    if value is None:
        return "(absent)"
    if isinstance(value, float) and unit is not None:
        si = f"{value:.6g} {unit}" if unit != "1" else f"{value:.6g}"
        return si if text is None or text.strip() == si or _plain_number(text) else f"{si} ({text})"
    shown = str(value)
    return shown if len(shown) <= 70 else shown[:67] + "..."


def _show_text_change(old: str, new: str) -> str:
    """Long texts (notes, sources): the neighbourhood of the first difference."""
    start = next((i for i, (a, b) in enumerate(zip(old, new)) if a != b), min(len(old), len(new)))
    lo = max(0, start - 20)
    cut = lambda s: ("..." if lo else "") + s[lo:start + 40].replace("\n", " ") + ("..." if len(s) > start + 40 else "")
    return f'"{cut(old)}" -> "{cut(new)}"'


def _plain_number(text: str) -> bool:
    try:
        float(text)
        return True
    except ValueError:
        return False


def format_diff(diff: CatalogDiff) -> str:
    """Plain text for the terminal: one line per added, removed or changed
    entry, one indented line per changed field."""
    lines = [f"catalog diff {diff.old} -> {diff.new}: {len(diff.added)} added, "
             f"{len(diff.removed)} removed, {len(diff.changed)} changed"]
    for e in diff.added:
        lines.append(f"+ {e.kind} {e.id} ({e.file})")
    for e in diff.removed:
        lines.append(f"- {e.kind} {e.id} ({e.file})")
    for e in diff.changed:
        lines.append(f"~ {e.kind} {e.id} ({e.file})")
        for c in e.fields:
            rel = f"  [{c.relative_change:+.1%}]" if c.relative_change is not None else ""
            if isinstance(c.old, str) and isinstance(c.new, str) and max(len(c.old), len(c.new)) > 70:
                lines.append(f"    {c.field}: {_show_text_change(c.old, c.new)}")
                continue
            lines.append(f"    {c.field}: {_show(c.old, c.unit, c.old_text)} -> {_show(c.new, c.unit, c.new_text)}{rel}")
    return "\n".join(lines)
