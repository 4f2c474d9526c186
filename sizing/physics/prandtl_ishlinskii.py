"""Prandtl-Ishlinskii hysteresis: a weighted sum of play (backlash) operators.

Source: M. Brokate and J. Sprekels, Hysteresis and Phase Transitions
(Springer 1996), ch. 2; for piezo stacks e.g. M. Al Janaideh et al.,
Sens. Actuators A 149 (2009) 32. Not in the seed: it is offered beside the
seed's Bouc-Wen model (eq. 2) as a second, linear-in-the-weights model.

    y_r(t) = max(v(t) - r, min(v(t) + r, y_r(t-)))     play operator, threshold r >= 0
    x(t)   = sum_i w_i y_{r_i}(t) + offset             w_i >= 0

r = 0 gives y = v, so w_0 is the linear (anhysteretic) slope. Weights in
m/V, thresholds in V.
"""
from __future__ import annotations

import numba
import numpy as np


@numba.njit(cache=True)
def _play(v, r, y0):
    n_t, n_r = v.shape[0], r.shape[0]
    out = np.empty((n_t, n_r))
    for i in range(n_r):
        y = y0[i]
        for k in range(n_t):
            lo, hi = v[k] - r[i], v[k] + r[i]
            y = lo if y < lo else (hi if y > hi else y)
            out[k, i] = y
    return out


def initial_state(v: np.ndarray, thresholds: np.ndarray, rest_fraction: float = 0.02) -> np.ndarray:
    """Operator outputs (n_r,) at the first sample, V.

    A run that starts at rest near 0 V starts from the virgin (demagnetised)
    state y = clip(0, v0 - r, v0 + r). A run cut from a longer periodic record
    is assumed to have come from the opposite extreme of its own range (the
    periodic steady state): the operators replay [far extreme, near extreme,
    v0] before the first sample."""
    v = np.asarray(v, float)
    r = np.asarray(thresholds, float)
    v0, span = v[0], float(np.ptp(v)) or 1.0
    if abs(v0) <= rest_fraction * max(float(np.max(np.abs(v))), 1e-300):
        return np.clip(0.0, v0 - r, v0 + r)
    moved = np.flatnonzero(np.abs(v - v0) > 0.01 * span)
    rising = moved.size == 0 or v[moved[0]] > v0
    first, second = (v.max(), v.min()) if rising else (v.min(), v.max())
    prefix = np.array([first, second, v0])
    y_start = first - r if rising else first + r
    return _play(prefix, r, y_start)[-1]


def play_operators(v: np.ndarray, thresholds: np.ndarray, y0: np.ndarray | None = None) -> np.ndarray:
    """Outputs (n_t, n_r) of the play operators, V, for input v (n_t,) V."""
    v = np.ascontiguousarray(v, dtype=float)
    r = np.ascontiguousarray(thresholds, dtype=float)
    y0 = initial_state(v, r) if y0 is None else np.asarray(y0, float)
    return _play(v, r, np.ascontiguousarray(y0))


def displacement(v: np.ndarray, thresholds: np.ndarray, weights: np.ndarray, offset: float = 0.0,
                 y0: np.ndarray | None = None) -> np.ndarray:
    """x (n_t,) m of the PI model."""
    return play_operators(v, thresholds, y0) @ np.asarray(weights, float) + offset
