"""The DC motor option on the same requirements, load cases and metrics.

Each catalog DC actuator is simulated (``technologies/dc_motor/actuator.py``: seed eq. 13-14 with
the load term of docs/models.md and the catalog's PID) for a step of the
required stroke under each load case. A stroke counts as reached at 98 % of
the step (``actuator.SETTLED``); speed = that travel / the time to reach it.
"""
from __future__ import annotations

from ...io.catalog import Catalog
from ...io.requirements import RequirementsFile
from ...engine import holding
from . import actuator as dc_engine
from ...engine.rank import ceiling_margin, floor_margin
from ...engine.records import Simulation, frozen
from .records import DCActuatorDesign
from ..piezohydraulic.search import temperature_margin


def dc_duration(req: RequirementsFile) -> float:
    """Simulated time: long enough to settle, at least 1 s."""
    return max(1.0, 4.0 * req.stroke_time)


def actuator_designs(req: RequirementsFile, catalog: Catalog, loads: list[float]) -> tuple[DCActuatorDesign, ...]:
    """Every catalog DC actuator, simulated under every load case."""
    return tuple(actuator_design(req, act, loads) for act in catalog.dc_actuators.values())


def actuator_design(req: RequirementsFile, act, loads: list[float]) -> DCActuatorDesign:
    r = req.requirements
    static = dict(dc_engine.static_figures(act, max(loads) if loads else 0.0), free_stroke_m=act.stroke)
    cases = holding.held_cases(dc_engine.step_cases(act, r.stroke, loads, dc_duration(req)),
                               static["output_stiffness_N_m"])
    return DCActuatorDesign(act, frozen(static), Simulation(True, "", tuple(cases)),
                            frozen(_margins(req, act, static, cases, loads)), frozen(dc_engine.metrics(act)))


def _margins(req: RequirementsFile, act, static: dict, cases: list[dict], loads: list[float]) -> dict:
    r = req.requirements
    reached = all(c["stroke_m"] >= dc_engine.SETTLED * r.stroke for c in cases)
    k, worst = static["output_stiffness_N_m"], max(loads) if loads else 0.0
    return {
        # a servo settles on its reference: the stroke is the actuator's travel, once the
        # simulation shows the step reached (to 98 %) under every load (from neutral: less
        # the rest offset, engine/holding.py)
        "stroke": (floor_margin(holding.travel(req, act.stroke, k, worst), r.stroke) if reached
                   else floor_margin(min(holding.travel(req, c["stroke_m"], k, c["load_N"]) for c in cases),
                                     r.stroke)),
        **holding.margins(req, k),
        "blocked_force": floor_margin(static["blocked_force_N"], r.blocked_force),
        "holding_force": floor_margin(act.continuous_force, max(loads) if loads else 0.0) if loads and max(loads) > 0 else 1.0,
        "speed": floor_margin(min(c["speed_m_s"] for c in cases), r.speed),
        "overshoot": ceiling_margin(max(c["overshoot"] for c in cases), req.options.max_overshoot),
        "temperature": temperature_margin(act.max_temperature, r.max_temperature),
    }
