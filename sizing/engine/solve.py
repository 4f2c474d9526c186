"""``sizing solve``: enumerate, size, verify by simulation, rank.

1. ``search.enumerate_combos``: every stack x fluid x seal x amplifier x
   stack count, pruned by temperature ratings, the work bound and the
   amplifier voltage, each with the requirement that rules it out.
2. ``piezo_designs``: one geometric program per surviving combination
   and variant (structure material, compensator) sizes R, the wide piston
   area, the drive voltage and units, the end cap / base plate thickness,
   the frame section and the gap with the whole force path in series.
3. The sized designs go through the same code as ``sizing evaluate``
   (``piezo.part_row``, ``verify.static_figures``, ``verify.metrics``), so
   their static figures agree with it, and are simulated under each load
   case (``verify.simulate_cases``), on and near the Pareto front first.
4. 100 degC: every design is kept as built ("uncompensated", judged on its
   whole thermal budget), with a passive low-expansion spacer where that
   cancels the budget ("passive", sized again with the spacer), and with
   each catalog compensator ("compensated"), each with its own margins.
5. The catalog's DC actuators are simulated under the same load cases and
   ranked in the same list (``dc_candidates.py``), and so are DC actuators
   sized from parts, motor x screw x gear x drive (``dc_sizing.py``).
"""
from __future__ import annotations

import math
import time
from collections import Counter
from dataclasses import dataclass, field
from types import SimpleNamespace

import numpy as np

from .. import __version__
from ..errors import SimulationError
from ..io.catalog import Catalog
from ..io.requirements import RequirementsFile
from . import assumed, names, piezo_designs, stage_cache
from .candidate import design_candidate, pruned_candidate, ruled_out_record
from .dc_candidate import actuator_candidate, parts_candidate
from .dc_candidates import actuator_designs
from .comparison import technology_comparison
from .dc_sizing import dc_parts_designs
from .flip import flips
from .loads import load_cases
from .piezo import Candidates
from .pump import pump_designs
from .pump_candidate import pump_candidate
from .rank import OBJECTIVE_KEYS, nondominated_levels, standings, verdict
from .records import DCDesign, DCPartsOutcome, PiezoBrief, PiezoDesign, Simulation, Stages, VerifiedDesign
from .search import Combo, combos_of, enumerate_combos
from .solve_summary import _assumptions, _clean, _requirements_si, _summary, _traces
from .verify import simulate_cases

SIM_CHUNK = 32
# margins the simulation order ignores: they depend on the duty or the
# compensation, not on what the simulation checks, and must not keep the
# designs that pass everything else from being simulated first
SCREEN_IGNORES = ("thermal_drift", "amplifier_continuous_current")


@dataclass(frozen=True)
class SolveOutput:
    results: dict                                  # results.json
    traces: list = field(default_factory=list)     # time traces of the top designs, for the report
    stages: Stages = Stages()                      # the records behind the results (robust takes them)


def _progress(callback, stage, done, total):
    if callback is not None:
        callback(stage, done, total)


@dataclass(frozen=True)
class Outcome:
    """One technology's part of a solve: its candidate records (results.json
    ``candidates``), what it ruled out without recording, by reason, the
    one-line records of designs that are not designs (results.json
    ``ruled_out``) and its own counts."""

    technology: str
    candidates: list
    ruled_out: Counter = field(default_factory=Counter)
    records: tuple = ()
    counts: dict = field(default_factory=dict)

    @property
    def ruled_out_all(self) -> Counter:
        return self.ruled_out + Counter(r["reason"] for r in self.records)


def solve(req: RequirementsFile, requirements_sha256: str, catalog: Catalog, progress=None,
          detail: str = "summary", fast: bool = False) -> SolveOutput:
    """Run the whole search: each technology enumerates, sizes and verifies
    its designs (``_piezohydraulic``, ``_dc_motor``), then all are ranked in
    one list. ``progress(stage, done, total)`` is called while candidates are
    sized and simulated. ``detail``: "summary" counts the combinations ruled
    out before sizing by reason; "full" also keeps a record of each, with the
    nominal figures of its parts. ``fast``: no flips (``flips`` null)."""
    start = time.perf_counter()
    cases = load_cases(req.load)
    loads = [c["load_N"] for c in cases]
    piezo, verified = _piezohydraulic(req, catalog, loads, progress, detail)
    dc, dc_records = _dc_motor(req, catalog, loads, progress, detail)
    pump, pumps = _piezo_pump(req, catalog, loads, progress)
    outcomes = (piezo, dc, pump)
    unranked = [c for o in outcomes for c in o.candidates]
    ranking = standings([c["margins"] for c in unranked], [c["metrics"] for c in unranked],
                        [OBJECTIVE_KEYS[k] for k in req.objectives.minimize])
    ranked = sorted((dict(c, **s.fields()) for c, s in zip(unranked, ranking)), key=lambda c: c["rank"])
    candidates = [dict(c, rests_on_assumed=assumed.of_candidate(catalog, c), name=n)
                  for c, n in zip(ranked, names.unique(ranked))]
    stages = Stages.of(verified, dc_records, pumps)
    results = _results(req, requirements_sha256, catalog, cases, candidates, outcomes,
                       _disagreements(verified, {c["id"]: c["name"] for c in candidates}))
    results["flips_cost"] = None if fast else _with_flips(req, catalog, loads, candidates, results["summary"])
    traces = _traces(req, candidates, stages, loads)
    if detail != "full":
        results = _keep_verified(results)
    results["summary"]["counts"] = summary_counts(results)
    results["runtime_s"] = time.perf_counter() - start
    return SolveOutput(results=_clean(results), traces=traces, stages=stages)


def _results(req, requirements_sha256, catalog, cases, candidates, outcomes, disagreements) -> dict:
    """results.json from the ranked candidates and each technology's outcome."""
    piezo = outcomes[0]
    ruled_out = sum((o.ruled_out_all for o in outcomes), Counter())
    counts = dict(piezo.counts, dc_parts=outcomes[1].counts)
    counts.update({o.technology: o.counts for o in outcomes[2:]})
    return {
        "tool_version": __version__,
        "requirements_sha256": requirements_sha256,
        "catalog_sha256": catalog.sha256,
        "candidates": candidates,
        "ruled_out": [r for o in outcomes for r in o.records],
        "requirements": _requirements_si(req),
        "load_cases": cases,
        "objectives": list(req.objectives.minimize),
        "assumptions": _assumptions(req),
        "summary": dict(_summary(req, candidates, catalog, piezo.ruled_out), ruled_out=dict(ruled_out.most_common()),
                        ruled_out_by_technology={o.technology: dict(o.ruled_out_all.most_common()) for o in outcomes}),
        "disagreements": disagreements,
        "hysteresis_time_scales": piezo_designs.hysteresis_time_scales(catalog),
        "counts": counts,
    }


def technology_stages() -> SimpleNamespace:
    """Each technology's stages of the solve, for the re-solves of the flips
    (``resolve.py``): ``piezohydraulic``, ``dc_motor``, ``piezo_pump``."""
    return SimpleNamespace(piezohydraulic=_piezohydraulic, dc_motor=_dc_motor, piezo_pump=_piezo_pump)


def _with_flips(req, catalog, loads, candidates, summary) -> dict:
    """Re-solve what would flip each verdict (``flip.py``) and rebuild the
    comparison with it; returns what that cost."""
    start, cpu = time.perf_counter(), time.process_time()
    techs = summary["comparison"]["technologies"]
    with stage_cache.reuse():
        found, solves = flips(req, catalog, loads, candidates, {t: e["deciding_assumed"] for t, e in techs.items()},
                              technology_stages())
    summary["comparison"] = technology_comparison(req, candidates, catalog, flips=found)
    return {"re_solves": solves, "seconds": time.perf_counter() - start, "cpu_seconds": time.process_time() - cpu}


def _piezohydraulic(req, catalog, loads, progress, detail, only=None,
                    variants=None, parts=None) -> tuple[Outcome, list[VerifiedDesign]]:
    """Enumerate, size, build and verify the piezohydraulic designs
    (``only(combo)``: the combinations to keep, ``variants(combo, variant)``:
    the structure materials and compensators to size, ``parts``: the
    (stack, fluid, seal, amplifier) ids to enumerate, for a re-solve)."""
    combos = [c for c in _enumerated(req, catalog, parts) if only is None or only(c)]
    to_size = [c for c in combos if not c.pruned]
    pruned = [c for c in combos if c.pruned]
    brief = PiezoBrief.of(req)               # what the stages read of the requirements, once
    sized = piezo_designs.size(brief, catalog, to_size, progress, variants)
    designs = piezo_designs.resize_passive(brief, catalog, piezo_designs.designs(brief, catalog, sized))
    verified = [VerifiedDesign(d, sim) for d, sim in zip(designs, _simulate(req, designs, loads, progress))]
    candidates = []
    if detail == "full":
        candidates = [pruned_candidate(c, nominal)
                      for c, nominal in zip(pruned, piezo_designs.nominal_figures(brief, catalog, pruned))]
    records = []
    for v in verified:
        record = ruled_out_record(v.design)
        if record is None:
            candidates.append(design_candidate(req, v))
        else:
            records.append(record)
    counts = {"combinations": len(combos), "pruned": len(pruned), "sized": len(to_size),
              "gp_feasible": sum(1 for d in designs if d.gp.success),
              "simulated": sum(1 for v in verified if v.simulation is not None)}
    return Outcome("piezohydraulic", candidates, Counter(_pruned_reason(c) for c in pruned), tuple(records),
                   counts), verified


def _enumerated(req, catalog, parts=None) -> list[Combo]:
    """``enumerate_combos``, read back inside ``stage_cache.reuse()`` for the
    same requirements and catalog (the catalog is kept with it, so its id
    names it while kept); only the combinations of ``parts`` when given."""
    if parts is not None:
        counts = range(1, req.options.max_stacks + 1)
        return [c for s, f, seal, a in sorted(parts)
                for c in combos_of(req, catalog.stacks[s], catalog.fluids[f], catalog.seals[seal],
                                   catalog.amplifiers[a], counts)]
    if not stage_cache.active():
        return enumerate_combos(req, catalog)
    key = ("combos", id(catalog), req.model_dump_json())
    return stage_cache.cached(key, lambda: (catalog, enumerate_combos(req, catalog)))[1]


def _dc_motor(req, catalog, loads, progress, detail, rows=None) -> tuple[Outcome, tuple]:
    """The catalog's DC actuators and those sized from parts; also their
    records (the report's traces re-simulate them). ``rows``: the only
    designs from parts to size (``dc_parts_designs``), for a re-solve."""
    if not req.options.dc_motors:
        return Outcome("dc_motor", [], counts=_dc_counts(DCPartsOutcome())), ()
    actuators = actuator_designs(req, catalog, loads)
    parts = dc_parts_designs(req, catalog, loads, progress, rows=rows)
    dropped = detail != "full"          # a design ruled out before simulation is counted, not recorded
    kept = [d for d in parts.designs if not (dropped and d.stage == "pruned")]
    ruled = Counter(parts.ruled_out) + Counter(_dc_pruned_reason(d) for d in parts.designs
                                               if dropped and d.stage == "pruned")
    candidates = ([actuator_candidate(req, catalog, d) for d in actuators]
                  + [parts_candidate(req, catalog, d) for d in kept])
    return Outcome("dc_motor", candidates, ruled, (), _dc_counts(parts)), actuators + parts.designs


def _piezo_pump(req, catalog, loads, progress) -> tuple[Outcome, tuple]:
    """The frequency-rectified piezo pump (``pump.py``) and its records."""
    out = pump_designs(req, catalog, loads, progress)
    return Outcome("piezo_pump", [pump_candidate(req, d) for d in out.designs], Counter(out.ruled_out),
                   out.records, dict(out.counts)), out.designs


# --- verification ---------------------------------------------------------
def _simulate(req, designs: list[PiezoDesign], loads, progress) -> list[Simulation | None]:
    """Simulate the sized designs under every load case: the statically
    feasible ones on the Pareto front first, then the next fronts, then the
    rest, up to ``options.max_simulated``. Per design, its simulation or
    None (not simulated)."""
    out: list[Simulation | None] = [None] * len(designs)
    pool = [i for i, d in enumerate(designs) if d.gp.success and d.built and d.ruled_out is None]
    if not pool:
        return out
    keys = [OBJECTIVE_KEYS[k] for k in req.objectives.minimize]
    F = np.array([[designs[i].metrics[k] for k in keys] for i in pool])
    ok = np.array([min(v for k, v in designs[i].static_margins.items() if k not in SCREEN_IGNORES) >= 0
                   for i in pool])
    level = np.full(len(pool), 10**6)
    if ok.any():
        level[ok] = nondominated_levels(F[ok])
    chosen = [pool[j] for j in np.lexsort((level, ~ok))[: req.options.max_simulated]]
    # designs that differ only in the structure material have the same force
    # path (the material screen keeps the members' stiffness) and so the same
    # dynamics: simulate one of each and share the result
    twins: dict[tuple, list[int]] = {}
    for i in chosen:
        twins.setdefault(_dynamic_key(designs[i]), []).append(i)
    unique = [group[0] for group in twins.values()]
    S = req.requirements.stroke
    if stage_cache.active():      # simulated before with the same input (a flip's re-solves)
        for i in unique:
            out[i] = stage_cache.lookup(stage_cache.simulation_key(designs[i], loads, S))
        unique = [i for i in unique if out[i] is None]
    for start in range(0, len(unique), SIM_CHUNK):
        chunk = unique[start:start + SIM_CHUNK]
        for i, sim in zip(chunk, _simulate_chunk([designs[i] for i in chunk], loads, S)):
            out[i] = sim
            if stage_cache.active():
                stage_cache.remember(stage_cache.simulation_key(designs[i], loads, S), sim)
        _progress(progress, "simulating", min(start + SIM_CHUNK, len(unique)), len(unique))
    for group in twins.values():
        for i in group[1:]:
            out[i] = out[group[0]]
    return out


def _dynamic_key(d: PiezoDesign) -> tuple:
    """What the simulation depends on, beyond the parts: the force path's
    mechanical and hydraulic stiffness, the ramp, the masses and the leak."""
    comp = d.variant.compensator
    return (d.combo.key, comp.id if comp else None, f"{d.static['force_path_stiffness_N_m']:.9e}",
            f"{d.ramp:.9e}", f"{float(d.cand.wide_mass[0]):.9e}", f"{d.spacer:.9e}")


def _simulate_chunk(chunk: list[PiezoDesign], loads, S) -> list[Simulation]:
    """The simulations of ``chunk``, in order; a chunk that fails is retried
    design by design, so one failure is that design's alone."""
    c = _stack_candidates([d.cand for d in chunk])
    ramps = np.array([d.ramp for d in chunk])
    try:
        sims = simulate_cases(c, loads, ramps, target_stroke=S)
    except SimulationError as exc:
        if len(chunk) == 1:
            return [Simulation.failed(str(exc))]
        return [s for d in chunk for s in _simulate_chunk([d], loads, S)]
    return [Simulation(True, "", tuple({k: float(np.asarray(v)[i]) for k, v in case.items()} for case in sims))
            for i in range(len(chunk))]


def _stack_candidates(parts: list[Candidates]) -> Candidates:
    from dataclasses import fields
    return Candidates(**{f.name: np.concatenate([getattr(p, f.name) for p in parts]) for f in fields(Candidates)})


# --- candidates -------------------------------------------------------------
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


def _keep_verified(results: dict) -> dict:
    """Keep the records of the designs that comply or come near (no check
    missed by more than 50 %) and of those the summary names (each group's
    best and closest, each technology's best and one-miss design, the design
    that flips its verdict); count the others by reason instead (``--detail
    full`` keeps them). Ranks stay contiguous. Returns new results."""
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
    ruled = dict(summary["ruled_out"])
    by_tech = {t: dict(counts) for t, counts in summary["ruled_out_by_technology"].items()}
    for (tech, why), n in dropped.items():
        ruled[why] = ruled.get(why, 0) + n
        counts = by_tech.setdefault(tech, {})
        counts[why] = counts.get(why, 0) + n
    return dict(results, candidates=[dict(c, rank=rank) for rank, c in enumerate(kept, start=1)],
                summary=dict(summary, ruled_out=ruled, ruled_out_by_technology=by_tech))


def summary_counts(results: dict) -> dict:
    """Every count the terminal and the report show, in one place
    (results.json ``summary.counts``): per technology the combinations
    enumerated, those ruled out before sizing, the designs left out
    before ranking (by reason in ``summary.ruled_out_by_technology``), those
    ranked in ``candidates`` and the feasible ones; the piezohydraulic
    combinations sized and designs simulated; totals."""
    raw, by_tech = results["counts"], results["summary"]["ruled_out_by_technology"]
    cands = results["candidates"]
    stages = {"piezohydraulic": raw, "dc_motor": raw.get("dc_parts") or {}, "piezo_pump": raw.get("piezo_pump") or {}}
    out = {}
    for tech, own in stages.items():
        ranked = [c for c in cands if c["technology"] == tech]
        catalog_units = sum(1 for c in ranked if "actuator" in (c.get("components") or {}))
        before = int(own.get("pruned", 0)) if tech == "piezohydraulic" else 0
        out[tech] = {"combinations": int(own.get("combinations", 0)) + catalog_units,
                     "ruled_out_before_sizing": before,
                     "left_out": int(sum(by_tech.get(tech, {}).values())) - before,
                     "simulated": int(own.get("simulated", 0)),
                     "ranked": len(ranked), "feasible": sum(1 for c in ranked if c["feasible"])}
    out["piezohydraulic"]["sized"] = int(raw.get("sized", 0))
    out["ranked"] = len(cands)
    out["feasible"] = sum(1 for c in cands if c["feasible"])
    return out


def _pruned_reason(combo: Combo) -> str:
    """The requirement a combination ruled out before sizing misses most."""
    return min(combo.margins, key=lambda k: combo.margins[k])


def _dc_pruned_reason(d: DCDesign) -> str:
    """The check a DC design ruled out before simulation misses most (a NaN
    margin rules it out but names no check)."""
    missed = [k for k, v in d.margins.items() if v < 0]
    return min(missed, key=lambda k: d.margins[k]) if missed else "pruned"


def _dc_counts(parts: DCPartsOutcome) -> dict:
    """DC combinations from parts: all of them, those ruled out (by reason,
    before or after the static screen) and those simulated."""
    stages = [d.stage for d in parts.designs]
    return {"combinations": int(parts.combinations), "pruned": sum(parts.ruled_out.values()) + stages.count("pruned"),
            "simulated": stages.count("simulated")}


def _disagreements(verified: list[VerifiedDesign], names: dict | None = None) -> list[dict]:
    """Where the static screen and the simulation disagree on a requirement's
    verdict (one margin >= 0, the other < 0), or differ by more than 10 %;
    each with the design's short name (``names``: id -> name)."""
    out = []
    for v in verified:
        d, sim = v.design, v.simulation
        if sim is None or not sim.success or not d.built:
            continue
        st, cases, sm = d.static, sim.cases, d.static_margins
        pairs = {"stroke": (st["free_stroke_m"], min(c["stroke_m"] for c in cases)),
                 "speed": (st["speed_m_s"], min(c["speed_m_s"] for c in cases))}
        for key, (a, b) in pairs.items():
            req_value = a / (1 + sm[key])
            m_sim = b / req_value - 1
            flip = (sm[key] >= 0) != (m_sim >= 0)
            if flip or abs(b / a - 1) > 0.10:
                out.append({"id": d.id, "name": (names or {}).get(d.id, d.id), "requirement": key, "static": a, "simulated": b,
                            "static_margin": sm[key], "simulated_margin": m_sim, "verdict_changes": flip})
    return out


# --- hook for sizing robust: re-verify fixed designs ------------
def verify_sized(req, catalog: Catalog, sized: list, loads: list[float], chunk: int = SIM_CHUNK,
                 temperatures=None) -> list[list[dict]]:
    """Re-verify designs whose geometry is fixed, through the very steps of
    ``solve`` (static figures, margins, simulation under every load case,
    verdict). ``sized``: (Combo, Variant, SizingResult) triples, e.g. one design whose
    parts were perturbed. ``temperatures``: optional, per triple, the
    temperature its parts work at instead of the required maximum (ratings
    are still judged at the maximum, by the combo's margins). Returns, per
    triple, its candidates (uncompensated, and compensated when the options
    ask) with ``feasible`` and ``driver``. A triple's as-built variant also
    yields its passive variant when the sample drifts (``piezo_designs``)."""
    temps = [None] * len(sized) if temperatures is None else [float(t) for t in temperatures]
    per_triple: list[list[PiezoDesign]] = [[] for _ in sized]
    reqs = {}
    for t in dict.fromkeys(temps):
        idx = [i for i, x in enumerate(temps) if x == t]
        reqs[t] = req if t is None else req.model_copy(update={
            "requirements": req.requirements.model_copy(update={"max_temperature": t})})
        for d in piezo_designs.designs(PiezoBrief.of(reqs[t]), catalog, [sized[i] for i in idx]):
            per_triple[idx[d.origin]].append(d)      # the as-built ones, then their passive variants
    flat = [(i, j) for i, ds in enumerate(per_triple) for j, d in enumerate(ds) if d.built]
    sims = {}
    for start in range(0, len(flat), chunk):
        part = flat[start:start + chunk]
        done = _simulate_chunk([per_triple[i][j] for i, j in part], loads, req.requirements.stroke)
        sims.update(zip(part, done))
    return [[_judged(reqs[t], VerifiedDesign(d, sims.get((i, j)))) for j, d in enumerate(ds)]
            for i, (ds, t) in enumerate(zip(per_triple, temps))]


def _judged(req, v: VerifiedDesign) -> dict:
    """A re-verified design's candidate with its verdict; a sample outside
    the members' validity or the envelope misses that check."""
    c = design_candidate(req, v)
    record = ruled_out_record(v.design)
    if record is not None:
        c = dict(c, margins={**c["margins"], record["reason"]: -math.inf}, ruled_out=record)
    feasible, driver = verdict(c["margins"])
    return dict(c, feasible=feasible, driver=driver)
