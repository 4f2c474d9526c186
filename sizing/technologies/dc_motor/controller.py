"""The position controller of a DC actuator sized from parts: the seed's
1.25 kHz PID (ARL-TR-10251 sec. 3.1) with gains from each design's plant by
pole placement.

Plant (seed eq. 13, current-driven, output position y):
    y'' = c1 y' + g (i - i_load),       g = (l / 2 pi) c2
Controller (I-PD: integral on the error, proportional and derivative on the
measurement, so the closed loop has no zeros and a step does not overshoot
while the current is not saturated):
    i = ki int(r - y) - kp y - kd y'
Closed loop: y / r = g ki / (s^3 + (g kd - c1) s^2 + g kp s + g ki).
Rule: a triple pole at s = -w0,
    kd = (3 w0 + c1) / g,  kp = 3 w0^2 / g,  ki = w0^3 / g,
(kd clipped at 0 when the plant's own pole is faster than 3 w0), so that
y / r = w0^3 / (s + w0)^3: its -3 dB bandwidth is w0 sqrt(2^(1/3) - 1) and
its step reaches 98 % at SETTLE_98 / w0 (the 0.98 quantile of a
gamma(3) distribution).
Target: the linear step settles within half the time the speed
requirement allows for the stroke (the other half is for the current- and
voltage-limited slew), w0 = 2 SETTLE_98 / (stroke / speed); capped at
1/SAMPLES_PER_POLE of the controller rate, so that the 1.25 kHz sampling
stays far faster than the loop (w0 Ts <= 2 pi / 40).
"""
from __future__ import annotations

import numpy as np

BANDWIDTH_FACTOR = float(np.sqrt(2.0 ** (1.0 / 3.0) - 1.0))   # -3 dB of w0^3/(s+w0)^3, in w0
SETTLE_98 = 7.5163                                          # gamma(3) 0.98 quantile
SAMPLES_PER_POLE = 40.0


def pole_target(stroke_time, rate):
    """Triple closed-loop pole w0 (rad/s) for a stroke allowed
    ``stroke_time`` seconds, with the controller running at ``rate`` Hz."""
    return np.minimum(2.0 * SETTLE_98 / np.asarray(stroke_time, float), 2 * np.pi * np.asarray(rate, float) / SAMPLES_PER_POLE)


def ipd_gains(c1, c2, lead, w0) -> dict[str, np.ndarray]:
    """kp (A/m), ki (A/(m s)), kd (A s/m) placing a triple pole at -w0 for
    the plant (c1, c2, lead): arrays over candidates."""
    g = np.asarray(lead, float) / (2 * np.pi) * np.asarray(c2, float)
    w0 = np.asarray(w0, float)
    return {"kp": 3 * w0**2 / g, "ki": w0**3 / g, "kd": np.maximum((3 * w0 + np.asarray(c1)) / g, 0.0)}


def bandwidth(w0):
    """-3 dB bandwidth (rad/s) of the closed loop with the triple pole w0."""
    return BANDWIDTH_FACTOR * np.asarray(w0, float)
