"""``sizing catalog``: list, show, validate and compare the parts catalog,
and add parts to it (a vendor sheet, the makers' motor tables)."""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, ClassVar

from ..errors import InputError
from ..io.catalog import Catalog, Entry, load_catalog
from . import output
from .output import Payload

if TYPE_CHECKING:                   # the types alone: not imported when the module loads
    from ..io.catalog_diff import CatalogDiff


def catalog(folder: str | Path | None = None) -> Catalog:
    """The catalog in ``folder`` (default: the one that ships with sizing)."""
    return load_catalog(folder)


def catalog_table(folder: str | Path | None = None) -> str:
    """Every entry: id, kind, name and source (``sizing catalog list``)."""
    from ..report.text import catalog_table as table
    return table(load_catalog(folder))


@dataclass(frozen=True)
class CatalogEntry:
    """One catalog entry and its kind."""

    kind: str
    entry: Entry

    def to_dict(self) -> dict:
        return {"kind": self.kind, **self.entry.model_dump(mode="json")}

    def details(self) -> str:
        """Every field with its unit and provenance (report/text.py)."""
        from ..report.text import entry_details
        return entry_details(self.kind, self.entry)


def catalog_entry(entry_id: str, folder: str | Path | None = None) -> CatalogEntry:
    """The entry ``entry_id``; InputError naming the nearest ids when absent."""
    cat = load_catalog(folder)
    try:
        return CatalogEntry(*cat.get(entry_id))
    except KeyError:
        import difflib
        near = difflib.get_close_matches(entry_id, [e.id for _, e in cat.entries()], n=3, cutoff=0.6)
        hint = f"; did you mean {', '.join(near)}?" if near else "; `sizing catalog list` lists them"
        raise InputError(str(cat.folder), "id", f"no entry {entry_id!r} in the catalog{hint}") from None


def catalog_validate(folder: str | Path | None = None, max_age_days: int = 730):
    """Schema, units, ids and plausibility (InputError on the first
    problem); the ValidationReport lists stale entries as warnings."""
    from ..io.validate import validate_catalog
    return validate_catalog(folder, max_age_days=max_age_days)


def catalog_diff(old: str | Path, new: str | Path | None = None):
    """Added, removed and changed entries (a CatalogDiff: ``to_dict()``,
    ``text()``) between two catalogs, each a folder or a git revision;
    ``new`` defaults to the shipped catalog."""
    from ..io.catalog import DEFAULT_CATALOG
    from ..io.catalog_diff import diff_catalogs
    return CatalogDiffResult(diff_catalogs(old, str(new) if new is not None else str(DEFAULT_CATALOG)))


@dataclass(frozen=True)
class CatalogDiffResult:
    diff: CatalogDiff

    def to_dict(self) -> dict:
        return self.diff.to_dict()

    def text(self) -> str:
        from ..io.catalog_diff import format_diff
        return format_diff(self.diff)


@dataclass(frozen=True)
class CatalogUpdate(Payload):
    """Catalog files to write ({path: text}) and what they add: ``added``
    (``catalog add``: file, kind, ids; ``import-mgdb``: counts, skipped,
    files). Reads as ``added``."""

    added: dict
    texts: dict
    inputs: tuple = ()
    layout: ClassVar[str] = "files"

    def _payload(self) -> dict:
        return self.added

    def files(self) -> dict:
        return dict(self.texts)


def _read_back(texts: dict[Path, str], check=None) -> None:
    """Load the catalog with ``texts`` ({path: text}, one folder) in place of
    its files, in a scratch folder, before anything is written;
    ``check(catalog)`` for what loading does not check."""
    from ..io.atomic import scratch_folder
    from ..io.catalog import KINDS
    folder = next(iter(texts)).parent
    names = {path.name: text for path, text in texts.items()}
    kept = {name: (folder / name).read_bytes() for name in KINDS if (folder / name).exists() and name not in names}
    with scratch_folder({**kept, **names}, prefix="sizing-catalog-") as tmp:
        catalog = load_catalog(tmp)
        if check is not None:
            check(catalog)


def catalog_add(kind: str, sheet: str | Path, folder: str | Path | None = None) -> CatalogUpdate:
    """Validate a vendor sheet (CSV) and append its parts to the kind's
    catalog file, atomically, once the whole catalog loads with them."""
    from ..io.catalog_import import plan_parts
    planned = plan_parts(kind, sheet, folder)
    try:
        _read_back({planned.file: planned.text})
    except InputError as exc:
        raise InputError(str(sheet), exc.field,
                         f"{exc.message} (in the {planned.file.name} this sheet would give)") from None
    update = CatalogUpdate({"file": planned.file, "kind": planned.kind, "ids": list(planned.ids)},
                           {planned.file: planned.text})
    output.write(update)
    return update


def catalog_import_mgdb(tables: str | Path, screws: str | Path | None = None,
                        folder: str | Path | None = None) -> CatalogUpdate:
    """Brushless motors, their gearheads and ball screws from makers' tables
    into motors-mgdb.toml, gears-mgdb.toml (and screws-sourced.toml), once
    the catalog reads back with them and is physically plausible."""
    from ..io.mgdb import plan_mgdb
    counts, texts, check = plan_mgdb(tables, screws, folder)
    _read_back(texts, check)
    update = CatalogUpdate(counts, texts)
    output.write(update, option="--catalog")
    return update
