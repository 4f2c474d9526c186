"""Sensor delay: the position logger lags the input (filtering in a laser
sensor, a late trigger between two loggers).

Model: measured y(t) = y_sim(t - tau), at rest before the run starts.
Sizes: 5 ms and 15 ms (a Keyence LK-G series sensor averaging 64-256
samples at 1-2 kHz; an unsynchronised logger).
"""
from __future__ import annotations

import numpy as np

from .base import Effect, Param


def delay(t: np.ndarray, y: np.ndarray, tau: float) -> np.ndarray:
    """y(t - tau) by linear interpolation; y(t0) before the start."""
    return np.interp(t - tau, t, y, left=y[0])


class SensorDelay(Effect):
    def measure(self, t, y, values):
        return delay(t, y, float(values["delay_s"]))


PARAMS = (Param("delay_s", 0.0, 0.05, doc="lag of the position measurement"),)
SIZES = ({"delay_s": 0.005}, {"delay_s": 0.015})
SOURCE = "pure time delay of the measurement path"

PIEZO = SensorDelay(name="sensor_delay", technology="piezohydraulic", params=PARAMS, sizes=SIZES,
                    source=SOURCE, post=True)
DC = SensorDelay(name="sensor_delay", technology="dc_motor", params=PARAMS, sizes=SIZES,
                 source=SOURCE, post=True)

# the forms this module adds to the library (effects.library), the family's default first
FORMS = (PIEZO, DC)
