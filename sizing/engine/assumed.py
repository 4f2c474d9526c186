"""What a design rests on: the catalog values marked ``assumed:`` among its
parts, and which of them enter the margin that binds it (``decides``).

``INPUTS`` says, per margin, which fields of which part kind enter it; a
field enters the binding margin when the candidate's driver lists it. The
map follows the formulas of ``verify.static_figures``, the margins of
``piezo_designs`` and the simulation (which uses every dynamic field).
"""
from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .candidate import Candidate

_STROKE = {"stack": {"stroke", "stroke_per_volt", "stiffness", "max_voltage", "stroke_temperature_coefficient"}}
_OIL = {"fluid": {"bulk_modulus", "bulk_modulus_temperature_coefficient"}}
_SEAL = {"seal": {"friction_per_length", "friction_pressure_coefficient", "breakaway_ratio"}}
_DRIVE = {"stack": {"capacitance"}, "amplifier": {"max_current", "continuous_current", "peak_duration", "slew_rate"}}
_PATH = {"material": {"youngs_modulus", "poisson"}, "compensator": {"volume_stiffness"}}
_DYNAMIC = {"fluid": {"density", "viscosity_40C", "viscosity_100C"}}


def _merge(*maps) -> dict[str, set[str]]:
    out: dict[str, set[str]] = {}
    for m in maps:
        for kind, names in m.items():
            out.setdefault(kind, set()).update(names)
    return out


_TEMPERATURE = {k: {"max_temperature", "min_temperature"}
                for k in ("stack", "fluid", "seal", "material", "compensator", "motor", "screw", "gear", "drive")}
INPUTS: dict[str, dict[str, set[str]]] = {
    "stroke": _merge(_STROKE, _OIL, _SEAL, _DRIVE, _PATH, _DYNAMIC),
    "speed": _merge(_STROKE, _OIL, _SEAL, _DRIVE, _PATH, _DYNAMIC),
    "overshoot": _merge(_STROKE, _OIL, _SEAL, _DRIVE, _PATH, _DYNAMIC),
    "blocked_force": _merge(_STROKE, _OIL, _SEAL, _PATH),
    "natural_frequency": _merge(_STROKE, _OIL, _PATH, {"fluid": {"density"}}),
    "temperature": _TEMPERATURE,
    "amplifier_temperature": {"amplifier": {"max_temperature"}},
    "pressure": _merge(_STROKE, {"seal": {"pressure_rating"}}),
    "drive_current": _DRIVE,
    "amplifier_continuous_current": _DRIVE,
    "amplifier_units": _DRIVE,
    "thermal_drift": {"fluid": {"thermal_expansion"}, "material": {"thermal_expansion"},
                      "stack": {"thermal_expansion"}},
    "compensator_capacity": {"compensator": {"capacity"}, "fluid": {"thermal_expansion"}},
    "compensator_hold": _merge({"compensator": {"leak_conductance"}}, _SEAL),
    "stack_temperature": {"stack": {"loss_factor", "capacitance", "max_temperature"}},
    "wide_gap": {"stack": {"stroke"}},
    "packing": {"stack": {"diameter"}},
    "work": {"stack": {"stiffness", "stroke", "max_voltage"}},
    # DC designs from parts (the fields of motors, screws, gears and drives)
    "winding_temperature": {"motor": {"winding_resistance", "thermal_resistance", "torque_constant",
                                      "max_winding_temperature"}, "screw": {"efficiency", "lead"},
                            "gear": {"efficiency", "ratio"}},
    "magnet_temperature": {"motor": {"max_magnet_temperature", "max_winding_temperature"}},
}


def rests_on(parts: dict[str, object], driver: str | None) -> list[dict]:
    """``[{"part", "field", "decides"}]`` for every assumed value of ``parts``
    (kind -> catalog entry or None), ``decides`` when it enters ``driver``'s margin."""
    entering = INPUTS.get(driver or "", {})
    out = []
    for kind, part in parts.items():
        if part is None or not hasattr(part, "assumed"):
            continue
        for field in part.assumed():
            out.append({"part": part.id, "field": field, "decides": field in entering.get(kind, ())})
    return out


def rests_on_components(catalog, components: dict, driver: str | None) -> list[dict]:
    """The same from a candidate's ``components`` (kind -> id): for results
    whose parts are named, not held. Ids the catalog does not hold are skipped."""
    return rests_on(parts_of(catalog, components), driver)


def parts_of(catalog, components: dict) -> dict:
    """{kind: catalog entry} of a candidate's ``components`` (kind -> id);
    ids the catalog does not hold, and non-id entries, are skipped."""
    parts = {}
    for ident in components.values():
        if not isinstance(ident, str):
            continue
        try:
            found_kind, entry = catalog.get(ident)
        except KeyError:
            continue
        parts[found_kind] = entry
    return parts


def of_candidates(catalog, candidates: list[Candidate]) -> list[list[dict]]:
    """Each ranked candidate's ``rests_on_assumed``, never null: the list
    its engine gave when it is the contract's, else read from its parts;
    each set of parts and driver read once (a solve ranks thousands of
    designs on a few hundred such sets)."""
    read: dict[tuple, list[dict]] = {}
    out = []
    for c in candidates:
        given = c.rests_on_assumed
        if given and all(isinstance(x, dict) for x in given):
            out.append(list(given))
            continue
        key = (tuple((k, v) for k, v in c.components.items() if isinstance(v, str)), c.driver)
        if key not in read:
            read[key] = rests_on_components(catalog, c.components, c.driver)
        out.append([dict(row) for row in read[key]])
    return out


def in_words(catalog, record: dict) -> str:
    """An assumed value as people read it, naming the part by maker and
    model rather than by catalog key: "the motor's max temperature, 100 degC
    (Allied Motion MF0127008_48V)". The key where the catalog
    does not hold the part."""
    from ..display import of_kind
    from ..io.catalog_diff import quantity_kind
    part, field = record["part"], record["field"]
    try:
        kind, entry = catalog.get(part)
    except (KeyError, AttributeError):
        return f"{part} {field}"
    value = getattr(entry, field, None)
    shown = f", {of_kind(value, quantity_kind(type(entry), field), field)}" if isinstance(value, (int, float)) else ""
    return f"the {kind.replace('_', ' ')}'s {field.replace('_', ' ')}{shown} ({_model(entry.name)})"


def _model(name: str) -> str:
    """A catalog name cut after its model number ("PI E-481 PICA high-power
    ..." -> "PI E-481"); up to its first comma when it has none."""
    words = name.split(",")[0].split(" (")[0].split()
    for i, word in enumerate(words):
        if any(ch.isdigit() for ch in word):
            return " ".join(words[: i + 1])
    return " ".join(words)


def assumed_clause(words: list[str], limit: int = 3) -> str:
    """ "one assumed value, the motor's ..." / "3 assumed values: ...; ...". """
    shown = "; ".join(words[:limit]) + (f" and {len(words) - limit} more" if len(words) > limit else "")
    return f"one assumed value, {shown}" if len(words) == 1 else f"{len(words)} assumed values: {shown}"
