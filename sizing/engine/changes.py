"""What a catalog (or model) change did to the ranking (``sizing solve --baseline``).

``rank_changes(baseline, results, catalog_diff)`` compares two results.json
dicts (docs/formats.md) candidate by candidate, matched by ``id``, and lists
the designs that entered or left the feasible set or the Pareto front,
appeared or disappeared, or moved in rank, with the catalog fields
responsible: the changed, added or removed entries among the candidate's
``components`` (from ``catalog_diff``), and, without a diff, the
``stack_params`` that differ between the two runs.

Pure data in, data out: no files, no printing.
"""
from __future__ import annotations

import math

from .candidate import Candidate, as_candidate
from .rank import OBJECTIVE_KEYS
from ..display import field_name, number, quantity
from ..technologies.registry import label

# order of the events in the list, most important first
EVENTS = ("entered_feasible", "left_feasible", "entered_pareto", "left_pareto",
          "new_candidate", "dropped_candidate", "rank_up", "rank_down")
_PARAM_TOL = 1e-9


def _as_dict(catalog_diff) -> dict | None:
    if catalog_diff is None:
        return None
    if isinstance(catalog_diff, dict):
        return catalog_diff
    return catalog_diff.to_dict()


def _index(results: dict) -> dict[str, Candidate]:
    """The candidates of a solve's results or of a results.json read back, by id."""
    return {c.id: c for c in map(as_candidate, (results or {}).get("candidates", []))}


def _component_ids(candidate: Candidate) -> list[str]:
    return [v for v in candidate.components.values() if isinstance(v, str)]


def _catalog_causes(candidate: Candidate, diff: dict | None) -> list[dict]:
    if not diff:
        return []
    ids = set(_component_ids(candidate))
    causes = []
    for entry in diff.get("changed", []):
        if entry["id"] in ids:
            for f in entry.get("fields", []):
                causes.append({"entry": entry["id"], "kind": entry.get("kind"), "field": f["field"],
                               "old": f.get("old"), "new": f.get("new"), "unit": f.get("unit"),
                               "relative_change": f.get("relative_change")})
    for key, word in (("added", "added"), ("removed", "removed")):
        for entry in diff.get(key, []):
            if entry["id"] in ids:
                causes.append({"entry": entry["id"], "kind": entry.get("kind"), "field": None,
                               "old": None, "new": None, "unit": None, "change": f"entry {word}"})
    return causes


def _param_causes(old: Candidate | None, new: Candidate | None) -> list[dict]:
    """Differences of ``stack_params`` between the two runs (SI, unit in the key)."""
    if old is None or new is None:
        return []
    a, b = old.own.get("stack_params") or {}, new.own.get("stack_params") or {}
    causes = []
    for key in sorted(set(a) | set(b)):
        x, y = a.get(key), b.get(key)
        if isinstance(x, (int, float)) and isinstance(y, (int, float)):
            if math.isclose(x, y, rel_tol=_PARAM_TOL, abs_tol=0.0):
                continue
        elif x == y:
            continue
        stack = new.components.get("stack")
        causes.append({"entry": stack, "kind": "stack", "field": key, "old": x, "new": y, "unit": None,
                       "relative_change": (y / x - 1) if isinstance(x, (int, float)) and isinstance(y, (int, float)) and x else None,
                       "change": "stack_params differ between the runs"})
    return causes


def _summary(cid: str, events: list[str], old_rank, new_rank, causes: list[dict], indirect: str = "") -> str:
    words = {"entered_feasible": "became feasible", "left_feasible": "is no longer feasible",
             "entered_pareto": "entered the Pareto front", "left_pareto": "left the Pareto front",
             "new_candidate": "is a new candidate", "dropped_candidate": "is no longer a candidate"}
    parts = [words[e] for e in events if e in words]
    if old_rank is not None and new_rank is not None and old_rank != new_rank:
        parts.append(f"rank {old_rank} -> {new_rank}")
    text = ", ".join(parts)
    named = []
    for c in causes:
        if c.get("field") is None:
            named.append(f"{c['entry']} {c.get('change', 'changed')}")
        elif isinstance(c.get("old"), (int, float)) and isinstance(c.get("new"), (int, float)):
            named.append(f"{c['entry']}.{c['field']} {_with_unit(c['field'], c['old'], c.get('unit'))} -> "
                         f"{_with_unit(c['field'], c['new'], c.get('unit'))}")
        else:
            named.append(f"{c['entry']}.{c['field']}")
    if named:
        text += "; because of " + ", ".join(named[:4]) + (f" and {len(named) - 4} more" if len(named) > 4 else "")
    elif indirect:
        text += f" ({indirect})"
    return text


def rank_changes(baseline: dict, results: dict, catalog_diff=None) -> list[dict]:
    """Designs whose standing changed between ``baseline`` and ``results``.

    Parameters
    ----------
    baseline, results : dict
        Two results (a solve's, or results.json read back; docs/formats.md);
        candidates matched by ``id``.
    catalog_diff : CatalogDiff, its ``to_dict()``, or None
        The catalog change between the two runs; used to name the fields
        responsible (entries among each candidate's ``components``).

    Returns
    -------
    list of dict, most important first, one per design that moved:
    ``id``, ``technology``, ``events`` (subset of ``EVENTS``),
    ``feasible`` / ``pareto`` / ``rank`` as [old, new] (None where absent),
    ``rank_move`` (old rank - new rank: positive is better, None if absent
    on one side), ``driver`` [old, new], ``causes`` (list of
    {entry, kind, field, old, new, unit, ...}) and a one-line ``summary``.
    """
    diff = _as_dict(catalog_diff)
    old_by_id, new_by_id = _index(baseline), _index(results)
    order = list(new_by_id) + [cid for cid in old_by_id if cid not in new_by_id]
    changes = []
    for cid in order:
        old, new = old_by_id.get(cid), new_by_id.get(cid)
        events = []
        if old is None:
            events.append("new_candidate")
        if new is None:
            events.append("dropped_candidate")
        of, nf = bool(old and old.feasible), bool(new and new.feasible)
        op, np_ = bool(old and old.pareto), bool(new and new.pareto)
        if nf and not of:
            events.append("entered_feasible")
        if of and not nf:
            events.append("left_feasible")
        if np_ and not op:
            events.append("entered_pareto")
        if op and not np_:
            events.append("left_pareto")
        old_rank, new_rank = (old.rank if old else None), (new.rank if new else None)
        move = old_rank - new_rank if old_rank is not None and new_rank is not None else None
        if move:
            events.append("rank_up" if move > 0 else "rank_down")
        if not events:
            continue
        # a candidate absent on one side: the diff decides from whichever side exists
        causes = _catalog_causes(new or old, diff)
        if not causes and diff is None:
            causes = _param_causes(old, new)
        events.sort(key=EVENTS.index)
        changes.append({
            "id": cid,
            "name": (new or old).name or cid,
            "technology": (new or old).technology,
            "events": events,
            "feasible": [old.feasible if old else None, new.feasible if new else None],
            "pareto": [old.pareto if old else None, new.pareto if new else None],
            "rank": [old_rank, new_rank],
            "rank_move": move,
            "driver": [old.driver if old else None, new.driver if new else None],
            "causes": causes,
            "summary": _summary(cid, events, old_rank, new_rank, causes, indirect=_indirect(baseline, results, diff)),
        })
    changes.sort(key=_importance)
    return changes


def _indirect(baseline: dict, results: dict, diff) -> str:
    """Why a design whose own parts did not change moved anyway."""
    if requirement_changes(baseline, results):
        return "its parts did not change: the requirements did"
    return "its own parts did not change: other designs moved" if diff is not None else ""


def _flat(d: dict, prefix: str = "") -> dict:
    out = {}
    for k, v in (d or {}).items():
        if isinstance(v, dict):
            out.update(_flat(v, f"{prefix}{k}."))
        else:
            out[f"{prefix}{k}"] = v
    return out


def requirement_changes(baseline: dict, results: dict) -> list[dict]:
    """The requirement, duty, envelope and option values (results.json
    ``requirements``, SI) that differ between the two runs; a value only
    one run records (an older results.json) is not called a change."""
    old, new = _flat(baseline.get("requirements") or {}), _flat(results.get("requirements") or {})
    out = []
    for key in sorted(set(old) & set(new)):
        a, b = old.get(key), new.get(key)
        same = (isinstance(a, (int, float)) and isinstance(b, (int, float))
                and math.isclose(a, b, rel_tol=_PARAM_TOL, abs_tol=0.0)) or a == b
        if not same:
            out.append({"field": key, "old": a, "new": b})
    return out


def change_causes(baseline: dict, results: dict, changes: list[dict], catalog_diff=None) -> dict:
    """What changed between the runs, cause by cause, and how many designs
    moved: ``requirements`` (field, old, new), ``catalog`` (entries changed,
    added, removed; None when the baseline's catalog is unknown),
    ``tool_version`` [old, new] when it differs, ``designs_moved`` and a
    one-line ``text`` (the terminal prints it)."""
    diff = _as_dict(catalog_diff)
    reqs = requirement_changes(baseline, results)
    catalog = None if diff is None else {k: len(diff.get(k, [])) for k in ("changed", "added", "removed")}
    versions = [baseline.get("tool_version"), results.get("tool_version")]
    parts = []
    if reqs:
        shown = ", ".join(requirement_words(reqs)[:3])
        parts.append(f"{len(reqs)} requirement value{'s' if len(reqs) > 1 else ''} changed ({shown}"
                     + (f" and {len(reqs) - 3} more" if len(reqs) > 3 else "") + ")")
    if catalog and any(catalog.values()):
        parts.append(f"catalog: {catalog['changed']} entries changed, {catalog['added']} added, {catalog['removed']} removed")
    if versions[0] != versions[1]:
        parts.append(f"tool version {versions[0]} -> {versions[1]}")
    moved = len(changes)
    causes = ("; ".join(parts) or "no requirement, catalog or version change") + f": {moved} design{'s' if moved != 1 else ''} changed standing"
    answer = answer_change(baseline, results)
    techs = technology_changes(baseline, results)
    return {"requirements": reqs, "catalog": catalog, "tool_version": versions if versions[0] != versions[1] else None,
            "designs_moved": moved, "answer": answer, "technologies": techs,
            "text": ". ".join([answer, *techs, causes])}


# requirement values people set, in their units: results.json key -> (name, unit, factor from SI)
SHOWN = {"stroke_m": ("stroke", "mm", 1e3), "blocked_force_N": ("blocked force", "N", 1.0),
         "speed_m_s": ("speed", "mm/s", 1e3), "max_temperature_degC": ("max temperature", "degC", 1.0),
         "envelope.max_length": ("envelope max length", "mm", 1e3),
         "envelope.max_diameter": ("envelope max diameter", "mm", 1e3),
         "envelope.max_width": ("envelope max width", "mm", 1e3), "envelope.max_mass": ("envelope max mass", "kg", 1.0),
         "min_natural_frequency_Hz": ("minimum natural frequency", "Hz", 1.0), "max_overshoot": ("max overshoot", "", 1.0)}
# values derived from the others (stroke time = stroke / speed ...): listed after those people set
DERIVED = ("stroke_time_s", "max_thermal_drift_m", "min_natural_frequency_Hz")


def recommended(results: dict) -> dict | None:
    """The design a results.json recommends: the technologies' best
    feasible designs, the lightest in the first objective (``summary.
    comparison.recommended`` where the results carry it)."""
    comparison = (results.get("summary") or {}).get("comparison") or {}
    if isinstance(comparison.get("recommended"), dict):
        rec = comparison["recommended"]
        tech = (comparison.get("technologies") or {}).get(rec.get("technology"), {})
        return dict(tech, technology=rec.get("technology"), best=rec.get("id", tech.get("best")),
                    name=rec.get("name", tech.get("name")))
    key = OBJECTIVE_KEYS.get((results.get("objectives") or ["mass"])[0], "mass_kg")
    feasible = [dict(t, technology=name) for name, t in (comparison.get("technologies") or {}).items() if t.get("feasible")]
    value = lambda t: (t.get("metrics") or {}).get(key)      # noqa: E731
    feasible = [t for t in feasible if isinstance(value(t), (int, float))]
    return min(feasible, key=value) if feasible else None


def _design_words(t: dict | None) -> str:
    if t is None:
        return "none (no technology meets every requirement)"
    figures = ", ".join(_metric(k, v) for k, v in (t.get("metrics") or {}).items())
    return f"{t.get('name') or t.get('best')} ({label(t['technology'])}{', ' + figures if figures else ''})"


def _metric(key: str, value) -> str:
    if not isinstance(value, (int, float)):
        return f"{key.split('_')[0]} n/a"
    return {"mass_kg": f"{value:.4g} kg", "cost_usd": f"{value:,.0f} USD", "volume_m3": f"{value * 1e3:.3g} L",
            "power_W": f"{value:.3g} W"}.get(key, f"{key} {value:.4g}")


def answer_change(baseline: dict, results: dict) -> str:
    """The first line of "What changed": whether the recommendation changed,
    from which design to which."""
    old, new = recommended(baseline), recommended(results)
    if (old or {}).get("best") == (new or {}).get("best"):
        return f"Recommendation unchanged: {_design_words(new)}"
    return f"Recommendation changed: {_design_words(old)} -> {_design_words(new)}"


def technology_changes(baseline: dict, results: dict) -> list[str]:
    """Per technology, its best design and verdict before and after."""
    old = ((baseline.get("summary") or {}).get("comparison") or {}).get("technologies") or {}
    new = ((results.get("summary") or {}).get("comparison") or {}).get("technologies") or {}
    lines = []
    for tech in dict.fromkeys([*new, *old]):
        a, b = old.get(tech), new.get(tech)
        word = lambda t: ("absent" if t is None else      # noqa: E731
                          f"{t.get('name') or t.get('best')} {'feasible' if t.get('feasible') else 'infeasible'}")
        same = a is not None and b is not None and a.get("best") == b.get("best") and a.get("feasible") == b.get("feasible")
        lines.append(f"{label(tech)}: {word(b)}" + (" (unchanged)" if same else f" (was {word(a)})"))
    return lines


def requirement_words(reqs: list[dict]) -> list[str]:
    """The requirement changes in people's names and units, those they set
    first, derived values after."""
    def shown(r):
        name, unit, factor = SHOWN.get(r["field"], (r["field"], "", 1.0))
        value = lambda v: f"{v * factor:.4g}" if isinstance(v, (int, float)) else str(v)    # noqa: E731
        return f"{name} {value(r['old'])} -> {value(r['new'])}{' ' + unit if unit else ''}"
    first = [r for r in reqs if r["field"] not in DERIVED]
    return [shown(r) for r in first] + [shown(r) for r in reqs if r["field"] in DERIVED]


def _with_unit(field: str, v, unit: str | None) -> str:
    """A catalog value in the unit given (SI), else the unit its key's suffix names."""
    if not isinstance(v, (int, float)) or isinstance(v, bool):
        return str(v)
    return f"{number(v)} {unit}" if unit else quantity(field, v)


def _importance(change: dict):
    first = min(EVENTS.index("rank_up" if e == "rank_down" else e) for e in change["events"])
    best_rank = min((r for r in change["rank"] if r is not None), default=math.inf)
    return (first, -abs(change["rank_move"] or 0), best_rank)
