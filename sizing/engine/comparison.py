"""The technologies side by side: for each, its best design, the check
that binds it (its smallest margin: the design driver when feasible, the
blocking requirement when not), and how far the best of each is from the
other in every objective."""
from __future__ import annotations

import math

from .rank import OBJECTIVE_KEYS
from .assumed import assumed_clause, in_words
from .candidate import Candidate
from .describe import describe
from .flip import smallest
from ..technologies.registry import get as technology, technologies



def actuator_noun(name: str) -> str:
    """What a technology's designs are called (its label and "actuator")."""
    tech = technology(name)
    return tech.actuator if tech is not None else name


STAGE_ORDER = {"pruned": 0, "gp_failed": 0, "gp_infeasible": 1, "sized": 2, "simulated": 3}


def progress(c: Candidate) -> tuple:
    """How far a candidate got (simulated > sized > pruned), then how close
    to feasible it is: the one that names what really blocks a technology."""
    m = c.margins.get(c.driver) if c.driver else None
    return STAGE_ORDER.get(c.stage, 0), (m if m is not None and math.isfinite(m) else -math.inf)


def _best(members: list[Candidate]) -> tuple[Candidate, bool]:
    feasible = [c for c in members if c.feasible]
    if feasible:
        return min(feasible, key=lambda c: c.rank), True
    return max(members, key=progress), False


# the one check a design can miss and still stand in for its technology:
# more amplifier units buy it back, so the design with the units it needs
# (their mass and cost added) is a like-for-like rival; a design that misses
# a requirement (speed, force, stroke) delivers less and is not
BOUGHT_CHECKS = ("amplifier_units",)


def _misses(c: Candidate) -> list[str]:
    return [k for k, v in c.margins.items() if v is None or not (v >= 0)]


def _with_what_it_needs(c: Candidate, req, catalog, keys) -> dict | None:
    """A design missing only the amplifier count, with the units it needs:
    {"units", "allowed", "metrics"} (the added units' mass and cost), or
    None when its needs cannot be priced."""
    needed = c.static.get("amplifier_units_needed")
    amp = catalog.amplifiers.get(c.components.get("amplifier")) if catalog is not None else None
    if needed is None or amp is None:
        return None
    allowed = req.options.max_amplifier_units
    extra = max(float(needed) - min(float(needed), allowed), 0.0)
    metrics = dict(c.metrics)
    for key, per_unit in (("mass_kg", amp.mass), ("cost_usd", amp.cost_usd)):
        if metrics.get(key) is not None:
            metrics[key] = metrics[key] + extra * per_unit
    return {"units": int(needed), "allowed": int(allowed), "metrics": {k: metrics.get(k) for k in keys}}


def _one_miss(members, keys, req=None, catalog=None):
    """The fair stand-in when a technology has no feasible design: the design
    that misses only the amplifier count, with the units it needs, best in
    the objectives (then the next); else the design that misses exactly one
    check, best in the objectives, marked not comparable (it delivers less
    than required, so no ratio is drawn from it)."""
    ones = [c for c in members if c.stage == "simulated" and len(_misses(c)) == 1
            and all(c.metrics.get(k) is not None for k in keys)]
    bought = []
    for c in ones:
        needs = _with_what_it_needs(c, req, catalog, keys) if _misses(c)[0] in BOUGHT_CHECKS and req else None
        if needs is not None:
            bought.append((c, needs))
    if bought:
        c, needs = min(bought, key=lambda cn: tuple(cn[1]["metrics"][k] for k in keys))
        return c, needs
    if ones:
        return min(ones, key=lambda c: tuple(c.metrics[k] for k in keys)), None
    return None, None


def technology_comparison(req, candidates: list[Candidate], catalog=None, flips: dict | None = None) -> dict:
    """{technology: {best, feasible, binding, binding_margin, metrics, flips, flip}, text}.
    ``flips``: per technology its re-solved flips (``flip.flips``); None
    when they were not computed (``solve --fast``)."""
    keys = [OBJECTIVE_KEYS[k] for k in req.objectives.minimize]
    out, lines = {}, []
    labelled = [(t.name, t.label) for t in technologies()]
    for tech, label in labelled:
        members = [c for c in candidates if c.technology == tech and c.metrics]
        if not members:
            continue
        best, ok = _best(members)
        m = best.margins.get(best.driver) if best.driver else None
        out[tech] = {"best": best.id, "name": best.name or best.id, "feasible": ok, "binding": best.driver, "binding_margin": m,
                     "metrics": {k: best.metrics.get(k) for k in keys},
                     "n_feasible": sum(1 for c in members if c.feasible)}
        out[tech]["flips"] = None if flips is None else flips.get(tech, [])
        out[tech]["flip"] = smallest(out[tech]["flips"])
        held = _holding(best)
        if held is not None:
            out[tech]["holding"] = held
        rests = list(best.rests_on_assumed)
        out[tech]["rests_on_assumed"] = rests
        out[tech]["deciding_assumed"] = [f"{r['part']}.{r['field']}" for r in rests if r.get("decides")]
        out[tech]["deciding_assumed_words"] = [in_words(catalog, r) for r in rests if r.get("decides")]
        out[tech]["description"] = describe(best, catalog)
        near, needs = (None, None) if ok else _one_miss(members, keys, req, catalog)
        if near is not None:
            out[tech]["one_miss"] = {"id": near.id, "name": near.name or near.id, "misses": _misses(near)[0],
                                     "comparable": needs is not None,
                                     "metrics": needs["metrics"] if needs else {k: near.metrics.get(k) for k in keys}}
            if needs is not None:
                out[tech]["one_miss"]["needs"] = {"amplifier_units": needs["units"], "allowed": needs["allowed"],
                                                  "metrics_as_sized": {k: near.metrics.get(k) for k in keys}}
        figures = ", ".join(format_metric(k, best.metrics.get(k)) for k in keys)
        if ok:
            lines.append(f"{label}: best {best.name or best.id} ({figures}); binding check {best.driver} "
                         f"(margin {m:+.1%})")
        else:
            lines.append(f"{label}: no feasible design; the closest, {best.name or best.id} ({figures}), "
                         f"misses {best.driver} {_miss(m)}")
            if near is not None:
                lines.append(_one_miss_text(label, out[tech]["one_miss"], keys))
    for tech, label in labelled:
        if tech in out:
            lines.append(f"{label}: " + _rests_text(out[tech]) + "; " + _flip_text(out[tech]))
    held = [(label, out[tech]["holding"]) for tech, label in labelled if tech in out and "holding" in out[tech]]
    if held:
        lines.append(_holding_text(held))
    for t in technologies():                # a technology's own figures beside its verdict
        if t.name in out and t.comparison_fields is not None:
            out[t.name].update(t.comparison_fields(req, candidates))
            lines.append(t.comparison_words(out[t.name]))
    for t in technologies():
        if t.name in out and t.compared_with in out:
            lines.append(_ratio_line(out[t.name], out[t.compared_with], keys, t.label, technology(t.compared_with).label))
    return {"technologies": out, "text": ". ".join(lines) + ("." if lines else ""),
            "recommendation": _recommendation(out, keys)}


def _holding(best: Candidate) -> dict | None:
    """How the best design holds the surface under its largest load case:
    its output stiffness at rest, where the load leaves it at zero drive and
    the travel it reaches from neutral (engine/holding.py)."""
    k = best.static.get("output_stiffness_N_m")
    cases = best.simulated.get("cases") or []
    if k is None or not cases:
        return None
    worst = max(cases, key=lambda c: c["load_N"])
    return {"output_stiffness_N_m": k, "load_N": worst["load_N"], "rest_offset_m": worst.get("rest_offset_m"),
            "travel_from_neutral_m": worst.get("travel_from_neutral_m")}


def _holding_text(held: list) -> str:
    parts = []
    for label, h in held:
        offset, travel = h["rest_offset_m"], h["travel_from_neutral_m"]
        parts.append(f"{label} {h['output_stiffness_N_m']:.3g} N/m"
                     + (f", pushed back {offset * 1e3:.3g} mm" if offset is not None else "")
                     + (f", {travel * 1e3:.3g} mm from neutral" if travel is not None else ""))
    load = max(h["load_N"] for _, h in held)
    return f"holding the surface under the largest load ({load:.0f} N), output stiffness at rest: " + "; ".join(parts)


def _one_miss_text(label, entry, keys) -> str:
    figures = ", ".join(format_metric(k, entry["metrics"].get(k)) for k in keys)
    if entry.get("needs"):
        n = entry["needs"]
        return (f"the best {label} design that misses only the amplifier count, {entry['name']}, needs "
                f"{n['amplifier_units']} amplifier units ({n['allowed']} allowed): {figures} with them")
    return (f"the best {label} design that misses only one check, {entry['name']} ({figures}), misses "
            f"{entry['misses']}: it delivers less than required, so it is not compared")


def _rival(t):
    """What a technology is compared by: its best feasible design, or its
    one-miss design with what it needs; None when neither exists."""
    if t["feasible"]:
        return t
    near = t.get("one_miss")
    return near if near and near.get("comparable") else None


def _ratio_line(a, b, keys, label, other) -> str:
    """``label`` best over the ``other`` best in every objective (like with like:
    an infeasible side only through its one-miss design with what it needs)."""
    sides = [(name, t, _rival(t)) for name, t in ((label, a), (other, b))]
    missing = [name for name, _, r in sides if r is None]
    if missing:
        return f"{' and '.join(missing)}: no design to compare like with like (none meets every check but the amplifier count)"
    ma, mb = (r["metrics"] for _, _, r in sides)
    ratios = []
    for k in keys:
        x, y = ma.get(k), mb.get(k)
        if x and y and math.isfinite(x) and math.isfinite(y) and y > 0:
            ratios.append(f"{k.split('_')[0]} x{x / y:.3g}")
    names = [f"{name} " + ("best" if t["feasible"] else
                           f"{r['name']} with {r['needs']['amplifier_units']} amplifier units")
             for name, t, r in sides]
    return " / ".join(names) + ": " + (", ".join(ratios) or "not comparable")


def recommendation_sentence(out: dict, keys: list[str], pick: dict | None = None, clause: str = "") -> str:
    """The one-sentence answer; ``pick``: a candidate chosen by a policy
    (``studies/compliance.py``) instead of the nominal one, ``clause`` what
    the policy adds."""
    if pick is None:
        return _recommendation(out, keys, clause=clause)
    deciding = [f"{r['part']}.{r['field']}" for r in pick.rests_on_assumed or [] if r.get("decides")]
    entry = {"name": pick.name or pick.id, "metrics": pick.metrics, "deciding_assumed": deciding}
    best = out.get(pick.technology) or {}
    if best.get("best") == pick.id:          # the technology's best: its assumed values in words
        entry["deciding_assumed_words"] = best.get("deciding_assumed_words")
    return _recommendation(out, keys, (pick.technology, entry), clause)


def _recommendation(out: dict, keys: list[str], pick: tuple | None = None, clause: str = "") -> str:
    """One sentence: the feasible technology best in the first objective
    (or ``pick``: (technology, its entry)), against the other's best (or
    its one-miss design)."""
    feasible = {t: e for t, e in out.items() if e["feasible"]}
    if not feasible or not keys:
        return ("No technology meets every requirement: see what blocks each and what would flip it"
                + _own_clauses(out) + ".")
    key = keys[0]
    tech, best = pick or min(feasible.items(), key=lambda kv: kv[1]["metrics"].get(key) or math.inf)
    text = f"Choose the {actuator_noun(tech)}: {best['name']} ({format_metric(key, best['metrics'].get(key))})"
    for other, entry in out.items():
        if other == tech:
            continue
        rival = _rival(entry)
        if rival and rival["metrics"].get(key) and best["metrics"].get(key):
            ratio = rival["metrics"][key] / best["metrics"][key]
            what = (f"the best {actuator_noun(other)} design" if entry["feasible"] else
                    f"the {actuator_noun(other)} design {rival['name']} with the "
                    f"{rival['needs']['amplifier_units']} amplifier units it needs")
            text += (f", {ratio:.3g} x lighter than {what}" if key == "mass_kg"
                     else f", {ratio:.3g} x better in {key.split('_')[0]} than {what}")
    deciding = best.get("deciding_assumed_words") or best.get("deciding_assumed") or []
    if deciding:
        text += f"; its binding check rests on {assumed_clause(deciding)}"
    return text + clause + _own_clauses(out) + "."


def _own_clauses(out: dict) -> str:
    """The technologies' own figures (``comparison_words``), after the recommendation."""
    return "".join("; " + t.comparison_words(out[t.name]) for t in technologies()
                   if t.name in out and t.comparison_fields is not None)


def _rests_text(entry) -> str:
    rests, deciding = entry["rests_on_assumed"], entry.get("deciding_assumed_words") or entry["deciding_assumed"]
    if not rests:
        return "its best design rests on no assumed catalog value"
    text = f"its best design rests on {len(rests)} assumed catalog values"
    if deciding:
        shown = "; ".join(deciding[:4]) + (" ..." if len(deciding) > 4 else "")
        text += f", {len(deciding)} of them in its binding margin ({shown})"
    return text


def _flip_text(entry) -> str:
    if entry["flips"] is None:
        return "what would flip its verdict was not computed (solve --fast)"
    if entry["flip"] is None:
        return "no single requirement or deciding catalog value flips its verdict within the ranges searched"
    return f"what would flip it: {entry['flip']['text']}"


def format_metric(key, value) -> str:
    """An objective with its unit, as people read it (whole dollars)."""
    if value is None or not math.isfinite(value):
        return f"{key}: n/a"
    unit = {"mass_kg": "kg", "cost_usd": "USD", "volume_m3": "m^3", "power_W": "W"}[key]
    if key == "cost_usd":
        return f"{value:,.0f} {unit}"
    return f"{value:.4g} {unit}"


def _miss(m) -> str:
    """How far a check is missed: "by 35%"; "entirely" when the margin has no
    finite value (nothing of the requirement achieved, or no figure for it)."""
    return "entirely" if m is None or not math.isfinite(m) else f"by {-m:.0%}"
