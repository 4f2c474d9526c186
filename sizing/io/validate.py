"""``sizing catalog validate``: schema and units (through the loader), then
physical plausibility and staleness of every entry."""
from __future__ import annotations

import datetime as dt
from dataclasses import dataclass, field
from pathlib import Path

from ..errors import InputError
from .catalog import KINDS, Catalog, Entry, load_catalog

# Blocked force should be close to stiffness x stroke for a stack (datasheets
# round both and measure them differently; more than this is a unit error).
STACK_CONSISTENCY = 0.5
STROKE_PER_VOLT_TOLERANCE = 0.05


@dataclass
class ValidationReport:
    folder: Path
    n_entries: int
    warnings: list[str] = field(default_factory=list)

    @property
    def n_warnings(self) -> int:
        return len(self.warnings)


def _file_of(kind: str) -> str:
    return next(name for name, (array, _) in KINDS.items() if array == kind)


def _fail(catalog: Catalog, kind: str, entry: Entry, field_name: str, message: str):
    raise InputError(str(catalog.folder / _file_of(kind)), f"[[{kind}]] {entry.id}: {field_name}", message)


def plausibility(catalog: Catalog) -> None:
    """Raise InputError on the first physically implausible entry."""
    for kind, entry in catalog.entries():
        low, high = getattr(entry, "min_temperature", None), getattr(entry, "max_temperature", None)
        if low is not None and high is not None and not low < high:
            _fail(catalog, kind, entry, "max_temperature", f"expected above min_temperature ({low:g} degC), got {high:g} degC")
        if kind == "stack":
            _check_stack(catalog, entry)
        if kind == "amplifier" and not entry.min_voltage < entry.max_voltage:
            _fail(catalog, kind, entry, "max_voltage", "expected above min_voltage")
        if kind == "amplifier" and entry.continuous_current > entry.max_current * (1 + 1e-9):
            _fail(catalog, kind, entry, "continuous_current", "expected at most max_current")
        if kind == "dc_actuator":
            _check_dc(catalog, entry)
        if kind == "seal" and entry.breakaway_ratio < 1.0:
            _fail(catalog, kind, entry, "breakaway_ratio", f"expected >= 1 (static friction is not below running), got {entry.breakaway_ratio:g}")


def _check_stack(catalog: Catalog, s) -> None:
    nominal = s.stroke / s.max_voltage
    if abs(s.stroke_per_volt / nominal - 1) > STROKE_PER_VOLT_TOLERANCE:
        _fail(catalog, "stack", s, "stroke_per_volt",
              f"expected stroke / max_voltage = {nominal:.3g} m/V within {STROKE_PER_VOLT_TOLERANCE:.0%}, got {s.stroke_per_volt:.3g} m/V")
    implied = s.stiffness * s.stroke
    if not (1 - STACK_CONSISTENCY) < s.blocked_force / implied < 1 / (1 - STACK_CONSISTENCY):
        _fail(catalog, "stack", s, "blocked_force",
              f"expected about stiffness x stroke = {implied:.4g} N, got {s.blocked_force:.4g} N (unit error?)")
    if s.curie_temperature is not None and s.curie_temperature <= s.max_temperature:
        _fail(catalog, "stack", s, "curie_temperature", "expected above max_temperature")


def _check_dc(catalog: Catalog, a) -> None:
    if a.c1 >= 0:
        _fail(catalog, "dc_actuator", a, "c1", f"expected a negative rate (-lambda/J, 1/s), got {a.c1:g}")
    if a.c2 <= 0:
        _fail(catalog, "dc_actuator", a, "c2", f"expected a positive k_t/J, got {a.c2:g}")
    if a.continuous_force > a.max_force * (1 + 1e-9):
        _fail(catalog, "dc_actuator", a, "continuous_force", "expected at most max_force")
    if not 0 < a.screw_efficiency <= 1:
        _fail(catalog, "dc_actuator", a, "screw_efficiency", f"expected in (0, 1], got {a.screw_efficiency:g}")


def stale_entries(catalog: Catalog, max_age_days: int, today: dt.date | None = None) -> list[str]:
    today = today or dt.date.today()
    return [f"{kind} {entry.id}: retrieved {entry.retrieved.isoformat()}, older than {max_age_days} days"
            for kind, entry in catalog.entries() if (today - entry.retrieved).days > max_age_days]


def validate_catalog(folder: str | Path | None = None, max_age_days: int = 730) -> ValidationReport:
    catalog = load_catalog(folder)
    plausibility(catalog)
    report = ValidationReport(folder=catalog.folder, n_entries=len(catalog.entries()))
    report.warnings.extend(stale_entries(catalog, max_age_days))
    return report
