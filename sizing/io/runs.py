"""Measured runs: CSV files of a test campaign (docs/formats.md).

A header line, then one row per sample. Every error names the file, the CSV
line (the header is line 1) and the column.

Dialects people produce are accepted: a UTF-8 byte-order mark (spreadsheet
programs write one), CRLF line ends, quoted numbers (``"0.1"``), blank
lines. A duplicated column name, a line with another separator than the
header's and a value outside the column's plausible range
(``units.PLAUSIBLE``: 1e300 overflowed further in) are rejected with the
line. The number of samples is estimated from the file size before
reading (``limits.check_samples``); files are read with pandas' C reader
(a progress bar on stderr for large ones) and, on any problem, again with
the csv module to name the exact line.
"""
from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..errors import InputError
from ..limits import check_samples
from ..units import UnitError, check_range

PIEZO_COLUMNS = ("time_s", "voltage_V", "position_m")
PIEZO_OPTIONAL = ("load_N",)
DC_COLUMNS = ("time_s", "reference_m", "position_m")
DC_OPTIONAL = ("current_A",)
MIN_SAMPLES = 3
# Kind of quantity of each column, for its plausible range.
COLUMN_KINDS = {"time_s": "time", "voltage_V": "voltage", "position_m": "length", "load_N": "force",
                "reference_m": "length", "current_A": "current"}
HEAD_BYTES = 65536               # read to find the header and estimate the row count
PROGRESS_BYTES = 20_000_000      # show a progress bar above this file size
CHUNK_ROWS = 200_000
OTHER_SEPARATORS = (";", "\t", "|")


@dataclass
class Run:
    """One measured run: name (file stem), time (n,) s, and the columns."""

    name: str
    path: Path
    time: np.ndarray
    columns: dict[str, np.ndarray] = field(default_factory=dict)

    def __getitem__(self, column: str) -> np.ndarray:
        return self.columns[column]

    def __len__(self) -> int:
        return len(self.time)


def _head(path: Path) -> tuple[str, int]:
    """The first HEAD_BYTES of the file as text (BOM removed) and its size."""
    try:
        size = path.stat().st_size
        with path.open("rb") as handle:
            raw = handle.read(HEAD_BYTES)
    except FileNotFoundError:
        raise InputError(str(path), None, "file not found") from None
    except IsADirectoryError:
        raise InputError(str(path), None, "expected a CSV text file, got a folder") from None
    except OSError as exc:   # symlink loop, permission denied
        raise InputError(str(path), None, f"cannot read the CSV file: {exc.strerror or exc}") from None
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        if not (len(raw) == HEAD_BYTES and exc.start >= len(raw) - 3):   # not just a character cut by the read
            raise InputError(str(path), None, "expected a CSV text file (UTF-8)") from None
        text = raw[:exc.start].decode("utf-8")
    if "\x00" in text:
        raise InputError(str(path), None, "expected a CSV text file, got binary data")
    return text.removeprefix("\ufeff"), size


def estimate_samples(path: str | Path) -> int:
    """About how many data rows the file holds (file size / mean line length)."""
    text, size = _head(Path(path))
    lines = text.splitlines()
    if len(lines) <= 1:
        return max(len(lines) - 1, 0)
    mean = len(text.encode("utf-8")) / len(lines)
    return int(size / max(mean, 1.0)) - 1


def _header(path: Path, text: str, required) -> list[str]:
    first = next(csv.reader(io.StringIO(text.splitlines()[0] if text.strip() else "")), [])
    header = [name.strip() for name in first]
    if not header or not any(header):
        raise InputError(str(path), "line 1", f"empty file; expected a header {','.join(required)}")
    for sep in OTHER_SEPARATORS:
        if len(header) == 1 and sep in header[0]:
            raise InputError(str(path), "line 1", f"expected comma-separated columns, got {sep!r} as separator")
    known = set()
    for name in header:
        if name in known and name:
            raise InputError(str(path), "line 1", f"duplicated column {name!r}; each column must appear once")
        known.add(name)
    missing = [name for name in required if name not in header]
    if missing:
        raise InputError(str(path), "line 1", f"missing column {missing[0]!r}; expected {','.join(required)}, "
                                              f"got {','.join(header)}")
    return header


def read_run(path: str | Path, required=PIEZO_COLUMNS, optional=PIEZO_OPTIONAL) -> Run:
    """Read and check one run CSV. Raises InputError naming file, line, column."""
    path = Path(path)
    text, size = _head(path)
    header = _header(path, text, required)
    check_samples(estimate_samples(path), str(path))
    wanted = list(required) + [name for name in optional if name in header]
    data = _fast(path, header, wanted, size)
    if data is None:
        data = _numbers(path, header, wanted)
    if len(data[wanted[0]]) < MIN_SAMPLES:
        raise InputError(str(path), f"line {len(data[wanted[0]]) + 2}, column {wanted[0]}",
                         f"the data end before this line: expected at least {MIN_SAMPLES} samples, "
                         f"got {len(data[wanted[0]])}")
    time = data.pop("time_s")
    steps = np.diff(time)
    if np.any(steps <= 0):
        bad = _line_of_row(path, int(np.argmax(steps <= 0)) + 1)
        raise InputError(str(path), f"line {bad}, column time_s", "expected time to increase strictly from row to row")
    return Run(name=path.stem, path=path, time=time, columns=data)


def _fast(path: Path, header: list[str], wanted: list[str], size: int) -> dict[str, np.ndarray] | None:
    """pandas' C reader; None when anything looks wrong (the slow path then
    names the line)."""
    import pandas as pd

    try:
        # no usecols: with it pandas silently drops the extra fields of a bad line
        reader = pd.read_csv(path, encoding="utf-8-sig", skipinitialspace=True,
                             dtype={name: np.float64 for name in wanted}, skip_blank_lines=True,
                             engine="c", chunksize=CHUNK_ROWS)
        with _progress(path, size) as advance:
            chunks = []
            for chunk in reader:
                chunks.append(chunk[wanted])
                advance(len(chunk))
        frame = pd.concat(chunks) if chunks else None
    except Exception:   # ParserError, ValueError on a bad cell, ...: let the slow path name the line
        return None
    if frame is None or len(frame.columns) != len(wanted):
        return None
    out = {name: frame[name].to_numpy(dtype=float, copy=True) for name in wanted}
    for name, values in out.items():
        low, high = _range(name)
        if not (np.all(np.isfinite(values)) and np.all(values >= low) and np.all(values <= high)):
            return None
    return out


def _range(column: str) -> tuple[float, float]:
    from ..units import DEFAULT_RANGE, PLAUSIBLE
    return PLAUSIBLE.get(COLUMN_KINDS.get(column, ""), DEFAULT_RANGE)


class _progress:
    """A transient rich progress bar on stderr for large files, else nothing."""

    def __init__(self, path: Path, size: int):
        self.path, self.size, self.bar = path, size, None

    def __enter__(self):
        if self.size < PROGRESS_BYTES:
            return lambda rows: None
        from rich.console import Console
        from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn
        self.bar = Progress(TextColumn(f"reading {self.path.name}"), BarColumn(), TextColumn("{task.completed:,} rows"),
                            TimeElapsedColumn(), console=Console(stderr=True), transient=True)
        self.bar.start()
        task = self.bar.add_task("read", total=None)
        return lambda rows: self.bar.advance(task, rows)

    def __exit__(self, *exc):
        if self.bar is not None:
            self.bar.stop()
        return False


def _rows(path: Path):
    """(line number, cells) of every line after the header, BOM removed."""
    try:
        with path.open(newline="", encoding="utf-8-sig") as handle:
            reader = csv.reader(handle, skipinitialspace=True)
            next(reader, None)
            for cells in reader:
                yield reader.line_num, cells
    except UnicodeDecodeError:
        raise InputError(str(path), None, "expected a CSV text file (UTF-8)") from None
    except csv.Error as exc:
        raise InputError(str(path), None, f"malformed CSV: {exc}") from None


def _line_of_row(path: Path, row: int) -> int:
    """The line number of data row ``row`` (0-based, blank lines skipped)."""
    kept = -1
    for line_no, cells in _rows(path):
        if cells and any(cell.strip() for cell in cells):
            kept += 1
            if kept == row:
                return line_no
    return row + 2


def _numbers(path: Path, header: list[str], wanted: list[str]) -> dict[str, np.ndarray]:
    index = {name: header.index(name) for name in wanted}
    out: dict[str, list[float]] = {name: [] for name in wanted}
    for line_no, row in _rows(path):
        if not row or all(not cell.strip() for cell in row):
            continue
        _separators(path, line_no, row, header)
        for name, col in index.items():
            text = row[col].strip() if col < len(row) else ""
            where = f"line {line_no}, column {name}"
            try:
                value = float(text)
            except ValueError:
                raise InputError(str(path), where, f"expected a number, got {text[:40]!r}") from None
            if not math.isfinite(value):
                raise InputError(str(path), where, f"expected a finite number, got {text[:40]!r}")
            try:
                check_range(value, COLUMN_KINDS.get(name, ""), text)
            except UnitError as exc:
                raise InputError(str(path), where, str(exc)) from None
            out[name].append(value)
    return {name: np.array(values, dtype=float) for name, values in out.items()}


def _separators(path: Path, line_no: int, row: list[str], header: list[str]) -> None:
    """A data line must have the header's fields, separated by commas."""
    for sep in OTHER_SEPARATORS:
        if any(sep in cell for cell in row):
            raise InputError(str(path), f"line {line_no}", f"mixed separators: {sep!r} in a comma-separated file")
    extra = [cell for cell in row[len(header):] if cell.strip()]
    if extra:
        raise InputError(str(path), f"line {line_no}", f"expected {len(header)} fields as in the header, got {len(row)}")


def read_runs(paths, kind: str = "piezohydraulic") -> list[Run]:
    required, optional = (PIEZO_COLUMNS, PIEZO_OPTIONAL) if kind == "piezohydraulic" else (DC_COLUMNS, DC_OPTIONAL)
    paths = list(paths)
    if len(paths) > 1:   # all runs together, before reading any (each is also checked alone)
        check_samples(sum(estimate_samples(p) for p in paths), str(paths[0]), "all runs")
    runs = [read_run(p, required, optional) for p in paths]
    names = [r.name for r in runs]
    duplicate = next((n for n in names if names.count(n) > 1), None)
    if duplicate:
        raise InputError(duplicate + ".csv", None, "two runs share this name; run names must be unique")
    return runs


def split_holdout(runs: list[Run], holdout: list[str] | None, source: str) -> tuple[list[Run], list[Run]]:
    """(training, holdout) runs. Every holdout name must name a run, and at
    least one run must remain for fitting."""
    holdout = list(holdout or [])
    names = {r.name for r in runs}
    for name in holdout:
        if name not in names:
            raise InputError(source, "--holdout", f"no run named {name!r} (runs: {', '.join(sorted(names))})")
    train = [r for r in runs if r.name not in holdout]
    if not train:
        raise InputError(source, "--holdout", "every run is held out; keep at least one run for fitting")
    return train, [r for r in runs if r.name in holdout]
