"""The whole thermal budget, against hand calculations from a
thermal expansion table and the reviewer's figures (PHYSICS-NOTES, second
round)."""
from __future__ import annotations

import math

import pytest

from sizing.physics import thermal

# the first round's best design: 340 mm bore, R 233, 3 mm gap, 42 mm stroke
A_W = math.pi * 0.34**2 / 4          # 0.09079 m^2
R = 233.0
A_N = A_W / R
V = A_W * 3e-3 + A_N * 0.042         # 2.724e-4 + 1.64e-5 = 2.888e-4 m^3
DT = 80.0                            # 20 -> 100 degC


def _budget(**kw):
    args = dict(delta_T=DT, ratio=R, narrow_area=A_N, oil_volume_m3=V, oil_expansion=7.5e-4,
                casing_expansion=0.0, stack_expansion=0.0, stack_length=0.15, frame_expansion=0.0,
                frame_length=0.15, piston_expansion=0.0, wide_piston_thickness=0.03, narrow_piston_length=0.07)
    args.update(kw)
    return thermal.budget(**args)


def test_oil_term_by_hand():
    # dV = 2.888e-4 m^3 x 7.5e-4 /K x 80 K = 1.733e-5 m^3; / A_n 3.897e-4 m^2 = 44.5 mm (the review: about 45 mm)
    b = _budget()
    assert b["oil_m"] == pytest.approx(0.0445, rel=0.005)
    assert b["net_m"] == pytest.approx(b["oil_m"])


def test_frame_against_stacks_by_hand():
    # review: 233 x 20 ppm/K x 0.15 m x 80 K = 55.9 mm, opposite in sign to the oil
    b = _budget(frame_expansion=23e-6, stack_expansion=3e-6)
    assert b["frame_m"] + b["stacks_m"] == pytest.approx(-233 * 20e-6 * 0.15 * 80, rel=1e-9)
    assert b["frame_m"] + b["stacks_m"] == pytest.approx(-0.0559, rel=1e-3)
    # steel (12.3 ppm/K, MatWeb 4340): 233 x 9.3e-6 x 0.15 x 80 = 26.0 mm ("about 25 mm")
    b = _budget(frame_expansion=12.3e-6, stack_expansion=3e-6)
    assert -(b["frame_m"] + b["stacks_m"]) == pytest.approx(0.0260, rel=2e-3)


def test_casing_takes_its_radial_expansion_off_the_oil():
    # 2 x 23.6e-6 / 7.5e-4 = 6.3 % of the oil term (the axial 1/3 is the frame's term)
    b = _budget(casing_expansion=23.6e-6)
    assert -b["casing_m"] / b["oil_m"] == pytest.approx(2 * 23.6e-6 / 7.5e-4)


def test_pistons_by_hand():
    # 233 x 23.6e-6 x 0.03 m x 80 + 23.6e-6 x 0.07 x 80 = 13.20 mm + 0.13 mm
    b = _budget(piston_expansion=23.6e-6)
    assert b["pistons_m"] == pytest.approx(233 * 23.6e-6 * 0.03 * 80 + 23.6e-6 * 0.07 * 80)


def test_net_is_the_sum_and_a_compensator_takes_the_hydraulic_terms():
    kw = dict(casing_expansion=23.6e-6, stack_expansion=11e-6, frame_expansion=23.6e-6, frame_length=0.19,
              piston_expansion=23.6e-6)
    b = _budget(**kw)
    assert b["net_m"] == pytest.approx(sum(b[k] for k in thermal.TERMS))
    c = _budget(compensated=True, **kw)
    # all that remains is the narrow piston's own growth, outside the oil
    assert c["net_m"] == pytest.approx(23.6e-6 * 0.07 * 80, rel=1e-9)
    assert c["compensator_volume_m3"] == pytest.approx(abs(b["net_m"] - 23.6e-6 * 0.07 * 80) * A_N)
    half = _budget(compensated=True, compensator_capacity=0.5 * c["compensator_volume_m3"], **kw)
    assert half["compensator_m"] == pytest.approx(0.5 * c["compensator_m"])


def test_passive_frame_length_cancels_the_budget():
    kw = dict(casing_expansion=23.6e-6, stack_expansion=11e-6, frame_expansion=23.6e-6,
              piston_expansion=23.6e-6)
    L = thermal.passive_frame_length(DT, R, A_N, V, 7.5e-4, 23.6e-6, 11e-6, 0.15, 23.6e-6, 23.6e-6, 0.03, 0.07)
    assert _budget(frame_length=L, **kw)["net_m"] == pytest.approx(0.0, abs=1e-12)
