"""``sizing catalog validate``: schema, units and duplicate ids (through the
loader), then physical plausibility and staleness of every entry.

Plausibility has two layers:
- ranges: each quantity must lie in a broad physical range for its kind of
  part (``RANGES``). A value outside is almost always a unit slip
  (``"4.33e8 N/mm"``, ``"870 g/m^3"``) and fails with the range in the message;
- consistency: blocked force = stiffness x stroke for a stack, stroke per
  volt = stroke / max voltage, temperature ranges ordered (min < max <
  Curie, flash point above the operating range), viscosity falling with
  temperature, a pressure rating on every seal, continuous ratings below
  peak ratings, a retrieval date that is not in the future.

Every problem is an ``InputError`` naming file, entry and field; the CLI
turns the first into exit 2. Staleness is a warning only.
"""
from __future__ import annotations

import datetime as dt
from dataclasses import dataclass, field
from pathlib import Path

from ..errors import InputError
from .catalog import KINDS, Catalog, Entry, load_catalog

# Blocked force should be close to stiffness x stroke for a stack (datasheets
# give both to few digits and measure them differently; more than this is a unit error).
STACK_CONSISTENCY = 0.5
STROKE_PER_VOLT_TOLERANCE = 0.05
# The Bouc-Wen linear term d33 and the nominal stroke per volt differ (the
# hysteresis term lowers the slope, catalogs/stacks.toml notes) but not by more.
BOUC_WEN_D33_FACTOR = 4.0
DEFAULT_MAX_AGE_DAYS = 730
# a motor's catalog continuous torque and the one its R, R_th and winding
# limit imply differ by datasheet rounding and the housing's mounting (maxon
# rates on a plastic flange): more than this factor is a contradiction
MOTOR_SELF_CONSISTENCY = 1.5
KT_KE_TOLERANCE = 0.15       # k_t (N m/A) against a bus-referred k_e (V s/rad), SI
SIZE_FACTOR = 1.25           # motors of a mass within this factor are of the same size
POPULATION_SLACK = 1.0       # outside the sourced range
WARNING = "warning: "    # prefix of a message that flags, but does not fail

# Broad physical ranges, SI (temperatures in degC): (low, high) inclusive.
# Wide on purpose: they catch unit slips (factors of 1000), not bad parts.
TEMPERATURE_RANGE = (-273.15, 1200.0)
RANGES: dict[str, dict[str, tuple[float, float]]] = {
    "stack": {
        "stiffness": (1e4, 1e11), "stroke_per_volt": (1e-10, 1e-5), "max_voltage": (1.0, 1e4),
        "min_voltage": (-1e4, 1e3), "stroke": (1e-7, 1e-2), "blocked_force": (0.1, 1e6),
        "capacitance": (1e-11, 1e-2), "mass": (1e-5, 100.0), "length": (1e-4, 2.0),
        "diameter": (1e-4, 0.5), "stroke_temperature_coefficient": (-0.05, 0.05), "cost_usd": (0.0, 1e7),
    },
    "fluid": {
        "density": (500.0, 2500.0), "viscosity_40C": (1e-7, 1e-2), "viscosity_100C": (1e-7, 1e-2),
        "bulk_modulus": (1e8, 1e10), "bulk_modulus_temperature_coefficient": (-0.05, 0.0),
        "thermal_expansion": (1e-5, 5e-3), "cost_usd": (0.0, 1e5),
    },
    "seal": {
        "friction_per_length": (0.0, 1e5), "friction_pressure_coefficient": (0.0, 1e-1),
        "breakaway_ratio": (1.0, 20.0), "pressure_rating": (1e5, 2e9), "cost_usd": (0.0, 1e5),
    },
    "amplifier": {
        "max_voltage": (0.0, 1e5), "min_voltage": (-1e5, 1e5), "max_current": (1e-5, 1e4),
        "continuous_current": (1e-6, 1e4), "max_power": (1e-3, 1e7), "slew_rate": (1.0, 1e10),
        "mass": (1e-3, 1000.0), "cost_usd": (0.0, 1e7),
    },
    "material": {
        "youngs_modulus": (1e9, 1e12), "density": (500.0, 25000.0), "thermal_expansion": (1e-8, 1e-4),
        "yield_strength": (1e6, 5e9), "cost_usd": (0.0, 1e5),
    },
    "compensator": {
        "volume_stiffness": (1e6, 1e16), "leak_conductance": (0.0, 1e-6), "capacity": (1e-9, 1e-1),
        "mass": (0.0, 100.0), "cost_usd": (0.0, 1e6),
    },
    "dc_actuator": {
        "max_force": (0.1, 1e7), "continuous_force": (0.01, 1e7), "max_speed": (1e-5, 100.0),
        "stroke": (1e-4, 10.0), "mass": (1e-3, 1000.0), "length": (1e-3, 10.0), "diameter": (1e-3, 2.0),
        "screw_lead": (1e-5, 0.5), "torque_constant": (1e-4, 100.0), "current_limit": (1e-3, 1e4),
        "supply_voltage": (0.1, 1e4), "cost_usd": (0.0, 1e7),
        "back_emf_constant": (1e-4, 100.0), "winding_resistance": (1e-4, 1e3),
    },
    "motor": {
        "torque_constant": (1e-4, 100.0), "back_emf_constant": (1e-4, 100.0), "winding_resistance": (1e-4, 1e3),
        "resistance_temperature_coefficient": (0.0, 0.01), "torque_constant_temperature_coefficient": (-0.01, 0.0),
        "inductance": (1e-7, 1.0), "rotor_inertia": (1e-11, 1.0), "viscous_damping": (0.0, 10.0),
        "continuous_torque": (1e-5, 1e4), "peak_torque": (1e-5, 1e4), "max_speed": (1.0, 1e5),
        "rated_voltage": (1.0, 1e4), "thermal_resistance": (0.01, 1000.0), "thermal_time_constant": (1.0, 1e5),
        "mass": (1e-4, 1000.0), "cost_usd": (0.0, 1e7),
    },
    "screw": {
        "lead": (1e-4, 0.1), "diameter": (1e-3, 0.2), "dynamic_load_rating": (10.0, 1e7),
        "inertia_per_length": (1e-9, 1.0), "mass_per_length": (1e-3, 100.0), "nut_mass": (0.0, 100.0),
        "max_speed": (1.0, 1e4), "elastic_modulus": (1e9, 1e12), "cost_usd": (0.0, 1e7),
    },
    "gear": {
        "ratio": (1.0, 1e5), "inertia": (0.0, 1.0), "mass": (1e-4, 1000.0), "max_input_speed": (1.0, 1e5),
        "max_output_torque": (1e-3, 1e5), "cost_usd": (0.0, 1e7),
    },
    "drive": {
        "bus_voltage": (1.0, 1e4), "continuous_current": (1e-3, 1e4), "peak_current": (1e-3, 1e4),
        "rate": (10.0, 1e6), "mass": (1e-3, 1000.0), "cost_usd": (0.0, 1e7),
    },
}


@dataclass
class ValidationReport:
    folder: Path
    n_entries: int
    warnings: list[str] = field(default_factory=list)
    stale: list[str] = field(default_factory=list)      # ids of stale entries
    n_assumed: int = 0                                    # values with status "assumed: ..."

    @property
    def n_warnings(self) -> int:
        return len(self.warnings)


def _file_of(kind: str) -> str:
    return next(name for name, (array, _) in KINDS.items() if array == kind)


def _problem(catalog: Catalog, kind: str, entry: Entry, field_name: str, message: str) -> InputError:
    file_name = catalog.origin.get(entry.id) or _file_of(kind)
    return InputError(str(catalog.folder / file_name), f"[[{kind}]] {entry.id}: {field_name}", message)


def problems(catalog: Catalog, today: dt.date | None = None, warnings: list[str] | None = None) -> list[InputError]:
    """Every physically implausible value of the catalog, in file order.
    Doubtful but possible values are appended to ``warnings`` instead."""
    today = today or dt.date.today()
    found: list[InputError] = []
    for kind, entry in catalog.entries():
        for field_name, message in _entry_problems(kind, entry, today):
            problem = _problem(catalog, kind, entry, field_name, message.removeprefix(WARNING))
            if message.startswith(WARNING):
                if warnings is not None:
                    warnings.append(str(problem))
            else:
                found.append(problem)
    if warnings is not None:
        warnings.extend(str(w) for w in motor_population_warnings(catalog))
    return found


def plausibility(catalog: Catalog) -> None:
    """Raise InputError on the first physically implausible entry."""
    found = problems(catalog)
    if found:
        first = found[0]
        more = f" (and {len(found) - 1} more problem{'s' * (len(found) > 2)})" if len(found) > 1 else ""
        raise InputError(first.file, first.field, first.message + more)


def _entry_problems(kind: str, entry: Entry, today: dt.date):
    if entry.retrieved > today:
        yield "retrieved", f"expected a date not in the future, got {entry.retrieved.isoformat()}"
    yield from _range_problems(kind, entry)
    low, high = getattr(entry, "min_temperature", None), getattr(entry, "max_temperature", None)
    if low is not None and high is not None and not low < high:
        yield "max_temperature", f"expected above min_temperature ({low:g} degC), got {high:g} degC"
    checks = {"stack": _stack, "fluid": _fluid, "seal": _seal, "amplifier": _amplifier, "dc_actuator": _dc,
              "motor": _motor, "screw": _no_check, "gear": _no_check, "drive": _drive,
              "material": _no_check, "compensator": _no_check, "valve": _no_check, "accumulator": _no_check}
    yield from checks.get(kind, _no_check)(entry)


def _range_problems(kind: str, entry: Entry):
    for name in entry.quantity_fields():
        value = getattr(entry, name, None)
        if not isinstance(value, (int, float)):
            continue
        if "temperature" in name or name == "flash_point":
            low, high = TEMPERATURE_RANGE
            unit = "degC"
        elif name in RANGES.get(kind, {}):
            low, high = RANGES[kind][name]
            unit = _si_unit(entry, name)
        else:
            continue
        if not low <= value <= high:
            yield name, (f"implausible value {value:.4g} {unit}: expected {low:.3g} to {high:.3g} {unit} "
                         f"for a {kind.replace('_', ' ')} (unit error?)")


def _si_unit(entry: Entry, name: str) -> str:
    from .catalog_diff import field_unit
    return field_unit(type(entry), name) or ""


def _stack(s):
    if not s.min_voltage < s.max_voltage:
        yield "max_voltage", f"expected above min_voltage ({s.min_voltage:g} V), got {s.max_voltage:g} V"
    nominal = s.stroke / s.max_voltage
    if abs(s.stroke_per_volt / nominal - 1) > STROKE_PER_VOLT_TOLERANCE:
        yield "stroke_per_volt", (f"expected stroke / max_voltage = {nominal:.3g} m/V within "
                                  f"{STROKE_PER_VOLT_TOLERANCE:.0%}, got {s.stroke_per_volt:.3g} m/V")
    implied = s.stiffness * s.stroke
    if not (1 - STACK_CONSISTENCY) < s.blocked_force / implied < 1 / (1 - STACK_CONSISTENCY):
        yield "blocked_force", (f"expected about stiffness x stroke = {implied:.4g} N, "
                                f"got {s.blocked_force:.4g} N (unit error?)")
    if s.curie_temperature is not None and s.curie_temperature <= s.max_temperature:
        yield "curie_temperature", f"expected above max_temperature ({s.max_temperature:g} degC), got {s.curie_temperature:g} degC"
    if s.bouc_wen is not None:
        ratio = s.bouc_wen.d33 / s.stroke_per_volt
        if not 1 / BOUC_WEN_D33_FACTOR < ratio < BOUC_WEN_D33_FACTOR:
            yield "bouc_wen.d33", (f"expected within a factor {BOUC_WEN_D33_FACTOR:g} of stroke_per_volt "
                                   f"({s.stroke_per_volt:.3g} m/V), got {s.bouc_wen.d33:.3g} m/V")


def _fluid(f):
    if not f.viscosity_100C < f.viscosity_40C:
        yield "viscosity_100C", (f"expected below viscosity_40C ({f.viscosity_40C * 1e6:.3g} mm^2/s; "
                                 f"oils thin as they warm), got {f.viscosity_100C * 1e6:.3g} mm^2/s")
    if not f.flash_point > f.max_temperature:
        yield "flash_point", (WARNING + f"flash point {f.flash_point:g} degC is below max_temperature "
                              f"({f.max_temperature:g} degC): acceptable only in a closed, air-free system")


def _seal(s):
    if getattr(s, "pressure_rating", None) is None:
        yield "pressure_rating", "required for a seal: the pressure it holds (Pa)"
    if s.breakaway_ratio < 1.0:
        yield "breakaway_ratio", f"expected >= 1 (static friction is not below running), got {s.breakaway_ratio:g}"


def _amplifier(a):
    if not a.min_voltage < a.max_voltage:
        yield "max_voltage", f"expected above min_voltage ({a.min_voltage:g} V), got {a.max_voltage:g} V"
    if a.continuous_current > a.max_current * (1 + 1e-9):
        yield "continuous_current", f"expected at most max_current ({a.max_current:g} A), got {a.continuous_current:g} A"


def _dc(a):
    if a.c1 >= 0:
        yield "c1", f"expected a negative rate (-lambda/J, 1/s), got {a.c1:g}"
    if a.c2 <= 0:
        yield "c2", f"expected a positive k_t/J, got {a.c2:g}"
    if a.continuous_force > a.max_force * (1 + 1e-9):
        yield "continuous_force", f"expected at most max_force ({a.max_force:g} N), got {a.continuous_force:g} N"
    if not 0 < a.screw_efficiency <= 1:
        yield "screw_efficiency", f"expected in (0, 1], got {a.screw_efficiency:g}"


def _motor(m):
    if m.continuous_torque > m.peak_torque * (1 + 1e-9):
        yield "continuous_torque", f"expected at most peak_torque ({m.peak_torque:g} N m), got {m.continuous_torque:g} N m"
    implied = implied_continuous_torque(m)
    if not 1 / MOTOR_SELF_CONSISTENCY <= m.continuous_torque / implied <= MOTOR_SELF_CONSISTENCY:
        yield "continuous_torque", (WARNING + f"{m.continuous_torque:.3g} N m contradicts winding_resistance and "
                                    f"thermal_resistance: at the {m.max_winding_temperature:g} degC winding limit "
                                    f"and 25 degC they give {implied:.3g} N m")
    if abs(m.torque_constant / m.back_emf_constant - 1) > KT_KE_TOLERANCE:
        yield "torque_constant", (WARNING + f"{m.torque_constant:.4g} N m/A against back_emf_constant "
                                  f"{m.back_emf_constant:.4g} V s/rad: in SI they agree within "
                                  f"{KT_KE_TOLERANCE:.0%} for a brushless motor with a bus-referred k_e")


def implied_continuous_torque(m) -> float:
    """The continuous torque (N m) at 25 degC ambient that the motor's own
    R, R_th and winding limit give: k_t sqrt((T_max - 25) / (R_th R(T_max)))
    (physics/motor.py: rms_current_allowed)."""
    from ..physics.motor import rms_current_allowed
    i = rms_current_allowed(m.thermal_resistance, m.winding_resistance, m.resistance_temperature_coefficient,
                            25.0, m.max_winding_temperature)
    return float(m.torque_constant * i)


def motor_population_warnings(catalog: Catalog) -> list[InputError]:
    """Motors not from a maker's table whose torque per root watt (k_t /
    sqrt(R)) or continuous torque per kilogram lies outside the range of the
    sourced motors of their size (mass within a factor SIZE_FACTOR), by more
    than the factor POPULATION_SLACK: such a part is likely optimistic."""
    import numpy as np
    motors = list(catalog.motors.values())
    sourced = [m for m in motors if m.status.get("torque_constant", "").startswith("sourced")]
    if len(sourced) < 10:
        return []
    mass = np.array([m.mass for m in sourced])
    km = np.array([m.torque_constant / m.winding_resistance ** 0.5 for m in sourced])
    tpk = np.array([m.continuous_torque / m.mass for m in sourced])
    # a housed motor is compared with housed ones (winding-housing and housing-ambient
    # resistances given), a frameless one with all
    housed = np.array(["Rth1 + Rth2" in m.status.get("thermal_resistance", "") for m in sourced])
    out = []
    for m in motors:
        if m in sourced:
            continue
        kind = np.ones(len(sourced), bool) if "frameless" in (m.id + m.name).lower() else housed
        size = kind & (mass >= m.mass / SIZE_FACTOR) & (mass <= m.mass * SIZE_FACTOR)
        if size.sum() < 3:
            continue
        for name, value, pool, what, unit in (
                ("torque_constant", m.torque_constant / m.winding_resistance ** 0.5, km, "torque per root watt k_t/sqrt(R)", "N m/sqrt(W)"),
                ("continuous_torque", m.continuous_torque / m.mass, tpk, "continuous torque per kg", "N m/kg")):
            lo, hi = pool[size].min(), pool[size].max()
            if not lo / POPULATION_SLACK <= value <= hi * POPULATION_SLACK:
                out.append(_problem(catalog, "motor", m, name,
                                    f"{what} {value:.3g} {unit} is outside the {lo:.3g} to {hi:.3g} of the "
                                    f"{int(size.sum())} sourced {'' if kind is not housed else 'housed '}motors of {m.mass / SIZE_FACTOR:.2g} to "
                                    f"{m.mass * SIZE_FACTOR:.2g} kg"))
    return out


def _drive(d):
    if d.continuous_current > d.peak_current * (1 + 1e-9):
        yield "continuous_current", f"expected at most peak_current ({d.peak_current:g} A), got {d.continuous_current:g} A"


def _no_check(_entry):
    return iter(())


def stale_entries(catalog: Catalog, max_age_days: int, today: dt.date | None = None) -> list[str]:
    """One line per entry retrieved more than ``max_age_days`` ago."""
    today = today or dt.date.today()
    return [f"{_file_of(kind)}: [[{kind}]] {entry.id}: retrieved {entry.retrieved.isoformat()}, "
            f"{(today - entry.retrieved).days} days ago (older than {max_age_days}): re-check the source"
            for kind, entry in catalog.entries() if (today - entry.retrieved).days > max_age_days]


def validate_catalog(folder: str | Path | None = None, max_age_days: int = DEFAULT_MAX_AGE_DAYS,
                     today: dt.date | None = None) -> ValidationReport:
    """Load (schema, units, duplicate ids), check plausibility (InputError
    on the first problem) and list stale entries as warnings."""
    if max_age_days < 0:
        raise InputError(None, "--max-age-days", f"expected a non-negative number of days, got {max_age_days}")
    catalog = load_catalog(folder)
    cautions: list[str] = []
    found = problems(catalog, today, cautions)
    if found:
        first = found[0]
        more = f" (and {len(found) - 1} more problem{'s' * (len(found) > 2)})" if len(found) > 1 else ""
        raise InputError(first.file, first.field, first.message + more)
    report = ValidationReport(folder=catalog.folder, n_entries=len(catalog.entries()))
    stale = stale_entries(catalog, max_age_days, today)
    report.warnings.extend(cautions + stale)
    report.stale = [line.split("] ", 1)[1].split(":", 1)[0] for line in stale]
    report.n_assumed = sum(len(e.assumed()) for _, e in catalog.entries())
    return report
