"""The frequency-rectified piezo pump as the solve and the stages after it
see it (``registry.Technology``)."""
from __future__ import annotations

from typing import TYPE_CHECKING

from ..registry import Group, Technology, on_call
from . import resolving, presentation, stage, words
from .designs import BEST_DEMONSTRATED_POWER_W, BEST_DEMONSTRATED_SOURCE

if TYPE_CHECKING:
    from ...engine.candidate import Candidate


def pump_power(req, candidates: list[Candidate]) -> dict:
    """The pump's required output power (the largest load at the required
    speed) against the best demonstrated pump power (``designs.BEST_DEMONSTRATED_POWER_W``)."""
    loads = [k["load_N"] for c in candidates if c.technology == "piezo_pump"
             for k in (c.simulated or {}).get("cases", [])]
    required = max(loads, default=0.0) * req.requirements.speed
    return {"required_output_power_W": required, "best_demonstrated_power_W": BEST_DEMONSTRATED_POWER_W,
            "best_demonstrated_source": BEST_DEMONSTRATED_SOURCE}


def pump_power_words(entry: dict) -> str:
    need, best = entry["required_output_power_W"], entry["best_demonstrated_power_W"]
    return (f"the piezo pump must deliver {need:.3g} W at the output ({need / best:.2g} x the best demonstrated "
            f"piezo pump, {best:.3g} W)")


def study_design(req, catalog, c: Candidate, stages):
    """What robust perturbs: the pump's design file, from its record."""
    from .evaluate import design_file_of
    return design_file_of(req, c.design or {})


TECHNOLOGY = Technology(
    name="piezo_pump", label="piezo pump", order=2,
    part_kinds=("stack", "amplifier", "fluid", "seal", "valve", "accumulator"),
    solve=stage.solve, alongside=True,      # beside the others: its serial kernel (sim/pump.py) releases the GIL
    groups=(Group("pump", "piezo pump: stacks pumping through reed check valves into a cylinder"),),
    short_name=words.short_name, describe=words.describe,
    rests_on=("sizing.physics.pump", "sizing.physics.stack", "sizing.sim.pump"),
    compared_with="dc_motor", comparison_fields=pump_power, comparison_words=pump_power_words,
    # only when asked for: its parts have no tolerance model in the probability of compliance yet
    perturbable=lambda candidate, asked: asked == "piezo_pump" and candidate.stage == "simulated",
    evaluate=on_call("sizing.technologies.piezo_pump.evaluate", "evaluate_pump"),
    study_design=study_design, verify_perturbed=on_call("sizing.technologies.piezo_pump.perturbed", "verify_perturbed"),
    report=presentation.PRESENTATION, resolving=resolving.RESOLVING,
    judge=on_call("sizing.technologies.piezo_pump.judge", "judge"),
)
