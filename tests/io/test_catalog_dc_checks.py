"""``sizing catalog validate`` warns where a motor contradicts itself or the
sourced motors of its size, and still passes the shipped catalog."""
from __future__ import annotations

import math
from dataclasses import replace

import pytest

from sizing.io import validate
from sizing.io.catalog import load_catalog

from ..conftest import run_cli


@pytest.fixture(scope="module")
def shipped():
    return load_catalog()


def test_implied_continuous_torque_of_the_generic_42mm_motor(shipped):
    """gen-bldc42-28v-h: k_t 0.05 N m/A, R 0.15 ohm at 25 degC, R_th 4 K/W,
    180 degC winding: i = sqrt(155 / (4 x 0.15 (1 + 0.00393 x 155))) = 12.68 A,
    0.634 N m (PHYSICS-NOTES: 'R and R_th imply 0.63 N m ... against its catalog 0.30')."""
    m = shipped.motors["gen-bldc42-28v-h"]
    hand = 0.05 * math.sqrt(155 / (4.0 * 0.15 * (1 + 0.00393 * 155)))
    assert validate.implied_continuous_torque(m) == pytest.approx(hand)
    assert hand == pytest.approx(0.634, abs=1e-3)
    problems = dict(validate._motor(m))
    assert "0.634 N m" in problems["continuous_torque"]


def test_kt_against_ke(shipped):
    m = shipped.motors["gen-bldc42-28v-h"]
    assert "torque_constant" not in dict(validate._motor(m))
    bad = m.model_copy(update={"back_emf_constant": 0.07})
    assert "torque_constant" in dict(validate._motor(bad))


def test_population_flags_the_optimistic_generic_motors(shipped):
    """No housed sourced motor of 0.36-0.56 kg reaches the 42 mm and 40 mm
    generics' torque per root watt (0.129 and 0.101 N m/sqrt(W))."""
    lines = [str(w) for w in validate.motor_population_warnings(shipped)]
    for ident in ("gen-bldc42-28v-h", "gen-bldc40-48v-h"):
        assert any(ident in line and "torque per root watt" in line for line in lines), ident
    assert not any("motors-mgdb.toml" in line for line in lines)      # sourced motors are the yardstick
    # without sourced motors there is no yardstick, and no warning
    own = replace(shipped, motors={k: v for k, v in shipped.motors.items() if "mgdb" not in shipped.origin[k]})
    assert validate.motor_population_warnings(own) == []


def test_validate_lists_the_warnings_and_passes():
    code, out, err = run_cli("catalog", "validate")
    assert code == 0, err
    assert "entries valid" in out
    for ident in ("gen-bldc42-28v-h", "gen-bldc40-48v-h", "gen-bldc60-48v-h"):
        assert ident in err
    assert "motors-mgdb.toml: [[motor]] maxon-" in err          # a warning names the file the entry is in


def test_large_ball_screws_follow_iso_3408_from_the_sourced_20_mm_screw():
    """The 25, 32 and 40 mm ball screws are the sourced HIWIN R20-05K4
    scaled at the same ball, lead and turns (ISO 3408-5: C_a ~ Z^(2/3),
    C_0a ~ Z, Z ~ d_0): recomputed here from the sourced entry; with them a
    20 kN design force has a screw whose static safety C_0 / F reaches 2."""
    from sizing.io.catalog import load_catalog
    cat = load_catalog()
    base = cat.screws["hiwin-r20-05k4-fscdin"]
    for d in (25, 32, 40):
        s = cat.screws[f"ball-{d}x5"]
        k = d / 20
        assert s.dynamic_load_rating == pytest.approx(base.dynamic_load_rating * k ** (2 / 3), rel=1e-3)
        assert s.static_load_rating == pytest.approx(base.static_load_rating * k, rel=1e-3)
        assert s.lead == base.lead and s.diameter == pytest.approx(base.diameter + (d - 20) * 1e-3)
        assert s.mass_per_length == pytest.approx(7850 * math.pi / 4 * (d * 1e-3) ** 2, rel=1e-3)
        assert s.max_speed == pytest.approx(70000 / d * 2 * math.pi / 60, rel=1e-3)
    assert max(s.static_load_rating for s in cat.screws.values()) / 20e3 >= 2.0
