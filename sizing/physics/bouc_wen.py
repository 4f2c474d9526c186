"""Non-symmetric Bouc-Wen hysteresis of a piezoelectric stack.

Source: ARL-TR-10251 eqs. 1-2, the seed's transcription of Zhu and Wang,
Sens. Actuators A 181 (2012) 51-60. Implemented exactly as the seed writes it
(docs/models.md, corrections to the seed, item 6):

    x_free = d33 v + h                                            (1)
    dh/dt  = {alpha - [beta sgn(v' h) + gamma] |h|^n} v'
             + delta v sgn(v')                                    (2)

Units are the seed's SI numbers: d33 and alpha in m/V, h in m, delta in
m/(V s); beta and gamma carry whatever makes |h|^n dimensionally consistent.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numba
import numpy as np


@dataclass(frozen=True)
class BoucWen:
    """Parameters of eq. 1-2 for one stack (SI)."""

    d33: float    # m/V, linear term of eq. 1
    alpha: float  # m/V
    beta: float
    gamma: float
    delta: float  # m/(V s)
    n: float

    def as_array(self) -> np.ndarray:
        return np.array([self.d33, self.alpha, self.beta, self.gamma, self.delta, self.n])

    @classmethod
    def from_array(cls, values) -> "BoucWen":
        return cls(*(float(v) for v in values))


# The loop keeps the same shape when voltage and displacement are both
# scaled. With v = V_max u and h = H g (H the stack's nominal stroke, so
# H / V_max = d_nom its nominal stroke per volt), eq. 2 becomes
#   dg = {alpha/d_nom - [beta H^n/d_nom sgn + gamma H^n/d_nom] |g|^n} du
#        + (delta/d_nom) u sgn dt
# so these five groups (and d33/d_nom for eq. 1) are what transfers between
# stacks. The notes take H = d33 V_max; we take the nominal (datasheet) stroke
# because it is the one quantity every datasheet gives, and it keeps the
# transferred stack's simulated stroke at its datasheet stroke.
def params_to_groups(theta, stroke: float, max_voltage: float) -> np.ndarray:
    """Dimensionless groups [d33/d, alpha/d, beta H^n/d, gamma H^n/d, delta/d, n]
    of parameters ``theta`` (..., 6) in the order of ``BoucWen.as_array``;
    H = ``stroke`` (m), d = H / ``max_voltage`` (m/V)."""
    theta = np.asarray(theta, float)
    d = stroke / max_voltage
    out = theta.copy()
    out[..., 0:2] = theta[..., 0:2] / d
    out[..., 2:4] = theta[..., 2:4] * stroke ** theta[..., 5:6] / d
    out[..., 4] = theta[..., 4] / d
    return out


def groups_to_params(groups, stroke: float, max_voltage: float) -> np.ndarray:
    """Inverse of ``params_to_groups``: parameters (..., 6) from groups (..., 6)."""
    z = np.asarray(groups, float)
    d = stroke / max_voltage
    out = z.copy()
    out[..., 0:2] = z[..., 0:2] * d
    out[..., 2:4] = z[..., 2:4] * d / stroke ** z[..., 5:6]
    out[..., 4] = z[..., 4] * d
    return out


def groups_jacobian(groups, stroke: float, max_voltage: float) -> np.ndarray:
    """d params / d groups (6, 6) of ``groups_to_params`` at ``groups`` (6,)."""
    z = np.asarray(groups, float)
    d = stroke / max_voltage
    T = np.zeros((6, 6))
    T[0, 0] = T[1, 1] = T[4, 4] = d
    T[2, 2] = T[3, 3] = d / stroke ** z[5]
    T[2, 5] = -z[2] * d / stroke ** z[5] * np.log(stroke)
    T[3, 5] = -z[3] * d / stroke ** z[5] * np.log(stroke)
    T[5, 5] = 1.0
    return T


def normalised_groups(params: BoucWen, nominal_stroke: float, max_voltage: float) -> np.ndarray:
    """Dimensionless groups [d33/d, alpha/d, beta H^n/d, gamma H^n/d, delta/d, n]."""
    return params_to_groups(params.as_array(), nominal_stroke, max_voltage)


def from_groups(groups: np.ndarray, nominal_stroke: float, max_voltage: float) -> BoucWen:
    """Inverse of ``normalised_groups`` for a stack of the given nominal stroke."""
    return BoucWen.from_array(groups_to_params(groups, nominal_stroke, max_voltage))


def transfer(params: BoucWen, source_stroke: float, source_vmax: float,
             target_stroke: float, target_vmax: float) -> BoucWen:
    """Carry measured parameters from one stack to another of similar
    material (docs/models.md, corrections to the seed, item 4): same dimensionless loop, new scales."""
    groups = normalised_groups(params, source_stroke, source_vmax)
    return from_groups(groups, target_stroke, target_vmax)


def linear(d33: float) -> BoucWen:
    """No hysteresis: x_free = d33 v."""
    return BoucWen(d33=d33, alpha=0.0, beta=0.0, gamma=0.0, delta=0.0, n=1.0)


def scaled(params: BoucWen, **changes: float) -> BoucWen:
    return replace(params, **changes)


@numba.njit(cache=True, error_model="numpy")
def hysteresis_step(h, v0, v1, dt, alpha, beta, gamma, delta, n, hold_rate=0.0):
    """Advance h over one sample in which v goes from v0 to v1 in dt seconds.
    Sub-steps keep the explicit update well inside its stability limit when
    the voltage jumps (the rate of eq. 2 scales with |h|^(n-1) |dv|).

    ``hold_rate`` (V/s, >= 0) is the deadband of sgn(v') in the delta term:
    a voltage moving slower than it is held, and the delta term, which adds
    delta v sgn(v') dt whatever the rate, is off. A measured voltage is never
    exactly flat in a hold (its noise, or the slope a fit leaves in it), and
    at 120 V the delta term turns that slope's sign into a drift of the
    output of the order of a millimetre a second. 0: the exact sign of eq. 2."""
    dv = v1 - v0
    if dv == 0.0:
        return h
    sgn_v = 1.0 if dv > 0.0 else -1.0
    if abs(dv) <= hold_rate * dt:
        delta = 0.0
    ah = abs(h)
    hn = ah ** n
    # |d(rate)/dh| |dv| = (|beta| + |gamma|) n |h|^(n-1) |dv|; |h|^n / |h|
    # reuses the one power this step needs anyway.
    scale = (abs(beta) + abs(gamma)) * n * (hn / ah if ah > 1e-12 else 0.0) * abs(dv)
    if scale <= 0.05:
        sgn_vh = sgn_v if h > 0.0 else (-sgn_v if h < 0.0 else 0.0)
        return h + (alpha - (beta * sgn_vh + gamma) * hn) * dv + delta * v0 * sgn_v * dt
    nsub = min(256, int(scale / 0.05) + 1)
    ddv = dv / nsub
    ddt = dt / nsub
    v = v0
    for _ in range(nsub):
        sgn_vh = sgn_v if h > 0.0 else (-sgn_v if h < 0.0 else 0.0)
        rate = alpha - (beta * sgn_vh + gamma) * abs(h) ** n
        h = h + rate * ddv + delta * v * sgn_v * ddt
        v += ddv
    return h


@numba.njit(cache=True)
def _free_displacement_batch(t, v, P, h0):
    n_cand = P.shape[0]
    n_t = t.shape[0]
    out = np.empty((n_cand, n_t))
    for c in range(n_cand):
        d33, alpha, beta, gamma, delta, n = P[c, 0], P[c, 1], P[c, 2], P[c, 3], P[c, 4], P[c, 5]
        h = h0[c]
        out[c, 0] = d33 * v[0] + h
        for k in range(n_t - 1):
            h = hysteresis_step(h, v[k], v[k + 1], t[k + 1] - t[k], alpha, beta, gamma, delta, n)
            out[c, k + 1] = d33 * v[k + 1] + h
    return out


def free_displacement(t: np.ndarray, v: np.ndarray, params, h0=0.0) -> np.ndarray:
    """Free displacement x_free (eq. 1) of a stack driven by v(t).

    t, v : ndarray (n_t,), s and V
    params : BoucWen, or ndarray (n_cand, 6) of [d33, alpha, beta, gamma, delta, n]
    h0 : float or ndarray (n_cand,), initial hysteresis state, m
    Returns ndarray (n_t,) for one BoucWen, else (n_cand, n_t), m.
    """
    single = isinstance(params, BoucWen)
    P = np.atleast_2d(params.as_array() if single else np.asarray(params, dtype=float))
    h0_arr = np.broadcast_to(np.asarray(h0, dtype=float), (P.shape[0],)).copy()
    out = _free_displacement_batch(np.asarray(t, float), np.asarray(v, float), P, h0_arr)
    return out[0] if single else out


# The delta term of eq. 2 integrates delta v sgn(v') over time, so a ramp's
# end stroke depends on how long the ramp takes (docs/models.md, piezo
# stack): the transferred model matches the datasheet stroke at one time
# scale only. These two functions say which, and what a design's own ramp gives.
def ramp_stroke(params: BoucWen, v_max: float, ramp_time: float, points: int = 4000) -> float:
    """Free stroke (m) at the end of a linear ramp 0 -> v_max lasting ramp_time (s)."""
    t = np.linspace(0.0, ramp_time, points)
    return float(free_displacement(t, v_max * t / ramp_time, params)[-1])


def matching_ramp_time(params: BoucWen, v_max: float, stroke: float, t_lo: float = 1e-3,
                       t_hi: float = 100.0) -> float:
    """Ramp time (s) at which the model's end stroke equals ``stroke`` (the
    datasheet's), by bisection in log time; nan when it is not bracketed."""
    f = lambda T: ramp_stroke(params, v_max, T) - stroke  # noqa: E731
    lo, hi = f(t_lo), f(t_hi)
    if lo * hi > 0:
        return float("nan")
    a, b = np.log(t_lo), np.log(t_hi)
    for _ in range(40):
        m = 0.5 * (a + b)
        if (f(np.exp(m)) > 0) == (lo > 0):
            a = m
        else:
            b = m
    return float(np.exp(0.5 * (a + b)))
