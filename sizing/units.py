"""The one pint registry, and conversion of input quantities to SI floats.

Quantities in input files are strings with a unit (``"40 mm"``) or bare
numbers that already are SI (temperatures: bare numbers are degC). pint is
40-250x slower than floats, so values are converted once, when a file is read,
and the models only ever see floats. Loading pint and building its registry
takes most of a second, so the registry is built on the first conversion, and
each text's SI value is kept on disk (``disk_cache``): a run that reads the
same files again converts nothing and never loads pint.
"""
from __future__ import annotations

import math
import re
from functools import lru_cache

from . import disk_cache


@lru_cache(maxsize=1)
def registry():
    """The one pint registry (offset units such as degC convert to kelvin)."""
    import pint
    return pint.UnitRegistry(autoconvert_offset_to_baseunit=True)


def __getattr__(name: str):
    if name == "ureg":
        return registry()
    if name == "Q_":
        return registry().Quantity
    raise AttributeError(name)

# SI unit of each kind of quantity, with the word used in error messages.
KINDS: dict[str, tuple[str, str]] = {
    "length": ("m", "a length"),
    "area": ("m**2", "an area"),
    "volume": ("m**3", "a volume"),
    "force": ("N", "a force"),
    "stiffness": ("N/m", "a stiffness"),
    "pressure": ("Pa", "a pressure"),
    "voltage": ("V", "a voltage"),
    "current": ("A", "a current"),
    "capacitance": ("F", "a capacitance"),
    "mass": ("kg", "a mass"),
    "time": ("s", "a time"),
    "frequency": ("Hz", "a frequency"),
    "speed": ("m/s", "a speed"),
    "slew": ("V/s", "a voltage rate"),
    "density": ("kg/m**3", "a density"),
    "kinematic_viscosity": ("m**2/s", "a kinematic viscosity"),
    "per_kelvin": ("1/K", "a coefficient per kelvin"),
    "strain_per_volt": ("m/V", "a length per volt"),
    "torque_constant": ("N*m/A", "a torque constant"),
    "friction_per_length": ("N/m", "a force per length"),
    "friction_per_length_pressure": ("N/m/Pa", "a force per length per pascal"),
    "power": ("W", "a power"),
    "damping": ("N*s/m", "a damping coefficient"),
    "conductance": ("m**3/s/Pa", "a flow conductance"),
    "volume_stiffness": ("Pa/m**3", "a pressure per volume"),
    "torque": ("N*m", "a torque"),
    "angular_speed": ("rad/s", "an angular speed"),
    "back_emf_constant": ("V*s/rad", "a back-EMF constant"),
    "rotational_damping": ("N*m*s/rad", "a rotational damping coefficient"),
    "inertia": ("kg*m**2", "a moment of inertia"),
    "inertia_per_length": ("kg*m", "a moment of inertia per length"),
    "mass_per_length": ("kg/m", "a mass per length"),
    "resistance": ("ohm", "a resistance"),
    "inductance": ("H", "an inductance"),
    "thermal_resistance": ("K/W", "a thermal resistance"),
    "dimensionless": ("", "a plain number"),
    "temperature": ("degC", "a temperature"),
}

# Broad plausibility range of each kind, SI (temperatures in degC):
# (low, high) inclusive, on the value itself. Far wider than any real part
# (catalog validate's per-field RANGES lie inside them, tests/cli/test_bad_input.py
# checks it); they stop "1e30 mm" or 1e300 before a model allocates or
# overflows on it. A kind missing here gets DEFAULT_RANGE.
DEFAULT_RANGE = (-1e15, 1e15)
PLAUSIBLE: dict[str, tuple[float, float]] = {
    "length": (-1e6, 1e6), "area": (-1e6, 1e6), "volume": (-1e6, 1e6),
    "force": (-1e12, 1e12), "stiffness": (-1e15, 1e15), "pressure": (-1e12, 1e12),
    "voltage": (-1e7, 1e7), "current": (-1e6, 1e6), "capacitance": (-1e3, 1e3),
    "mass": (-1e9, 1e9), "time": (-1e9, 1e9), "frequency": (-1e12, 1e12), "speed": (-1e5, 1e5),
    "slew": (-1e15, 1e15), "density": (-1e6, 1e6), "kinematic_viscosity": (-1e3, 1e3),
    "per_kelvin": (-1e3, 1e3), "strain_per_volt": (-0.1, 0.1), "torque_constant": (-1e4, 1e4),
    "friction_per_length": (-1e12, 1e12), "friction_per_length_pressure": (-1e3, 1e3),
    "power": (-1e12, 1e12), "damping": (-1e15, 1e15), "conductance": (-1e3, 1e3),
    "dimensionless": (-1e12, 1e12), "temperature": (-273.15, 1e5),
    # force path and compensators, motors, screws, gears
    "volume_stiffness": (-1e25, 1e25), "torque": (-1e7, 1e7), "angular_speed": (-1e7, 1e7),
    "back_emf_constant": (-1e4, 1e4), "rotational_damping": (-1e6, 1e6), "inertia": (-1e6, 1e6),
    "inertia_per_length": (-1e6, 1e6), "mass_per_length": (-1e6, 1e6), "resistance": (-1e9, 1e9),
    "inductance": (-1e3, 1e3), "thermal_resistance": (-1e6, 1e6),
}

# Smallest non-zero magnitude accepted, SI: "1e-300" as a stroke overflowed
# the convex sizing (found by the fuzz test); 1e-24 m still solves.
TINY = 1e-24

# Input limits checked before pint sees a string: pint's parser is
# quadratic in the length (100,000 characters took 99 s), recursive in the
# nesting (RecursionError thousands deep) and evaluates exponent towers
# (m**2**2**2**2**2**2 never returns).
MAX_QUANTITY_CHARS = 100
MAX_NESTING = 4
MAX_EXPONENT = 12
_UNIT_CHARS = re.compile(r"^[A-Za-z_%\u00b0\u00b2\u00b3\u00b5\u03bc\u2126\u03a90-9.*/^()\s-]*$")
_EXPONENT = re.compile(r"(\*\*|\^)\s*")
# Units that measure a difference or a fraction, never an absolute
# temperature (pint gives "delta_degC" the dimension [temperature]).
_RELATIVE_TEMPERATURE = re.compile(r"delta|%|percent|ppm|permille", re.IGNORECASE)

_NUMBER_UNIT = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")


class UnitError(ValueError):
    """A value that is not a quantity of the expected kind."""


def _shown(text: str) -> str:
    """``text`` for a one-line message: at most 40 characters, no newline."""
    one_line = " ".join(text.split())
    return one_line if len(one_line) <= 40 else one_line[:37] + "..."


def _check_unit_syntax(unit: str, text: str) -> None:
    """Reject unit expressions pint would choke on, before it sees them."""
    if not _UNIT_CHARS.match(unit):
        raise UnitError(f'unknown unit "{_shown(unit)}" in "{_shown(text)}"')
    depth = 0
    for char in unit:
        depth += char == "("
        depth -= char == ")"
        if depth < 0 or depth > MAX_NESTING:
            break
    if depth != 0:
        why = "unbalanced parentheses" if depth <= MAX_NESTING else f"nested deeper than {MAX_NESTING}"
        raise UnitError(f'bad unit "{_shown(unit)}" in "{_shown(text)}": {why}')
    for match in _EXPONENT.finditer(unit):
        tail = unit[match.end():]
        exponent = re.match(r"-?\d+(?:\.\d+)?", tail)
        rest = tail[exponent.end():].lstrip() if exponent else ""
        if not exponent or abs(float(exponent.group())) > MAX_EXPONENT or rest.startswith(("**", "^")):
            raise UnitError(f'bad unit "{_shown(unit)}" in "{_shown(text)}": '
                            f"an exponent must be one number of at most {MAX_EXPONENT}")


def parse_quantity(text: str):
    """Parse ``"1.96e7 N/m"`` or ``"100 degC"``. Offset units (degC) cannot be
    multiplied, so the number and the unit are split before pint sees them.
    Every failure (too long, bad syntax, unknown unit, division by zero, a
    non-finite number) is a UnitError with a one-line message."""
    if len(text) > MAX_QUANTITY_CHARS:
        raise UnitError(f"expected a number with a unit of at most {MAX_QUANTITY_CHARS} characters, "
                        f"got {len(text)} characters")
    match = _NUMBER_UNIT.match(text)
    if not match:
        raise UnitError(f'expected a number with a unit, got "{_shown(text)}"')
    number, unit = match.groups()
    magnitude = float(number)
    if not math.isfinite(magnitude):
        raise UnitError(f'expected a finite number, got "{_shown(text)}"')
    _check_unit_syntax(unit, text)
    try:
        quantity = registry().Quantity(magnitude, unit or "")
    except Exception as exc:   # pint raises many types (ZeroDivisionError, TokenError, ...)
        raise UnitError(f'unknown unit "{_shown(unit)}" in "{_shown(text)}"') from exc
    if not all(math.isfinite(float(p)) for p in quantity.dimensionality.values()):
        raise UnitError(f'bad unit "{_shown(unit)}" in "{_shown(text)}"')
    return quantity


def _temperature(quantity, value: str, word: str) -> float:
    """An absolute temperature in degC; a difference or a fraction is refused."""
    if _RELATIVE_TEMPERATURE.search(_NUMBER_UNIT.match(value).group(2)):
        raise UnitError(f'expected {word} (an absolute one, e.g. "100 degC"), got the relative "{_shown(value)}"')
    if quantity.unitless:
        return float(quantity.magnitude)
    if not quantity.check("[temperature]"):
        hint = ' (write degC or degF: "C" is the coulomb)' if re.search(r"\d\s*[CF]\s*$", value) else ""
        raise UnitError(f'expected {word}, got "{_shown(value)}"{hint}')
    return float(quantity.to("degC").magnitude)


def to_si(value: object, kind: str) -> float:
    """Return ``value`` as a float in the SI unit of ``kind`` (degC for
    temperatures), inside the kind's plausible range (``PLAUSIBLE``).
    Raises UnitError with a one-line message meant for the user."""
    unit, word = KINDS[kind]
    if isinstance(value, bool):
        raise UnitError(f"expected {word}, got {value!r}")
    if isinstance(value, (int, float)):
        try:
            result = float(value)
        except OverflowError:
            raise UnitError(f"expected {word}, got a number too large") from None
    elif isinstance(value, str):
        result = _text_to_si(value, kind)
    else:
        raise UnitError(f"expected {word}, got {_shown(repr(value))}")
    return check_range(result, kind, value)


@disk_cache.memo("pint")
def _text_to_si(value: str, kind: str) -> float:
    """A quantity's text in the SI unit of ``kind`` (degC for temperatures)."""
    unit, word = KINDS[kind]
    quantity = parse_quantity(value)
    try:
        if kind == "temperature":
            return _temperature(quantity, value, word)
        return float(quantity.to(unit).magnitude)
    except UnitError:
        raise
    except Exception as exc:   # DimensionalityError, OverflowError, ...
        raise UnitError(f'expected {word}, got "{_shown(value)}"') from exc


def check_range(number: float, kind: str, given: object = None) -> float:
    """``number`` (SI) if finite and inside the kind's plausible range, else
    UnitError naming the range. ``given``: what the user wrote, for the message."""
    shown = _shown(repr(given if given is not None else number))
    if not math.isfinite(number):
        raise UnitError(f"expected a finite number, got {shown}")
    low, high = PLAUSIBLE.get(kind, DEFAULT_RANGE)
    if number != 0.0 and abs(number) < TINY:
        raise UnitError(f"expected 0 or a magnitude of at least {TINY:g} (SI), got {shown}")
    if kind == "temperature" and number < low:
        raise UnitError(f"expected a temperature above absolute zero ({low:g} degC), got {shown}")
    if not low <= number <= high:
        unit = "degC" if kind == "temperature" else KINDS.get(kind, ("",))[0]
        raise UnitError(f"expected {KINDS.get(kind, (None, 'a value'))[1]} between {low:g} and {high:g}"
                        f"{' ' + unit if unit else ''}, got {shown}")
    return number
