"""The two technologies side by side: for each, its best design, the check
that binds it (its smallest margin: the design driver when feasible, the
blocking requirement when not), and how far the best of each is from the
other in every objective."""
from __future__ import annotations

import math

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


def technology_comparison(req, candidates: list[dict]) -> dict:
    """{technology: {best, feasible, binding, binding_margin, metrics}, text}."""
    keys = [OBJECTIVE_KEYS[k] for k in req.objectives.minimize]
    out, lines = {}, []
    for tech, label in (("piezohydraulic", "piezohydraulic"), ("dc_motor", "DC motor")):
        members = [c for c in candidates if c["technology"] == tech and c.get("metrics")]
        if not members:
            continue
        best, ok = _best(members)
        m = best["margins"].get(best["driver"]) if best.get("driver") else None
        out[tech] = {"best": best["id"], "feasible": ok, "binding": best.get("driver"), "binding_margin": m,
                     "metrics": {k: best["metrics"].get(k) for k in keys},
                     "n_feasible": sum(1 for c in members if c["feasible"])}
        figures = ", ".join(_fmt(k, best["metrics"].get(k)) for k in keys)
        if ok:
            lines.append(f"{label}: best {best['id']} ({figures}); binding check {best['driver']} "
                         f"(margin {m:+.1%})")
        else:
            lines.append(f"{label}: no feasible design; the closest, {best['id']} ({figures}), "
                         f"misses {best['driver']} by {_miss(m)}")
    if len(out) == 2:
        a, b = out["piezohydraulic"], out["dc_motor"]
        ratios = []
        for k in keys:
            x, y = a["metrics"].get(k), b["metrics"].get(k)
            if x and y and math.isfinite(x) and math.isfinite(y) and y > 0:
                ratios.append(f"{k.split('_')[0]} x{x / y:.3g}")
        tag = {(True, True): "both feasible", (True, False): "only piezohydraulic feasible",
               (False, True): "only DC motor feasible", (False, False): "neither feasible"}[(a["feasible"], b["feasible"])]
        lines.append(f"piezohydraulic best over DC best ({tag}): " + (", ".join(ratios) or "not comparable"))
    return {"technologies": out, "text": ". ".join(lines) + ("." if lines else "")}


def _fmt(key, value) -> str:
    if value is None or not math.isfinite(value):
        return f"{key}: n/a"
    unit = {"mass_kg": "kg", "cost_usd": "USD", "volume_m3": "m^3", "power_W": "W"}[key]
    return f"{value:.4g} {unit}"


def _miss(m) -> str:
    return "an unbounded amount" if m is None or not math.isfinite(m) else f"{-m:.0%}"
