"""The DC motor option on the same requirements, load cases and metrics.

Each catalog DC actuator is simulated (``engine/dc.py``: seed eq. 13-14 with
the load term of docs/models.md and the catalog's PID) for a step of the
required stroke under each load case. A stroke counts as reached at 98 % of
the step (``dc.SETTLED``); speed = that travel / the time to reach it.
"""
from __future__ import annotations

from ..io.catalog import Catalog
from ..io.requirements import RequirementsFile
from . import dc as dc_engine
from . import dc_assumed
from .rank import ceiling_margin, floor_margin
from .search import temperature_margin


def dc_duration(req: RequirementsFile) -> float:
    """Simulated time: long enough to settle, at least 1 s."""
    return max(1.0, 4.0 * req.stroke_time)


def dc_candidates(req: RequirementsFile, catalog: Catalog, loads: list[float]) -> dict:
    r = req.requirements
    out = []
    for act in catalog.dc_actuators.values():
        cases = dc_engine.step_cases(act, r.stroke, loads, dc_duration(req))
        worst = max(cases, key=lambda c: c["load_N"])
        reached = all(c["stroke_m"] >= dc_engine.SETTLED * r.stroke for c in cases)
        static = dc_engine.static_figures(act, max(loads) if loads else 0.0)
        static["free_stroke_m"] = act.stroke
        margins = {
            # a servo settles on its reference: the stroke is the actuator's travel, once the
            # simulation shows the step reached (to 98 %) under every load
            "stroke": (floor_margin(act.stroke, r.stroke) if reached
                       else floor_margin(min(c["stroke_m"] for c in cases), r.stroke)),
            "blocked_force": floor_margin(static["blocked_force_N"], r.blocked_force),
            "holding_force": floor_margin(act.continuous_force, max(loads) if loads else 0.0) if loads and max(loads) > 0 else 1.0,
            "speed": floor_margin(min(c["speed_m_s"] for c in cases), r.speed),
            "overshoot": ceiling_margin(max(c["overshoot"] for c in cases), req.options.max_overshoot),
            "temperature": temperature_margin(act.max_temperature, r.max_temperature),
        }
        out.append({
            "id": f"dc-{act.id}", "technology": "dc_motor", "variant": "catalog", "stage": "simulated",
            "components": {"actuator": act.id},
            "stack_params": {},          # no stacks: the key is kept so every candidate has the same keys
            "static": static,
            "simulated": {"stroke_m": worst["stroke_m"], "time_to_stroke_s": worst["time_to_stroke_s"],
                          "speed_m_s": min(c["speed_m_s"] for c in cases), "overshoot": worst["overshoot"],
                          "load_N": worst["load_N"], "cases": cases,
                          "peak_speed_m_s": max(c["peak_speed_m_s"] for c in cases)},
            "margins": margins,
            "metrics": dc_engine.metrics(act),
            "temperatures": {f"dc_actuator {act.id}": {"rated_degC": act.max_temperature,
                                                        "required_degC": r.max_temperature}},
            "design": {"technology": "dc_motor", "actuator": act.id, "step": r.stroke,
                       "duration": dc_duration(req), "temperature": r.max_temperature},
            "reason": "",
        })
        dc_assumed.fill(catalog, out[-1])
    return {"candidates": out, "actuators": dict(catalog.dc_actuators)}
