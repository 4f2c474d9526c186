"""The piezohydraulic actuator as the solve and the stages after it see it
(``registry.Technology``)."""
from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ..registry import Group, Technology, on_call
from . import resolving, designs, presentation, stage, words
from .thermal_words import thermal_statement
from .verify import simulate_cases

if TYPE_CHECKING:
    from ...engine.candidate import Candidate


def amplifier_caveat(req, feasible: list[Candidate], catalog) -> str:
    """Feasible only because the amplifier sits in the electronics bay: say so
    next to the verdict, not only among the assumptions."""
    T = req.requirements.max_temperature
    if req.options.amplifier_location != "bay":
        return ""
    ratings = {c.components["amplifier"]: catalog.amplifiers[c.components["amplifier"]].max_temperature
               for c in feasible if c.components.get("amplifier") in catalog.amplifiers}
    below = {k: v for k, v in ratings.items() if v < T}
    if not below or len(below) < len(ratings):
        return ""
    return (f"; every one relies on its amplifier sitting in an electronics bay at "
            f"{req.options.electronics_bay_temperature:g} degC (rated {max(below.values()):g} degC at best, below "
            f"{T:g} degC): with the amplifier at the actuator none is feasible")


def traces(req, c: Candidate, stages, loads) -> list[dict] | None:
    """Design ``c`` re-simulated under every load case with its traces kept."""
    d = stages.held("piezohydraulic", c.id)
    if d is None or not d.built:
        return None
    sims = simulate_cases(d.cand, loads, np.array([d.ramp]), target_stroke=req.requirements.stroke, keep_traces=True)
    return [{"load_N": float(s["load_N"][0]), "t": s["t"], "position_m": s["position_m"][0]} for s in sims]


def study_design(req, catalog, c: Candidate, stages):
    """What robust perturbs: the (Combo, Variant, SizingResult) triple, as
    the solve sized it or read back from its record."""
    from .read_back import sized_designs
    held = stages.held("piezohydraulic", c.id) if stages is not None else None
    return held.sized if held is not None else sized_designs(req, catalog, [c])[0]


TECHNOLOGY = Technology(
    name="piezohydraulic", label="piezohydraulic", order=0,
    part_kinds=("stack", "fluid", "seal", "amplifier", "material", "compensator"),
    solve=stage.solve,
    groups=(Group("uncompensated", "piezohydraulic, as built (no thermal compensation)", caveat=amplifier_caveat),
            Group("passive", "piezohydraulic, passive compensation (low-expansion spacer, longer frame)",
                  caveat=amplifier_caveat),
            Group("compensated", "piezohydraulic with thermal compensator", caveat=amplifier_caveat)),
    short_name=words.short_name, describe=words.describe,
    rests_on=("sizing.physics.stack", "sizing.physics.hydraulics", "sizing.physics.structure", "sizing.physics.thermal",
              "sizing.sim.piezohydraulic"),
    traces=traces, disagreements=stage.disagreements,
    counts_key=None, prunes_before_sizing=True, extra_counts=("sized",),
    results_fields=lambda catalog: {"hysteresis_time_scales": designs.hysteresis_time_scales(catalog)},
    in_every_sweep_point=True, compared_with="dc_motor",
    perturbable=lambda candidate, asked: True,
    thermal_statement=thermal_statement, evaluate=on_call("sizing.technologies.piezohydraulic.evaluate_file", "evaluate_piezo"), study_design=study_design,
    verify_perturbed=on_call("sizing.technologies.piezohydraulic.perturbed", "verify_perturbed"),
    report=presentation.PRESENTATION, resolving=resolving.RESOLVING,
    judge=on_call("sizing.technologies.piezohydraulic.judge", "judge"),
    held=lambda records: {v.design.id: v.design for v in records},     # its records are VerifiedDesigns
)
