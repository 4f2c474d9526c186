"""Sensor vibration, two forms of one family.

Form "default" (a structural mode excited by motion): the position sensor
sits on a lightly damped mount that the actuator's motion shakes, so the
measurement carries a ringing at the mount's frequency that is not in the
actuator (seed sec. 3: "the steady-state oscillations in Figure 15 were the
result of sensor vibration").

Model: measured = y + z with z'' + 2 zeta w z' + w^2 z = -g y'' (a base-excited
mount, H(s) = -g s^2 / (s^2 + 2 zeta w s + w^2)), discretised by the
bilinear transform. Sizes: 20 Hz, zeta 0.02, g 0.2 and 12 Hz, zeta 0.01,
g 0.3 (a sensor on a light bracket; about 0.1-0.3 mm of ringing after a
current-limited step). Screening also starts from the lines of the training
residual's spectrum (sizing/spectrum.py): for each line frequency and a few
damping ratios the gain, to which the ringing is proportional, is solved
by least squares.

Form "sinusoid" (an additive disturbance: a pump, a fan, mains pick-up, a
neighbouring machine): measured = y + A_r sin(2 pi f t + phase_r). Its
frequency f is a property of the disturbance and is fitted on the training
runs, started at the strongest line of their residual spectrum (a peak
well above the spectrum's local median, sizing/spectrum.py) and refined;
amplitude and phase are linear once f is fixed (a sin + b cos) and are
solved by least squares on each run, the holdout runs included: the phase
relative to the start of a run is not a property of the rig, and the
amplitude of a pick-up is not either. Two coefficients per run of 1000s of
samples remove a negligible share of noise; the frequency is never fitted
on the holdout. Sizes (for synthetic campaigns): 50 Hz at 1 % of the span
and 23 Hz at 2 % of the span.
"""
from __future__ import annotations

import dataclasses

import numpy as np
from ... import spectrum
from ...physics.sensor_mount import mount_response
from .base import Effect, Param


DAMPING_STARTS = (0.005, 0.01, 0.02, 0.05, 0.1)


def _training_residuals(bench, head, z_head):
    """[(t, measured - simulated position)] of the training runs with the
    head (re-calibrated parameters) at z_head, and the simulated positions."""
    runs = bench.train
    if head:
        Y = [y[0, 0] for y in bench.simulate_channels(list(head), np.atleast_2d(z_head), runs)]
    else:
        Y = [bench.nominal()[i] for i in runs]
    return [(bench.runs[i].t, bench.runs[i].y - y) for i, y in zip(runs, Y)], Y


class SensorVibration(Effect):
    def measure(self, t, y, values):
        return y + mount_response(t, y, float(values["frequency_Hz"]), float(values["damping_ratio"]),
                                  float(values["gain"]))

    def starts(self, bench, head=(), z_head=np.zeros(0)) -> list:
        """Unit start points from the lines of the training residual: each
        line frequency x DAMPING_STARTS, the gain by least squares."""
        res, sims = _training_residuals(bench, head, z_head)
        out = []
        for freq, _ratio in spectrum.lines(res, sims):
            for zeta in DAMPING_STARTS:
                Z1 = [mount_response(t, y, freq, zeta, 1.0) for (t, _e), y in zip(res, sims)]
                num = sum(float(np.dot(e, z)) for (_t, e), z in zip(res, Z1))
                den = sum(float(np.dot(z, z)) for z in Z1) or 1.0
                gain = float(np.clip(num / den, self.params[2].lo, self.params[2].hi))
                if gain <= 0.0:
                    continue                        # no ringing of this shape: no start
                out.append(self.unit({"frequency_Hz": freq, "damping_ratio": zeta, "gain": gain}))
        return out


class SensorSinusoid(Effect):
    """Additive sinusoid (form "sinusoid", module docstring)."""

    def measure(self, t, y, values):
        """Synthesis: add A sin(2 pi f t + phase) when the values carry
        ``amplitude_m`` and ``phase_rad``; otherwise the measurement is
        completed run by run by ``fit_run``."""
        if "amplitude_m" in values:
            return y + float(values["amplitude_m"]) * np.sin(
                2 * np.pi * float(values["frequency_Hz"]) * (t - t[0]) + float(values.get("phase_rad", 0.0)))
        return y

    def fit_run(self, t, y, measured, values):
        """y plus the least-squares sinusoid at the frequency in ``values``
        of the run's residual measured - y."""
        return y + spectrum.sinusoid(t, measured - y, float(values["frequency_Hz"]))[2]

    def observable(self, bench, head=(), z_head=np.zeros(0)) -> bool:
        """Only offered when the training residuals hold a common line."""
        return bool(self.starts(bench, head, z_head))

    def starts(self, bench, head=(), z_head=np.zeros(0)) -> list:
        """The strongest common lines of the training residuals, refined
        (least-squares sinusoid over the runs, fine grid)."""
        res, sims = _training_residuals(bench, head, z_head)
        p = self.params[0]
        out = []
        for freq, _ratio in spectrum.lines(res, sims):
            if p.lo <= freq <= p.hi:
                out.append(self.unit({"frequency_Hz": float(np.clip(spectrum.refine(res, freq), p.lo, p.hi))}))
        return out

    def inject(self, t, y, size, rng):
        """Synthetic campaigns: A = ``amplitude_of_span`` x the run's span,
        a random phase per run."""
        return y + size["amplitude_of_span"] * float(np.ptp(y)) * np.sin(
            2 * np.pi * size["frequency_Hz"] * (t - t[0]) + rng.uniform(0, 2 * np.pi))


MOUNT = SensorVibration(
    form="mount",
    name="sensor_vibration", technology="dc_motor",
    params=(Param("frequency_Hz", 3.0, 300.0, log=True, doc="natural frequency of the sensor mount"),
            Param("damping_ratio", 0.002, 0.5, log=True, doc="damping ratio of the mount"),
            Param("gain", 0.0, 1.0, doc="mount displacement per output displacement at high frequency")),
    sizes=({"frequency_Hz": 20.0, "damping_ratio": 0.02, "gain": 0.2},
           {"frequency_Hz": 12.0, "damping_ratio": 0.01, "gain": 0.3}),
    source="seed sec. 3 (Figure 15); base excitation of a single-degree-of-freedom mount", post=True)

SINUSOID = SensorSinusoid(
    name="sensor_vibration", technology="dc_motor", form="sinusoid",
    params=(Param("frequency_Hz", 2.0, 500.0, log=True, doc="frequency of the additive disturbance"),),
    sizes=({"frequency_Hz": 50.0, "amplitude_of_span": 0.01}, {"frequency_Hz": 23.0, "amplitude_of_span": 0.02}),
    source="an additive sinusoid of unknown frequency and phase (pump, fan, mains pick-up); "
           "frequency from the residual spectrum, amplitude and phase by linear least squares per run",
    post=True, extra={"fd_step": 1e-4})

# A sensor on a bracket vibrates on a piezohydraulic rig too: the same two forms.
PIEZO_MOUNT = dataclasses.replace(MOUNT, technology="piezohydraulic")
PIEZO_SINUSOID = dataclasses.replace(SINUSOID, technology="piezohydraulic")

# the forms this module adds to the library (effects.library), the family's default first
FORMS = (MOUNT, SINUSOID, PIEZO_MOUNT, PIEZO_SINUSOID)
