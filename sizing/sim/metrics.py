"""Figures of a simulated step or ramp response, vectorised over candidates."""
from __future__ import annotations

import numpy as np


def last_sample(t: np.ndarray, n_cand: int, horizon=None) -> np.ndarray:
    """Index of each candidate's last sample within its ``horizon`` (s from
    t[0]; None: the whole run)."""
    if horizon is None:
        return np.full(n_cand, len(t) - 1)
    return np.clip(np.searchsorted(t - t[0], np.asarray(horizon, float) * (1 + 1e-12), side="right") - 1,
                   0, len(t) - 1)


def final_value(t: np.ndarray, y: np.ndarray, horizon=None) -> np.ndarray:
    """Each candidate's value at the end of its own run."""
    y = np.atleast_2d(y)
    return y[np.arange(len(y)), last_sample(t, len(y), horizon)]


def step_metrics(t: np.ndarray, y: np.ndarray, target, horizon=None) -> dict[str, np.ndarray]:
    """t (n_t,), y (n_cand, n_t) from rest, target (n_cand,) the travel that
    counts as "reached". Returns stroke_m (final value), peak_m, overshoot
    (peak over final minus one, >= 0), time_to_stroke_s (first time y >=
    target; inf when never) and speed_m_s (target / time to reach it, or the
    stroke reached over the whole run when the target is missed).

    ``horizon`` (n_cand,), s from t[0]: each candidate's own run ends there
    (its samples after it are not read), so a candidate's figures do not
    depend on the longer runs it was simulated beside."""
    y = np.atleast_2d(y)
    target = np.asarray(target, dtype=float)
    last = last_sample(t, len(y), horizon)
    inside = np.arange(len(t))[None, :] <= last[:, None]
    final = y[np.arange(len(y)), last]
    peak = np.where(inside, y, -np.inf).max(axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        overshoot = np.where(final > 0, np.maximum(peak / final - 1.0, 0.0), 0.0)
    reached = (y >= target[:, None]) & inside
    hit = reached.any(axis=1)
    first = np.argmax(reached, axis=1)
    time = np.where(hit, t[first] - t[0], np.inf)
    duration = t[last] - t[0]
    with np.errstate(divide="ignore", invalid="ignore"):
        speed = np.where(hit & (time > 0), target / time, np.where(hit, np.inf, np.maximum(final, 0) / duration))
    return {"stroke_m": final, "peak_m": peak, "overshoot": overshoot,
            "time_to_stroke_s": time, "speed_m_s": speed}
