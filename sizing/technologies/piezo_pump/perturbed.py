"""Piezo pump designs under part tolerances (``sizing robust --technology``):
every perturbed sample through the pump's screen checks and cycle
simulation (``evaluate.verify_samples``)."""
from __future__ import annotations

import numpy as np

from ...studies.tolerances import BOUC_WEN_PREFIX, perturbed_combo
from ..piezohydraulic.parts import reference_bouc_wen, stack_bouc_wen
from . import screen
from .evaluate import verify_samples


def verify_perturbed(task, tols: list, f: np.ndarray, temps) -> tuple[list[dict], float]:
    """The pump's checks on each sample's perturbed parts, at the required
    maximum temperature; (per sample its verdict, simulated seconds)."""
    d, cat = task.design, task.catalog
    group = screen.Group(cat.stacks[d.stack], d.n_stacks, cat.amplifiers[d.amplifier], cat.valves[d.valve],
                         cat.accumulators[d.accumulator], cat.fluids[d.fluid], cat.seals[d.seal])
    bw = None
    if any(t.key.startswith(BOUC_WEN_PREFIX) for t in tols):
        bw = stack_bouc_wen(group.stack, reference_bouc_wen(cat.stacks))[0]
    groups = [perturbed_combo(group, tols, row, bw) for row in f]
    picked = verify_samples(d, cat, groups, task.loads)
    return picked, f.shape[0] * len(task.loads) * 2.0 * d.stroke / d.speed
