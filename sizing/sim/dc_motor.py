"""Closed-loop simulation of the DC motor lead-screw actuator (seed sec. 3).

A discrete PID at the controller rate (1.25 kHz in the seed) sets the motor
current from the reference and the measured position; the current is held
over each period and clipped at the current limit (conditional integration
stops wind-up). The plant is advanced over the period with the exact
zero-order-hold solution of eq. 13 (eq. 14 for the velocity), with the load
current of PHYSICS-NOTES and optional Coulomb friction (Karnopp: a piston at
rest stays at rest while the net current is inside the friction band).
Many candidates run at once; positions are reported from the rest position.
"""
from __future__ import annotations

from dataclasses import dataclass

import numba
import numpy as np

from ..errors import SimulationError
from .params import ParameterSet

PARAMS = (
    "c1", "c2", "lead", "rate", "kp", "ki", "kd", "derivative_on_measurement",
    "current_limit", "load_force", "load_stiffness", "efficiency", "torque_constant",
    "coulomb_friction",
)
CHANNELS = ("position_m", "velocity_m_s", "current_A")


@dataclass
class DCMotorModel(ParameterSet):
    PARAMS = PARAMS  # the kernel's column order
    """Parameters (float or (n_cand,) array), SI: c1 1/s, c2 rad/(s^2 A),
    lead m, rate Hz, kp A/m, ki A/(m s), kd A s/m, current_limit A, load N and
    N/m, efficiency -, torque_constant N m/A, coulomb_friction N."""

    c1: object
    c2: object
    lead: object
    rate: object = 1250.0
    kp: object = 0.0
    ki: object = 0.0
    kd: object = 0.0
    derivative_on_measurement: object = 0.0
    current_limit: object = np.inf
    load_force: object = 0.0
    load_stiffness: object = 0.0
    efficiency: object = 0.9
    torque_constant: object = 1.0
    coulomb_friction: object = 0.0



@numba.njit(cache=True)
def _plant_step(y, v, u, a, b, a_y, b_y, c1, g, Ts, i_fric):
    """Advance eq. 13 over one hold period with net current u (before
    friction). Returns y, v."""
    if i_fric > 0.0:
        if v == 0.0 and abs(u) <= i_fric:
            return y, 0.0
        s = 1.0 if v > 0.0 else (-1.0 if v < 0.0 else (1.0 if u > 0.0 else -1.0))
        u = u - s * i_fric
        v_new = a * v + b * u
        if v_new * s < 0.0:
            # the friction stops the motion inside the period: find when
            # v(t) = 0 for v' = c1 v + g u, integrate to it, stick there.
            if c1 != 0.0:
                t_stop = np.log((g * u / c1) / (v + g * u / c1)) / c1
            else:
                t_stop = -v / (g * u)
            t_stop = min(max(t_stop, 0.0), Ts)
            e = np.exp(c1 * t_stop)
            phi = (e - 1.0) / c1 if c1 != 0.0 else t_stop
            psi = (phi - t_stop) / c1 if c1 != 0.0 else t_stop * t_stop / 2
            return y + phi * v + psi * g * u, 0.0
        return y + a_y * v + b_y * u, v_new
    return y + a_y * v + b_y * u, a * v + b * u


@numba.njit(cache=True)
def _simulate_one(p, t_ref, r_row, t_out, rec):
    c1, c2, lead, rate, kp, ki, kd = p[0], p[1], p[2], p[3], p[4], p[5], p[6]
    d_meas, i_max, F0, kL, eta, kt, Fc = p[7], p[8], p[9], p[10], p[11], p[12], p[13]
    Ts = 1.0 / rate
    g = lead / (2.0 * np.pi) * c2
    a = np.exp(c1 * Ts)
    phi = (a - 1.0) / c1 if c1 != 0.0 else Ts
    psi = (phi - Ts) / c1 if c1 != 0.0 else Ts * Ts / 2
    b, a_y, b_y = phi * g, phi, psi * g
    to_current = lead / (2.0 * np.pi * eta * kt)     # A per N at the output
    i_fric = Fc * to_current
    y, v = 0.0, 0.0
    # rest under the load: the integrator already holds the load current
    integ = (F0 * to_current / ki) if ki != 0.0 else 0.0
    e_prev = np.interp(t_out[0], t_ref, r_row) - y
    y_prev = y
    t = t_out[0]
    i = ki * integ          # the holding current, so the rest is a rest
    j = 0
    n_out = t_out.shape[0]
    while j < n_out:
        # record every output time that falls inside this control period
        while j < n_out and t_out[j] < t + Ts - 1e-12:
            tau = t_out[j] - t
            e = np.exp(c1 * tau)
            ph = (e - 1.0) / c1 if c1 != 0.0 else tau
            ps = (ph - tau) / c1 if c1 != 0.0 else tau * tau / 2
            u = i - (F0 + kL * y) * to_current
            if v == 0.0 and abs(u) <= i_fric:
                rec[0, j], rec[1, j] = y, 0.0
            else:
                rec[0, j] = y + ph * v + ps * g * u
                rec[1, j] = e * v + ph * g * u
            rec[2, j] = i
            j += 1
        if j >= n_out:
            break
        # controller tick at time t + Ts: sample, compute, hold
        y, v = _plant_step(y, v, i - (F0 + kL * y) * to_current, a, b, a_y, b_y, c1, g, Ts, i_fric)
        t += Ts
        r = np.interp(t, t_ref, r_row)
        err = r - y
        deriv = -(y - y_prev) / Ts if d_meas > 0.5 else (err - e_prev) / Ts
        i_try = kp * err + ki * (integ + err * Ts) + kd * deriv
        if abs(i_try) < i_max or i_try * err < 0.0:
            integ += err * Ts
        i_new = kp * err + ki * integ + kd * deriv
        i = min(max(i_new, -i_max), i_max)
        e_prev, y_prev = err, y
    return rec


@numba.njit(cache=True, parallel=True)
def _simulate(P, t_ref, R, t_out, r_stride):
    n_cand = P.shape[0]
    out = np.empty((n_cand, 3, t_out.shape[0]))
    for c in numba.prange(n_cand):
        _simulate_one(P[c], t_ref, R[c * r_stride], t_out, out[c])
    return out


def simulate(model: DCMotorModel, t_ref, reference, t_out=None) -> dict[str, np.ndarray]:
    """Simulate each candidate following ``reference`` (m) given at t_ref (s).
    Returns {channel: (n_cand, n_out)} for CHANNELS."""
    P = model.matrix()
    t_ref = np.ascontiguousarray(t_ref, dtype=float)
    R = np.ascontiguousarray(np.atleast_2d(np.asarray(reference, dtype=float)))
    t_out = t_ref if t_out is None else np.ascontiguousarray(t_out, dtype=float)
    out = _simulate(P, t_ref, R, t_out, np.int64(R.shape[0] > 1))
    bad = ~np.all(np.isfinite(out), axis=(1, 2))
    if bad.any():
        raise SimulationError(f"simulation diverged for candidates {np.flatnonzero(bad).tolist()}")
    return {name: out[:, i, :] for i, name in enumerate(CHANNELS)}
