"""New forms of the DC simulator: a drive-side current
limit the controller does not know, Stribeck friction; hand-computed numbers,
and the nominal path bit-identical when the new fields are at their defaults."""
import numpy as np
import pytest

from sizing.sim.dc_motor import DCMotorModel, _friction_level, simulate

C1, C2, LEAD = -25.5552, 2987.02, 0.002
G = LEAD / (2 * np.pi) * C2                 # m/s^2 per A at the output
TO_I = LEAD / (2 * np.pi * 0.9 * 1.0)       # A per N (efficiency 0.9, kt 1)


def _open_loop_speed(i, t):
    """v(t) of v' = c1 v + g i from rest (closed form)."""
    return -G * i / C1 * (1.0 - np.exp(C1 * t))


def test_drive_limit_clips_the_motor_current_and_logs_the_command():
    """Command saturates at the controller's 10 A, the drive delivers 2 A:
    the logged current is 10 A, the speed is the 2 A closed form."""
    model = DCMotorModel(c1=C1, c2=C2, lead=LEAD, kp=1e6, current_limit=10.0, drive_current_limit=2.0)
    t = np.arange(0, 0.3, 1e-3)
    out = simulate(model, t, np.where(t > 0, 1.0, 0.0))
    k = t > 2e-3                      # after the first controller tick (0.8 ms)
    assert np.all(out["current_A"][0, k] == 10.0)
    t0 = 1 / 1250                     # the first command is held from the first tick
    np.testing.assert_allclose(out["velocity_m_s"][0, k], _open_loop_speed(2.0, t[k] - t0), rtol=1e-9)


def test_command_limit_logs_the_clipped_current():
    model = DCMotorModel(c1=C1, c2=C2, lead=LEAD, kp=1e6, current_limit=2.0)
    t = np.arange(0, 0.3, 1e-3)
    out = simulate(model, t, np.where(t > 0, 1.0, 0.0))
    assert np.max(out["current_A"]) == 2.0


def test_drive_limit_winds_up_the_integrator():
    """The controller does not know the drive limit: its integrator grows
    past what a known limit allows, so the drive form overshoots more."""
    kw = dict(c1=C1, c2=C2, lead=LEAD, kp=4000.0, ki=8000.0, kd=90.0, derivative_on_measurement=1.0,
              torque_constant=0.05)
    t = np.arange(0, 1.0, 1e-3)
    ref = np.where(t > 0.05, 0.01, 0.0)
    known = simulate(DCMotorModel(**kw, current_limit=3.0), t, ref)
    drive = simulate(DCMotorModel(**kw, current_limit=10.0, drive_current_limit=3.0), t, ref)
    assert np.max(drive["current_A"]) > 3.0 + 1.0                # the logged command is not clipped
    assert np.max(drive["position_m"]) > np.max(known["position_m"])


def test_stribeck_friction_level_closed_form():
    """F(v) = F_c + (F_s - F_c) exp(-(v/v_s)^2): at v = v_s, F_c + (F_s - F_c)/e."""
    run, stick = _friction_level(0.002, 1.0, 1.5, 0.002)
    assert run == pytest.approx(1.0 + 0.5 / np.e, rel=1e-12) and stick == 1.5
    assert _friction_level(0.0, 1.0, 1.5, 0.002)[0] == pytest.approx(1.5)
    assert _friction_level(0.05, 1.0, 1.5, 0.002)[0] == pytest.approx(1.0, abs=1e-12)
    assert _friction_level(0.0, 1.0, 1.5, 0.0) == (1.0, 1.0)              # Coulomb only


def test_stribeck_breakaway_and_steady_speed():
    """No control, a constant load force F pushes the output: F between the
    running 20 N and the breakaway 30 N keeps it at rest; F = 50 N moves it
    to the steady speed |v| that solves |c1| |v| = g TO_I (F - F(|v|)) on the
    Stribeck curve (one scalar root)."""
    from scipy.optimize import brentq
    t = np.arange(0, 1.0, 1e-3)
    kw = dict(c1=C1, c2=C2, lead=LEAD, coulomb_friction=20.0, static_friction=30.0,
              stribeck_velocity=1e-3, efficiency=0.9, torque_constant=1.0)
    held = simulate(DCMotorModel(**kw, load_force=25.0), t, np.zeros_like(t))
    assert np.all(held["position_m"] == 0.0)
    moved = simulate(DCMotorModel(**kw, load_force=50.0), t, np.zeros_like(t))
    F = lambda v: 20.0 + 10.0 * np.exp(-(v / 1e-3) ** 2)
    v_ss = brentq(lambda v: -C1 * v - G * TO_I * (50.0 - F(v)), 0.0, 1.0)
    assert moved["velocity_m_s"][0, -1] == pytest.approx(-v_ss, rel=1e-6)
    coulomb = simulate(DCMotorModel(**{**kw, "static_friction": 0.0}, load_force=25.0), t, np.zeros_like(t))
    assert coulomb["velocity_m_s"][0, -1] == pytest.approx(G * TO_I * (25.0 - 20.0) / C1, rel=1e-6)


def test_new_fields_at_defaults_are_bit_identical():
    """inf drive limit and no Stribeck give exactly the nominal traces."""
    kw = dict(c1=C1, c2=C2, lead=LEAD, kp=4000.0, ki=8000.0, kd=90.0, derivative_on_measurement=1.0,
              current_limit=10.0, torque_constant=0.05, coulomb_friction=np.array([0.0, 30.0]),
              bus_voltage=24.0, back_emf_constant=0.05)
    t = np.arange(0, 1.0, 1e-3)
    ref = 0.01 * (t > 0.1) - 0.006 * (t > 0.5)
    a = simulate(DCMotorModel(**kw), t, ref)
    b = simulate(DCMotorModel(**kw, drive_current_limit=np.inf, static_friction=0.0, stribeck_velocity=0.0), t, ref)
    c = simulate(DCMotorModel(**kw, static_friction=np.array([0.0, 30.0]), stribeck_velocity=1e-3), t, ref)  # F_s = F_c
    for k in a:
        assert np.array_equal(a[k], b[k]) and np.array_equal(a[k], c[k])


def test_a_play_inside_the_loop_holds_the_measurement_until_the_motor_reaches_the_flank():
    """A 0.3 mm play between screw and measured output, the loop closed on
    the measured output (``loop_backlash``). At 0 the traces are the
    nominal's bit for bit. After a 2 mm step the motor, starting centred in
    the gap and at rest, must travel b/2 = 0.15 mm before it moves the
    measurement; at most the 10 A limit accelerates it, g i_max =
    lead / (2 pi) c2 x 10 A = 9.51 m/s^2, so it needs at least
    sqrt(b / (g i_max)) = 5.6 ms: the measurement stays at 0 for the first
    five 1 ms samples, while the nominal's has moved from the first."""
    from sizing.sim.dc_motor import DCMotorModel, simulate

    base = dict(c1=-25.5552, c2=2987.02, lead=0.002, rate=1000.0, kp=1500.0, kd=25.0, current_limit=10.0)
    t = np.arange(0.0, 0.3, 1e-3)
    r = np.where(t >= 0.01, 2e-3, 0.0)
    nominal = simulate(DCMotorModel(**base), t, r)["position_m"][0]
    assert np.array_equal(simulate(DCMotorModel(**base, loop_backlash=0.0), t, r)["position_m"][0], nominal)
    played = simulate(DCMotorModel(**base, loop_backlash=3e-4), t, r)["position_m"][0]
    g = 0.002 / (2 * np.pi) * 2987.02 * 10.0
    assert np.sqrt(3e-4 / g) > 0.0055
    step = int(np.argmax(t >= 0.01))
    assert np.all(played[:step + 6] == 0.0)
    assert np.all(nominal[step + 2:step + 6] > 0.0)
