"""The brushless DC motor lead-screw actuator as the solve and the stages
after it see it (``registry.Technology``)."""
from __future__ import annotations

from typing import TYPE_CHECKING

from .records import DCActuatorDesign, DCDesign
from ...sim.dc_motor import DCMotorModel
from ..registry import Group, Technology, on_call
from . import resolving, actuator, presentation, stage, words
from .catalog_actuators import dc_duration
from .verdict import dc_sourced

if TYPE_CHECKING:
    from ...engine.candidate import Candidate


def supply_caveat(req, feasible: list[Candidate], catalog) -> str:
    """Designs from parts: their drives and windings follow the supply."""
    if req.requirements.supply_voltage is None:
        return ""
    return f"; drives and windings chosen for the {req.requirements.supply_voltage:g} V supply"


def traces(req, c: Candidate, stages, loads) -> list[dict] | None:
    """Design ``c`` re-simulated under every load case with its traces kept."""
    d, S = stages.held("dc_motor", c.id), req.requirements.stroke
    if isinstance(d, DCActuatorDesign):
        return actuator.step_cases(d.actuator, S, loads, dc_duration(req), keep_traces=True)
    if d is not None and d.model:
        params = dict(d.model)
        return actuator.step_cases_for(lambda force: DCMotorModel(**params, load_force=force), S, loads,
                                       dc_duration(req), keep_traces=True)
    return None


def study_design(req, catalog, c: Candidate, stages):
    """What robust perturbs: a design from parts (``read_back.DCPartsDesign``),
    as the solve sized it or read back from its record."""
    from .read_back import dc_parts_design, read_back_parts
    held = stages.held("dc_motor", c.id) if stages is not None else None
    return dc_parts_design(catalog, held) if isinstance(held, DCDesign) else read_back_parts(catalog, c)


TECHNOLOGY = Technology(
    name="dc_motor", label="DC motor", order=1,
    part_kinds=("dc_actuator", "motor", "screw", "gear", "drive"),
    solve=stage.solve, alongside=True,      # beside the others: its parallel kernels take PARALLEL_LAUNCH (sim/)
    groups=(Group("catalog", "DC motor lead-screw actuators (catalog)", empty="none in the catalog"),
            Group("parts", "DC motor actuators sized from parts (motor x screw x gear x drive)",
                  empty="none in the catalog", caveat=supply_caveat)),
    short_name=words.short_name, describe=words.describe,
    rests_on=("sizing.physics.dc_motor", "sizing.physics.motor", "sizing.physics.screw", "sizing.sim.dc_motor"),
    traces=traces, counts_key="dc_parts", in_every_sweep_point=True,
    summary_fields=lambda catalog, candidates: {"dc_sourced": dc_sourced(catalog, candidates)},
    perturbable=lambda candidate, asked: candidate.variant == "parts",     # not the catalog's actuators
    evaluate=on_call("sizing.technologies.dc_motor.evaluate_file", "evaluate_dc"),
    study_design=study_design, verify_perturbed=on_call("sizing.technologies.dc_motor.perturbed", "verify_perturbed"),
    report=presentation.PRESENTATION, resolving=resolving.RESOLVING,
    judge=on_call("sizing.technologies.dc_motor.judge", "judge"),
    reached=f"{actuator.SETTLED:.0%}".replace("%", " %") + " of it",
)
