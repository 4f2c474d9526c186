"""Backlash between the screw and the measured output: the externally
measured output follows the motor only after the play is taken up, so on
every reversal the measurement lags by the play.

The controller closes its loop on the motor side (its encoder), so both
forms are a post-processing of the simulated motor position into the
measured load position. Two forms, the two classical backlash models
(Nordin and Gutman, Controlling mechanical systems with backlash - a
survey, Automatica 38 (2002) 1633, sec. 2):
- ``play``: the "hysteresis" model, a play operator of width b (centred at
  the start): the load has no inertia of its own and stays where the motor
  left it. Sizes: 0.1 and 0.3 mm (a worn lead screw and its clevis pins).
- ``coasting``: the "dead-zone" model in the stiff-contact limit: the load
  has inertia and a viscous drag to ground (its guides and seals), so when
  the motor decelerates faster than the load's own drag would stop it, the
  load separates and coasts across the gap, v' = -v / tau with tau = m / c,
  until it stops or meets the other flank; in contact it moves with the
  motor. tau -> 0 is the play operator. Sizes: b = 0.1 mm with a 1 kg load
  on 300 N s/m (tau about 3 ms), b = 0.3 mm with a 5 kg load on 500 N s/m
  (10 ms): linear guides and rod seals.

A third form, ``in_loop``, is the play when the loop is closed on the
measured output itself (a load-side sensor and no motor encoder): the
controller sees the play, so at each reversal it drives the motor across
the gap while the measurement stands still, and the motor then overshoots
what a post-processed play would show (field ``loop_backlash`` of
sizing/sim/dc_motor.py, a play operator sampled with the loop). Its
signature is in the position alone, at the reversals, where no form on the
motor side reproduces it. Sizes: 0.1 and 0.3 mm, as the play.
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


@numba.njit(cache=True)
def coasting(t, y, width, tau):
    """Load position behind a dead band of total width ``width`` driven by
    the motor position y(t) (rigid contact), the load coasting with
    v' = -v / tau while out of contact; starts centred and at rest."""
    out = np.empty_like(y)
    half = 0.5 * width
    o, v = y[0], 0.0
    out[0] = o
    for k in range(1, y.shape[0]):
        dt = t[k] - t[k - 1]
        if tau > 0.0:
            e = np.exp(-dt / tau)
            o_free, v_free = o + v * tau * (1.0 - e), v * e
        else:
            o_free, v_free = o, 0.0
        if y[k] - o_free > half:
            o_new = y[k] - half
        elif o_free - y[k] > half:
            o_new = y[k] + half
        else:
            o_new = o_free
        if o_new != o_free:          # in contact: moves with the motor
            v = (o_new - o) / dt if dt > 0.0 else 0.0
        else:
            v = v_free
        o = o_new
        out[k] = o
    return out


class Backlash(Effect):
    def measure(self, t, y, values):
        return play(np.ascontiguousarray(y, dtype=float), float(values["backlash_m"]))


class CoastingBacklash(Effect):
    def measure(self, t, y, values):
        return coasting(np.ascontiguousarray(t, dtype=float), np.ascontiguousarray(y, dtype=float),
                        float(values["backlash_m"]), float(values["coast_time_s"]))


PLAY = Backlash(
    name="backlash", technology="dc_motor", form="play",
    params=(Param("backlash_m", 0.0, 2e-3, doc="total play between motor and measured output"),),
    sizes=({"backlash_m": 1e-4}, {"backlash_m": 3e-4}),
    source="play operator (Tao and Kokotovic, Adaptive control of systems with actuator and sensor nonlinearities, 1996)", post=True)

COASTING = CoastingBacklash(
    name="backlash", technology="dc_motor", form="coasting",
    params=(Param("backlash_m", 0.0, 2e-3, doc="total play between motor and measured output"),
            Param("coast_time_s", 1e-4, 0.05, log=True, doc="load mass / its viscous drag: how long it coasts when free")),
    sizes=({"backlash_m": 1e-4, "coast_time_s": 3e-3}, {"backlash_m": 3e-4, "coast_time_s": 1e-2}),
    source="dead-zone backlash model with load inertia (Nordin and Gutman, Automatica 38 (2002) 1633)", post=True)

IN_LOOP = Effect(
    name="backlash", technology="dc_motor", form="in_loop",
    params=(Param("backlash_m", 0.0, 2e-3, doc="total play between motor and measured output"),),
    sizes=({"backlash_m": 1e-4}, {"backlash_m": 3e-4}), fields={"backlash_m": "loop_backlash"},
    source="play operator inside the position loop (Nordin and Gutman, Automatica 38 (2002) 1633, sec. 2)")

# the forms this module adds to the library (effects.library), the family's default first
FORMS = (PLAY, COASTING, IN_LOOP)
