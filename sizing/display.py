"""How a value reads to people: a number with its unit, at most four
significant digits (no float noise such as 0.00017999999999999998), in the
unit an engineer would write (mm, not 0.04 m).

Three ways in, by what the caller knows of the value:

- ``quantity(key, value)``: a results.json key whose suffix names the SI unit
  (``stroke_m``, ``blocked_force_N``, ``speed_m_s``);
- ``requirement(field, value)``: a field of requirements.toml by the name
  the user wrote (``stroke``, ``max_temperature``, ``options.wide_gap``);
- ``of_kind(value, kind)``: a quantity of a ``units.KINDS`` kind (catalog
  fields).

Pure Python, no unit library: the conversions are fixed factors.
"""
from __future__ import annotations

import math

# key suffix -> (factor from SI, unit shown); the longest suffix that matches wins
SUFFIXES = {"_m": (1e3, "mm"), "_N": (1.0, "N"), "_Pa": (1e-6, "MPa"), "_Hz": (1.0, "Hz"),
            "_A": (1.0, "A"), "_s": (1.0, "s"), "_m_s": (1e3, "mm/s"), "_J": (1.0, "J"),
            "_kg": (1.0, "kg"), "_usd": (1.0, "USD"), "_m3": (1e6, "cm^3"), "_W": (1.0, "W"),
            "_N_m": (1.0, "N/m"), "_V": (1.0, "V"), "_VA": (1.0, "VA"), "_degC": (1.0, "degC"),
            "_K": (1.0, "K"), "_V_s": (1.0, "V/s"), "_rad_s": (1.0, "rad/s"), "_m2": (1e6, "mm^2"),
            "_m3_s_Pa": (1.0, "m^3/(s Pa)"), "_m_V": (1e9, "nm/V"), "_m2_s": (1e6, "mm^2/s")}

# kind (units.KINDS) -> (factor from SI, unit shown)
KIND_UNITS = {"length": (1e3, "mm"), "area": (1e6, "mm^2"), "volume": (1e6, "cm^3"), "force": (1.0, "N"),
              "stiffness": (1e-6, "N/um"), "pressure": (1e-6, "MPa"), "voltage": (1.0, "V"),
              "current": (1.0, "A"), "capacitance": (1e6, "uF"), "mass": (1.0, "kg"), "time": (1.0, "s"),
              "frequency": (1.0, "Hz"), "speed": (1e3, "mm/s"), "slew": (1.0, "V/s"),
              "density": (1.0, "kg/m^3"), "kinematic_viscosity": (1e6, "mm^2/s"), "per_kelvin": (1.0, "1/K"),
              "strain_per_volt": (1e9, "nm/V"), "torque_constant": (1.0, "N m/A"),
              "friction_per_length": (1.0, "N/m"), "friction_per_length_pressure": (1.0, "N/(m Pa)"),
              "power": (1.0, "W"), "damping": (1.0, "N s/m"), "conductance": (1.0, "m^3/(s Pa)"),
              "volume_stiffness": (1.0, "Pa/m^3"), "torque": (1.0, "N m"), "angular_speed": (1.0, "rad/s"),
              "back_emf_constant": (1.0, "V s/rad"), "rotational_damping": (1.0, "N m s/rad"),
              "inertia": (1.0, "kg m^2"), "inertia_per_length": (1.0, "kg m"), "mass_per_length": (1.0, "kg/m"),
              "resistance": (1.0, "ohm"), "inductance": (1e3, "mH"), "thermal_resistance": (1.0, "K/W"),
              "temperature": (1.0, "degC"), "dimensionless": (1.0, "")}

# requirements.toml fields (docs/formats.md) -> kind; a fraction reads as a percentage
REQUIREMENT_KINDS = {"stroke": "length", "blocked_force": "force", "speed": "speed", "max_temperature": "temperature",
                     "span": "length", "chord": "length", "thickness": "length", "density": "density",
                     "dynamic_pressure": "pressure", "force": "force", "stiffness": "stiffness",
                     "min_stiffness": "stiffness", "hold_time": "time", "max_length": "length",
                     "max_diameter": "length", "max_width": "length", "max_mass": "mass", "wide_gap": "length",
                     "min_natural_frequency": "frequency", "compensator_mass": "mass", "supply_voltage": "voltage",
                     "electronics_bay_temperature": "temperature", "drift_reference_temperature": "temperature"}
SHARES = {"overshoot", "compliance_force_fraction", "efficiency"}     # results keys that are fractions: read in %
FRACTIONS = {"design_margin", "max_overshoot", "max_drift_fraction", "min_compliance"}
REQUIREMENT_UNITS = {"dynamic_pressure": (1e-3, "kPa"), "stiffness": (1e-6, "MN/m"), "min_stiffness": (1e-6, "MN/m")}


def number(value, digits: int = 4) -> str:
    """``value`` to ``digits`` significant digits, without an exponent for
    everyday magnitudes (0.001 to 1e6)."""
    if value is None:
        return "n/a"
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return str(value)
    if isinstance(value, int):
        return str(value)
    if not math.isfinite(value):
        return "unbounded" if value > 0 else "-unbounded" if value < 0 else "n/a"
    if value != 0 and not 1e-3 <= abs(value) < 1e6:
        mantissa, _, exponent = f"{value:.{digits}e}".partition("e")
        mantissa = f"{float(mantissa):.{digits}g}"
        return f"{mantissa}e{int(exponent)}"
    text = f"{value:.{digits}g}"
    return text if "e" not in text else f"{value:.0f}"


def interval(lo, hi, show=None) -> str:
    """A 95 % interval as people read it: "0.861 to 0.987" (no bracketed
    pair that reads like a Python list)."""
    show = show or number
    return f"{show(lo)} to {show(hi)}"


def _with(value, factor: float, unit: str) -> str:
    if not isinstance(value, (int, float)) or isinstance(value, bool):
        return "n/a" if value is None else str(value)
    return f"{number(value * factor)} {unit}".strip()


def _suffix(key: str):
    for suffix in sorted(SUFFIXES, key=len, reverse=True):
        if key.endswith(suffix):
            return suffix
    return None


def quantity(key: str, value) -> str:
    """A value under a results.json key with a unit suffix ("stroke_m", 0.04 -> "40 mm")."""
    suffix = _suffix(key)
    if suffix is None:
        return f"{number(100 * value)} %" if key in SHARES and isinstance(value, (int, float)) else number(value)
    return _with(value, *SUFFIXES[suffix])


def label(key: str) -> str:
    """The key without its unit suffix, in words ("free_stroke_m" -> "free stroke")."""
    suffix = _suffix(key)
    return (key[: -len(suffix)] if suffix else key).replace("_", " ")


def field_name(key: str) -> str:
    """The key as the user names the field: without its unit suffix
    ("stroke_m" -> "stroke", "duty.strokes_per_second" unchanged)."""
    suffix = _suffix(key)
    return key[: -len(suffix)] if suffix else key


def requirement(field: str, value) -> str:
    """A requirements.toml field's SI value as the user would write it
    ("stroke", 0.04 -> "40 mm"; "options.design_margin", 0.05 -> "5 %")."""
    key = field.rpartition(".")[2]
    if key in FRACTIONS and isinstance(value, (int, float)):
        return f"{number(100 * value)} %"
    if key in REQUIREMENT_UNITS:
        return _with(value, *REQUIREMENT_UNITS[key])
    kind = REQUIREMENT_KINDS.get(key) or ("temperature" if key.endswith("temperature") else None)
    return of_kind(value, kind)


def of_kind(value, kind: str | None, field: str = "") -> str:
    """A quantity of ``kind`` (``units.KINDS``), SI in; a dimensionless
    ``*_usd`` field reads in USD. Lengths under a millimetre read in um."""
    if kind is None:
        return f"{number(value)} USD" if field.endswith("_usd") else number(value)
    factor, unit = KIND_UNITS.get(kind, (1.0, ""))
    if kind == "length" and isinstance(value, (int, float)) and 0 < abs(value) < 1e-3:
        factor, unit = 1e6, "um"
    if kind == "dimensionless" and field.endswith("_usd"):
        unit = "USD"
    return _with(value, factor, unit)
