"""Figures of a simulated step or ramp response, vectorised over candidates."""
from __future__ import annotations

import numpy as np


def step_metrics(t: np.ndarray, y: np.ndarray, target) -> dict[str, np.ndarray]:
    """t (n_t,), y (n_cand, n_t) from rest, target (n_cand,) the travel that
    counts as "reached". Returns stroke_m (final value), peak_m, overshoot
    (peak over final minus one, >= 0), time_to_stroke_s (first time y >=
    target; inf when never) and speed_m_s (target / time to reach it, or the
    stroke reached over the whole run when the target is missed)."""
    y = np.atleast_2d(y)
    target = np.asarray(target, dtype=float)
    final = y[:, -1]
    peak = y.max(axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        overshoot = np.where(final > 0, np.maximum(peak / final - 1.0, 0.0), 0.0)
    reached = y >= target[:, None]
    hit = reached.any(axis=1)
    first = np.argmax(reached, axis=1)
    time = np.where(hit, t[first] - t[0], np.inf)
    with np.errstate(divide="ignore", invalid="ignore"):
        speed = np.where(hit & (time > 0), target / time, np.where(hit, np.inf, np.maximum(final, 0) / (t[-1] - t[0])))
    return {"stroke_m": final, "peak_m": peak, "overshoot": overshoot,
            "time_to_stroke_s": time, "speed_m_s": speed}
