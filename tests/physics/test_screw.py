"""Screw and gear: force from torque, buckling and life (physics/screw.py)."""
import math

import numpy as np
import pytest

from sizing.physics import screw


def test_force_from_torque_hand_computed():
    # F = 2 pi eta T / l: 1 N m through a 5 mm lead at 90 % -> 1130.97 N
    assert screw.force_from_torque(1.0, 0.005, 0.9) == pytest.approx(2 * math.pi * 0.9 / 0.005)
    assert screw.force_from_torque(1.0, 0.005, 0.9) == pytest.approx(1130.973, rel=1e-6)
    # a 4:1 gear at 90 % multiplies by 3.6
    assert screw.force_from_torque(1.0, 0.005, 0.9, 4.0, 0.9) == pytest.approx(1130.973 * 3.6, rel=1e-6)
    # and torque_for_force is its inverse
    assert screw.torque_for_force(1130.973, 0.005, 0.9) == pytest.approx(1.0, rel=1e-6)


def test_power_balance():
    """Energy balance: eta x motor power = output power, F v = eta T w."""
    T, w, lead, eta, N, eta_g = 0.3, 400.0, 0.002, 0.9, 3.5, 0.9
    F = screw.force_from_torque(T, lead, eta, N, eta_g)
    v = screw.output_speed(w, lead, N)
    assert F * v == pytest.approx(eta * eta_g * T * w)


def test_euler_buckling_hand_computed():
    """Solid 10 mm root, steel 200 GPa, 0.5 m: I = pi d^4 / 64 = 4.909e-10 m^4;
    pinned-pinned P = pi^2 E I / L^2 = 3875.8 N (Shigley eq. 4-43)."""
    p = screw.buckling_load(200e9, 0.010, 0.5, "pinned-pinned")
    assert p == pytest.approx(math.pi**2 * 200e9 * (math.pi * 0.01**4 / 64) / 0.25)
    assert p == pytest.approx(3875.8, rel=1e-4)
    assert screw.buckling_load(200e9, 0.010, 0.5, "fixed-free") == pytest.approx(p / 4)
    assert screw.buckling_load(200e9, 0.010, 0.5, "fixed-pinned") == pytest.approx(p / 0.49)
    assert screw.ACTUATOR_END_FIXITY == "fixed-pinned"
    with pytest.raises(KeyError):
        screw.buckling_load(200e9, 0.010, 0.5, "glued")


def test_l10_life():
    # ISO 3408-5: (C / F)^3 x 10^6 revolutions: 10 kN at 2 kN -> 125 million
    assert screw.l10_revolutions(10e3, 2e3) == pytest.approx(125e6)
    # cubic mean of half the revolutions at 1 kN and half at 2 kN: (4.5e9)^(1/3)
    assert screw.cubic_mean_load([1e3, 2e3], [0.5, 0.5]) == pytest.approx(4.5e9 ** (1 / 3))
    assert screw.cubic_mean_load(np.array([2e3, 2e3]), [0.3, 0.7]) == pytest.approx(2e3)


# --- makers' ratings (THK General Catalog, HIWIN BS-08-2-EN-1704-K) ----------
def test_static_safety_thk_bnk1202():
    """THK BNK1202-3: C0a 3.6 kN. At the seed's 2.5 kN blocked force
    f_s = 1.44 (PHYSICS-NOTES: 'static safety ... is 1.4'), below THK's 2.0
    for machinery with vibration."""
    fs = screw.static_safety(3600.0, 2500.0)
    assert fs == pytest.approx(1.44)
    assert fs < screw.STATIC_SAFETY_WITH_VIBRATION
    assert screw.static_safety(np.inf, 2500.0) == np.inf


def test_l10_hours_thk_rating_against_the_catalog_one():
    """12 x 2 mm screw, 1209.7 N (the seed's 25 kPa case), one 40 mm stroke out
    and back a second = 40 rev/s. At the old catalog's C = 3.9 kN:
    (3900 / 1209.7)^3 1e6 / 40 / 3600 = 232.7 h (PHYSICS-NOTES: 'L10 233 h');
    at THK's C_a = 1.7 kN: (1700 / 1209.7)^3 1e6 / 144000 = 19.27 h."""
    assert screw.l10_hours(3900.0, 1209.7, 40.0) == pytest.approx(232.7, rel=1e-3)
    assert screw.l10_hours(1700.0, 1209.7, 40.0) == pytest.approx(19.27, rel=1e-3)
    assert screw.l10_hours(1700.0, 1209.7, 40.0, load_factor=1.2) == pytest.approx(19.27 / 1.2**3, rel=1e-3)


def test_dn_speed_limits():
    """THK: 70 000 / 12.3 mm = 5691 rpm precision, 50 000 / 12.3 = 4065 rpm
    rolled (catalog-sources-2.md: 5690 / 4065 rpm); HIWIN rolled 16 mm: 4375 rpm."""
    rpm = lambda w: w * 60 / (2 * math.pi)
    assert rpm(screw.dn_speed_limit(70000.0, 0.0123)) == pytest.approx(5691, abs=1)
    assert rpm(screw.dn_speed_limit(50000.0, 0.0123)) == pytest.approx(4065, abs=1)
    assert rpm(screw.dn_speed_limit(70000.0, 0.016)) == pytest.approx(4375)


def test_holding_torque_back_driven_against_forward():
    """1209.7 N on a 2 mm lead: driving it takes F l / (2 pi 0.9) = 0.4279 N m;
    holding it against the back-driving load F l 0.75 / (2 pi) = 0.2888 N m
    (HIWIN reverse efficiency 0.75); with k_t 0.05 N m/A and 0.2 ohm hot,
    holding costs 0.2 (0.2888 / 0.05)^2 = 6.67 W, a brake none."""
    T = screw.holding_torque(1209.7, 0.002, 0.75)
    assert T == pytest.approx(0.28877, rel=1e-4)
    assert screw.torque_for_force(1209.7, 0.002, 0.9) == pytest.approx(0.42786, rel=1e-4)
    assert 0.2 * (T / 0.05) ** 2 == pytest.approx(6.671, rel=1e-3)
    assert screw.holding_torque(1209.7, 0.002, 0.75, ratio=4.0, gear_back_efficiency=0.8) == pytest.approx(T * 0.2)
