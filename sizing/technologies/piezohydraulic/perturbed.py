"""Piezohydraulic designs under part tolerances (``sizing robust`` and the
probability of compliance): every perturbed sample through the solve's own
checks (``stage.verify_sized``)."""
from __future__ import annotations

import numpy as np

from ...studies.tolerances import BOUC_WEN_PREFIX, perturbed_combo
from .parts import reference_bouc_wen, stack_bouc_wen
from .stage import verify_sized
from .verify import SETTLE_TIME_S


def _pick(cands: list[dict], variant_id: str) -> dict:
    """The sample's candidate of the design under study. A passive design
    ("-pc") whose sample does not drift beyond the allowance needs no spacer:
    its as-built candidate stands for it."""
    by_id = {c["id"]: c for c in cands}
    return by_id.get(variant_id) or by_id[variant_id.removesuffix("-pc")]


def verify_perturbed(task, tols: list, f: np.ndarray, temps) -> tuple[list[dict], float]:
    """The solve's own checks (``verify_sized``) of each perturbed sample;
    (the design's candidate per sample, simulated seconds)."""
    combo, variant, res = task.design
    bw = None
    if any(t.key.startswith(BOUC_WEN_PREFIX) for t in tols):
        bw = stack_bouc_wen(combo.stack, reference_bouc_wen(task.catalog.stacks))[0]
    sized = [(perturbed_combo(combo, tols, row, bw), variant, res) for row in f]
    verified = verify_sized(task.req, task.catalog, sized, task.loads, chunk=task.size, temperatures=temps)
    picked = [_pick(cands, task.variant_id) for cands in verified]
    sim_s = sum(sum(case["ramp_time_s"] + SETTLE_TIME_S for case in c["simulated"].get("cases", []))
                for c in picked)
    return picked, sim_s
