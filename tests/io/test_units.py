import math

import pytest
from hypothesis import given, strategies as st

from sizing.units import UnitError, to_si


@pytest.mark.parametrize("text, kind, expected", [
    ("40 mm", "length", 0.04),
    ("2.5 kN", "force", 2500.0),
    ("100 mm/s", "speed", 0.1),
    ("1.96e7 N/m", "stiffness", 1.96e7),
    ("3.75 in", "length", 0.09525),          # 3.75 x 25.4 mm
    ("15 mm^2/s", "kinematic_viscosity", 15e-6),
    ("100 degC", "temperature", 100.0),
    ("373.15 K", "temperature", 100.0),
    ("212 degF", "temperature", 100.0),
    (25, "temperature", 25.0),                # bare temperatures are degC
    (0.04, "length", 0.04),                   # bare numbers are SI
])
def test_to_si(text, kind, expected):
    assert to_si(text, kind) == pytest.approx(expected, rel=1e-9)


@pytest.mark.parametrize("text, kind, match", [
    ("40 kg", "length", "expected a length"),
    ("nan", "length", "number with a unit"),
    (float("nan"), "force", "finite"),
    ("40 furlongz", "length", "unknown unit"),
    (True, "length", "expected a length"),
    ("30 kPa", "temperature", "expected a temperature"),
])
def test_to_si_rejects(text, kind, match):
    with pytest.raises(UnitError, match=match):
        to_si(text, kind)


@given(st.floats(min_value=1e-9, max_value=1e9, allow_nan=False))
def test_unit_round_trip(value):
    assert to_si(f"{value!r} mm", "length") == pytest.approx(value / 1000, rel=1e-12)
    assert math.isclose(to_si(f"{value!r} kN", "force"), value * 1000, rel_tol=1e-12)
