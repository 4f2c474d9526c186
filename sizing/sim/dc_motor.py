"""Closed-loop simulation of the DC motor lead-screw actuator (seed sec. 3).

A discrete PID at the controller rate (1.25 kHz in the seed) sets the motor
current from the reference and the measured position; the current is held
over each period and clipped at the current limit (conditional integration
stops wind-up: ``_integrate``). The drive's bus voltage U adds the back-EMF ceiling
(docs/models.md, DC motor actuator): when the held current would need more than U
(R i + k_e omega > U) the motor is voltage-driven for that period,
i = (U - k_e omega) / R, which turns eq. 13 into the same linear form with
the pole c1 - c2 k_e / R and input U / R; so the speed can never pass
(U - R i_load) / k_e. c1 itself stays the current-driven pole (viscous
only): the seed identified it with the drive's current loop closed. With
U = inf (the default) the model is the seed's eq. 13-14 unchanged. The
proportional term may act on the measurement instead of the error (I-PD,
``proportional_on_measurement``), which removes the closed loop's zeros. The plant is advanced over the period with the exact
zero-order-hold solution of eq. 13 (eq. 14 for the velocity), with the load
current of docs/models.md and optional Coulomb friction (Karnopp: a piston at
rest stays at rest while the net current is inside the friction band).
Two forms of the diagnose library add fields, inert at their
defaults (the traces are then bit-identical): ``drive_current_limit``, a
limit of the drive on the actual motor current that the controller does not
know (the motor gets the clipped current, the recorded ``current_A`` is the
command, the integrator winds up), and a Stribeck friction curve,
``static_friction`` (breakaway, N) above ``coulomb_friction`` falling over
``stribeck_velocity`` (m/s), F(v) = F_c + (F_s - F_c) exp(-(v/v_s)^2), taken at
the speed at the start of each interval; a piston at rest breaks away at F_s;
and ``loop_backlash`` (m, total width), a play between the screw and the
measured output *inside* the loop: the controller closes on the measured
(load-side) position, which follows the motor through a play operator
updated at each sample, so at a reversal the motor crosses the gap while
the measurement stands still (with the loop closed on the motor's encoder
instead, a play is a post-processing of the output: the diagnosis's
``backlash`` forms "play" and "coasting"). The reported position is the
measured one. ``integrate_to_limit`` (inert at 0) changes the anti-wind-up:
where a step of the integrator would carry the command past the current
limit, it takes the part that brings the command to the limit (instead of
none), so the closed loop is a continuous function of its parameters and
reference. ``simulate(heat=True)`` also returns the integral of the square
of the current flowing in the motor (the held current, or (U - k_e w) / R
while voltage-driven, integrated in closed form), accumulated over every
control period: an RMS read from it does not depend on the output grid.
Many candidates run at once; positions are reported from the rest position.
"""
from __future__ import annotations

from dataclasses import dataclass

import numba
import numpy as np

from ..errors import SimulationError
from . import PARALLEL_LAUNCH
from .params import ParameterSet

PARAMS = (
    "c1", "c2", "lead", "rate", "kp", "ki", "kd", "derivative_on_measurement",
    "current_limit", "load_force", "load_stiffness", "efficiency", "torque_constant",
    "coulomb_friction", "proportional_on_measurement", "bus_voltage", "back_emf_constant",
    "winding_resistance", "drive_current_limit", "static_friction", "stribeck_velocity", "loop_backlash",
    "integrate_to_limit",
)
CHANNELS = ("position_m", "velocity_m_s", "current_A")
HEAT = "current_squared_integral_A2s"   # the optional output of ``simulate(heat=True)``


@dataclass
class DCMotorModel(ParameterSet):
    PARAMS = PARAMS  # the kernel's column order
    """Parameters (float or (n_cand,) array), SI: c1 1/s, c2 rad/(s^2 A),
    lead m, rate Hz, kp A/m, ki A/(m s), kd A s/m, current_limit A, load N and
    N/m, efficiency -, torque_constant N m/A, coulomb_friction N,
    bus_voltage V (inf: no ceiling), back_emf_constant V s/rad (bus-referred),
    winding_resistance ohm, drive_current_limit A (inf: none),
    static_friction N (<= coulomb_friction: none), stribeck_velocity m/s,
    loop_backlash m (total play inside the loop; 0: none),
    integrate_to_limit (1: the integrator takes the part of a step that
    keeps the command within the current limit; 0: the whole step or
    none). ``lead`` is output metres per motor radian x 2 pi
    (screw lead / gear ratio)."""

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
    proportional_on_measurement: object = 0.0
    bus_voltage: object = np.inf
    back_emf_constant: object = 0.0
    winding_resistance: object = 1.0
    drive_current_limit: object = np.inf
    static_friction: object = 0.0
    stribeck_velocity: object = 0.0
    loop_backlash: object = 0.0
    integrate_to_limit: object = 0.0


@numba.njit(cache=True)
def _plant_step(y, v, u, a, b, a_y, b_y, c1, g, Ts, i_fric, i_stick):
    """Advance eq. 13 over one hold period with net current u (before
    friction): running friction i_fric, breakaway i_stick (>= i_fric; equal
    for Coulomb friction). Returns y, v."""
    if i_fric > 0.0:
        if v == 0.0 and abs(u) <= i_stick:
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
def _zoh(c1, g, Ts):
    a = np.exp(c1 * Ts)
    phi = (a - 1.0) / c1 if c1 != 0.0 else Ts
    psi = (phi - Ts) / c1 if c1 != 0.0 else Ts * Ts / 2
    return a, phi * g, phi, psi * g


@numba.njit(cache=True)
def _hit_time(v0, v_star, c, g, u):
    """Time at which v' = c v + g u, v(0) = v0, reaches v_star (inf if never)."""
    if c != 0.0:
        v_ss = -g * u / c
        ratio = (v_star - v_ss) / (v0 - v_ss) if v0 != v_ss else -1.0
        if ratio <= 0.0:
            return np.inf
        t = np.log(ratio) / c
        return t if t >= 0.0 else np.inf
    if g * u == 0.0:
        return np.inf
    t = (v_star - v0) / (g * u)
    return t if t >= 0.0 else np.inf


@numba.njit(cache=True)
def _friction_level(v, i_fric, i_stat, v_s):
    """Friction current at speed v: Coulomb i_fric, or with a Stribeck
    curve (v_s > 0, i_stat > i_fric) i_fric + (i_stat - i_fric) exp(-(v/v_s)^2),
    evaluated at the speed at the start of the step. Returns (running, breakaway)."""
    if v_s > 0.0 and i_stat > i_fric:
        r = v / v_s
        return i_fric + (i_stat - i_fric) * np.exp(-r * r), i_stat
    return i_fric, i_fric


@numba.njit(cache=True)
def _exp_square_integral(i0, i1, c, T):
    """Integral over [0, T] of i(t)^2 where i(t) = A + B exp(c t) runs from
    i0 to i1 (the voltage-driven current: the speed relaxes exponentially
    with the pole c, and i = (U - k_e w) / R is affine in it)."""
    cT = c * T
    if abs(cT) < 1e-6:          # linear within rounding: the mean square of a ramp
        return T * (i0 * i0 + i0 * i1 + i1 * i1) / 3.0
    e = np.exp(cT)
    B = (i1 - i0) / (e - 1.0)
    A = i0 - B
    return A * A * T + 2.0 * A * B * (e - 1.0) / c + B * B * (e * e - 1.0) / (2.0 * c)


@numba.njit(cache=True)
def _advance(y, v, i, dt, c1, c1v, g, load_i, i_fric, U, ke, Rw, to_speed, limited, i_stat, v_s):
    """Advance the plant over dt with the drive holding current i, except
    where the bus voltage cannot push it: then the motor is voltage-driven
    (i = (U - k_e w) / R) from the instant R i + k_e w reaches U.
    Returns y, v, the current flowing at the end and the integral of the
    square of the current flowing over dt (A^2 s: exact while the speed
    relaxes freely; a stop by friction inside a voltage-driven stretch
    is not followed)."""
    if not limited:
        a, b, a_y, b_y = _zoh(c1, g, dt)
        f_run, f_stick = _friction_level(v, i_fric, i_stat, v_s)
        y, v = _plant_step(y, v, i - load_i, a, b, a_y, b_y, c1, g, dt, f_run, f_stick)
        return y, v, i, i * i * dt
    need = Rw * i + ke * v * to_speed
    if abs(need) <= U:
        # current-driven until the needed voltage reaches the bus
        sgn = 1.0 if (i > 0.0 or (i == 0.0 and v >= 0.0)) else -1.0
        v_star = (sgn * U - Rw * i) / ke / to_speed
        t_hit = _hit_time(v, v_star, c1, g, i - load_i)
        t1 = min(t_hit, dt)
        a, b, a_y, b_y = _zoh(c1, g, t1)
        f_run, f_stick = _friction_level(v, i_fric, i_stat, v_s)
        y, v = _plant_step(y, v, i - load_i, a, b, a_y, b_y, c1, g, t1, f_run, f_stick)
        if t_hit >= dt:
            return y, v, i, i * i * dt
        sq = i * i * t1
        dt = dt - t1
        v = v_star
    else:
        sq = 0.0
    V_app = U if Rw * i + ke * v * to_speed > 0.0 else -U
    i0 = (V_app - ke * v * to_speed) / Rw
    a, b, a_y, b_y = _zoh(c1v, g, dt)
    f_run, f_stick = _friction_level(v, i_fric, i_stat, v_s)
    y, v = _plant_step(y, v, V_app / Rw - load_i, a, b, a_y, b_y, c1v, g, dt, f_run, f_stick)
    i1 = (V_app - ke * v * to_speed) / Rw
    return y, v, i1, sq + _exp_square_integral(i0, i1, c1v, dt)


@numba.njit(cache=True)
def _play(o, y, half):
    """The measured (load) position o after the motor moves to y through a
    play of half-width ``half``: it moves only when the motor pushes it."""
    if y - o > half:
        return y - half
    if o - y > half:
        return y + half
    return o


@numba.njit(cache=True)
def _interp(x, xp, fp):
    """``np.interp(x, xp, fp)`` for one x (``xp`` non-decreasing, as long as
    ``fp``, not empty), bit for bit, without the three arrays numba's
    ``np.interp`` makes for a scalar at every controller tick: the same
    segment (the last sample at or before x, which numpy's search finds
    whatever its guess) and the same formula."""
    n = xp.shape[0]
    if np.isnan(x):
        return x
    j = np.searchsorted(xp, x, side="right") - 1
    if j < 0:
        return fp[0]
    if j >= n - 1 or xp[j] == x:
        return fp[j]
    slope = (fp[j + 1] - fp[j]) / (xp[j + 1] - xp[j])
    r = slope * (x - xp[j]) + fp[j]
    if np.isnan(r):                 # nan one way: the other way, then the flat segment's value
        r = slope * (x - xp[j + 1]) + fp[j + 1]
        if np.isnan(r) and fp[j] == fp[j + 1]:
            r = fp[j]
    return r


@numba.njit(cache=True)
def _integrate(integ, err, Ts, i_try, ki, i_max, to_limit):
    """The integrator after a controller tick of error ``err`` and period
    ``Ts``, ``i_try`` the command with the whole step e Ts taken: the
    anti-wind-up at the current limit ``i_max``. Conditional integration
    takes the whole step while the command stays inside the limit or the
    error brings it back, else none; with ``to_limit`` a step that would
    carry the command past the limit takes the part that brings it to the
    limit instead of none. Two rules on purpose: conditional integration
    stands for the built-in PID of a catalog actuator or a test rig, whose
    rule neither the catalog nor rig.toml states (assumed: the common one;
    the shipped campaigns were synthesised with it); the designs sized from
    parts have the controller this tool specifies, and integrating to the
    limit makes their loop, and every simulated margin, continuous in the
    requirements (the whole-or-nothing rule jumps by ki e Ts where it
    switches)."""
    if abs(i_try) < i_max or i_try * err < 0.0:
        return integ + err * Ts
    if to_limit and ki != 0.0:
        room = ((i_max if i_try > 0.0 else -i_max) - (i_try - ki * err * Ts)) / ki
        if room * err > 0.0:
            return integ + room
    return integ


@numba.njit(cache=True)
def _simulate_one(p, t_ref, r_row, t_out, rec, heat):
    c1, c2, lead, rate, kp, ki, kd = p[0], p[1], p[2], p[3], p[4], p[5], p[6]
    d_meas, i_max, F0, kL, eta, kt, Fc = p[7], p[8], p[9], p[10], p[11], p[12], p[13]
    p_meas, U, ke, Rw = p[14], p[15], p[16], p[17]
    i_drv, Fs, v_s, half = p[18], p[19], p[20], 0.5 * p[21]
    to_limit = p[22] > 0.5
    Ts = 1.0 / rate
    g = lead / (2.0 * np.pi) * c2
    limited = U < np.inf and ke > 0.0
    c1v = c1 - c2 * ke / Rw if limited else c1          # voltage-driven pole
    to_speed = 2.0 * np.pi / lead                        # motor rad/s per m/s
    to_current = lead / (2.0 * np.pi * eta * kt)     # A per N at the output
    i_fric = Fc * to_current
    i_stat = Fs * to_current                             # Stribeck breakaway (0: Coulomb only)
    y, v = 0.0, 0.0
    m = y           # the measured position (behind the play; y without one)
    # rest under the load: the integrator already holds the load current
    integ = (F0 * to_current / ki) if ki != 0.0 else 0.0
    e_prev = _interp(t_out[0], t_ref, r_row) - y
    y_prev = y
    t = t_out[0]
    i = ki * integ          # the holding current, so the rest is a rest
    sq = 0.0                # integral of the square of the current flowing since t_out[0], A^2 s
    j = 0
    n_out = t_out.shape[0]
    while j < n_out:
        load_i = (F0 + kL * y) * to_current
        # a drive current limit the controller does not know: the motor
        # gets the clipped current, the logged current is the command
        i_act = min(max(i, -i_drv), i_drv)
        drive_clipped = i_act != i
        # record every output time that falls inside this control period
        while j < n_out and t_out[j] < t + Ts - 1e-12:
            tau = t_out[j] - t
            if tau <= 0.0:
                rec[0, j], rec[1, j], rec[2, j] = m, v, i
                if heat:
                    rec[3, j] = sq
            else:
                rec[0, j], rec[1, j], rec[2, j], sq_tau = _advance(y, v, i_act, tau, c1, c1v, g, load_i, i_fric,
                                                                  U, ke, Rw, to_speed, limited, i_stat, v_s)
                if heat:
                    rec[3, j] = sq + sq_tau
                if half > 0.0:
                    rec[0, j] = _play(m, rec[0, j], half)
                if drive_clipped:
                    rec[2, j] = i
            j += 1
        if j >= n_out:
            break
        # controller tick at time t + Ts: sample, compute, hold
        y, v, _, sq_Ts = _advance(y, v, i_act, Ts, c1, c1v, g, load_i, i_fric, U, ke, Rw, to_speed, limited,
                                  i_stat, v_s)
        sq += sq_Ts
        t += Ts
        m = _play(m, y, half) if half > 0.0 else y
        r = _interp(t, t_ref, r_row)
        err = r - m
        deriv = -(m - y_prev) / Ts if d_meas > 0.5 else (err - e_prev) / Ts
        prop = -m if p_meas > 0.5 else err
        i_try = kp * prop + ki * (integ + err * Ts) + kd * deriv
        integ = _integrate(integ, err, Ts, i_try, ki, i_max, to_limit)
        i_new = kp * prop + ki * integ + kd * deriv
        i = min(max(i_new, -i_max), i_max)
        e_prev, y_prev = err, m
    return rec


@numba.njit(cache=True, parallel=True, nogil=True)   # nogil: stages run in threads (sim/__init__.py)
def _simulate(P, t_ref, R, t_out, r_stride, heat):
    n_cand = P.shape[0]
    out = np.empty((n_cand, 4 if heat else 3, t_out.shape[0]))
    for c in numba.prange(n_cand):
        _simulate_one(P[c], t_ref, R[c * r_stride], t_out, out[c], heat)
    return out


def simulate(model: DCMotorModel, t_ref, reference, t_out=None, heat=False) -> dict[str, np.ndarray]:
    """Simulate each candidate following ``reference`` (m) given at t_ref (s).
    Returns {channel: (n_cand, n_out)} for CHANNELS; with ``heat``, also
    HEAT: the integral from t_out[0] of the square of the current flowing
    in the motor (A^2 s), accumulated over every control period whatever
    the output grid (the held current, or the voltage-driven current
    (U - k_e w) / R integrated in closed form), so an RMS current read
    from it does not alias the controller's staircase."""
    P = model.matrix()
    t_ref = np.ascontiguousarray(t_ref, dtype=float)
    R = np.ascontiguousarray(np.atleast_2d(np.asarray(reference, dtype=float)))
    t_out = t_ref if t_out is None else np.ascontiguousarray(t_out, dtype=float)
    with PARALLEL_LAUNCH:         # one parallel kernel at a time (sim/__init__.py)
        out = _simulate(P, t_ref, R, t_out, np.int64(R.shape[0] > 1), bool(heat))
    bad = ~np.all(np.isfinite(out), axis=(1, 2))
    if bad.any():
        raise SimulationError(f"simulation diverged for candidates {np.flatnonzero(bad).tolist()}")
    names = CHANNELS + ((HEAT,) if heat else ())
    return {name: out[:, i, :] for i, name in enumerate(names)}
