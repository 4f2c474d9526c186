"""What would flip a technology's verdict: the smallest single change of a
requirement or of a catalog value that makes an infeasible technology
feasible, or a feasible one infeasible.

Margins are linear in what sets them (``rank.floor_margin`` a / r - 1,
``rank.ceiling_margin`` 1 - a / A, the temperature margin (rated - T) / T),
so the value at which a margin m crosses zero is closed form:

    floor or temperature:  r' = r (1 + m)      (a requirement, or a rating a' = a / (1 + m))
    ceiling:               A' = A (1 - m)
    hold time (creep grows with it): h' = h / (1 - m)

An infeasible technology flips when one design's only missed margin
crosses zero: the smallest relaxation over its designs that miss exactly
one check. A feasible one flips when every feasible design misses: the
requirement tightened past the largest margin any of them has on it.
"""
from __future__ import annotations

import math


def _requirements(req) -> dict[str, tuple[str, float, str]]:
    """margin -> (what, today's value, how the margin moves with it)."""
    r, o = req.requirements, req.options
    return {
        "stroke": ("requirement stroke", r.stroke, "floor"),
        "blocked_force": ("requirement blocked_force", r.blocked_force, "floor"),
        "speed": ("requirement speed", r.speed, "floor"),
        "natural_frequency": ("option min_natural_frequency", req.natural_frequency, "floor"),
        "temperature": ("requirement max_temperature", r.max_temperature, "floor"),
        "thermal_drift": ("option max_drift_fraction", o.max_drift_fraction, "ceiling"),
        "overshoot": ("option max_overshoot", o.max_overshoot, "ceiling"),
        "compensator_hold": ("duty hold_time", req.duty.hold_time, "hold"),
        "amplifier_units": ("option max_amplifier_units", float(o.max_amplifier_units), "rating"),
    }


# margin -> (component kind, catalog field): a part's rating over what the design needs
RATINGS = {"amplifier_continuous_current": ("amplifier", "continuous_current"),
           "drive_current": ("amplifier", "max_current"),
           "pressure": ("seal", "pressure_rating"),
           "compensator_capacity": ("compensator", "capacity"),
           "amplifier_temperature": ("amplifier", "max_temperature"),
           "valve_resonance": ("valve", "max_frequency"),
           "accumulator_capacity": ("accumulator", "capacity")}


def _moved(value: float, margin: float, how: str) -> float:
    if how in ("floor",):
        return value * (1.0 + margin)
    if how == "rating":
        return value / (1.0 + margin)
    if how == "ceiling":
        return value * (1.0 - margin)
    return value / (1.0 - margin) if margin < 1.0 else math.inf     # hold


# how a person reads each changed value: (unit shown, factor from SI)
DISPLAY = {"requirement stroke": ("mm", 1e3), "requirement speed": ("mm/s", 1e3), "requirement blocked_force": ("N", 1.0),
           "requirement max_temperature": ("degC", 1.0), "duty hold_time": ("s", 1.0),
           "option min_natural_frequency": ("Hz", 1.0), "continuous_current": ("A", 1.0), "max_current": ("A", 1.0),
           "pressure_rating": ("MPa", 1e-6), "capacity": ("cm^3", 1e6), "max_temperature": ("degC", 1.0),
           "max_frequency": ("Hz", 1.0)}


def _shown(what: str, value: float) -> str:
    unit, factor = DISPLAY.get(what) or DISPLAY.get(what.split()[-1], ("", 1.0))
    return f"{value * factor:.4g} {unit}".strip()


def _change(what, old, new, design_id) -> dict:
    rel = abs(new / old - 1.0) if old else math.inf
    return {"what": what, "from": old, "to": new, "relative_change": rel, "design": design_id,
            "text": f"{what} from {_shown(what, old)} to {_shown(what, new)} ({rel:.1%})"}


def _relaxations(req, catalog, c) -> list[dict]:
    """Single changes that make design ``c`` (missing exactly one check) feasible."""
    missed = [k for k, v in c["margins"].items() if v is None or not v >= 0]
    if len(missed) != 1 or c["margins"][missed[0]] is None or not math.isfinite(c["margins"][missed[0]]):
        return []
    key, m = missed[0], c["margins"][missed[0]]
    out = []
    reqs = _requirements(req)
    if key in reqs:
        what, value, how = reqs[key]
        new = _moved(value, m, how) if how != "rating" else math.ceil(value / (1.0 + m) - 1e-9)
        out.append(_change(what, value, new, c["id"]))
    if key in RATINGS and catalog is not None:
        kind, field = RATINGS[key]
        part = _part(catalog, c.get("components", {}).get(kind))
        value = getattr(part, field, None) if part is not None else None
        if value:
            new = value - m * abs(value) if field == "max_temperature" else value / (1.0 + m)
            out.append(_change(f"{kind} {part.id} {field}", value, new, c["id"]))
    return out


def _part(catalog, ident):
    try:
        return catalog.get(ident)[1] if isinstance(ident, str) else None
    except KeyError:
        return None


def _tightenings(req, feasible: list[dict]) -> list[dict]:
    """Requirement changes that make every feasible design miss."""
    out = []
    for key, (what, value, how) in _requirements(req).items():
        if how == "rating":
            continue
        margins = [c["margins"].get(key) for c in feasible]
        if any(m is None or not math.isfinite(m) for m in margins):
            continue                          # a design that does not depend on it survives any change
        worst = max(margins, key=lambda m: m)
        best = max(feasible, key=lambda c: c["margins"][key])
        out.append(_change(what, value, _moved(value, worst, how), best["id"]))
    return out


def flip(req, catalog, members: list[dict]) -> dict | None:
    """The smallest single change that flips the verdict of a technology
    whose designs are ``members``; None when no single change is known to."""
    feasible = [c for c in members if c.get("feasible")]
    if feasible:
        options = _tightenings(req, feasible)
    else:
        options = [x for c in members for x in _relaxations(req, catalog, c)]
    options = [o for o in options if math.isfinite(o["relative_change"])]
    return min(options, key=lambda o: o["relative_change"]) if options else None
