"""DC designs from parts under part tolerances (``sizing robust`` and the
probability of compliance): every perturbed sample through the solve's own
checks (``from_parts.verify_parts``)."""
from __future__ import annotations

import numpy as np

from ...studies.tolerances import perturbed_parts
from .catalog_actuators import dc_duration
from .from_parts import verify_parts


def verify_perturbed(task, tols: list, f: np.ndarray, temps) -> tuple[list[dict], float]:
    """The DC solve's checks (``verify_parts``) of each perturbed sample,
    with the controller and drive limits as designed on the nominal parts;
    (per sample its verdict, simulated seconds)."""
    d = task.design
    n = f.shape[0]
    settings = {k: np.full(n, v) for k, v in d.settings.items()}
    duration = d.duration if d.duration is not None else dc_duration(task.req)
    picked = verify_parts(task.req, perturbed_parts(d.parts, tols, f), task.loads, settings,
                          ambient=temps, duration=duration)
    return picked, n * len(task.loads) * duration
