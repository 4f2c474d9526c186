"""DC motor closed loop (seed section 3, eq. 14)."""
import numpy as np
import pytest

from sizing.physics.dc_motor import zoh_coefficients
from sizing.sim.dc_motor import DCMotorModel, simulate

C1, C2, LEAD = -25.5552, 2987.02, 0.002   # seed section 3.2


def test_matches_eq14_step_by_step():
    """Proportional control, no limit, no load: replay eq. 14 by hand."""
    Ts, kp = 1 / 1250, 500.0
    model = DCMotorModel(c1=C1, c2=C2, lead=LEAD, kp=kp)
    t = np.arange(0, 0.2, Ts)
    ref = np.where(t > 0, 0.01, 0.0)
    out = simulate(model, t, ref)
    a = np.exp(C1 * Ts)
    b = (a - 1) / C1 * LEAD / (2 * np.pi) * C2          # eq. 14
    v, y, i = 0.0, 0.0, 0.0
    vs = [0.0]
    for k in range(1, len(t)):
        y = y + (a - 1) / C1 * v + ((a - 1) / C1 - Ts) / C1 * LEAD / (2 * np.pi) * C2 * i
        v = a * v + b * i
        i = kp * (ref[k] - y)
        vs.append(v)
    np.testing.assert_allclose(out["velocity_m_s"][0], vs, rtol=1e-9, atol=1e-12)


def test_zoh_coefficients_against_expm():
    from scipy.linalg import expm
    a, b, a_y, b_y = zoh_coefficients(C1, C2, LEAD, 1e-3)
    g = LEAD / (2 * np.pi) * C2
    M = np.zeros((3, 3))
    M[0, 0], M[0, 2], M[1, 0] = C1, g, 1.0       # states v, y; input u
    E = expm(M * 1e-3)
    assert a == pytest.approx(E[0, 0]) and b == pytest.approx(E[0, 2])
    assert a_y == pytest.approx(E[1, 0]) and b_y == pytest.approx(E[1, 2])


def test_current_limit_caps_speed():
    """Saturated current: the speed approaches -(l/2pi) c2 i_max / c1."""
    model = DCMotorModel(c1=C1, c2=C2, lead=LEAD, kp=1e5, current_limit=2.0)
    t = np.arange(0, 0.5, 1e-3)
    out = simulate(model, t, np.where(t > 0, 1.0, 0.0))
    v_limit = -LEAD / (2 * np.pi) * C2 * 2.0 / C1
    assert np.max(np.abs(out["current_A"])) == pytest.approx(2.0)
    assert out["velocity_m_s"][0, -1] == pytest.approx(v_limit, rel=1e-3)


def test_load_needs_holding_current_and_integrator_holds_it():
    model = DCMotorModel(c1=C1, c2=C2, lead=LEAD, kp=3000.0, ki=8000.0, kd=50.0, current_limit=10.0,
                         load_force=500.0, efficiency=0.9, torque_constant=0.1)
    t = np.arange(0, 1.0, 1e-3)
    out = simulate(model, t, np.zeros_like(t))
    i_load = 500.0 * LEAD / (2 * np.pi * 0.9 * 0.1)
    assert abs(out["position_m"][0]).max() < 1e-9         # starts and stays at rest
    assert out["current_A"][0, -1] == pytest.approx(i_load, rel=1e-6)


def test_coulomb_friction_sticks_inside_band():
    model = DCMotorModel(c1=C1, c2=C2, lead=LEAD, kp=100.0, coulomb_friction=1000.0,
                         efficiency=0.9, torque_constant=0.1)
    t = np.arange(0, 0.3, 1e-3)
    out = simulate(model, t, np.where(t > 0, 0.01, 0.0))
    # kp e = 1 A is far below the 1000 N friction band (3.5 A): no motion
    assert np.all(out["position_m"][0] == 0.0)


def test_scalar_interpolation_is_numpys_bit_for_bit():
    """The controller's reference lookup (``_interp``) gives numpy's
    ``np.interp`` exactly: inside, on and outside the samples, at repeated
    sample times, on a step and at NaN."""
    from sizing.sim.dc_motor import _interp
    rng = np.random.default_rng(3)
    xp = np.cumsum(rng.uniform(0.0, 1e-3, 200))
    xp[50:53] = xp[50]                                   # repeated sample times
    fp = rng.normal(size=200)
    fp[120:] = 0.05                                      # a flat step
    xs = np.concatenate([rng.uniform(xp[0] - 1e-3, xp[-1] + 1e-3, 2000), xp, [np.nan, xp[50], -np.inf, np.inf]])
    got = np.array([_interp(x, xp, fp) for x in xs])
    want = np.interp(xs, xp, fp)
    assert np.array_equal(got, want, equal_nan=True)
    assert _interp(0.3, xp[:1], fp[:1]) == fp[0]
