"""The one pint registry, and conversion of input quantities to SI floats.

Quantities in input files are strings with a unit (``"40 mm"``) or bare
numbers that already are SI (temperatures: bare numbers are degC). pint is
40-250x slower than floats, so values are converted once, when a file is read,
and the models only ever see floats.
"""
from __future__ import annotations

import math
import re

import pint

ureg = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
Q_ = ureg.Quantity

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

_NUMBER_UNIT = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")


class UnitError(ValueError):
    """A value that is not a quantity of the expected kind."""


def parse_quantity(text: str) -> pint.Quantity:
    """Parse ``"1.96e7 N/m"`` or ``"100 degC"``. Offset units (degC) cannot be
    multiplied, so the number and the unit are split before pint sees them."""
    match = _NUMBER_UNIT.match(text)
    if not match:
        raise UnitError(f'expected a number with a unit, got "{text}"')
    number, unit = match.groups()
    try:
        return Q_(float(number), unit or "")
    except (pint.errors.UndefinedUnitError, pint.errors.DefinitionSyntaxError, AttributeError, TypeError, ValueError) as exc:
        raise UnitError(f'unknown unit "{unit}" in "{text}"') from exc


def to_si(value: object, kind: str) -> float:
    """Return ``value`` as a float in the SI unit of ``kind`` (degC for
    temperatures). Raises UnitError with a message meant for the user."""
    unit, word = KINDS[kind]
    if isinstance(value, bool):
        raise UnitError(f"expected {word}, got {value!r}")
    if isinstance(value, (int, float)):
        result = float(value)
    elif isinstance(value, str):
        quantity = parse_quantity(value)
        if kind == "temperature":
            if quantity.dimensionless and quantity.unitless:
                result = float(quantity.magnitude)
            elif quantity.check("[temperature]"):
                result = float(quantity.to("degC").magnitude)
            else:
                raise UnitError(f'expected {word}, got "{value}"')
        else:
            try:
                result = float(quantity.to(unit).magnitude)
            except pint.errors.DimensionalityError as exc:
                raise UnitError(f'expected {word}, got "{value}"') from exc
    else:
        raise UnitError(f"expected {word}, got {value!r}")
    if not math.isfinite(result):
        raise UnitError(f"expected a finite number, got {value!r}")
    return result
