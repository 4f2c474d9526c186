"""The third generator's campaigns: case sets as data (``sets/*.json``,
listed with their purpose and seed offset in ``sets/manifest.json``).

The friction is the published LuGre model with the parameters of
Canudas de Wit et al. (1995), Table I (servo.py, named "table_i" in the
data), under the paper's PID; the null cases run the same servo without
friction. Sensor noise: white, on the position (option ``white_m``, m rms)
and on the logged command (``current_A``, A rms); each case has its own
seed. ``scale`` scales the set-points.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..crossform.common import Case, CaseSet, load_set, set_names
from . import servo

SETS_DIR = Path(__file__).resolve().parent / "sets"
FRICTION = {"table_i": servo.TABLE_I}     # the published parameter sets the data name


def sets() -> list[str]:
    return set_names(SETS_DIR)


def case_set(name: str) -> CaseSet:
    return load_set(SETS_DIR, name)


def excitations(scale: float = 1.0, fs: float = 1000.0, duration: float = 12.0) -> tuple[dict, np.ndarray]:
    """Set-point runs: two staircases of the paper's 1 m step size and a slow wave."""
    t = np.arange(0.0, duration, 1.0 / fs)

    def stairs(levels):
        levels = scale * np.asarray(levels, float)
        return levels[np.minimum((t / (duration / len(levels))).astype(int), len(levels) - 1)]

    wave = scale * 0.5 * (1 - np.cos(2 * np.pi * t / duration))
    return {"stairs_a": stairs([0, 1.0, 0.4, 0.8]), "wave": wave, "stairs_b": stairs([0, 0.5, 0.9, 0.2])}, t


def generate(case: Case):
    """(rig.toml, runs, holdout run) of one case."""
    friction = FRICTION[case.effects["friction"]] if case.effects.get("friction") else None
    options = case.options
    rng = np.random.default_rng(case.seed)
    refs, t = excitations(options.get("scale", 1.0))
    runs = {}
    for name, xd in refs.items():
        x, u = servo.simulate(t, xd, friction)
        runs[name] = {"time_s": t, "reference_m": xd,
                      "position_m": x + options.get("white_m", 1e-4) * rng.normal(size=t.size),
                      "current_A": u + options.get("current_A", 0.01) * rng.normal(size=t.size)}
    return servo.rig_toml(), runs, "stairs_b"
