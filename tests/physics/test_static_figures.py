"""Static figures against the seed's tables and PHYSICS-NOTES."""
import numpy as np
import pytest
from hypothesis import given, strategies as st

from sizing.physics import dc_motor, hydraulics, load, stack, thermal


def test_table2_full_scale():
    # PHYSICS-NOTES: R d33 V = 277 x 1.8e-7 x 1000 = 49.9 mm;
    # n k_s d33 V / R = 10 x 4.33e8 x 1.8e-4 / 277 = 2.81 kN.
    out = hydraulics.static_figures(10, 4.33e8, 1.8e-7 * 1000, 277)
    assert out["free_stroke_m"] == pytest.approx(0.04986, rel=1e-3)
    assert out["blocked_force_N"] == pytest.approx(2814, rel=1e-3)


def test_table3_prototype_ratio_from_geometry():
    # Table 3 swaps the diameters; 3.75 in / 0.375 in give R = 100, not 106.
    R = hydraulics.area_ratio(3.75 * 0.0254, 0.375 * 0.0254)
    assert R == pytest.approx(100.0, rel=1e-12)
    out = hydraulics.static_figures(3, 1.96e7, 100e-6, R)
    assert out["free_stroke_m"] == pytest.approx(0.010, rel=1e-9)
    assert out["blocked_force_N"] == pytest.approx(58.8, rel=1e-9)


def test_fluid_spring_in_series_lowers_blocked_force():
    # k_f = beta A^2 / V = 1.5e9 x 0.01^2 / 1e-4 = 1.5e9 N/m; stacks 1.5e9 N/m:
    # half the blocked force survives.
    out = hydraulics.static_figures(1, 1.5e9, 1e-4, 10, wide_area=0.01, oil_volume=1e-4, bulk_modulus=1.5e9)
    assert out["compliance_force_fraction"] == pytest.approx(0.5)
    assert out["blocked_force_compliant_N"] == pytest.approx(0.5 * 1.5e9 * 1e-4 / 10)


def test_pascal_at_rest():
    # eq. 10 without flow: F_wide = R F_narrow, so blocked force x R = stack force.
    out = hydraulics.static_figures(4, 2e7, 50e-6, 80)
    assert out["blocked_force_N"] * 80 == pytest.approx(out["stack_force_N"])
    assert hydraulics.pressure_drop(0.0, 870.0, 80, 0.5, 1.0) == 0.0


def test_flow_loss_resists_motion_both_ways():
    # PHYSICS-NOTES item 5: u|u|, and Borda-Carnot (1 - 1/R)^2 on return.
    R = 100.0
    forward = hydraulics.pressure_drop(0.1, 870.0, R, 0.5, hydraulics.expansion_loss_coefficient(R))
    back = hydraulics.pressure_drop(-0.1, 870.0, R, 0.5, hydraulics.expansion_loss_coefficient(R))
    assert forward > 0 > back
    assert forward == pytest.approx(0.5 * 870 * 0.01 * (1 - 1e-4 + 0.5))
    assert back == pytest.approx(-0.5 * 870 * 0.01 * (1 - 1e-4 + 0.99**2))


def test_surface_tip_force():
    # PHYSICS-NOTES: p b c / 2 = 484 N at 10 kPa, 1210 N at 25 kPa.
    b, c = 15 * 0.0254, 10 * 0.0254
    assert load.tip_force(10e3, b, c) == pytest.approx(483.9, abs=0.1)
    assert load.tip_force(25e3, b, c) == pytest.approx(1209.7, abs=0.1)


def test_work_bound_for_pi_stack():
    # 100 J / 14 J per PI stack -> at least 8 stacks (PHYSICS-NOTES).
    assert stack.work_capacity(1, 4.33e8, 180e-6) == pytest.approx(14.03, rel=1e-3)
    assert stack.min_stacks_for_work(2500, 0.04, 4.33e8, 180e-6) == 8


@given(n=st.integers(1, 40), k=st.floats(1e6, 1e9), x=st.floats(1e-6, 5e-4), R=st.floats(2, 1000),
       F=st.floats(1, 1e4), S=st.floats(1e-3, 0.1))
def test_work_bound_holds_for_every_design_that_meets_F_and_S(n, k, x, R, F, S):
    out = hydraulics.static_figures(n, k, x, R)
    if out["blocked_force_N"] >= F and out["free_stroke_m"] >= S:
        assert stack.work_capacity(n, k, x) >= F * S * (1 - 1e-12)


def test_thermal_drift_full_scale_exceeds_stroke():
    # 217 mm bore at 3 mm gap, R = 277: drift over 75 K beats the 40 mm stroke.
    A_w = np.pi * 0.217**2 / 4
    V = thermal.oil_volume(A_w, A_w / 277, 3e-3, 0.05)
    drift = thermal.output_drift(V, 7e-4, 75.0, A_w / 277)
    assert drift == pytest.approx(7e-4 * 75 * (3e-3 * 277 + 0.05), rel=1e-9)
    assert drift > 0.04


def test_dc_motor_static():
    # eq. 13 steady state: v = -(l/2pi) c2 i / c1.
    v = dc_motor.steady_speed(1.0, -25.5552, 2987.02, 0.002)
    assert v == pytest.approx(0.002 / (2 * np.pi) * 2987.02 / 25.5552, rel=1e-12)
    F = dc_motor.max_force(10.0, 0.002, 0.9, 0.1)
    assert dc_motor.load_current(F, 0.002, 0.9, 0.1) == pytest.approx(10.0)
