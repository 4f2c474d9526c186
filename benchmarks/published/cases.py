"""The third generator's campaigns: (name, truth, friction, options).

The friction is the published LuGre model with the parameters of
Canudas de Wit et al. (1995), Table I (servo.py), under the paper's PID;
the null cases run the same servo without friction. Sensor noise: white,
on the position (``white_m``, m rms) and on the logged command
(``current_A``, A rms); each case has its own seed.
"""
from __future__ import annotations

import numpy as np

from . import servo

DEV = [
    ("pub-null-1", "none", None, {}),
    ("pub-null-2", "none", None, {"white_m": 3e-4}),
    ("pub-lugre-1", "coulomb_friction", servo.TABLE_I, {}),
    ("pub-lugre-2", "coulomb_friction", servo.TABLE_I, {"white_m": 3e-4}),
    ("pub-lugre-half-steps", "coulomb_friction", servo.TABLE_I, {"scale": 0.5}),
]

# a set: (DC table, piezo table, seed offset), as benchmarks/crossform/cases.py
SETS = {"dev": (DEV, [], 70000)}


def excitations(scale: float = 1.0, fs: float = 1000.0, duration: float = 12.0) -> tuple[dict, np.ndarray]:
    """Set-point runs: two staircases of the paper's 1 m step size and a slow wave."""
    t = np.arange(0.0, duration, 1.0 / fs)

    def stairs(levels):
        levels = scale * np.asarray(levels, float)
        return levels[np.minimum((t / (duration / len(levels))).astype(int), len(levels) - 1)]

    wave = scale * 0.5 * (1 - np.cos(2 * np.pi * t / duration))
    return {"stairs_a": stairs([0, 1.0, 0.4, 0.8]), "wave": wave, "stairs_b": stairs([0, 0.5, 0.9, 0.2])}, t


def generate(case, seed: int, technology: str = "dc_motor"):
    """(rig.toml, runs, holdout run) of one case."""
    _name, _truth, friction, options = case
    rng = np.random.default_rng(seed)
    refs, t = excitations(options.get("scale", 1.0))
    runs = {}
    for name, xd in refs.items():
        x, u = servo.simulate(t, xd, friction)
        runs[name] = {"time_s": t, "reference_m": xd,
                      "position_m": x + options.get("white_m", 1e-4) * rng.normal(size=t.size),
                      "current_A": u + options.get("current_A", 0.01) * rng.normal(size=t.size)}
    return servo.rig_toml(), runs, "stairs_b"
