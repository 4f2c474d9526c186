"""Drive signals that several diagnosis tests build the same way."""
from __future__ import annotations

import numpy as np


def ramp_and_hold_500hz() -> tuple[np.ndarray, np.ndarray]:
    """(t, V): levels 40-150 V held 0.45 s, joined by 220 V/s ramps (0.44 V
    a sample at 500 Hz), so that the corners fall between samples."""
    t = np.arange(0.0, 5.0, 2e-3)
    knots_t, knots_v, at = [0.0, 0.2], [0.0, 0.0], 0.2
    for level in (40, 85, 125, 150, 100, 55, 15, 0):
        at += abs(level - knots_v[-1]) / 220.0
        knots_t += [at, at + 0.45]
        knots_v += [level, level]
        at += 0.45
    return t, np.interp(t, knots_t, knots_v)


def trapezoids(stroke: float, fs: float = 1000.0, duration: float = 2.0) -> dict:
    """Three runs of ramps and holds, moving about half of the time."""
    t = np.arange(0.0, duration, 1.0 / fs)
    knots = {"up": [0, 0.2, 0.7, 1.0, 1.5, 2.0], "down": [0, 0.3, 0.8, 1.1, 1.6, 2.0],
             "mid": [0, 0.1, 0.6, 1.0, 1.4, 2.0]}
    levels = {"up": [0, 0, 1, 1, 0.2, 0.2], "down": [0, 0, 0.8, 0.8, 0.1, 0.1], "mid": [0, 0, 0.6, 0.6, 0.9, 0.9]}
    return {k: (t, stroke * np.interp(t, knots[k], levels[k])) for k in knots}
