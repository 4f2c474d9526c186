"""The integral of the square of the motor current (``simulate(heat=True)``),
from which the DC designs' RMS current is read: closed forms (a held current,
a voltage-driven run at its speed ceiling), the same simulation sampled 50
times per control period as a brute-force reference, and the output grid
left out of it."""
import numpy as np
import pytest

from sizing.sim.dc_motor import CHANNELS, HEAT, DCMotorModel, simulate
from sizing.technologies.dc_motor import controller as ctl

C1, C2, LEAD = -25.5552, 2987.02, 0.002     # seed section 3.2
KT, KE, R, U = 0.05, 0.05, 0.5, 24.0        # a 24 V drive on a 0.05 N m/A motor
RATE = 1250.0


def _servo(**kw) -> DCMotorModel:
    """An I-PD servo placed as the DC designs' (triple pole for a 0.4 s
    stroke) with a 10 A limit and a 500 N load."""
    g = ctl.ipd_gains(C1, C2, LEAD, ctl.pole_target(0.4, RATE))
    base = dict(c1=C1, c2=C2, lead=LEAD, rate=RATE, kp=float(g["kp"]), ki=float(g["ki"]), kd=float(g["kd"]),
                derivative_on_measurement=1.0, proportional_on_measurement=1.0, current_limit=10.0,
                load_force=500.0, torque_constant=KT, bus_voltage=U, back_emf_constant=KE, winding_resistance=R)
    return DCMotorModel(**dict(base, **kw))


def _step(model, rate_out, duration=1.6, stroke=0.04):
    """A step at t = 0 (the same reference whatever the output grid)."""
    t = np.arange(0.0, duration + 0.5 / rate_out, 1.0 / rate_out)
    t_ref = np.array([0.0, 1e-9, duration + 1.0])
    return t, simulate(model, t_ref, np.array([0.0, stroke, stroke]), t_out=t, heat=True)


def test_a_held_current_heats_as_its_square():
    """At rest under a 500 N load the integrator holds the load current:
    the integral grows as i_load^2 t."""
    model = DCMotorModel(c1=C1, c2=C2, lead=LEAD, kp=3000.0, ki=8000.0, kd=50.0, current_limit=10.0,
                         load_force=500.0, efficiency=0.9, torque_constant=0.1)
    t = np.arange(0, 1.0, 1e-3)
    out = simulate(model, t, np.zeros_like(t), heat=True)
    i_load = 500.0 * LEAD / (2 * np.pi * 0.9 * 0.1)
    np.testing.assert_allclose(out[HEAT][0], i_load**2 * t, rtol=1e-9, atol=1e-15)


def test_a_voltage_driven_run_heats_as_the_back_emf_current():
    """A far reference at a 24 V bus: the motor runs at its speed ceiling,
    where the current flowing is (U - k_e w) / R, below the 10 A the
    controller commands; the integral grows as its square."""
    model = DCMotorModel(c1=C1, c2=C2, lead=LEAD, kp=1e5, current_limit=10.0, load_force=300.0,
                         torque_constant=KT, bus_voltage=U, back_emf_constant=KE, winding_resistance=R)
    t = np.arange(0, 1.0, 1e-3)
    out = simulate(model, t, np.where(t > 0, 10.0, 0.0), heat=True)
    w = out["velocity_m_s"][0, -1] * 2 * np.pi / LEAD
    i_flow = (U - KE * w) / R
    assert 0.5 < i_flow < 9.0                       # voltage-driven: under the command
    slope = (out[HEAT][0, -1] - out[HEAT][0, -201]) / (t[-1] - t[-201])
    assert slope == pytest.approx(i_flow**2, rel=1e-6)


def test_the_integral_matches_the_current_sampled_fifty_times_per_control_period():
    """A servo step that saturates in current and in voltage: the square of
    the current sampled at 50 x 1.25 kHz, summed, agrees with the integral
    within 0.5 %; and the integral does not depend on the output grid (1
    kHz, which falls on the 1.25 kHz held current in a fixed pattern, or 2
    kHz), while the 1 kHz samples' own sum is off."""
    model = _servo()
    fine_rate = 50 * RATE
    t_f, fine = _step(model, fine_rate)
    sampled = np.cumsum(fine["current_A"][0] ** 2) / fine_rate
    assert sampled[-1] == pytest.approx(fine[HEAT][0, -1], rel=5e-3)
    no_bus = _step(_servo(bus_voltage=np.inf), fine_rate)[1]
    assert abs(no_bus[HEAT][0, -1] / fine[HEAT][0, -1] - 1) > 0.05     # the bus voltage matters here
    for rate_out in (1000.0, 2000.0):
        t, out = _step(model, rate_out)
        # read between the fine samples, the reference is within one fine step's heat (16 us x 100 A^2)
        np.testing.assert_allclose(out[HEAT][0], np.interp(t, t_f, fine[HEAT][0]), rtol=0, atol=2e-3)
    t1, coarse = _step(model, 1000.0)
    assert abs(np.sum(coarse["current_A"][0, :-1] ** 2) / 1000.0 / coarse[HEAT][0, -1] - 1) > 5e-3


def test_the_integral_leaves_the_channels_as_they_were():
    model = _servo()
    t = np.arange(0.0, 1.0, 1e-3)
    ref = np.where(t > 0, 0.04, 0.0)
    plain, heated = simulate(model, t, ref), simulate(model, t, ref, heat=True)
    assert set(plain) == set(CHANNELS) and set(heated) == set(CHANNELS) | {HEAT}
    assert all(np.array_equal(plain[k], heated[k]) for k in CHANNELS)
