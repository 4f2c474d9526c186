"""Cycle-resolved simulation of the piezohydraulic pump, many candidates at once.

Model (docs/models.md, "Piezo pump"; the equations P1-P8 of physics/pump.py):
- stacks: a sine drive 0..V at the pumping frequency f, non-symmetric
  Bouc-Wen free displacement (seed eqs. 1-2, ``hysteresis_step``) scaled by
  the temperature derating, behind the stacks' stiffness K; the pump piston
  is quasi-static (its mass is negligible against K at f), so the chamber
  takes C dp = A_p dx_f - (Q_out - Q_in + Q_leak) dt with
  C = V_c / beta_e(p) + A_p^2 / K; below vapour pressure the chamber holds a
  vapour volume that the next compression collapses before the oil is
  compressed again;
- reed check valves (P3, P5): each reed a mass-spring-damper (its wetted
  mass, ``reed_mass``; 0 gives the quasi-static reed of P3) pushed by the
  pressure difference over its port, seated at 0 and stopped at its lift;
  the flow through the open curtain is an orifice in either direction, so a
  reed that closes late lets oil flow back;
- the line (P6): the oil in the line from the pump to the cylinder moves
  with the piston, a mass rho L A_c^2 / A_line on the load, and its laminar
  resistance a viscous force A_c^2 R_line u;
- output cylinder: the high side is an oil volume A_c (l_0 + y) plus the
  line's with the effective bulk modulus at its pressure; the low side and
  the inlet sit at the accumulator's bias pressure p_b; the piston leaks
  G (p_h - p_b) past its clearance (P7); the load mass m moves under
  (p_h - p_b) A_c - F_load and Karnopp seal friction pi D (f_0 + c_p p_h).

Integration, every step implicit in the coupled pressures: the high side
and the load advance by the trapezoidal rule (no numerical damping of the
load's ringing, which a converged mean speed needs); the chamber by
backward Euler; the outlet flow couples them. With the reed areas of the
step fixed, the chamber's volume balance is monotone in the outlet's
pressure difference and is solved by a bracketed secant (Illinois), so a
wide-open valve cannot make a step unstable. The reeds advance
semi-implicitly (backward Euler in their own stiffness and damping, the
pressure of the step's start). Fixed step: at least STEPS_PER_CYCLE steps a
pumping cycle, LOAD_STEP / omega of the load on the high-side oil and
REED_STEP of a reed's wetted period. The run stops when the output reaches
the target stroke.
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
    "reed_mass", "reed_damping_ratio", "line_mass", "line_damping", "line_volume",
    "piston_leakage", "pump_leakage", "vapour_pressure", "air_dissolution_pressure", "viscosity", "seat_width",
    "seat_gap",
)
IDX = {name: i for i, name in enumerate(PARAMS)}
OUTPUTS = ("stroke_m", "time_to_stroke_s", "mean_speed_m_s", "cycles", "pumped_volume_m3", "delivered_volume_m3",
           "peak_chamber_pressure_Pa", "peak_cylinder_pressure_Pa", "reached", "backflow_volume_m3",
           "vapour_volume_m3", "dt_s", "stack_work_J", "output_work_J", "free_stroke_m",
           "quasi_static_bound_J")
STEPS_PER_CYCLE = 100
LOAD_STEP = 0.2          # x 1 / omega of the load on the high-side oil
REED_STEP = 1.0 / 30.0   # x the reed's wetted period
P_ATM = 101325.0
POLYTROPIC = 1.4
ROOT_TOLERANCE = 0.5     # Pa on the outlet's pressure difference
ROOT_ITERATIONS = 80
# The step's functions are inlined into the kernel by numba (``inline="always"``),
# not left to LLVM: the chamber's root solve calls them a dozen times a step,
# and inlined the seed's pump simulations take 10 % less CPU. Inlining moves
# no operation (no fast-math, no contraction): the results are the same to
# the bit (benchmarks/fast_solve_parts.py checks it).


@dataclass
class PumpModel(StackParameters):
    """Parameters of the cycle-resolved model, floats or arrays (n_cand,), SI:
    N/m, m/V, V, Hz, m^2, m^3, Pa (gauge), kg, N, N/m (seal friction per
    circumference), N/(m Pa). ``air_fraction``: free air at atmospheric
    pressure; ``wall_compliance``: D / (E t) of the chamber and cylinder, 1/Pa.
    ``reed_mass``: a reed's wetted moving mass (kg, 0: quasi-static reeds),
    ``reed_damping_ratio`` its damping; ``line_mass`` (kg) and
    ``line_damping`` (N s/m): the line's oil as the load feels it;
    ``line_volume`` (m^3) joins the high side; ``piston_leakage`` and
    ``pump_leakage`` (m^3/(s Pa)): the cylinder's piston from the high to the
    low side, the pump piston from the chamber to the low side;
    ``vapour_pressure``: gauge, Pa; ``air_dissolution_pressure``: absolute,
    Pa, where the free air has all dissolved (P8)."""

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
    dt: object = 0.0         # <= 0: chosen from the frequency, the load mode and the reeds
    reed_mass: object = 0.0
    reed_damping_ratio: object = 0.0
    line_mass: object = 0.0
    line_damping: object = 0.0
    line_volume: object = 0.0
    piston_leakage: object = 0.0
    pump_leakage: object = 0.0
    vapour_pressure: object = 3e3 - P_ATM
    air_dissolution_pressure: object = np.inf    # absolute, Pa: all free air dissolved (P8); inf: none
    viscosity: object = 0.0      # dynamic, Pa s: the reeds' laminar resistance (P9); 0: orifice only
    seat_width: object = 0.0     # m, the land the oil crosses under a reed
    seat_gap: object = 0.0       # m, the gap a seated reed leaves (its leak, P7)


@numba.njit(cache=True, error_model="numpy", inline="always")
def _beta(p, bulk, a0, wall, pd):
    """Eq. P2 with the air's dissolution (P8) at gauge pressure p."""
    pa = max(p + P_ATM, 1e3)
    r = (P_ATM / pa) ** (1.0 / POLYTROPIC)
    share = 1.0
    dissolving = 0.0
    if pd < 1e300 and pa > P_ATM:
        share = max((pd - pa) / (pd - P_ATM), 0.0)
        if pa < pd:
            dissolving = a0 / (pd - P_ATM)
    va = a0 * share * r
    c = ((1.0 - a0) / bulk + dissolving * r + va / (POLYTROPIC * pa)) / (1.0 - a0 + va)
    return 1.0 / (c + wall)


@numba.njit(cache=True, error_model="numpy", inline="always")
def _quasi_static_lift(dp, pcr, Av, kv, lift):
    """P3: the lift of a massless reed."""
    return min(max((dp - pcr) * Av / kv, 0.0), lift)


@numba.njit(cache=True, error_model="numpy", inline="always")
def _reed(x, w, dp, pcr, Av, kv, mv, cv, lift, dt):
    """P5: one backward-Euler step of a reed (mass mv, stiffness kv preloaded
    to pcr, damping cv) under the pressure dp on its port; an impact on the
    seat or the stop stops it. Returns (lift, velocity)."""
    x1 = (x * (1.0 + dt * cv / mv) + dt * w + dt * dt * Av * (dp - pcr) / mv) / (1.0 + dt * cv / mv + dt * dt * kv / mv)
    if x1 <= 0.0:
        return 0.0, 0.0
    if x1 >= lift:
        return lift, 0.0
    return x1, (x1 - x) / dt


@numba.njit(cache=True, error_model="numpy", inline="always")
def _valve_q(x, dp, V):
    """Flow through a reed valve at lift x (x < 0: the quasi-static reed's
    lift at dp) under dp, either way (P3, P9): its curtain's laminar
    resistance 12 mu w / (pi d x^3) in series with the orifice of area
    min(pi d x, A_v), dp = R Q + Q |Q| / k^2 solved for Q. A seated reed
    leaves its seat's gap (P7). V: korif, pcr, Av, kv, lift, dport,
    12 mu w / (pi d), seat gap."""
    if x < 0.0:
        x = _quasi_static_lift(dp, V[1], V[2], V[3], V[4])
    x = max(x, V[7])
    if x <= 0.0:
        return 0.0
    k = V[0] * min(np.pi * V[5] * x, V[2])
    rl = V[6] / (x * x * x)
    a = abs(dp)
    q = 2.0 * a / (rl + np.sqrt(rl * rl + 4.0 * a / (k * k)))
    return q if dp >= 0.0 else -q


@numba.njit(cache=True, error_model="numpy", inline="always")
def _residual(d, alpha, gamma, xo, xi, V, C, p, dVeff, dt, pb, Gp):
    """The chamber's volume balance at an outlet pressure difference d, with
    the high side at alpha + gamma Q_out: C (p1 - p) - dV + dt (Q_out - Q_in +
    Q_leak), increasing in d. Returns (residual, p1, Q_out, Q_in)."""
    qo = _valve_q(xo, d, V)
    p1 = d + alpha + gamma * qo
    qi = _valve_q(xi, pb - p1, V)
    return C * (p1 - p) - dVeff + dt * (qo - qi + Gp * (p1 - pb)), p1, qo, qi


@numba.njit(cache=True, error_model="numpy", inline="always")
def _solve_chamber(alpha, gamma, xo, xi, V, C, p, dVeff, dt, pb, Gp):
    """The root of ``_residual`` in d: bracketed, then Illinois regula falsi.
    Returns (p1, Q_out, Q_in). ``xo``, ``xi``: the reeds' lifts over the
    step, or -1 for a quasi-static reed (``_valve_q``)."""
    d0 = p + dVeff / C - alpha                   # both valves shut, no leak
    r0, p1, qo, qi = _residual(d0, alpha, gamma, xo, xi, V, C, p, dVeff, dt, pb, Gp)
    if r0 == 0.0:
        return p1, qo, qi
    step = 1e3 + 1e-3 * abs(d0)
    lo, rlo, hi, rhi = d0, r0, d0, r0
    for _ in range(200):
        if r0 > 0.0:
            lo = lo - step
            rlo = _residual(lo, alpha, gamma, xo, xi, V, C, p, dVeff, dt, pb, Gp)[0]
            if rlo <= 0.0:
                break
        else:
            hi = hi + step
            rhi = _residual(hi, alpha, gamma, xo, xi, V, C, p, dVeff, dt, pb, Gp)[0]
            if rhi >= 0.0:
                break
        step *= 4.0
    side = 0
    for _ in range(ROOT_ITERATIONS):
        if hi - lo <= ROOT_TOLERANCE:
            break
        mid = (lo * rhi - hi * rlo) / (rhi - rlo)
        if not (lo < mid < hi):
            mid = 0.5 * (lo + hi)
        r = _residual(mid, alpha, gamma, xo, xi, V, C, p, dVeff, dt, pb, Gp)[0]
        if r == 0.0:
            lo = hi = mid
            break
        if r > 0.0:
            hi, rhi = mid, r
            if side == 1:
                rlo *= 0.5
            side = 1
        else:
            lo, rlo = mid, r
            if side == -1:
                rhi *= 0.5
            side = -1
    _, p1, qo, qi = _residual(0.5 * (lo + hi), alpha, gamma, xo, xi, V, C, p, dVeff, dt, pb, Gp)
    return p1, qo, qi


@numba.njit(cache=True, error_model="numpy", inline="always")
def _high_side(a, ph, u, dt, Ac, m, c, G, pb, F, Ff, s, stuck):
    """The high side and the load over a step, trapezoidal: the end pressure
    is alpha + gamma Q_out (the outlet flow Q_out over the step).
    Returns (alpha, gamma, e, B)."""
    if stuck:
        D = a + 0.5 * dt * G
        return (a * ph - dt * G * (0.5 * ph - pb)) / D, dt / D, 1.0, 0.0
    e = 1.0 + 0.5 * dt * c / m
    B = 0.5 * Ac * ph - Ac * pb - F - Ff * s
    D = a + 0.5 * dt * G + dt * dt * Ac * Ac / (4.0 * m * e)
    alpha = (a * ph - dt * Ac / e * (u + 0.5 * dt * B / m) - dt * G * (0.5 * ph - pb)) / D
    return alpha, dt / D, e, B


# nogil: the solve runs this stage beside the others (``Technology.alongside``)
@numba.njit(cache=True, error_model="numpy", nogil=True)
def _run(P, out):
    for c in range(P.shape[0]):
        row = P[c]
        K, d33, al, be, ga, de, nb, scale = row[0], row[1], row[2], row[3], row[4], row[5], row[6], row[7]
        V, f, Ap, Vc, bulk, a0, wall, rho = row[8], row[9], row[10], row[11], row[12], row[13], row[14], row[15]
        pcr, Av, kv, lift, cd = row[16], row[17], row[18], row[19], row[20]
        pb, Ac, l0, m0, F, f0, cp = row[21], row[22], row[23], row[24], row[25], row[26], row[27]
        S, t_end, dt = row[28], row[29], row[30]
        mv, zv, m_line, c_line, V_line, G, Gp, pvap = (row[31], row[32], row[33], row[34], row[35], row[36],
                                                      row[37], row[38])
        pdis, mu, seat = row[39], row[40], row[41]
        m = m0 + m_line
        cv = 2.0 * zv * np.sqrt(kv * mv) if mv > 0.0 else 0.0
        dport = np.sqrt(4.0 * Av / np.pi)
        korif = cd * np.sqrt(2.0 / rho)
        Vq = np.array([korif, pcr, Av, kv, lift, dport, 12.0 * mu * seat / (np.pi * dport), row[42]])
        perim = 2.0 * np.sqrt(np.pi * Ac)
        n_steps = int(t_end / dt) + 1
        p = pb
        ph = pb + F / Ac
        y = 0.0
        u = 0.0
        h = 0.0
        v0 = 0.0
        xf0 = 0.0
        xo, wo, xi, wi = 0.0, 0.0, 0.0, 0.0
        vap = 0.0
        pumped = 0.0
        delivered = 0.0
        back = 0.0
        vap_max = 0.0
        work = 0.0             # by the stacks, the integral of p dV, and by the output on the load
        out_work = 0.0
        xf_lo, xf_hi = 0.0, 0.0
        cyc_lo, cyc_hi = 0.0, 0.0      # the free stroke's range within the running cycle
        bound = 0.0            # the quasi-static work bound K x_f^2 / 4, summed over the cycles run
        p_max = p
        ph_max = ph
        t = 0.0
        reached = 0.0
        n_cycles = 0           # whole pumping cycles done, and the output's travel at the last one's end
        y_cycles = 0.0
        for k in range(n_steps):
            t = (k + 1) * dt
            v1 = 0.5 * V * (1.0 - np.cos(2.0 * np.pi * f * t))
            h = hysteresis_step(h, v0, v1, dt, al, be, ga, de, nb)
            xf1 = scale * (d33 * v1 + h)
            dV = Ap * (xf1 - xf0)
            if dV > 0.0:
                pumped += dV
            # the reeds over this step, pushed by the pressures at its start
            if mv > 0.0:
                xo, wo = _reed(xo, wo, p - ph, pcr, Av, kv, mv, cv, lift, dt)
                xi, wi = _reed(xi, wi, pb - p, pcr, Av, kv, mv, cv, lift, dt)
                so, si = xo, xi
            else:                                 # quasi-static reeds: their lift at the step's end
                so, si = -1.0, -1.0
            C = Vc / _beta(p, bulk, a0, wall, pdis) + Ap * Ap / K
            a = (Ac * (l0 + max(y, 0.0)) + V_line) / _beta(ph, bulk, a0, wall, pdis)
            Ff = perim * (f0 + cp * abs(ph))
            # the load: sliding in the direction it moves (or would move), or stuck
            stuck = u == 0.0 and abs((ph - pb) * Ac - F) <= Ff
            s = 1.0 if u > 0.0 else (-1.0 if u < 0.0 else (1.0 if (ph - pb) * Ac - F > 0.0 else -1.0))
            for attempt in range(2):
                alpha, gamma, e, B = _high_side(a, ph, u, dt, Ac, m, c_line, G, pb, F, Ff, s, stuck)
                p1, qo, qi = _solve_chamber(alpha, gamma, so, si, Vq, C, p, dV - vap, dt, pb, Gp)
                vap1 = 0.0
                if p1 < pvap:                     # the chamber cavitates: vapour takes the deficit
                    p1 = pvap
                    # the outlet at the cavitating chamber (shut when quasi-static): its
                    # orifice's closed form with the high side's rise, then its full law once
                    q0 = _outlet_at(korif * min(np.pi * dport * max(so, 0.0), Av), pvap - alpha, gamma)
                    qo = _valve_q(max(so, 0.0), pvap - alpha - gamma * q0, Vq)
                    qi = _valve_q(si, pb - pvap, Vq)
                    vap1 = C * (pvap - p) - (dV - vap) + dt * (qo - qi + Gp * (pvap - pb))
                ph1 = alpha + gamma * qo
                if stuck:
                    u1 = 0.0
                    net = (ph1 - pb) * Ac - F
                    if abs(net) > Ff and attempt == 0:   # breaks away within the step
                        stuck = False
                        s = 1.0 if net > 0.0 else -1.0
                        continue
                    break
                u1 = (u * (2.0 - e) + dt / m * (B + 0.5 * Ac * ph1)) / e
                if u != 0.0 and u1 * u < 0.0 and attempt == 0:   # friction stops it within the step
                    stuck = True
                    continue
                break
            y_start = y
            y += 0.5 * dt * (u + u1)
            work += 0.5 * (p + p1) * dV
            out_work += F * (y - y_start)
            xf_lo, xf_hi = min(xf_lo, xf1), max(xf_hi, xf1)
            cyc_lo, cyc_hi = min(cyc_lo, xf1), max(cyc_hi, xf1)
            if np.floor(t * f + 1e-9) > n_cycles:            # a cycle ends within the step
                n_cycles += 1
                y_cycles = y_start + (y - y_start) * (n_cycles / f - (t - dt)) / dt
                bound += 0.25 * K * (cyc_hi - cyc_lo) ** 2
                cyc_lo, cyc_hi = xf1, xf1
            delivered += qo * dt
            if qo < 0.0:
                back -= qo * dt
            if qi < 0.0:
                back -= qi * dt
            u = u1
            p = p1
            ph = ph1
            vap = vap1
            vap_max = max(vap_max, vap)
            v0 = v1
            xf0 = xf1
            p_max = max(p_max, p)
            ph_max = max(ph_max, ph)
            if y >= S:
                reached = 1.0
                break
        out[c, 0] = y
        out[c, 1] = t
        out[c, 2] = y_cycles * f / n_cycles if n_cycles > 0 else y / t     # over whole pumping cycles
        out[c, 3] = f * t
        out[c, 4] = pumped
        out[c, 5] = delivered
        out[c, 6] = p_max
        out[c, 7] = ph_max
        out[c, 8] = reached
        out[c, 9] = back
        out[c, 10] = vap_max
        out[c, 11] = dt
        out[c, 12] = work
        out[c, 13] = out_work
        out[c, 14] = xf_hi - xf_lo
        out[c, 15] = bound + 0.25 * K * (cyc_hi - cyc_lo) ** 2


@numba.njit(cache=True, error_model="numpy")
def _outlet_at(k, d_free, gamma):
    """Outlet flow q = k sign(d) sqrt(|d|) with d = d_free - gamma q (the
    high side rises with what it takes): the closed form of that quadratic."""
    if k <= 0.0:
        return 0.0
    if d_free >= 0.0:
        # q^2 = k^2 (d_free - gamma q), q >= 0
        return 0.5 * (-k * k * gamma + np.sqrt(k**4 * gamma * gamma + 4.0 * k * k * d_free))
    # q^2 = k^2 (gamma q - d_free), q <= 0
    return 0.5 * (k * k * gamma - np.sqrt(k**4 * gamma * gamma - 4.0 * k * k * d_free))


def stable_step(P: np.ndarray) -> np.ndarray:
    """STEPS_PER_CYCLE steps a pumping cycle, LOAD_STEP / omega of the load
    mass (with the line's) on the high-side oil (at the oil's own modulus, the
    stiffest) and REED_STEP of the reed's wetted period."""
    col = lambda name: P[:, IDX[name]]             # noqa: E731
    Ac, m = col("cylinder_area"), col("load_mass") + col("line_mass")
    Vh = Ac * col("dead_length") + col("line_volume")
    omega = np.sqrt(col("bulk_modulus") * Ac**2 / (Vh * m))
    dt = np.minimum(1.0 / (STEPS_PER_CYCLE * col("frequency")), LOAD_STEP / omega)
    mv = col("reed_mass")
    reed = np.where(mv > 0, REED_STEP * 2 * np.pi * np.sqrt(np.where(mv > 0, mv, 1.0) / col("reed_stiffness")), np.inf)
    return np.minimum(dt, reed)


def simulate(model: PumpModel, step_factor: float = 1.0) -> dict[str, np.ndarray]:
    """Run every candidate to the target stroke (or t_end). Returns
    {output: ndarray (n_cand,)} for each of OUTPUTS; the mean speed is the
    travel over the whole pumping cycles done before the output reached the
    stroke (the pump delivers in bursts: a part cycle would count a burst
    without the rest of its cycle). ``step_factor``
    scales the automatic step (a convergence check halves it)."""
    P = model.matrix().copy()
    auto = P[:, IDX["dt"]] <= 0
    P[auto, IDX["dt"]] = step_factor * stable_step(P)[auto]
    out = np.zeros((P.shape[0], len(OUTPUTS)))
    _run(P, out)
    return {name: out[:, i] for i, name in enumerate(OUTPUTS)}
