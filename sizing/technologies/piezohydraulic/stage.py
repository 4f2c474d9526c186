"""The piezohydraulic stages of ``sizing solve``:

1. ``search.enumerate_combos``: every stack x fluid x seal x amplifier x
   stack count, pruned by temperature ratings, the work bound and the
   amplifier voltage, each with the requirement that rules it out.
2. ``designs``: one geometric program per surviving combination and
   variant (structure material, compensator) sizes R, the wide piston
   area, the drive voltage and units, the end cap / base plate thickness,
   the frame section and the gap with the whole force path in series.
3. The sized designs go through the same code as ``sizing evaluate``
   (``parts.part_row``, ``verify.static_figures``, ``verify.metrics``), so
   their static figures agree with it, and are simulated under each load
   case (``verify.simulate_cases``), on and near the Pareto front first.
4. 100 degC: every design is kept as built ("uncompensated", judged on its
   whole thermal budget), with a passive low-expansion spacer where that
   cancels the budget ("passive", sized again with the spacer), and with
   each catalog compensator ("compensated"), each with its own margins.

``verify_sized`` re-verifies designs of fixed geometry through the same
steps, for ``sizing robust`` and ``sizing evaluate``.
"""
from __future__ import annotations

import math
from collections import Counter

import numpy as np

from ...engine.rank import OBJECTIVE_KEYS, nondominated_levels, verdict
from ...engine import stage_cache
from ...engine.records import Outcome, Simulation
from .records import PiezoBrief, PiezoDesign, VerifiedDesign
from ...errors import SimulationError
from ...io.catalog import Catalog
from . import designs as piezo_designs
from .parts import Candidates
from .record import design_candidate, pruned_candidate, ruled_out_record
from .search import Combo, combos_of, enumerate_combos
from .verify import SETTLE_TIME_S, simulate_cases


def _progress(callback, stage, done, total):
    if callback is not None:
        callback(stage, done, total)


SIM_CHUNK = 32
# margins the simulation order ignores: they depend on the duty or the
# compensation, not on what the simulation checks, and must not keep the
# designs that pass everything else from being simulated first
SCREEN_IGNORES = ("thermal_drift", "amplifier_continuous_current")


def solve(req, catalog, loads, progress, detail, only=None,
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
    budget = piezo_simulation_budget(req, catalog, len(loads))
    verified = [VerifiedDesign(d, sim) for d, sim in zip(designs, _simulate(req, designs, loads, progress, budget))]
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
    if budget < req.options.max_simulated:     # the step limit, not options.max_simulated, capped it
        counts["simulations_within_step_limit"] = budget
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


def piezo_simulation_budget(req, catalog, n_loads: int) -> int:
    """How many piezohydraulic designs are simulated: ``options.max_simulated``,
    or fewer when their steps (stroke time plus settling at 20 kHz, per load
    case) would pass the step limit (``--max-steps``) left after the other
    technologies' (``registry.reserved_steps``: the DC catalog actuators'); 0 when not even one fits (a slow, long stroke: 100 mm at
    3 mm/s is 1.3e6 steps a design). The designs not simulated stay
    unverified, never feasible."""
    from ...limits import current, piezo_steps, simulations_within
    from ..registry import reserved_steps
    each = piezo_steps(req.stroke_time + SETTLE_TIME_S, max(n_loads, 1))
    return simulations_within(each, req.options.max_simulated,
                              current().steps - reserved_steps(req, catalog, but="piezohydraulic"))


def _simulate(req, designs: list[PiezoDesign], loads, progress, budget: int) -> list[Simulation | None]:
    """Simulate the sized designs under every load case: the statically
    feasible ones on the Pareto front first, then the next fronts, then the
    rest, up to ``budget`` (``piezo_simulation_budget``). Per design, its
    simulation or None (not simulated)."""
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
    chosen = [pool[j] for j in np.lexsort((level, ~ok))[:budget]]
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


def _pruned_reason(combo: Combo) -> str:
    """The requirement a combination ruled out before sizing misses most."""
    return min(combo.margins, key=lambda k: combo.margins[k])


def disagreements(verified: list[VerifiedDesign], names: dict | None = None) -> list[dict]:
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
