"""A DC design's results.json record (docs/formats.md, results).

The one place that turns the DC records (``records.DCActuatorDesign``, a
catalog actuator; ``records.DCDesign``, a design from parts) into the
candidate dicts of results.json."""
from __future__ import annotations

from .catalog_actuators import dc_duration
from ...engine import holding
from .assumed import resting
from .parts import MASS_PARTS
from .structure import structure_members
from ...engine.records import Simulation
from .records import DCActuatorDesign, DCDesign
from .read_back import SETTINGS


def _cases(sim: Simulation, stiffness: float) -> list[dict]:
    """The simulated cases with their rest offset and travel from neutral (engine/holding.py)."""
    return holding.held_cases(sim.cases, stiffness)


def actuator_candidate(req, catalog, d: DCActuatorDesign) -> dict:
    """The record of a catalog DC actuator."""
    r, act = req.requirements, d.actuator
    cases = _cases(d.simulation, d.static["output_stiffness_N_m"])
    worst = max(cases, key=lambda c: c["load_N"])
    components = {"actuator": act.id}
    return {
        "id": d.id, "technology": "dc_motor", "variant": "catalog", "stage": "simulated",
        "components": components,
        "stack_params": {},          # no stacks: the key is kept so every candidate has the same keys
        "static": dict(d.static),
        "simulated": {"stroke_m": worst["stroke_m"], "time_to_stroke_s": worst["time_to_stroke_s"],
                      "speed_m_s": min(c["speed_m_s"] for c in cases), "overshoot": worst["overshoot"],
                      "load_N": worst["load_N"], "cases": cases,
                      "peak_speed_m_s": max(c["peak_speed_m_s"] for c in cases)},
        "margins": dict(d.margins),
        "metrics": dict(d.metrics),
        "temperatures": {f"dc_actuator {act.id}": {"rated_degC": act.max_temperature,
                                                    "required_degC": r.max_temperature}},
        "design": {"technology": "dc_motor", "actuator": act.id, "step": r.stroke,
                   "duration": dc_duration(req), "temperature": r.max_temperature},
        "reason": "",
        **resting(catalog, components, d.margins),
    }


# Checks a design from parts can be ruled out of, and why: a margin with
# nothing to check (an unrated part, no gear) is left out of ``margins``,
# never counted as passed, and named in ``unchecked`` with its reason.
UNCHECKED = {
    "magnet_temperature": "the motor's catalog entry gives no magnet temperature rating",
    "gear_torque": "the gear's catalog entry gives no continuous output torque",
    "static_safety": "the screw's catalog entry gives no static load rating",
}


def unchecked(margins, components: dict) -> list[dict]:
    """The checks left out of ``margins``, each with its reason."""
    reasons = dict(UNCHECKED)
    if components.get("gear") is None:
        reasons["gear_torque"] = "no gear (direct drive)"
    return [{"check": name, "reason": why} for name, why in reasons.items() if name not in margins]


def parts_candidate(req, catalog, d: DCDesign) -> dict:
    """The record of a DC design from parts."""
    r, o = req.requirements, req.options
    T, components, stage = r.max_temperature, d.parts.components(), d.stage
    simulated = dict(d.simulated)
    if "cases" in simulated:
        simulated["cases"] = _cases(d.simulation, d.static["output_stiffness_N_m"])
    return {
        "id": d.id, "technology": "dc_motor", "variant": "parts", "stage": stage,
        "components": components, "controller": dict(d.controller), "stack_params": {}, "static": dict(d.static),
        "simulated": simulated, "margins": dict(d.margins), "metrics": dict(d.metrics),
        "temperatures": {"ambient": {"rated_degC": d.rated_ambient, "required_degC": T}},
        "design": {"technology": "dc_motor", **components, "step": r.stroke, "duration": d.duration,
                   "temperature": T, "speed": r.speed, "strokes_per_second": req.duty.strokes_per_second,
                   "amplifier_location": o.amplifier_location,
                   "electronics_bay_temperature": o.electronics_bay_temperature,
                   "controller": {k: float(d.controller[k]) for k in SETTINGS},
                   **({} if r.supply_voltage is None else {"supply_voltage": r.supply_voltage}),
                   **({"brake": True} if o.dc_brake else {})},
        "reason": "" if not d.missed or stage == "simulated"
                  else "ruled out before simulation: " + ", ".join(d.missed),
        "mass_breakdown_kg": {name: d.static[f"mass_{name}_kg"] for name in MASS_PARTS
                              if f"mass_{name}_kg" in d.static},
        "structure": structure_members(d.static),
        "unchecked": unchecked(d.margins, components),
        **resting(catalog, components, d.margins),
    }
