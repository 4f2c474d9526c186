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
