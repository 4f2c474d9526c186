"""DC motor lead-screw actuators from the catalog: static figures, metrics
and closed-loop step responses under the load cases."""
from __future__ import annotations

import numpy as np

from ...io.catalog import DCActuator
from ...physics import dc_motor
from ...physics import motor as motor_phys
from ...physics import screw as screw_phys
from ...sim.dc_motor import DCMotorModel, simulate
from ...sim.metrics import step_metrics
from ...settings import STEP_SETTLED as SETTLED

OUTPUT_RATE_HZ = 2000.0
# Output samples of one simulated step response: the seed's 1.6 s at 2 kHz
# (its stroke time of 0.4 s, simulated four times over). A longer response is
# sampled at the same count, so a slow stroke keeps the same relative time
# resolution (800 samples per stroke time) without a memory that grows with
# its duration; the controller still ticks at its own rate in between.
OUTPUT_SAMPLES = 3200


def output_rate(duration: float) -> float:
    """Output sample rate (Hz) of a step response lasting ``duration`` s."""
    return min(OUTPUT_RATE_HZ, OUTPUT_SAMPLES / float(duration))


def output_times(duration: float) -> np.ndarray:
    """The output times (s) of a step response lasting ``duration`` s."""
    rate = output_rate(duration)
    return np.arange(0.0, duration + 0.5 / rate, 1.0 / rate)


def voltage_limit(act: DCActuator) -> dict:
    """The bus-voltage ceiling of a catalog actuator, where its catalog entry
    gives the back-EMF constant and the winding resistance (else none)."""
    if act.back_emf_constant is None or act.winding_resistance is None:
        return {}
    return {"bus_voltage": act.supply_voltage, "back_emf_constant": act.back_emf_constant,
            "winding_resistance": act.winding_resistance}


def max_speed(act: DCActuator, load_force: float = 0.0) -> float:
    """Output speed the bus allows under ``load_force`` (m/s): the motor's
    (U - R i_load) / k_e through the screw; inf without a voltage limit."""
    lim = voltage_limit(act)
    if not lim:
        return float("inf")
    i_load = dc_motor.load_current(load_force, act.screw_lead, act.screw_efficiency, act.torque_constant)
    w = motor_phys.speed_ceiling(lim["bus_voltage"], lim["back_emf_constant"], lim["winding_resistance"], i_load)
    return float(w * act.screw_lead / (2 * np.pi))


def model(act: DCActuator, load_force: float = 0.0, load_stiffness: float = 0.0) -> DCMotorModel:
    pid = act.pid
    return DCMotorModel(**voltage_limit(act),
        c1=act.c1, c2=act.c2, lead=act.screw_lead, rate=pid.rate, kp=pid.kp, ki=pid.ki, kd=pid.kd,
        derivative_on_measurement=float(pid.derivative_on == "measurement"),
        current_limit=act.current_limit, load_force=load_force, load_stiffness=load_stiffness,
        efficiency=act.screw_efficiency, torque_constant=act.torque_constant)


def static_figures(act: DCActuator, load_force: float = 0.0) -> dict[str, float]:
    """Force at the current limit, rated force and the no-load and loaded
    top speeds of eq. 13 at the current limit."""
    i_load = float(dc_motor.load_current(load_force, act.screw_lead, act.screw_efficiency, act.torque_constant))
    return {
        "blocked_force_N": float(min(act.max_force, dc_motor.max_force(
            act.current_limit, act.screw_lead, act.screw_efficiency, act.torque_constant))),
        "rated_force_N": act.max_force,
        "continuous_force_N": act.continuous_force,
        "stroke_m": act.stroke,
        "model_top_speed_m_s": float(dc_motor.steady_speed(act.current_limit, act.c1, act.c2, act.screw_lead)),
        "loaded_top_speed_m_s": float(dc_motor.steady_speed(act.current_limit - i_load, act.c1, act.c2, act.screw_lead)),
        "rated_speed_m_s": act.max_speed,
        "load_current_A": i_load,
        "max_speed_m_s": max_speed(act, load_force),
        "no_load_max_speed_m_s": max_speed(act, 0.0),
        # a catalog actuator gives no screw dimensions: its nut and support bearing (assumed) hold it
        "output_stiffness_N_m": float(screw_phys.held_stiffness()),
    }


def metrics(act: DCActuator) -> dict[str, float]:
    volume = np.pi / 4 * act.diameter**2 * act.length
    return {"mass_kg": act.mass, "cost_usd": act.cost_usd, "volume_m3": float(volume),
            "power_W": act.supply_voltage * act.current_limit}


def step_cases(act: DCActuator, step: float, load_forces, duration: float = 1.0, keep_traces=False):
    """Closed-loop response to a step of ``step`` metres under each load."""
    cases = step_cases_for(lambda force: model(act, force), step, load_forces, duration, keep_traces)
    for case in cases:
        case["max_speed_m_s"] = max_speed(act, case["load_N"])
    return cases


def step_cases_for(make_model, step: float, load_forces, duration: float = 1.0, keep_traces=False):
    """Closed-loop step response of ``make_model(force)`` under each load:
    the figures of ``step_metrics`` plus peak current and peak speed."""
    t = output_times(duration)
    reference = np.full_like(t, step)
    reference[0] = 0.0
    cases = []
    for force in load_forces:
        out = simulate(make_model(force), t, reference)
        y = out["position_m"]
        case = {k: float(v[0]) for k, v in step_metrics(t, y, np.array([SETTLED * step])).items()}
        case["load_N"] = float(force)
        case["peak_current_A"] = float(np.max(np.abs(out["current_A"])))
        case["peak_speed_m_s"] = float(np.max(np.abs(out["velocity_m_s"])))
        if keep_traces:
            case["t"] = t
            case["position_m"] = y[0]
        cases.append(case)
    return cases
