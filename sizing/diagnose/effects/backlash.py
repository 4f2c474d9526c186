"""Backlash between the screw and the measured output: the externally
measured output follows the motor only after the play is taken up, so on
every reversal the measurement lags by the play.

Model: a play operator of width b (centred at the start) between the
simulated motor position and the measured position. The controller closes
its loop on the motor side, so this is pure post-processing. Sizes: 0.1 and
0.3 mm (a worn lead screw and its clevis pins).
"""
from __future__ import annotations

import numba
import numpy as np

from .base import Effect, Param


@numba.njit(cache=True)
def play(y, width):
    """Output of a play (backlash) operator of total width ``width``,
    starting centred: out(0) = y(0)."""
    out = np.empty_like(y)
    half = 0.5 * width
    o = y[0]
    for k in range(y.shape[0]):
        if y[k] - o > half:
            o = y[k] - half
        elif o - y[k] > half:
            o = y[k] + half
        out[k] = o
    return out


class Backlash(Effect):
    def measure(self, t, y, values):
        return play(np.ascontiguousarray(y, dtype=float), float(values["backlash_m"]))


EFFECT = Backlash(
    name="backlash", technology="dc_motor",
    params=(Param("backlash_m", 0.0, 2e-3, doc="total play between motor and measured output"),),
    sizes=({"backlash_m": 1e-4}, {"backlash_m": 3e-4}),
    source="play operator (Tao and Kokotovic, Adaptive control of systems with actuator and sensor nonlinearities, 1996)", post=True)
