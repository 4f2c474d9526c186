"""Cycle-resolved simulation of the piezohydraulic pump, many candidates at once.

Model (docs/models.md, "Piezo pump"; the equations P1-P4 of physics/pump.py):
- stacks: a sine drive 0..V at the pumping frequency f, non-symmetric
  Bouc-Wen free displacement (seed eqs. 1-2, ``hysteresis_step``) scaled by
  the temperature derating, behind the stacks' stiffness K; the pump piston
  is quasi-static (its mass is negligible against K at f), so the chamber
  takes C dp = A_p dx_f - (Q_out - Q_in) dt with C = V_c / beta_e(p) + A_p^2 / K;
- reed check valves: quasi-static lift from the pressure difference above
  cracking, curtain area capped at the port, orifice flow (P3). The chamber
  pressure of each step is solved implicitly (bisection on the monotone
  volume balance), so a wide-open valve cannot make the step unstable;
- output cylinder: the high side is an oil volume A_c (l_0 + y) with the
  effective bulk modulus at its pressure, the low side and the inlet sit at
  the accumulator's bias pressure p_b; the load mass m moves under
  (p_h - p_b) A_c - F_load and Karnopp seal friction pi D (f_0 + c_p p_h).

Integration: fixed step, at least STEPS_PER_CYCLE steps a pumping cycle
and 0.2 / omega of the load on the high-side oil; semi-implicit Euler for
the load. The run stops when the output reaches the target stroke.
"""
from __future__ import annotations

from dataclasses import dataclass

import numba
import numpy as np

from ..physics.bouc_wen import hysteresis_step
from .params import StackParameters

PARAMS = (
    "k_stacks", "d33", "alpha", "beta", "gamma", "delta", "n_bw", "stroke_scale", "voltage", "frequency",
    "pump_area", "chamber_volume", "bulk_modulus", "air_fraction", "wall_compliance", "density",
    "cracking_pressure", "port_area", "reed_stiffness", "max_lift", "discharge_coefficient",
    "bias_pressure", "cylinder_area", "dead_length", "load_mass", "load_force", "friction", "friction_pressure",
    "target_stroke", "t_end", "dt",
)
IDX = {name: i for i, name in enumerate(PARAMS)}
OUTPUTS = ("stroke_m", "time_to_stroke_s", "mean_speed_m_s", "cycles", "pumped_volume_m3", "delivered_volume_m3",
           "peak_chamber_pressure_Pa", "peak_cylinder_pressure_Pa", "reached")
STEPS_PER_CYCLE = 100
P_ATM = 101325.0
POLYTROPIC = 1.4
BISECTION = 36


@dataclass
class PumpModel(StackParameters):
    """Parameters of the cycle-resolved model, floats or arrays (n_cand,), SI:
    N/m, m/V, V, Hz, m^2, m^3, Pa (gauge), kg, N, N/m (seal friction per
    circumference), N/(m Pa). ``air_fraction``: free air at atmospheric
    pressure; ``wall_compliance``: D / (E t) of the chamber and cylinder, 1/Pa."""

    PARAMS = PARAMS
    stroke_scale: object
    voltage: object
    frequency: object
    pump_area: object
    chamber_volume: object
    bulk_modulus: object
    air_fraction: object
    wall_compliance: object
    density: object
    cracking_pressure: object
    port_area: object
    reed_stiffness: object
    max_lift: object
    discharge_coefficient: object
    bias_pressure: object
    cylinder_area: object
    dead_length: object
    load_mass: object
    load_force: object
    friction: object = 0.0
    friction_pressure: object = 0.0
    target_stroke: object = 0.04
    t_end: object = 1.0
    dt: object = 0.0         # <= 0: chosen from the frequency and the load mode


@numba.njit(cache=True, error_model="numpy")
def _beta(p, bulk, a0, wall):
    """Eq. P2 at gauge pressure p."""
    pa = max(p + P_ATM, 1e3)
    va = a0 * (P_ATM / pa) ** (1.0 / POLYTROPIC)
    a = va / (1.0 - a0 + va)
    return 1.0 / ((1.0 - a) / bulk + a / (POLYTROPIC * pa) + wall)


@numba.njit(cache=True, error_model="numpy")
def _valve(dp, pcr, Av, kv, lift, cd, rho, dport):
    """Forward flow of a reed check valve (P3), m^3/s."""
    if dp <= pcr:
        return 0.0
    x = min((dp - pcr) * Av / kv, lift)
    return cd * min(np.pi * dport * x, Av) * np.sqrt(2.0 * dp / rho)


@numba.njit(cache=True, error_model="numpy")
def _chamber(p, ph, pb, C, dV, dt, pcr, Av, kv, lift, cd, rho, dport):
    """Chamber pressure after a step that sweeps dV: solves
    C (p1 - p) - dV + dt (Q_out(p1 - ph) - Q_in(pb - p1)) = 0 (increasing in p1)."""
    free = p + dV / C
    if pb - pcr <= free <= ph + pcr:
        return free                     # both valves shut: the chamber only compresses
    lo = min(free, ph + pcr, pb - pcr)
    hi = max(free, ph + pcr, pb - pcr)
    for _ in range(BISECTION):
        mid = 0.5 * (lo + hi)
        r = C * (mid - p) - dV + dt * (_valve(mid - ph, pcr, Av, kv, lift, cd, rho, dport)
                                       - _valve(pb - mid, pcr, Av, kv, lift, cd, rho, dport))
        if r > 0.0:
            hi = mid
        else:
            lo = mid
    return max(0.5 * (lo + hi), 1e3 - P_ATM)      # no lower than vapour: the chamber cavitates


@numba.njit(cache=True, error_model="numpy")
def _run(P, out):
    for c in range(P.shape[0]):
        row = P[c]
        K, d33, al, be, ga, de, nb, scale = row[0], row[1], row[2], row[3], row[4], row[5], row[6], row[7]
        V, f, Ap, Vc, bulk, a0, wall, rho = row[8], row[9], row[10], row[11], row[12], row[13], row[14], row[15]
        pcr, Av, kv, lift, cd = row[16], row[17], row[18], row[19], row[20]
        pb, Ac, l0, m, F, f0, cp = row[21], row[22], row[23], row[24], row[25], row[26], row[27]
        S, t_end, dt = row[28], row[29], row[30]
        dport = np.sqrt(4.0 * Av / np.pi)
        perim = 2.0 * np.sqrt(np.pi * Ac)
        n_steps = int(t_end / dt) + 1
        p = pb
        ph = pb + F / Ac
        y = 0.0
        u = 0.0
        h = 0.0
        v0 = 0.0
        xf0 = 0.0
        pumped = 0.0
        delivered = 0.0
        p_max = p
        ph_max = ph
        t = 0.0
        reached = 0.0
        for k in range(n_steps):
            t = (k + 1) * dt
            v1 = 0.5 * V * (1.0 - np.cos(2.0 * np.pi * f * t))
            h = hysteresis_step(h, v0, v1, dt, al, be, ga, de, nb)
            xf1 = scale * (d33 * v1 + h)
            dV = Ap * (xf1 - xf0)
            if dV > 0.0:
                pumped += dV
            C = Vc / _beta(p, bulk, a0, wall) + Ap * Ap / K
            p1 = _chamber(p, ph, pb, C, dV, dt, pcr, Av, kv, lift, cd, rho, dport)
            q_out = _valve(p1 - ph, pcr, Av, kv, lift, cd, rho, dport)
            delivered += q_out * dt
            # the load: semi-implicit Euler, Karnopp friction
            Ff = perim * (f0 + cp * abs(ph))
            Fn = (ph - pb) * Ac - F
            if u == 0.0 and abs(Fn) <= Ff:
                u1 = 0.0
            else:
                s = u if u != 0.0 else Fn
                u1 = u + dt * (Fn - (Ff if s > 0.0 else -Ff)) / m
                if u != 0.0 and u1 * u < 0.0:
                    u1 = 0.0
            Vh = Ac * (l0 + max(y, 0.0))
            ph = ph + dt * _beta(ph, bulk, a0, wall) * (q_out - Ac * u1) / Vh
            y += dt * u1
            u = u1
            p = p1
            v0 = v1
            xf0 = xf1
            p_max = max(p_max, p)
            ph_max = max(ph_max, ph)
            if y >= S:
                reached = 1.0
                break
        out[c, 0] = y
        out[c, 1] = t
        out[c, 2] = y / (np.ceil(t * f - 1e-9) / f)     # over whole pumping cycles
        out[c, 3] = f * t
        out[c, 4] = pumped
        out[c, 5] = delivered
        out[c, 6] = p_max
        out[c, 7] = ph_max
        out[c, 8] = reached


def stable_step(P: np.ndarray) -> np.ndarray:
    """STEPS_PER_CYCLE steps a pumping cycle, and 0.2 / omega of the load
    mass on the high-side oil (at the oil's own modulus, the stiffest)."""
    Ac, m = P[:, IDX["cylinder_area"]], P[:, IDX["load_mass"]]
    Vh = Ac * P[:, IDX["dead_length"]]
    omega = np.sqrt(P[:, IDX["bulk_modulus"]] * Ac**2 / (Vh * m))
    return np.minimum(1.0 / (STEPS_PER_CYCLE * P[:, IDX["frequency"]]), 0.2 / omega)


def simulate(model: PumpModel) -> dict[str, np.ndarray]:
    """Run every candidate to the target stroke (or t_end). Returns
    {output: ndarray (n_cand,)} for each of OUTPUTS; the mean speed is the
    travel over the whole pumping cycles it took (the cycle that finishes
    the stroke counted whole: the pump delivers in bursts)."""
    P = model.matrix().copy()
    auto = P[:, IDX["dt"]] <= 0
    P[auto, IDX["dt"]] = stable_step(P)[auto]
    out = np.zeros((P.shape[0], len(OUTPUTS)))
    _run(P, out)
    return {name: out[:, i] for i, name in enumerate(OUTPUTS)}
