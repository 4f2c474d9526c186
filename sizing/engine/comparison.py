"""The two technologies side by side: for each, its best design, the check
that binds it (its smallest margin: the design driver when feasible, the
blocking requirement when not), and how far the best of each is from the
other in every objective."""
from __future__ import annotations

import math

from .flip import smallest

LABELS = {"piezohydraulic": "piezohydraulic actuator", "dc_motor": "DC motor actuator",
          "piezo_pump": "piezo pump actuator"}
TECHNOLOGIES = (("piezohydraulic", "piezohydraulic"), ("dc_motor", "DC motor"), ("piezo_pump", "piezo pump"))

OBJECTIVE_KEYS = {"mass": "mass_kg", "cost": "cost_usd", "volume": "volume_m3", "power": "power_W"}
STAGE_ORDER = {"pruned": 0, "gp_failed": 0, "gp_infeasible": 1, "sized": 2, "simulated": 3}


def _closest(members):
    def key(c):
        m = c["margins"].get(c["driver"]) if c.get("driver") else None
        return STAGE_ORDER.get(c.get("stage"), 0), (m if m is not None and math.isfinite(m) else -math.inf)
    return max(members, key=key)


def _best(members):
    feasible = [c for c in members if c["feasible"]]
    if feasible:
        return min(feasible, key=lambda c: c["rank"]), True
    return _closest(members), False


def _one_miss(members, keys):
    """The design that misses exactly one check and is best in the first
    objective (then the next): the fair stand-in when a technology has no
    feasible design, rather than the design whose smallest miss is smallest."""
    def misses(c):
        return sum(1 for v in c["margins"].values() if v is None or not (v >= 0))
    ones = [c for c in members if c.get("stage") == "simulated" and misses(c) == 1
            and all(c["metrics"].get(k) is not None for k in keys)]
    return min(ones, key=lambda c: tuple(c["metrics"][k] for k in keys)) if ones else None


def technology_comparison(req, candidates: list[dict], catalog=None, flips: dict | None = None) -> dict:
    """{technology: {best, feasible, binding, binding_margin, metrics, flips, flip}, text}.
    ``flips``: per technology its re-solved flips (``flip.flips``); None
    when they were not computed (``solve --fast``)."""
    keys = [OBJECTIVE_KEYS[k] for k in req.objectives.minimize]
    out, lines = {}, []
    for tech, label in TECHNOLOGIES:
        members = [c for c in candidates if c["technology"] == tech and c.get("metrics")]
        if not members:
            continue
        best, ok = _best(members)
        m = best["margins"].get(best["driver"]) if best.get("driver") else None
        out[tech] = {"best": best["id"], "name": best.get("name", best["id"]), "feasible": ok, "binding": best.get("driver"), "binding_margin": m,
                     "metrics": {k: best["metrics"].get(k) for k in keys},
                     "n_feasible": sum(1 for c in members if c["feasible"])}
        out[tech]["flips"] = None if flips is None else flips.get(tech, [])
        out[tech]["flip"] = smallest(out[tech]["flips"])
        rests = best.get("rests_on_assumed") or []
        out[tech]["rests_on_assumed"] = rests
        out[tech]["deciding_assumed"] = [f"{r['part']}.{r['field']}" for r in rests if r.get("decides")]
        near = None if ok else _one_miss(members, keys)
        if near is not None:
            out[tech]["one_miss"] = {"id": near["id"], "misses": near["driver"],
                                     "metrics": {k: near["metrics"].get(k) for k in keys}}
        figures = ", ".join(format_metric(k, best["metrics"].get(k)) for k in keys)
        if ok:
            lines.append(f"{label}: best {best.get('name', best['id'])} ({figures}); binding check {best['driver']} "
                         f"(margin {m:+.1%})")
        else:
            lines.append(f"{label}: no feasible design; the closest, {best.get('name', best['id'])} ({figures}), "
                         f"misses {best['driver']} by {_miss(m)}")
            if near is not None:
                lines.append(f"the best {label} design that misses only one check, {near.get('name', near['id'])} "
                             f"({', '.join(format_metric(k, near['metrics'].get(k)) for k in keys)}), misses "
                             f"{near['driver']}")
    for tech, label in TECHNOLOGIES:
        if tech in out:
            lines.append(f"{label}: " + _rests_text(out[tech]) + "; " + _flip_text(out[tech]))
    if "piezo_pump" in out:
        out["piezo_pump"].update(pump_power(req, candidates))
        lines.append(_pump_power_text(out["piezo_pump"]))
    for first, second in (("piezohydraulic", "dc_motor"), ("piezo_pump", "dc_motor")):
        if first in out and second in out:
            lines.append(_ratio_line(out[first], out[second], keys, LABELS[first].removesuffix(" actuator")))
    return {"technologies": out, "text": ". ".join(lines) + ("." if lines else ""),
            "recommendation": _recommendation(out, keys)}


def pump_power(req, candidates) -> dict:
    """The pump's required output power (the largest load at the required
    speed) against the best demonstrated pump power (``pump.BEST_DEMONSTRATED_POWER_W``)."""
    from .pump import BEST_DEMONSTRATED_POWER_W, BEST_DEMONSTRATED_SOURCE
    loads = [k["load_N"] for c in candidates if c["technology"] == "piezo_pump"
             for k in (c.get("simulated") or {}).get("cases", [])]
    required = max(loads, default=0.0) * req.requirements.speed
    return {"required_output_power_W": required, "best_demonstrated_power_W": BEST_DEMONSTRATED_POWER_W,
            "best_demonstrated_source": BEST_DEMONSTRATED_SOURCE}


def _pump_power_text(entry) -> str:
    need, best = entry["required_output_power_W"], entry["best_demonstrated_power_W"]
    return (f"the piezo pump must deliver {need:.3g} W at the output ({need / best:.2g} x the best demonstrated "
            f"piezo pump, {best:.3g} W)")


def _ratio_line(a, b, keys, label) -> str:
    """``label`` best over the DC best in every objective."""
    ma, mb = (t.get("one_miss", t)["metrics"] for t in (a, b))   # an infeasible side: its one-miss design
    ratios = []
    for k in keys:
        x, y = ma.get(k), mb.get(k)
        if x and y and math.isfinite(x) and math.isfinite(y) and y > 0:
            ratios.append(f"{k.split('_')[0]} x{x / y:.3g}")
    sides = [f"{name} " + ("best" if t["feasible"] else "one-miss design" if "one_miss" in t else "closest design")
             for name, t in ((label, a), ("DC motor", b))]
    return " / ".join(sides) + ": " + (", ".join(ratios) or "not comparable")


def _recommendation(out: dict, keys: list[str]) -> str:
    """One sentence: the feasible technology best in the first objective,
    against the other's best (or its one-miss design)."""
    feasible = {t: e for t, e in out.items() if e["feasible"]}
    if not feasible or not keys:
        return ("No technology meets every requirement: see what blocks each and what would flip it"
                + _pump_clause(out) + ".")
    key = keys[0]
    tech, best = min(feasible.items(), key=lambda kv: kv[1]["metrics"].get(key) or math.inf)
    text = f"Choose the {LABELS.get(tech, tech)}: {best['name']} ({format_metric(key, best['metrics'].get(key))})"
    for other, entry in out.items():
        if other == tech:
            continue
        rival = entry if entry["feasible"] else entry.get("one_miss")
        if rival and rival["metrics"].get(key) and best["metrics"].get(key):
            ratio = rival["metrics"][key] / best["metrics"][key]
            text += (f", {ratio:.3g} x lighter than the best {LABELS.get(other, other)} design" if key == "mass_kg"
                     else f", {ratio:.3g} x better in {key.split('_')[0]} than the best {LABELS.get(other, other)} design")
    deciding = best.get("deciding_assumed") or []
    if deciding:
        text += f"; its binding check rests on assumed {', '.join(deciding[:3])}"
    return text + _pump_clause(out) + "."


def _pump_clause(out: dict) -> str:
    entry = out.get("piezo_pump", {})
    return "; " + _pump_power_text(entry) if "required_output_power_W" in entry else ""


def _rests_text(entry) -> str:
    rests, deciding = entry["rests_on_assumed"], entry["deciding_assumed"]
    if not rests:
        return "its best design rests on no assumed catalog value"
    text = f"its best design rests on {len(rests)} assumed catalog values"
    if deciding:
        shown = ", ".join(deciding[:4]) + (" ..." if len(deciding) > 4 else "")
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
    return "an unbounded amount" if m is None or not math.isfinite(m) else f"{-m:.0%}"
