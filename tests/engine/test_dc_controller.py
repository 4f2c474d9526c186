"""Controller gains of a DC design from its plant (technologies/dc_motor/controller.py)."""
import math

import numpy as np
import pytest
from scipy import stats

from sizing.technologies.dc_motor import controller as ctl
from sizing.sim.dc_motor import DCMotorModel, simulate

C1, C2, LEAD = -25.5552, 2987.02, 0.002   # the seed's plant (ARL-TR-10251 sec. 3.2)


def _closed_loop(c1, c2, lead, g):
    """State space of plant + I-PD built by hand: x = (y, v, z = int e)."""
    gg = lead / (2 * math.pi) * c2
    A = np.array([[0.0, 1.0, 0.0],
                  [-gg * g["kp"], c1 - gg * g["kd"], gg * g["ki"]],
                  [-1.0, 0.0, 0.0]])
    B = np.array([[0.0], [0.0], [1.0]])
    C = np.array([[1.0, 0.0, 0.0]])
    return A, B, C


def test_gains_place_a_triple_pole():
    w0 = 40.0
    g = ctl.ipd_gains(C1, C2, LEAD, w0)
    A, _, _ = _closed_loop(C1, C2, LEAD, g)
    poles = np.linalg.eigvals(A)
    np.testing.assert_allclose(np.sort(poles.real), [-w0] * 3, rtol=2e-3)
    assert np.max(np.abs(poles.imag)) < 0.05 * w0      # a triple root splits by rounding only


def test_closed_loop_bandwidth_is_the_stated_one():
    """-3 dB of the hand-built closed loop = sqrt(2^(1/3) - 1) w0."""
    w0 = 30.0
    A, B, C = _closed_loop(C1, C2, LEAD, ctl.ipd_gains(C1, C2, LEAD, w0))
    wb = ctl.bandwidth(w0)
    H = [(C @ np.linalg.solve(1j * w * np.eye(3) - A, B))[0, 0] for w in (1e-3, wb)]
    assert abs(H[0]) == pytest.approx(1.0, abs=1e-4)
    assert 20 * np.log10(abs(H[1])) == pytest.approx(-3.0103, abs=0.01)


def test_settling_constant_and_discrete_step():
    """98 % of the step at SETTLE_98 / w0 (gamma(3) quantile), also with the
    1.25 kHz discrete PID of the simulation for a small (unsaturated) step."""
    assert ctl.SETTLE_98 == pytest.approx(stats.gamma.ppf(0.98, 3), rel=1e-4)
    w0 = float(ctl.pole_target(0.4, 1250.0))
    assert w0 == pytest.approx(2 * ctl.SETTLE_98 / 0.4)
    g = ctl.ipd_gains(C1, C2, LEAD, w0)
    model = DCMotorModel(c1=C1, c2=C2, lead=LEAD, kp=g["kp"], ki=g["ki"], kd=g["kd"],
                         derivative_on_measurement=1.0, proportional_on_measurement=1.0)
    t = np.arange(0, 1.0, 1e-4)
    y = simulate(model, t, np.where(t > 0, 1e-3, 0.0))["position_m"][0]
    t98 = t[np.argmax(y >= 0.98e-3)]
    assert t98 == pytest.approx(ctl.SETTLE_98 / w0, rel=0.05)
    assert y.max() <= 1e-3 * 1.01          # no zeros, no overshoot


def test_pole_capped_by_the_controller_rate():
    assert ctl.pole_target(1e-3, 1250.0) == pytest.approx(2 * math.pi * 1250 / ctl.SAMPLES_PER_POLE)
