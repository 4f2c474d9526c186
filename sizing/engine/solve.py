"""``sizing solve``: enumerate, size, verify by simulation, rank.

1. ``search.enumerate_combos``: every stack x fluid x seal x amplifier x
   stack count, pruned by temperature ratings, the work bound and the
   amplifier voltage, each with the requirement that rules it out.
2. ``piezo_designs``: one geometric program per surviving combination
   (and open accumulator) sizes R, the wide piston area, the drive voltage,
   the end cap / base plate thickness and the frame section with the whole
   force path in series; the other structure materials are re-sized in
   closed form.
3. The sized designs go through the same code as ``sizing evaluate``
   (``piezo.part_row``, ``verify.static_figures``, ``verify.metrics``), so
   their static figures agree with it, and are simulated under each load
   case (``verify.simulate_cases``), on and near the Pareto front first.
4. 100 degC: every design is kept as built ("uncompensated", judged on its
   whole thermal budget), with a passive low-expansion spacer where that
   cancels the budget ("passive"), and with each catalog compensator
   ("compensated"), each with its own margins.
5. The catalog's DC actuators are simulated under the same load cases and
   ranked in the same list (``dc_candidates.py``), and so are DC actuators
   sized from parts, motor x screw x gear x drive (``dc_sizing.py``).
"""
from __future__ import annotations

import copy
import math
import time
from collections import Counter
from dataclasses import dataclass, field

import numpy as np

from .. import __version__
from ..errors import SimulationError
from ..io.catalog import Catalog
from ..io.requirements import RequirementsFile
from ..physics import fluid as fluid_props
from ..physics import stack as stack_phys, thermal
from . import assumed, names, piezo_designs
from .dc_candidates import dc_candidates
from .dc_sizing import dc_parts_candidates
from .evaluate import load_cases
from .piezo import Candidates
from .piezo_designs import Variant, effective_gap, sizing_input, variants  # noqa: F401  (the module's API)
from .rank import ceiling_margin, floor_margin, nondominated_levels, rank_order, verdict
from .search import Combo, enumerate_combos
from .solve_summary import _assumptions, _clean, _requirements_si, _summary, _traces
from .verify import simulate_cases

SIM_CHUNK = 32
# margins the simulation order ignores: they depend on the duty or the
# compensation, not on what the simulation checks, and must not keep the
# designs that pass everything else from being simulated first
SCREEN_IGNORES = ("thermal_drift", "amplifier_continuous_current")
OBJECTIVE_KEYS = {"mass": "mass_kg", "cost": "cost_usd", "volume": "volume_m3", "power": "power_W"}


@dataclass
class SolveOutput:
    results: dict                                  # results.json
    traces: list = field(default_factory=list)     # time traces of the top designs, for the report


def _progress(callback, stage, done, total):
    if callback is not None:
        callback(stage, done, total)


def solve(req: RequirementsFile, requirements_sha256: str, catalog: Catalog, progress=None,
          detail: str = "summary") -> SolveOutput:
    """Run the whole search. ``progress(stage, done, total)`` is called while
    candidates are sized and simulated. ``detail``: "summary" counts the
    combinations ruled out before sizing by reason; "full" also keeps a
    record of each, with the nominal figures of its parts."""
    start = time.perf_counter()
    cases = load_cases(req.load)
    loads = [c["load_N"] for c in cases]
    combos = enumerate_combos(req, catalog)
    to_size = [c for c in combos if not c.pruned]
    sized = piezo_designs.size(req, catalog, to_size, progress)
    designs = piezo_designs.designs(req, catalog, sized)
    _simulate(req, designs, loads, progress)
    pruned = [c for c in combos if c.pruned]
    ruled_out = Counter(_pruned_reason(c) for c in pruned)
    piezo_pruned = Counter(ruled_out)
    dc_ruled = Counter()
    candidates = []
    if detail == "full":
        candidates = [_pruned_candidate(req, c) for c in pruned]
        piezo_designs.nominal_figures(req, catalog, pruned, candidates)
    excluded = []
    for d in designs:
        record = _ruled_out_record(d)
        if record is not None:
            excluded.append(record)
            ruled_out[record["reason"]] += 1
            continue
        candidates.extend(_design_candidates(req, d))
    dc = dc_candidates(req, catalog, loads) if req.options.dc_motors else []
    candidates.extend(dc["candidates"] if dc else [])
    parts = dc_parts_candidates(req, catalog, loads, progress) if req.options.dc_motors else {}
    for reason, count in parts.get("ruled_out", {}).items():
        dc_ruled[reason] += count
    for c in parts.get("candidates", []):
        if c.get("stage") == "pruned" and detail != "full":
            dc_ruled[_dc_pruned_reason(c)] += 1
        else:
            candidates.append(c)
    ruled_out.update(dc_ruled)
    if dc:
        dc["models"] = parts.get("models", {})
    _rank(req, candidates)
    candidates.sort(key=lambda c: c["rank"])
    assumed.fill(catalog, candidates)
    names.fill(candidates)
    results = {
        "tool_version": __version__,
        "requirements_sha256": requirements_sha256,
        "catalog_sha256": catalog.sha256,
        "candidates": candidates,
        "ruled_out": excluded,
        "requirements": _requirements_si(req),
        "load_cases": cases,
        "objectives": list(req.objectives.minimize),
        "assumptions": _assumptions(req),
        "summary": dict(_summary(req, candidates, catalog, piezo_pruned), ruled_out=dict(ruled_out.most_common()),
                        ruled_out_by_technology={
                            "piezohydraulic": dict((piezo_pruned + Counter(x["reason"] for x in excluded)).most_common()),
                            "dc_motor": dict(dc_ruled.most_common())}),
        "disagreements": _disagreements(designs),
        "hysteresis_time_scales": piezo_designs.hysteresis_time_scales(catalog),
        "counts": {"combinations": len(combos), "pruned": len(combos) - len(to_size), "sized": len(to_size),
                   "gp_feasible": sum(1 for d in designs if d["gp_success"]),
                   "simulated": sum(1 for d in designs if d["simulated"] is not None),
                   "dc_parts": _dc_counts(parts)},
    }
    traces = _traces(req, candidates, designs, dc, loads)
    if detail != "full":
        _keep_verified(results)
    results["runtime_s"] = time.perf_counter() - start
    return SolveOutput(results=_clean(results), traces=traces)


# --- verification ---------------------------------------------------------
def _simulate(req, designs, loads, progress) -> None:
    """Simulate the sized designs under every load case: the statically
    feasible ones on the Pareto front first, then the next fronts, then the
    rest, up to ``options.max_simulated``."""
    pool = [d for d in designs if d["gp_success"] and not d.get("ruled_out")]
    if not pool:
        return
    keys = [OBJECTIVE_KEYS[k] for k in req.objectives.minimize]
    F = np.array([[d["metrics"][k] for k in keys] for d in pool])
    ok = np.array([min(v for k, v in d["static_margins"].items() if k not in SCREEN_IGNORES) >= 0 for d in pool])
    level = np.full(len(pool), 10**6)
    if ok.any():
        level[ok] = nondominated_levels(F[ok])
    order = np.lexsort((level, ~ok))[: req.options.max_simulated]
    chosen = [pool[i] for i in order]
    # designs that differ only in the structure material have the same force
    # path (the material screen keeps the members' stiffness) and so the same
    # dynamics: simulate one of each and share the result
    twins: dict[tuple, list] = {}
    for d in chosen:
        twins.setdefault(_dynamic_key(d), []).append(d)
    unique = [group[0] for group in twins.values()]
    S = req.requirements.stroke
    for start in range(0, len(unique), SIM_CHUNK):
        chunk = unique[start:start + SIM_CHUNK]
        _simulate_chunk(chunk, loads, S)
        _progress(progress, "simulating", min(start + SIM_CHUNK, len(unique)), len(unique))
    for group in twins.values():
        for d in group[1:]:
            d["simulated"] = group[0]["simulated"]


def _dynamic_key(d) -> tuple:
    """What the simulation depends on, beyond the parts: the force path's
    mechanical and hydraulic stiffness, the ramp, the masses and the leak."""
    st, c = d["static"], d["cand"]
    comp = d["variant"].compensator
    return (d["combo"].key, comp.id if comp else None, f"{st['force_path_stiffness_N_m']:.9e}",
            f"{d['ramp']:.9e}", f"{float(c.wide_mass[0]):.9e}", f"{d['spacer']:.9e}")


def _simulate_chunk(chunk, loads, S) -> None:
    c = _stack_candidates([d["cand"] for d in chunk])
    ramps = np.array([d["ramp"] for d in chunk])
    try:
        sims = simulate_cases(c, loads, ramps, target_stroke=S)
    except SimulationError:
        if len(chunk) == 1:
            chunk[0]["simulated"] = {"failed": True, "cases": []}
            return
        for d in chunk:
            _simulate_chunk([d], loads, S)
        return
    for i, d in enumerate(chunk):
        d["simulated"] = {"cases": [{k: float(np.asarray(v)[i]) for k, v in case.items()} for case in sims]}


def _stack_candidates(parts: list[Candidates]) -> Candidates:
    from dataclasses import fields
    return Candidates(**{f.name: np.concatenate([getattr(p, f.name) for p in parts]) for f in fields(Candidates)})


def _sim_margins(req, sim) -> tuple[dict, dict]:
    """Margins and the contract's ``simulated`` figures from the cases."""
    r = req.requirements
    if sim.get("failed"):
        return {"simulation": -math.inf}, {"failed": True}
    cases = sim["cases"]
    worst = max(cases, key=lambda c: c["load_N"])
    figures = {"stroke_m": worst["stroke_m"], "time_to_stroke_s": worst["time_to_stroke_s"],
               "speed_m_s": min(c["speed_m_s"] for c in cases), "overshoot": worst["overshoot"],
               "load_N": worst["load_N"], "cases": cases}
    margins = {"stroke": floor_margin(min(c["stroke_m"] for c in cases), r.stroke),
               "speed": floor_margin(min(c["speed_m_s"] for c in cases), r.speed),
               "overshoot": ceiling_margin(max(c["overshoot"] for c in cases), req.options.max_overshoot)}
    return margins, figures


# --- candidates -------------------------------------------------------------
def _components(combo: Combo, ratio) -> dict:
    return {"stack": combo.stack.id, "n_stacks": combo.n, "ratio": ratio, "fluid": combo.fluid.id,
            "seal": combo.seal.id, "amplifier": combo.amplifier.id}


def _stack_params(combo: Combo) -> dict:
    s = combo.stack
    return {"stiffness_N_m": s.stiffness, "d33_m_V": s.stroke_per_volt, "max_voltage_V": s.max_voltage}


def _temperatures(combo: Combo) -> dict:
    return {k: {"rated_degC": a, "required_degC": b} for k, (a, b) in combo.temperatures.items()}


UNVERIFIED = ("sized", "gp_infeasible")
UNVERIFIED_REASON = "not simulated: misses a static check"
# a simulated design that misses a check by more than this (margin -0.5: it
# delivers half of what is asked, or needs twice what is allowed) is far from
# any design an engineer would adjust into compliance: counted, not recorded
FAR_MISS = -0.5
FAR_MISS_REASON = "simulated: misses {} by more than 50 %"


def _dropped_reason(c: dict, named: set) -> str | None:
    """Why a candidate's record is left out of the default results.json
    (None: it is kept)."""
    if c["feasible"] or c["id"] in named:
        return None
    if c.get("stage") in UNVERIFIED:
        return UNVERIFIED_REASON
    worst = c["margins"].get(c["driver"]) if c.get("driver") else None
    if worst is not None and worst < FAR_MISS:
        return FAR_MISS_REASON.format(c["driver"])
    return None


def _keep_verified(results: dict) -> None:
    """Keep the records of the designs that comply or come near (no check
    missed by more than 50 %) and of those the summary names (each group's
    best and closest, each technology's best and one-miss design, the design
    that flips its verdict); count the others by reason instead (``--detail
    full`` keeps them). Ranks stay contiguous."""
    summary = results["summary"]
    named = {g.get(k) for g in summary["groups"] for k in ("best", "closest")}
    for t in summary["comparison"]["technologies"].values():
        named |= {t.get("best"), (t.get("one_miss") or {}).get("id"), (t.get("flip") or {}).get("design")}
    kept, dropped = [], Counter()
    for c in results["candidates"]:
        why = _dropped_reason(c, named)
        if why is None:
            kept.append(c)
        else:
            dropped[(c["technology"], why)] += 1
    for rank, c in enumerate(kept, start=1):
        c["rank"] = rank
    results["candidates"] = kept
    for (tech, why), n in dropped.items():
        summary["ruled_out"][why] = summary["ruled_out"].get(why, 0) + n
        by_tech = summary["ruled_out_by_technology"].setdefault(tech, {})
        by_tech[why] = by_tech.get(why, 0) + n


def _pruned_reason(combo: Combo) -> str:
    """The requirement a combination ruled out before sizing misses most."""
    return min(combo.margins, key=lambda k: combo.margins[k])


def _dc_pruned_reason(c: dict) -> str:
    missed = [k for k, v in c.get("margins", {}).items() if v is not None and v < 0]
    return min(missed, key=lambda k: c["margins"][k]) if missed else "pruned"


def _ruled_out_record(d) -> dict | None:
    """One line for a design that is not a design (a plate beyond its model,
    a body outside the envelope): never ranked, plotted or named a best."""
    why = d.get("ruled_out")
    res = d["gp"]
    if why is None and not res.success and res.ruled_out is not None:
        why = {"reason": res.ruled_out, "detail": "no design of these parts fits: " + ", ".join(res.binding)}
    if why is None:
        return None
    return {"id": d["id"], "technology": "piezohydraulic", "variant": d["variant"].name, **why}


def _pruned_candidate(req, combo: Combo) -> dict:
    s, a = combo.stack, combo.amplifier
    reasons = [k for k, v in combo.margins.items() if v < 0]
    return {
        "id": combo.key, "technology": "piezohydraulic", "variant": "uncompensated", "stage": "pruned",
        "components": _components(combo, None), "stack_params": _stack_params(combo),
        "static": {"work_J": float(stack_phys.work_capacity(combo.n, s.stiffness, combo.stack_stroke * combo.voltage_fraction_max))},
        "simulated": {}, "margins": dict(combo.margins),
        "metrics": {"mass_kg": combo.n * s.mass + a.mass,
                    "cost_usd": combo.n * s.cost_usd + a.cost_usd},
        "metrics_lower_bound": True, "temperatures": _temperatures(combo),
        "reason": "ruled out before sizing: " + ", ".join(reasons),
    }


def _design_candidates(req, d) -> list[dict]:
    combo, res, var = d["combo"], d["gp"], d["variant"]
    comp = var.compensator
    components = dict(_components(combo, res.ratio), material=var.material.id,
                      compensator=comp.id if comp else None)
    base = {
        "id": combo.key + var.suffix(), "technology": "piezohydraulic", "variant": var.name,
        "components": components, "stack_params": _stack_params(combo), "temperatures": _temperatures(combo),
    }
    if d["index"] is None:
        return [dict(base, stage="gp_failed", static={}, simulated={},
                     margins={**combo.margins, res.driver or "solver": -math.inf},
                     metrics={}, reason=f"the geometric program failed ({res.status})")]
    margins = dict(d["static_margins"])
    margins["work"] = combo.margins["work"]
    simulated = {}
    if d["simulated"] is not None:
        sim_m, simulated = _sim_margins(req, d["simulated"])
        margins.update(sim_m)
    stage = "simulated" if simulated else ("sized" if res.success else "gp_infeasible")
    T = req.requirements.max_temperature
    f = combo.fluid
    st = d["static"]
    base.update({
        "stage": stage, "static": st, "simulated": simulated,
        "static_margins": d["static_margins"],
        "force_path": d["force_path"],
        "thermal_budget": {k: st["thermal_" + k] for k in (*thermal.TERMS, "net_m")},
        "seal_friction_N": d["seal_friction"],
        "compensator": _compensator_entry(comp, d),
        "design": {"technology": "piezohydraulic", "stack": combo.stack.id, "n_stacks": combo.n,
                   "voltage": d["cand"].voltage[0], "wide_diameter": st["wide_diameter_m"],
                   "narrow_diameter": st["narrow_diameter_m"], "fluid": f.id, "seal": combo.seal.id,
                   "amplifier": combo.amplifier.id, "wide_gap": st["wide_gap_m"], "rise_time": d["ramp"],
                   "temperature": T, "material": var.material.id, "end_cap_thickness": res.cap_thickness,
                   "frame_area": res.frame_area, "compensator": comp.id if comp else None,
                   "strokes_per_second": req.duty.strokes_per_second},
        "fluid_at_temperature": {
            "kinematic_viscosity_m2_s": float(fluid_props.kinematic_viscosity(f.viscosity_40C, f.viscosity_100C, T)),
            "bulk_modulus_Pa": float(d["cand"].bulk_modulus[0]),
            "flash_point_degC": f.flash_point},
        "bouc_wen_source": d["bouc_wen_source"],
        "hysteresis": (piezo_designs.hysteresis(combo.stack, d["bw"][0], float(d["cand"].voltage[0]), d["ramp"])
                       if d["simulated"] is not None else None),
        "gp": {"success": res.success, "status": res.status, "binding": res.binding, "slack": res.slack},
        "reason": "" if res.success else "no design of these parts meets: " + ", ".join(res.binding),
        "metrics": dict(d["metrics"]), "margins": margins,
    })
    if d["spacer"] > 0:
        base["passive_compensation"] = {"spacer_length_m": d["spacer"],
                                        "spacer_material": next(r["material"] for r in d["force_path"] if r["member"] == "spacer")}
        base["design"]["spacer_length"] = d["spacer"]
    return [base]


def _compensator_entry(comp, d) -> dict | None:
    if comp is None:
        return None
    k = next((r["stiffness_N_m"] for r in d["force_path"] if r["member"] == "compensator"), None)
    return {"id": comp.id, "kind": comp.kind, "stiffness_N_m": k, "leak_m3_s_Pa": comp.leak_conductance,
            "mass_kg": comp.mass, "cost_usd": comp.cost_usd, "capacity_m3": comp.capacity,
            "volume_taken_m3": d["static"]["thermal_compensator_volume_m3"]}


def _rank(req, candidates) -> None:
    keys = [OBJECTIVE_KEYS[k] for k in req.objectives.minimize]
    for c in candidates:
        c["feasible"], c["driver"] = verdict(c["margins"])
    feasible = np.array([c["feasible"] for c in candidates], dtype=bool)
    F = np.array([[_objective(c["metrics"].get(k)) for k in keys] for c in candidates], dtype=float)
    F = F.reshape(len(candidates), len(keys))
    worst = np.array([c["margins"][c["driver"]] if c["driver"] else -math.inf for c in candidates], dtype=float)
    rank = rank_order(feasible, F, worst)
    level = np.zeros(len(candidates), dtype=int)
    if feasible.any():
        level[feasible] = nondominated_levels(F[feasible])
    for i, c in enumerate(candidates):
        c["rank"] = int(rank[i])
        c["pareto"] = bool(feasible[i] and level[i] == 1)
        c["pareto_level"] = int(level[i]) if feasible[i] else None


def _dc_counts(parts: dict) -> dict:
    """DC combinations from parts: all of them, those ruled out (by reason,
    before or after the static screen) and those simulated."""
    records = parts.get("candidates", [])
    stages = [c["stage"] for c in records]
    ruled = sum(parts.get("ruled_out", {}).values()) + stages.count("pruned")
    return {"combinations": int(parts.get("combinations", len(records))), "pruned": ruled,
            "simulated": stages.count("simulated")}


def _objective(value) -> float:
    return math.inf if value is None or not math.isfinite(value) else float(value)


def _disagreements(designs) -> list[dict]:
    """Where the static screen and the simulation disagree on a requirement's
    verdict (one margin >= 0, the other < 0), or differ by more than 10 %."""
    out = []
    for d in designs:
        if not d.get("simulated") or d["simulated"].get("failed") or d["index"] is None:
            continue
        st = d["static"]
        cases = d["simulated"]["cases"]
        pairs = {"stroke": (st["free_stroke_m"], min(c["stroke_m"] for c in cases)),
                 "speed": (st["speed_m_s"], min(c["speed_m_s"] for c in cases))}
        sm = d["static_margins"]
        for key, (a, b) in pairs.items():
            req_value = a / (1 + sm[key])
            m_sim = b / req_value - 1
            flip = (sm[key] >= 0) != (m_sim >= 0)
            if flip or abs(b / a - 1) > 0.10:
                out.append({"id": d["id"], "requirement": key, "static": a, "simulated": b,
                            "static_margin": sm[key], "simulated_margin": m_sim, "verdict_changes": flip})
    return out



# --- hook for sizing robust: re-verify fixed designs ------------
def verify_sized(req, catalog: Catalog, sized: list, loads: list[float], chunk: int = SIM_CHUNK,
                 temperatures=None) -> list[list[dict]]:
    """Re-verify designs whose geometry is fixed, through the very steps of
    ``solve`` (static figures, margins, simulation under every load case,
    verdict). ``sized``: (Combo, Variant, SizingResult) triples, e.g. one design whose
    parts were perturbed. ``temperatures``: optional, per pair, the
    temperature its parts work at instead of the required maximum (ratings
    are still judged at the maximum, by the combo's margins). Returns, per
    triple, its candidates (uncompensated, and compensated when the options
    ask) with ``feasible`` and ``driver``. A triple's as-built variant also
    yields its passive variant when the sample drifts (``piezo_designs``)."""
    temps = [None] * len(sized) if temperatures is None else [float(t) for t in temperatures]
    designs, reqs = [None] * len(sized), {}
    for t in dict.fromkeys(temps):
        idx = [i for i, x in enumerate(temps) if x == t]
        reqs[t] = req if t is None else req.model_copy(update={
            "requirements": req.requirements.model_copy(update={"max_temperature": t})})
        # a shallow copy of each combo tells the designs apart (a passive
        # variant carries its parent's combo object)
        own = {i: (copy.copy(sized[i][0]),) + tuple(sized[i][1:]) for i in idx}
        built_t = piezo_designs.designs(reqs[t], catalog, [own[i] for i in idx])
        owner = {id(own[i][0]): i for i in idx}
        for i in idx:
            designs[i] = []
        for d in built_t:                             # the as-built ones, then their passive variants
            designs[owner[id(d["combo"])]].append(d)
    built = [d for ds in designs for d in ds if d["index"] is not None]
    for start in range(0, len(built), chunk):
        _simulate_chunk(built[start:start + chunk], loads, req.requirements.stroke)
    out = []
    for ds, t in zip(designs, temps):
        cands = []
        for d in ds:
            record = _ruled_out_record(d)
            for c in _design_candidates(reqs[t], d):
                if record is not None:          # a sample outside the members' validity or the envelope
                    c["margins"][record["reason"]] = -math.inf
                    c["ruled_out"] = record
                cands.append(c)
        for c in cands:
            c["feasible"], c["driver"] = verdict(c["margins"])
        out.append(cands)
    return out
