"""Measured runs: CSV files of a test campaign (CONTRACTS.md).

A header line, then one row per sample. Every error names the file, the CSV
line (the header is line 1) and the column.
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..errors import InputError

PIEZO_COLUMNS = ("time_s", "voltage_V", "position_m")
PIEZO_OPTIONAL = ("load_N",)
DC_COLUMNS = ("time_s", "reference_m", "position_m")
DC_OPTIONAL = ("current_A",)
MIN_SAMPLES = 3


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


def read_run(path: str | Path, required=PIEZO_COLUMNS, optional=PIEZO_OPTIONAL) -> Run:
    """Read and check one run CSV. Raises InputError naming file, line, column."""
    path = Path(path)
    try:
        with path.open(newline="", encoding="utf-8") as handle:
            rows = list(csv.reader(handle))
    except FileNotFoundError:
        raise InputError(str(path), None, "file not found") from None
    except (UnicodeDecodeError, IsADirectoryError):
        raise InputError(str(path), None, "expected a CSV text file") from None
    if not rows:
        raise InputError(str(path), "line 1", f"empty file; expected a header {','.join(required)}")
    header = [name.strip() for name in rows[0]]
    missing = [name for name in required if name not in header]
    if missing:
        raise InputError(str(path), "line 1", f"missing column {missing[0]!r}; expected {','.join(required)}, got {','.join(header)}")
    wanted = list(required) + [name for name in optional if name in header]
    data = _numbers(path, rows[1:], header, wanted)
    if len(data[wanted[0]]) < MIN_SAMPLES:
        raise InputError(str(path), f"line {len(data[wanted[0]]) + 2}, column {wanted[0]}",
                         f"the data end before this line: expected at least {MIN_SAMPLES} samples, "
                         f"got {len(data[wanted[0]])}")
    time = data.pop("time_s")
    steps = np.diff(time)
    if np.any(steps <= 0):
        bad = int(np.argmax(steps <= 0)) + 3
        raise InputError(str(path), f"line {bad}, column time_s", "expected time to increase strictly from row to row")
    return Run(name=path.stem, path=path, time=time, columns=data)


def _numbers(path: Path, rows: list[list[str]], header: list[str], wanted: list[str]) -> dict[str, np.ndarray]:
    index = {name: header.index(name) for name in wanted}
    out = {name: np.empty(len(rows)) for name in wanted}
    kept = 0
    for line_no, row in enumerate(rows, start=2):
        if not row or all(not cell.strip() for cell in row):
            continue
        for name, col in index.items():
            text = row[col].strip() if col < len(row) else ""
            try:
                value = float(text)
            except ValueError:
                raise InputError(str(path), f"line {line_no}, column {name}", f"expected a number, got {text!r}") from None
            if not math.isfinite(value):
                raise InputError(str(path), f"line {line_no}, column {name}", f"expected a finite number, got {text!r}")
            out[name][kept] = value
        kept += 1
    return {name: values[:kept] for name, values in out.items()}


def read_runs(paths, kind: str = "piezohydraulic") -> list[Run]:
    required, optional = (PIEZO_COLUMNS, PIEZO_OPTIONAL) if kind == "piezohydraulic" else (DC_COLUMNS, DC_OPTIONAL)
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
