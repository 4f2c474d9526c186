"""Motor limits: back-EMF speed ceiling and winding temperature (physics/motor.py)
and the voltage-limited closed loop (sim/dc_motor.py)."""
import math

import numpy as np
import pytest

from sizing.physics import motor
from sizing.sim.dc_motor import DCMotorModel, simulate


def test_back_emf_ceiling_against_maxon_100degC_column():
    """maxon EC-4pole 32 HD 220 W, 48 V, 100 degC column (catalog page
    flippingbook 1042987/296, catalog-sources.md 2a): speed constant 139 rpm/V,
    no-load speed 6650 rpm, R 1.31 ohm, stall current 36.7 A."""
    ke = 60 / (2 * math.pi * 139)                   # V s/rad from k_n
    w0 = motor.speed_ceiling(48.0, ke, 1.31, 0.0)
    assert w0 * 60 / (2 * math.pi) == pytest.approx(6650, rel=0.01)   # no-load current neglected
    assert motor.speed_ceiling(48.0, ke, 1.31, 36.7) == pytest.approx(0.0, abs=1.0)   # stall
    # linear in the current between the two: halfway, half the speed
    assert motor.speed_ceiling(48.0, ke, 1.31, 48 / 1.31 / 2) == pytest.approx(48 / ke / 2)


def test_winding_rise_hand_computed():
    """R_th 2 K/W, R_25 1 ohm, alpha 0.004 1/K, ambient 100 degC, 5 A:
    dT = 2 x 1 x (1 + 0.004 (100 + dT - 25)) x 25 = 65 + 0.2 dT -> dT = 81.25 K."""
    assert motor.winding_rise(2.0, 1.0, 0.004, 100.0, 5.0) == pytest.approx(81.25)
    # without the copper coefficient: R_th R i^2 (= 50 K)
    assert motor.winding_rise(2.0, 1.0, 0.0, 100.0, 5.0) == pytest.approx(50.0)


def test_winding_rise_is_a_fixed_point_and_its_inverse():
    """Cross-check by fixed-point iteration of dT = R_th R(T_a + dT) i^2."""
    rth, r25, alpha, ta, i = 4.5, 1.01, 0.00396, 100.0, 3.0
    dT = 0.0
    for _ in range(200):
        dT = rth * r25 * (1 + alpha * (ta + dT - 25)) * i**2
    assert motor.winding_rise(rth, r25, alpha, ta, i) == pytest.approx(dT, rel=1e-9)
    i_ok = motor.rms_current_allowed(rth, r25, alpha, ta, 180.0)
    assert ta + motor.winding_rise(rth, r25, alpha, ta, i_ok) == pytest.approx(180.0)


def test_thermal_runaway_is_infinite():
    # alpha R_th R_25 i^2 = 0.004 x 10 x 1 x 25 = 1: copper loss outruns cooling
    assert np.isinf(motor.winding_rise(10.0, 1.0, 0.004, 25.0, 5.0))


def test_simulated_speed_settles_at_the_voltage_ceiling():
    """A motor pushed far (saturated current) against a load settles where the
    torque balance k_t (U - k_e w) / R = b w + k_t i_load holds (independent of
    the kernel's voltage-mode pole)."""
    J, b, kt, ke, R, U, lead, eta, F = 2e-5, 1e-4, 0.06, 0.06, 0.5, 24.0, 0.004, 0.9, 300.0
    i_load = F * lead / (2 * math.pi * eta * kt)
    w = (kt * U / R - kt * i_load) / (b + kt * ke / R)
    model = DCMotorModel(c1=-b / J, c2=kt / J, lead=lead, kp=1e6, current_limit=40.0, load_force=F,
                         efficiency=eta, torque_constant=kt, bus_voltage=U, back_emf_constant=ke,
                         winding_resistance=R)
    t = np.arange(0, 0.3, 5e-4)
    out = simulate(model, t, np.where(t > 0, 10.0, 0.0))
    v = out["velocity_m_s"][0]
    assert v[-1] == pytest.approx(w * lead / (2 * math.pi), rel=1e-4)
    assert v.max() <= motor.speed_ceiling(U, ke, R, i_load) * lead / (2 * math.pi) * (1 + 1e-9)
    # the current then is what the voltage leaves, below the 40 A limit
    assert out["current_A"][0, -1] == pytest.approx((U - ke * w) / R, rel=1e-4)


def test_no_bus_voltage_keeps_the_seed_model():
    """U = inf (default): identical to the seed's current-driven eq. 13."""
    base = dict(c1=-25.5552, c2=2987.02, lead=0.002, kp=4000.0, ki=8000.0, kd=90.0, current_limit=10.0,
                derivative_on_measurement=1.0)
    t = np.arange(0, 0.3, 5e-4)
    ref = np.where(t > 0, 0.01, 0.0)
    a = simulate(DCMotorModel(**base), t, ref)["position_m"]
    # a bus far above what the step needs changes nothing either
    b = simulate(DCMotorModel(**base, bus_voltage=1e4, back_emf_constant=0.05, winding_resistance=0.5), t, ref)["position_m"]
    np.testing.assert_allclose(a, b, rtol=0, atol=1e-15)


# --- ratings at temperature ---------------------------------------------------
def test_torque_constant_derating_ndfeb_and_smco():
    """NdFeB remanence falls 0.12 %/K (e-magnetsuk.com, N and M grades), SmCo
    0.035 %/K (PHYSICS-NOTES): 100 K above 25 degC, k_t is 12 % and 3.5 % lower."""
    assert motor.torque_constant_at(0.1, -0.0012, 125.0) == pytest.approx(0.088)
    assert motor.torque_constant_at(0.1, -0.00035, 125.0) == pytest.approx(0.0965)
    # maxon EC-4pole 32 HD datasheet columns: 70.5 mNm/A at 25 degC, 68.7 at 100 degC
    beta = (68.7 / 70.5 - 1) / 75
    assert motor.torque_constant_at(70.5, beta, 100.0) == pytest.approx(68.7)


def test_derated_winding_is_the_fixed_point():
    """0.3 N m RMS, k_t 0.1 N m/A (NdFeB), R 1 ohm, alpha 0.004, R_th 2 K/W, 100 degC:
    without derating i = 3 A and dT = 18 (1.3 + 0.004 dT) -> 25.21 K; with the
    magnets at the winding, T_w solves T_w = 100 + 2 R(T_w) (0.3 / k_t(T_w))^2
    (found here by bisection, independently of the iteration)."""
    from scipy.optimize import brentq
    f = lambda Tw: Tw - 100 - 2 * (1 + 0.004 * (Tw - 25)) * (0.3 / (0.1 * (1 - 0.0012 * (Tw - 25)))) ** 2
    Tw_ref = brentq(f, 100.0, 300.0)
    Tw, kt, i = motor.derated_winding(2.0, 1.0, 0.004, 0.1, -0.0012, 100.0, 0.3)
    assert float(Tw) == pytest.approx(Tw_ref, rel=1e-6)
    assert float(i) == pytest.approx(0.3 / kt) and float(kt) < 0.1
    Tw0, kt0, i0 = motor.derated_winding(2.0, 1.0, 0.004, 0.1, 0.0, 100.0, 0.3)
    assert float(Tw0) == pytest.approx(100 + 23.4 / (1 - 0.072)) and float(i0) == pytest.approx(3.0)
    assert Tw > Tw0 + 4.0          # the weaker magnets cost current, the current heat


def test_continuous_torque_derating_exlar_note():
    """Exlar's elevated-ambient de-rating (catalog-sources.md 2b): a 130 degC
    stator keeps sqrt((130 - 55) / 105) = 84.5 % at 55 degC and 53 % at 100 degC."""
    assert motor.continuous_torque_at(1.0, 130.0, 55.0) == pytest.approx(0.845, abs=5e-4)
    assert motor.continuous_torque_at(1.0, 130.0, 100.0) == pytest.approx(0.5345, abs=5e-4)
    assert motor.continuous_torque_at(1.0, 130.0, 140.0) == 0.0


def test_holding_temperature_first_order():
    """From 120 degC towards 150 degC for one time constant: 150 - 30 / e."""
    assert motor.holding_temperature(120.0, 150.0, 600.0, 600.0) == pytest.approx(150 - 30 / math.e)
    assert motor.holding_temperature(120.0, np.inf, 60.0, 600.0) == np.inf
