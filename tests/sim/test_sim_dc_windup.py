"""The integrator at the current limit (``integrate_to_limit``): taking the
part of a step that brings the command to the limit, instead of the whole
step or none, makes the closed loop depend continuously on what it is
asked; a servo step's time to 98 % then moves by small, same-sign steps
with the stroke."""
import numpy as np
import pytest

from sizing.sim.dc_motor import DCMotorModel, simulate
from sizing.technologies.dc_motor import controller as ctl

C1, C2, LEAD = -25.5552, 2987.02, 0.002     # seed section 3.2
SPEED = 0.1                                 # m/s: the pole is placed for stroke / speed


def _speeds(integrate_to_limit):
    """Mean speed to 98 % of strokes 39.0 ... 40.0 mm (0.1 mm apart) under a
    500 N load, 10 A and a 24 V bus, each with its own triple pole."""
    S = np.linspace(0.039, 0.040, 11)
    g = ctl.ipd_gains(C1, C2, LEAD, ctl.pole_target(S / SPEED, 1250.0))
    model = DCMotorModel(c1=C1, c2=C2, lead=LEAD, kp=g["kp"], ki=g["ki"], kd=g["kd"], derivative_on_measurement=1.0,
                         proportional_on_measurement=1.0, current_limit=10.0, load_force=500.0, torque_constant=0.05,
                         bus_voltage=24.0, back_emf_constant=0.05, winding_resistance=0.5,
                         integrate_to_limit=integrate_to_limit)
    t = np.arange(0.0, 0.8, 1 / 62500)              # 50 samples per control period
    steps = np.column_stack([np.zeros_like(S), S, S])
    y = simulate(model, np.array([0.0, 1e-9, 1.0]), steps, t_out=t)["position_m"]
    return 0.98 * S / t[np.argmax(y >= 0.98 * S[:, None], axis=1)]


def test_the_time_to_stroke_is_continuous_in_the_stroke_when_integrating_to_the_limit():
    """Integrating to the limit: the speed rises with the stroke (the pole
    slows with it, so the slew at the limits takes a smaller share) by at
    most 0.05 % per 0.1 mm. The whole-or-nothing rule jumps by up to 0.5 %
    either way over the same steps: one more or one less step of e Ts in
    the integrator where the command crosses the limit."""
    smooth = np.diff(_speeds(1.0)) / _speeds(1.0)[:-1]
    assert np.all(smooth > 0) and np.all(smooth < 5e-4)
    jumps = np.diff(_speeds(0.0)) / _speeds(0.0)[:-1]
    assert (jumps < 0).any() and np.abs(jumps).max() > 3e-3


def test_the_two_anti_wind_up_rules_by_hand():
    """ki 100 A/(m s), Ts 1 ms, limit 10 A: a command at 9.995 A before the
    step, whose error 0.1 m adds ki e Ts = 0.01 A (10.005 A with it)."""
    from sizing.sim.dc_motor import _integrate

    before, err, Ts, ki = 9.995, 0.1, 1e-3, 100.0
    i_try = before + ki * err * Ts
    assert _integrate(0.0, err, Ts, i_try, ki, 10.0, False) == 0.0                    # past the limit: none
    assert _integrate(0.0, err, Ts, i_try, ki, 10.0, True) == pytest.approx(5e-5)    # (10 - 9.995) / ki
    assert _integrate(0.0, err, Ts, 9.5, ki, 10.0, True) == pytest.approx(1e-4)      # inside: the whole e Ts
    assert _integrate(0.0, -err, Ts, 12.0, ki, 10.0, False) == pytest.approx(-1e-4)  # back towards it: whole
    assert _integrate(0.0, err, Ts, 12.0, ki, 10.0, True) == 0.0                     # already past: none
