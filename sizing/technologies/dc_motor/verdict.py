"""The DC verdict on real parts: the best feasible DC design whose parts all
exist (each has values read from a maker's table, a datasheet or a
measurement, not only ``assumed:`` ones) beside the best on any parts, with what the latter rests
on. Best: lowest mass among the feasible, then cost (the ranking's first
objective; the seed's objectives are mass and cost)."""
from __future__ import annotations

from typing import TYPE_CHECKING

from ...engine.assumed import assumed_clause, in_words

if TYPE_CHECKING:
    from ...engine.candidate import Candidate

REAL = ("sourced", "datasheet", "measured")


def is_real(entry) -> bool:
    """A part that exists: at least one value from a maker's table, a
    datasheet or a measurement (a generic part's values are assumed, bar a
    setting such as the seed's loop rate)."""
    return any(text.split(":", 1)[0].strip() in REAL for text in entry.status.values())


def _real_design(catalog, c: Candidate) -> bool:
    for ident in (c.components or {}).values():
        if not isinstance(ident, str):
            continue
        try:
            _, entry = catalog.get(ident)
        except KeyError:
            return False
        if not is_real(entry):
            return False
    return True


def _brief(c: Candidate) -> dict:
    m = c.margins or {}
    driver = c.driver or (min(m, key=m.get) if m else None)
    sim = c.simulated or {}
    return {"id": c.id, "name": c.name, "components": c.components or {}, "mass_kg": c.metrics.get("mass_kg"),
            "cost_usd": c.metrics.get("cost_usd"), "driver": driver,
            "binding_margin": m.get(driver) if driver else None,
            "blocked_force_N": (c.static or {}).get("blocked_force_N"),
            "winding_temperature_degC": sim.get("winding_temperature_degC"),
            "speed_m_s": [case.get("speed_m_s") for case in sim.get("cases", [])],
            "rests_on_assumed": list(c.rests_on_assumed or ()), "rests_on_rules": c.own.get("rests_on_rules", [])}


def dc_sourced(catalog, candidates: list[Candidate]) -> dict:
    """``summary.dc_sourced``: {"best_on_sourced_parts", "best_on_any_parts",
    "best_on_sourced_parts_binding_on_no_assumed_value" (else
    "closest_on_sourced_parts_binding_on_no_assumed_value"), "feasible_on_sourced_parts", "feasible_on_any_parts", "text"}; a best is
    null when no feasible DC design exists on such parts."""
    dc = [c for c in candidates if c.technology == "dc_motor" and c.variant == "parts"
          and c.feasible and c.metrics]
    key = lambda c: (c.metrics.get("mass_kg", float("inf")), c.metrics.get("cost_usd", float("inf")))
    real = [c for c in dc if _real_design(catalog, c)]
    best_any = min(dc, key=key) if dc else None
    best_real = min(real, key=key) if real else None
    # real parts whose binding margin rests on no assumed value (a maker's rule may enter it);
    # when none is feasible, the closest such design
    firm_of = lambda pool: [c for c in pool if not any(x["decides"] for x in (c.rests_on_assumed or []))]
    firm = firm_of(real)
    best_firm = min(firm, key=key) if firm else None
    tried = firm_of([c for c in candidates if c.technology == "dc_motor" and c.variant == "parts"
                     and c.stage == "simulated" and c.driver and _real_design(catalog, c)])
    closest = max(tried, key=lambda c: c.margins[c.driver]) if tried and best_firm is None else None
    out = {"feasible_on_sourced_parts": len(real), "feasible_on_any_parts": len(dc),
           "best_on_sourced_parts": _brief(best_real) if best_real else None,
           "best_on_any_parts": _brief(best_any) if best_any else None,
           "best_on_sourced_parts_binding_on_no_assumed_value": _brief(best_firm) if best_firm else None,
           "closest_on_sourced_parts_binding_on_no_assumed_value": _brief(closest) if closest else None}
    out["text"] = _text(out, catalog)
    return out


def _label(entry: dict) -> str:
    """The short name people read (the id stays in the entry)."""
    return entry.get("name") or entry["id"]


def _text(out: dict, catalog=None) -> str:
    a, r = out["best_on_any_parts"], out["best_on_sourced_parts"]
    if a is None:
        return "No feasible DC design from parts."
    deciding = [in_words(catalog, x) for x in a["rests_on_assumed"] if x["decides"]]
    line = (f"Best DC design on any parts: {_label(a)} ({a['mass_kg']:.2f} kg, binding {a['driver']} "
            f"{a['binding_margin']:+.1%}); its binding margin rests on "
            + (f"{assumed_clause(deciding)}." if deciding else "no assumed value."))
    if r is None:
        return line + " No feasible DC design on sourced parts."
    if r["id"] == a["id"]:
        line += " It is also the best on sourced parts."
    else:
        line += (f" Best on sourced parts: {_label(r)} ({r['mass_kg']:.2f} kg, binding {r['driver']} "
                 f"{r['binding_margin']:+.1%}).")
    f = out["best_on_sourced_parts_binding_on_no_assumed_value"]
    if f is not None and f["id"] != r["id"]:
        line += (f" Best on sourced parts whose binding margin rests on no assumed value: {_label(f)} "
                 f"({f['mass_kg']:.2f} kg, binding {f['driver']} {f['binding_margin']:+.1%}).")
    c = out["closest_on_sourced_parts_binding_on_no_assumed_value"]
    if f is None and c is not None:
        line += (f" No feasible design on sourced parts has a binding margin free of assumed values; the closest, "
                 f"{_label(c)} ({c['mass_kg']:.2f} kg), misses {c['driver']} by {-c['binding_margin']:.1%}.")
    return line
