"""A position sensor on a lightly damped mount that the measured motion
shakes (seed sec. 3, Figure 15: steady-state oscillations from sensor
vibration): measured = y + z, z'' + 2 zeta w z' + w^2 z = -g y'' (a
base-excited mount, H(s) = -g s^2 / (s^2 + 2 zeta w s + w^2)),
discretised by the bilinear (Tustin) transform. Shared by the DC motor fit
(sizing/fit/dc_motor.py) and the diagnosis's sensor_vibration effect.
"""
from __future__ import annotations

import numpy as np
from scipy import signal


def mount_response(t: np.ndarray, y: np.ndarray, freq: float, zeta: float, gain: float) -> np.ndarray:
    """z(t) of the mount driven by the measured motion y(t) (evenly sampled
    on the median step)."""
    if gain == 0.0:
        return np.zeros_like(np.asarray(y, float))   # no mount motion (and no all-zero filter)
    fs = 1.0 / float(np.median(np.diff(t)))
    freq = min(freq, 0.45 * fs)
    w = 2 * np.pi * freq
    # bilinear (Tustin) transform of -gain s^2 / (s^2 + 2 zeta w s + w^2),
    # written out: scipy's bilinear warns of a badly conditioned numerator
    # for the tiny gains the screen tries, though the section is exact
    k = 2.0 * fs
    a0 = k * k + 2 * zeta * w * k + w * w
    b = -gain * k * k * np.array([1.0, -2.0, 1.0]) / a0
    a = np.array([1.0, (2 * w * w - 2 * k * k) / a0, (k * k - 2 * zeta * w * k + w * w) / a0])
    y0 = y - y[0]
    return signal.lfilter(b, a, y0)
