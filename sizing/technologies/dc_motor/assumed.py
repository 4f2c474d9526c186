"""What a DC design rests on: its parts' catalog values marked ``assumed:``
(``rests_on_assumed``, docs/formats.md) and, apart, those stated
from a maker's family rule (``rests_on_rules``), each with ``decides``:
the value enters the margin named by the candidate's driver.

``INPUTS`` lists, per DC margin, the fields of each part kind its formula
uses (``parts.static_screen``, the simulation in ``from_parts``, the
catalog actuators of ``catalog_actuators``).
"""
from __future__ import annotations

from ...engine.assumed import parts_of
from ...engine.rank import verdict

_LOAD_PATH = {"screw": {"lead", "efficiency"}, "gear": {"ratio", "efficiency"}}
_THERMAL = {"motor": {"winding_resistance", "resistance_temperature_coefficient", "thermal_resistance",
                      "torque_constant", "torque_constant_temperature_coefficient", "max_winding_temperature"}}
_FORCE = {"motor": {"torque_constant", "torque_constant_temperature_coefficient", "peak_torque",
                    "winding_resistance", "thermal_resistance"},
          "drive": {"peak_current"}, "gear": {"max_output_torque"}}
_DYNAMIC = {"motor": {"back_emf_constant", "winding_resistance", "resistance_temperature_coefficient",
                      "torque_constant", "torque_constant_temperature_coefficient", "rotor_inertia",
                      "viscous_damping", "max_speed", "thermal_resistance"},
            "drive": {"bus_voltage", "peak_current", "rate"},
            "gear": {"inertia", "max_input_speed"},
            "screw": {"inertia_per_length", "mass_per_length", "nut_mass", "max_speed"}}
_ACTUATOR_DYNAMIC = {"dc_actuator": {"c1", "c2", "current_limit", "supply_voltage", "back_emf_constant",
                                     "winding_resistance", "screw_lead", "screw_efficiency", "torque_constant",
                                     "stroke", "max_force"}}


def _merge(*maps) -> dict[str, set[str]]:
    """Union per part kind."""
    return {kind: set().union(*(m.get(kind, ()) for m in maps)) for kind in set().union(*maps)}


INPUTS: dict[str, dict[str, set[str]]] = {
    "blocked_force": _merge(_FORCE, _LOAD_PATH, {"dc_actuator": {"max_force", "torque_constant", "current_limit",
                                                                 "screw_lead", "screw_efficiency"}}),
    "speed": _merge(_DYNAMIC, _LOAD_PATH, _ACTUATOR_DYNAMIC),
    "stroke": _merge(_DYNAMIC, _LOAD_PATH, _ACTUATOR_DYNAMIC),
    "overshoot": _merge(_DYNAMIC, _LOAD_PATH, _ACTUATOR_DYNAMIC),
    "winding_temperature": _merge(_THERMAL, _LOAD_PATH, _DYNAMIC),
    "magnet_temperature": _merge(_THERMAL, _LOAD_PATH, {"motor": {"magnet_max_temperature"}}),
    "continuous_torque": _merge(_THERMAL, _LOAD_PATH, {"motor": {"continuous_torque"}}),
    "holding": _merge(_THERMAL, {"screw": {"lead"}, "gear": {"ratio", "efficiency"},
                                 "motor": {"thermal_time_constant"}}),
    "temperature": {k: {"max_temperature"} for k in ("motor", "screw", "gear", "dc_actuator")},
    "drive_temperature": {"drive": {"max_temperature"}},
    "drive_current": _merge(_THERMAL, _LOAD_PATH, {"drive": {"continuous_current"}}),
    "buckling": {"screw": {"diameter", "elastic_modulus"}},
    "screw_life": {"screw": {"dynamic_load_rating", "lead"}},
    "static_safety": _merge(_FORCE, _LOAD_PATH, {"screw": {"static_load_rating"}}),
    "gear_torque": {"gear": {"continuous_output_torque"}, "screw": {"lead", "efficiency"}},
    "mechanical_speed": _merge(_DYNAMIC, {"motor": {"max_speed"}, "gear": {"max_input_speed", "ratio"},
                                          "screw": {"max_speed", "lead"}}),
    "holding_force": {"dc_actuator": {"continuous_force"}},
}


def rests_on(parts: dict, driver: str | None, status: str = "assumed") -> list[dict]:
    """``[{"part", "field", "decides"}]`` for every value of ``parts`` (kind
    -> catalog entry or None) whose status starts with ``status``."""
    entering = INPUTS.get(driver or "", {})
    # the ambient margin is the lowest rating's: only the parts that hold it decide
    rated = {k: p.max_temperature for k, p in parts.items() if p is not None and k in entering
             and getattr(p, "max_temperature", None) is not None} if driver == "temperature" else {}
    lowest = min(rated.values(), default=None)
    out = []
    for kind, part in parts.items():
        if part is None:
            continue
        for name, text in part.status.items():
            if text.split(":", 1)[0].strip() == status:
                decides = name in entering.get(kind, ()) and (not rated or rated.get(kind) == lowest)
                out.append({"part": part.id, "field": name, "decides": decides})
    return out


def resting(catalog, components: dict, margins: dict) -> dict:
    """A DC candidate's ``rests_on_assumed`` and ``rests_on_rules`` ([] when
    none), judged against the margin that binds it."""
    parts = parts_of(catalog, components)
    _, driver = verdict(margins)
    return {"rests_on_assumed": rests_on(parts, driver, "assumed"), "rests_on_rules": rests_on(parts, driver, "rule")}
