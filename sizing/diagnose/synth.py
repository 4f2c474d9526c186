"""Synthetic campaigns: the "measured" runs a rig would give with an effect
injected, plus realistic sensor noise. Used by ``--check``, the benchmark,
the tests and studies/campaigns/make_campaigns.py.

Noise (defaults): position noise 0.1 % of the run's span (a laser
displacement sensor on a 10 mm stroke: 10 um rms), piezo voltage noise
0.3 V rms on the logged voltage. DC references are digital: no noise.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..io.runs import Run
from .bench import Bench

POSITION_NOISE = 1e-3     # of the span of the run
VOLTAGE_NOISE_V = 0.3


def piezo_excitations(v_max: float, fs: float = 1000.0, duration: float = 2.0) -> dict[str, tuple]:
    """A ramp up and down and two staircases of voltage steps (0..v_max)."""
    t = np.arange(0.0, duration, 1.0 / fs)
    ramp = v_max * np.interp(t, [0, 0.1, 0.9, 1.1, 1.7, duration], [0, 0, 1, 1, 0, 0])

    def stairs(levels):
        levels = np.asarray(levels, float)
        return v_max * levels[np.minimum((t / (duration / len(levels))).astype(int), len(levels) - 1)]

    return {"ramp": (t, ramp), "steps": (t, stairs([0, 0.3, 0.7, 1.0, 0.5, 0.15, 0.6, 0.0])),
            "steps_b": (t, stairs([0, 0.5, 0.8, 0.2, 0.9, 0.4, 0.0, 0.3]))}


def dc_excitations(stroke: float, fs: float = 1000.0, duration: float = 2.0) -> dict[str, tuple]:
    """Two staircases of reference steps and a periodic run (a 2-5 Hz
    chirp of 40 % of the stroke)."""
    t = np.arange(0.0, duration, 1.0 / fs)

    def stairs(levels):
        levels = np.asarray(levels, float)
        return stroke * levels[np.minimum((t / (duration / len(levels))).astype(int), len(levels) - 1)]

    sine = 0.2 * stroke * (1 - np.cos(2 * np.pi * (2.0 + 0.75 * t) * t))
    return {"steps": (t, stairs([0, 1.0, 0.4, 0.8, 0.2, 0.6])), "sine": (t, sine),
            "steps_b": (t, stairs([0, 0.5, 0.9, 0.3, 0.7, 0.0]))}


@dataclass
class Noise:
    position: float = POSITION_NOISE     # rms, fraction of the run's span
    voltage_V: float = VOLTAGE_NOISE_V   # rms on a logged piezo voltage
    seed: int = 0


def synthesize(kind: str, rig, inputs: dict[str, tuple], effects=(), values=(), noise: Noise | None = None,
               hidden=None) -> list[Run]:
    """Runs measured on ``rig`` driven by the clean ``inputs`` {name: (t, u)},
    with ``effects`` injected at ``values`` (one {param: value} each) and
    ``hidden`` (optional callable (t, y, rng) -> y) an effect outside the
    library; then noise is added. Positions from rest, as in a campaign."""
    noise = noise or Noise()
    rng = np.random.default_rng(noise.seed)
    runs = [Run(name, None, np.asarray(t, float),
                {"voltage_V" if kind == "piezohydraulic" else "reference_m": np.asarray(u, float),
                 "position_m": np.zeros(len(t))}) for name, (t, u) in inputs.items()]
    bench = Bench(kind, rig, runs, [])
    bench.fit_linear = False        # nothing measured yet: per-run linear terms are injected below
    for run in bench.runs:          # simulate the true (clean) input
        run.u = run.u_raw.copy()
    bench._nominal = None
    Z = np.concatenate([e.unit(v) for e, v in zip(effects, values)]) if effects else np.zeros(0)
    Y = bench.simulate(list(effects), Z[None, :]) if effects else [y[None, :] for y in bench.nominal()]
    out = []
    for run, y in zip(runs, Y):
        y = y[0].copy()
        for effect, value in zip(effects, values):
            if hasattr(effect, "inject"):      # effects with per-run terms (an additive sinusoid)
                y = effect.inject(run.time, y, value, rng)
        if hidden is not None:
            y = hidden(run.time, y, rng)
        span = float(np.ptp(y)) or 1e-3
        y_meas = y + rng.normal(0.0, noise.position * span, len(y))
        cols = dict(run.columns)
        cols["position_m"] = y_meas
        if kind == "piezohydraulic":
            cols["voltage_V"] = cols["voltage_V"] + rng.normal(0.0, noise.voltage_V, len(y))
        out.append(Run(run.name, None, run.time, cols))
    return out
