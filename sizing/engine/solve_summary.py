"""What ``solve`` says about its results: the requirements in SI, the
assumptions it made, a summary per technology (what blocks it), and the
time traces of the top designs for the report."""
from __future__ import annotations

import math
from collections import Counter

import numpy as np

from ..io.requirements import RequirementsFile
from ..physics import stack as stack_phys
from ..technologies.registry import technologies
from .candidate import Candidate
from .comparison import progress, technology_comparison

TRACE_POINTS = 600


def groups():
    """((technology, variant), Group) of every registered technology's groups, in order."""
    return tuple(((t.name, g.variant), g) for t in technologies() for g in t.groups)


def _requirements_si(req: RequirementsFile) -> dict:
    r, o = req.requirements, req.options
    return {"stroke_m": r.stroke, "blocked_force_N": r.blocked_force, "speed_m_s": r.speed,
            "max_temperature_degC": r.max_temperature, "stroke_time_s": req.stroke_time,
            "min_natural_frequency_Hz": req.natural_frequency, "max_overshoot": o.max_overshoot,
            "max_thermal_drift_m": o.max_drift_fraction * r.stroke,
            "min_stiffness_N_m": r.min_stiffness, "stroke_from": r.stroke_from,
            "options": o.model_dump(), "duty": req.duty.model_dump(), "envelope": req.envelope.model_dump()}


def _reached() -> str:
    """The technologies that count the stroke reached short of all of it
    (``Technology.reached``), each after its label."""
    said = [f"{t.label}: {t.reached}" for t in technologies() if t.reached]
    return f" ({'; '.join(said)})" if said else ""


def _assumptions(req: RequirementsFile) -> list[str]:
    o, r = req.options, req.requirements
    amp = ("the amplifier sits at the actuator and must work at the required temperature"
           if o.amplifier_location == "actuator" else
           f"the amplifier sits in a conditioned electronics bay at {o.electronics_bay_temperature:g} degC, "
           f"not at the actuator (options.amplifier_location = \"actuator\" to require {r.max_temperature:g} degC of it)")
    return [
        f"stack counts 1 to {o.max_stacks}; every stack, fluid, seal and amplifier of the catalog combined",
        f"static sizing margin {o.design_margin:.0%} on stroke and blocked force (the simulation then checks them)",
        ("wide-chamber oil gap sized: the stack stroke plus a clearance and a manufacturing tolerance"
         + (f", at least {o.wide_gap * 1e3:g} mm" if o.wide_gap else "") + "; oil volume = A_wide gap + A_narrow stroke"),
        "blocked force: the stack stroke over the summed compliances of the whole force path (stacks, base plate, "
        "tie-rod frame, wide piston, oil column at the required temperature, open accumulator, end cap, narrow piston), "
        "over R, less the seal friction at the blocked pressure; plates simply supported (Roark, mean deflection)",
        f"end caps, base plate and frame at least {o.structure_stiffness_ratio:g} x the stacks' stiffness and within "
        "half the yield; every structure material and compensator sized by its own geometric program",
        "seal friction grows with the chamber pressure (friction_per_length + friction_pressure_coefficient x p), "
        "in the static screen and in the simulation",
        f"amplifier continuous current over {req.duty.strokes_per_second:g} full strokes per second ([duty])",
        "pressure: the stack force over the wide piston must stay within the seal's pressure rating",
        f"drive current: the charge n C_large V that reaches the stroke must flow within stroke/speed = {req.stroke_time:g} s; "
        f"C_large = {stack_phys.LARGE_SIGNAL_CAPACITANCE_FACTOR:g} x the small-signal capacitance",
        "drive profile for the simulation: the voltage ramp sized with the amplifier units (the fewest units "
        "that reach the free stroke at the required speed and carry the duty, then the shortest ramp they drive), "
        "slowed to what the amplifier's slew rate allows",
        f"natural frequency at least {req.natural_frequency:.3g} Hz (10 cycles per stroke time unless options.min_natural_frequency); "
        f"simulated overshoot at most {o.max_overshoot:.0%}",
        "stroke under load: the aerodynamic load is a constant force; strokes are measured from the loaded rest; "
        "speed = required stroke / time to reach it" + _reached(),
        f"thermal drift of the enclosed oil from {o.drift_reference_temperature:g} to {r.max_temperature:g} degC must stay "
        f"within {o.max_drift_fraction:.0%} of the stroke unless compensated",
        ("compensated designs carry a catalog compensator (catalogs/compensators.toml) in their force path and "
         "simulation; passive designs a low-expansion spacer that cancels the thermal budget"
         if o.thermal_compensation else "no compensated designs evaluated"),
        amp,
        "temperature margin = (rated - required) / required, temperatures in kelvin",
        _envelope_statement(req),
        "end caps and base plate: Reissner-Mindlin plates (bending and shear), valid to thickness/radius "
        "0.5; a design whose plates would be thicker, or that leaves the envelope, is ruled out, not ranked",
        f"amplifier units in parallel, at most {o.max_amplifier_units}: a unit's peak current only within its rated "
        "pulse, the ramp and the duty's rms current otherwise on its continuous rating",
        f"stack self-heating: (pi/4) x 7 tan(delta) C V^2 f per stack (Noliac), shed at 10 W/(m^2 K) from its side",
        f"a leaking compensator's creep under the largest load is counted over a {req.duty.hold_time:g} s hold",
        "Bouc-Wen hysteresis of stacks without their own data is transferred in normalised form from the measured stack",
        "masses and costs of the hydraulic stage from physics/geometry.py (6061-T6, plate and thin-wall formulas, "
        "60 USD/kg machining, 1500 USD assembly)",
    ]


def _envelope_statement(req) -> str:
    env = req.envelope
    given = [f"{k} {v * f:g} {u}" for k, v, f, u in (("length", env.max_length, 1e3, "mm"),
                                                     ("diameter", env.diameter, 1e3, "mm"),
                                                     ("mass", env.max_mass, 1.0, "kg")) if v is not None]
    mass = "" if env.max_mass is not None else "; without a mass limit, 10 t is the plausibility ceiling"
    return "envelope: " + (", ".join(given) if given else "none given") + mass


def _group(c: Candidate) -> tuple[str, str]:
    return c.technology, c.variant or "catalog"


def _summary(req: RequirementsFile, candidates: list[Candidate], catalog, pruned=None) -> dict:
    """Per technology group: counts, best, what blocks it. ``pruned``: per
    technology, its combinations ruled out before sizing, counted by reason
    (they name the blocker of a group none of whose combinations was sized)."""
    out = []
    for key, group in groups():
        members = [c for c in candidates if _group(c) == key]
        feasible = [c for c in members if c.feasible]
        entry = {"technology": key[0], "variant": key[1], "label": group.label, "n_candidates": len(members),
                 "n_feasible": len(feasible)}
        ruled = (pruned or {}).get(key[0])
        if not members and ruled:
            entry["blocking"] = ruled.most_common(1)[0][0]
            entry["text"] = ("no feasible design: every combination was ruled out before sizing ("
                             + ", ".join(f"{k}: {n}" for k, n in ruled.most_common()) + ")")
            out.append(entry)
            continue
        if not members:
            entry["text"] = group.empty
            out.append(entry)
            continue
        best = min(members, key=lambda c: c.rank)
        furthest = max(members, key=progress)
        entry["best"] = best.id
        entry["drivers"] = dict(Counter(c.driver for c in members if not c.feasible).most_common())
        if feasible:
            entry["text"] = f"{len(feasible)} feasible; best ranked {_label(best)} (driver: {best.driver})"
            entry["text"] += group.caveat(req, feasible, catalog)
        else:
            m = furthest.margins[furthest.driver]
            entry["blocking"] = furthest.driver
            entry["closest"] = furthest.id
            entry["text"] = (f"no feasible design: blocked by {furthest.driver} - the candidate that gets furthest, "
                             f"{_label(furthest)} ({furthest.stage}), misses it {_pct(m)}")
        out.append(entry)
    return {"groups": out, "thermal": _thermal_statement(req, candidates),
            "comparison": technology_comparison(req, candidates, catalog),
            "feasible": sum(1 for c in candidates if c.feasible),
            "pareto": [c.id for c in candidates if c.pareto],
            **{k: v for t in technologies() for k, v in t.summary_fields(catalog, candidates).items()}}


def _label(c: Candidate) -> str:
    """What people read: the candidate's short name (the id is for machines)."""
    return c.name or c.id


def _pct(margin) -> str:
    """"by 35%", or "entirely" when the margin has no finite value."""
    if margin is None or not math.isfinite(margin):
        return "entirely"
    return f"by {-margin:.0%}" if margin < 0 else f"by {margin:.0%}"


def _thermal_statement(req, candidates) -> str:
    """The thermal budget in words, from the technologies that state one."""
    return " ".join(words for t in technologies() if t.thermal_statement is not None
                    and (words := t.thermal_statement(req, candidates)))


def downsample(t, y):
    t, y = np.asarray(t), np.asarray(y)
    step = max(1, len(t) // TRACE_POINTS)
    return t[::step].tolist(), y[::step].tolist()


def _traces(req, candidates, stages, loads, top=3) -> list[dict]:
    """Time traces of the top designs: the best feasible ones, the best of
    each technology group, re-simulated with their traces kept. ``stages``:
    the solve's records (``records.Stages``)."""
    chosen = [c for c in candidates if c.feasible][:top]
    for key, _ in groups():
        members = [c for c in candidates if _group(c) == key and c.stage in ("simulated", "sized")]
        if members and members[0] not in chosen:
            chosen.append(members[0])
    out, known = [], set()
    techs = {t.name: t for t in technologies()}
    for c in chosen:
        base = c.id
        if base in known or c.technology not in techs:
            continue
        known.add(base)
        sims = techs[c.technology].traces(req, c, stages, loads)
        if sims is None:
            continue
        cases = []
        for s in sims:
            t, y = downsample(s["t"], s["position_m"])
            cases.append({"load_N": s["load_N"], "t": t, "position_m": y})
        out.append({"id": c.id, "name": c.name or c.id, "technology": c.technology,
                    "feasible": c.feasible, "cases": cases})
    return out


def _clean(obj):
    """JSON-safe: numpy to Python, non-finite floats to None."""
    t = type(obj)
    if t is float:
        return obj if math.isfinite(obj) else None
    if t is str or t is int or t is bool or obj is None:
        return obj
    if t is dict:
        return {k if type(k) is str else str(k): _clean(v) for k, v in obj.items()}
    if isinstance(obj, dict):
        return {str(k): _clean(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_clean(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return _clean(obj.tolist())
    if isinstance(obj, (np.floating, float)):
        v = float(obj)
        return v if math.isfinite(v) else None
    if isinstance(obj, np.integer):
        return int(obj)
    if isinstance(obj, np.bool_):
        return bool(obj)
    return obj
