"""``sizing evaluate`` of a DC design file (``Technology.evaluate``)."""
from __future__ import annotations

from ...engine import holding
from ...engine.evaluate import finite_or_none, lookup, worst_case
from ...engine.loads import load_cases
from ...errors import InputError
from ...io.catalog import Catalog
from .design_file import DCDesignFile
from . import actuator as dc_engine
from .from_parts import evaluate_parts


def evaluate_dc(design: DCDesignFile, catalog: Catalog, file: str) -> dict:
    """Static figures, simulated load cases and metrics of one DC design
    file: a catalog actuator, or a design from parts (``from_parts``)."""
    if design.actuator is None:
        cases = load_cases(design.load)
        parts = {kind: lookup(catalog, getattr(catalog, kind + "s"), getattr(design, kind), file, kind)
                 for kind in ("motor", "screw", "gear", "drive")}
        gear, motor = parts["gear"], parts["motor"]
        if gear is not None and gear.mount is not None and gear.mount not in (motor.gear_mounts or ()):
            raise InputError(file, "gear", f"gearhead {gear.id} (mount {gear.mount}) does not mount on motor {motor.id} "
                             f"(its mounts: {', '.join(motor.gear_mounts or ()) or 'none'})")
        out = evaluate_parts(design, catalog, parts, cases)
        if parts["drive"].bus_voltage < parts["motor"].rated_voltage:
            # the solve ranks such designs too: the motor runs at the bus voltage
            out["warnings"].append(f"drive {parts['drive'].id} has a {parts['drive'].bus_voltage:g} V bus, below the "
                                   f"{parts['motor'].rated_voltage:g} V rated voltage of motor {parts['motor'].id}: "
                                   "the motor runs at the bus voltage")
        return out
    act = lookup(catalog, catalog.dc_actuators, design.actuator, file, "actuator")
    cases = load_cases(design.load)
    sims = dc_engine.step_cases(act, design.step, [c["load_N"] for c in cases], design.duration)
    static = dc_engine.static_figures(act, max(c["load_N"] for c in cases) if cases else 0.0)
    simulated = holding.held_cases([dict(case, **{k: finite_or_none(v) for k, v in sim.items()})
                                    for case, sim in zip(cases, sims)], static["output_stiffness_N_m"])
    warnings = []
    if design.temperature > act.max_temperature:
        warnings.append(f"{act.id} is rated to {act.max_temperature:g} degC, below {design.temperature:g} degC")
    return {
        "technology": "dc_motor",
        "design": {"actuator": act.id, "step_m": design.step, "pid": act.pid.model_dump(),
                   "c1": act.c1, "c2": act.c2, "screw_lead_m": act.screw_lead},
        "static": static,
        "simulated": {"cases": simulated, "worst": worst_case(simulated)},
        "metrics": dc_engine.metrics(act),
        "warnings": warnings,
    }
