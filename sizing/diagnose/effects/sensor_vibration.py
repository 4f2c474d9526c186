"""Sensor vibration: the position sensor sits on a lightly damped mount
that the actuator's motion shakes, so the measurement carries a ringing at
the mount's frequency that is not in the actuator (seed sec. 3: "the
steady-state oscillations in Figure 15 were the result of sensor
vibration").

Model: measured = y + z with z'' + 2 zeta w z' + w^2 z = -g y'' (a base-excited
mount, H(s) = -g s^2 / (s^2 + 2 zeta w s + w^2)), discretised by the
bilinear transform. Sizes: 20 Hz, zeta 0.02, g 0.2 and 12 Hz, zeta 0.01,
g 0.3 (a sensor on a light bracket; about 0.1-0.3 mm of ringing after a
current-limited step).
"""
from __future__ import annotations

import numpy as np
from scipy import signal

from .base import Effect, Param


def mount_response(t: np.ndarray, y: np.ndarray, freq: float, zeta: float, gain: float) -> np.ndarray:
    """z(t) of the mount driven by the measured motion y(t) (evenly sampled
    on the median step)."""
    fs = 1.0 / float(np.median(np.diff(t)))
    freq = min(freq, 0.45 * fs)
    w = 2 * np.pi * freq
    b, a = signal.bilinear([-gain, 0.0, 0.0], [1.0, 2 * zeta * w, w * w], fs=fs)
    y0 = y - y[0]
    return signal.lfilter(b, a, y0)


class SensorVibration(Effect):
    def measure(self, t, y, values):
        return y + mount_response(t, y, float(values["frequency_Hz"]), float(values["damping_ratio"]),
                                  float(values["gain"]))


EFFECT = SensorVibration(
    name="sensor_vibration", technology="dc_motor",
    params=(Param("frequency_Hz", 3.0, 300.0, log=True, doc="natural frequency of the sensor mount"),
            Param("damping_ratio", 0.002, 0.5, log=True, doc="damping ratio of the mount"),
            Param("gain", 0.0, 1.0, doc="mount displacement per output displacement at high frequency")),
    sizes=({"frequency_Hz": 20.0, "damping_ratio": 0.02, "gain": 0.2},
           {"frequency_Hz": 12.0, "damping_ratio": 0.01, "gain": 0.3}),
    source="seed sec. 3 (Figure 15); base excitation of a single-degree-of-freedom mount", post=True)
