"""``sizing robust``: probability of compliance of the best designs under
part tolerances (docs/formats.md, robust.json).

For each of the K best designs of ``sizing solve`` that its technology
lets robust perturb (``Technology.perturbable``), N samples of the
tolerated catalog fields that apply to the design (``tolerances.py``) are
drawn, and every sample is re-verified by the solve's own checks
(``Technology.verify_perturbed``: static figures, margins and a full
dynamic simulation under every load case). Work is split into tasks of one design x
one batch of samples, each seeded by (seed, design, batch), and run by
``executor.Executor`` (serial, local Dask cluster or a scheduler): the same
seed gives the same numbers wherever they ran.

Per design: P(compliance) with its 95 % Wilson interval, P per requirement,
and first-order RBD-FAST indices of the worst margin over the tolerances
(``stats.py``), the largest of which names the tolerance that drives failure.
With ``operating.temperature`` the samples also spread over the required
temperature range (``tolerances.py``), verified in groups of equal
(rounded) temperature.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..engine.candidate import Candidate, as_candidate
from ..engine.loads import load_cases
from ..engine.rank import nondominated_levels
from ..engine.sized import study_designs
from ..technologies.registry import get
from .executor import Executor, task_seed
from .stats import sensitivity, wilson
from .tolerances import Tolerance, applicable, factors, operating_temperatures, tolerances_of

BATCH = 250                 # samples per task: one vectorised simulation per load case
WORST_FLOOR = -1.0          # worst margin of a failed simulation, for the sensitivity


@dataclass
class BatchTask:
    req: object
    catalog: object
    design: object          # what engine.sized.study_designs gives for the candidate
    variant_id: str         # the candidate id to read
    tolerances: list[Tolerance]     # all of them: run_batch keeps those that apply to the design
    seed: int
    design_index: int
    batch_index: int
    size: int
    loads: list[float]
    technology: str         # whose ``verify_perturbed`` re-verifies the samples


def run_batch(task: BatchTask) -> dict:
    """One design x one batch: perturb the tolerances that apply to the
    design, re-verify, return margins per sample."""
    tols = applicable(task.tolerances, task.design)
    rng = task_seed(task.seed, task.design_index, task.batch_index)
    z = rng.standard_normal((task.size, len(tols)))
    f = factors(tols, z)
    r, o = task.req.requirements, task.req.options
    temps = operating_temperatures(tols, f, o.drift_reference_temperature, r.max_temperature)
    picked, sim_s = get(task.technology).verify_perturbed(task, tols, f, temps)
    keys = sorted({k for c in picked for k in c["margins"]})
    margins = {k: np.array([_finite(c["margins"].get(k)) for c in picked]) for k in keys}
    return {"keys": [t.key for t in tols], "z": z, "margins": margins,
            "feasible": np.array([c["feasible"] for c in picked]), "simulated_s": float(sim_s)}


def _finite(v) -> float:
    return -math.inf if v is None or (isinstance(v, float) and math.isnan(v)) else float(v)


def pick_designs(results: dict, k: int, technology: str | None = None) -> list[Candidate]:
    """The K best candidates robust can perturb, in rank order (their
    technology says which: ``Technology.perturbable``, some only when
    asked for by name); only ``technology``'s when given. ``results``: a
    solve's, or a results.json read back."""
    out = [c for c in map(as_candidate, results["candidates"]) if c.design is not None
           and (tech := get(c.technology)) is not None and tech.perturbable(c, technology)
           and technology in (None, c.technology)]
    return out[:k]


def robust(req, catalog, candidates: list, samples: int, seed: int, executor: Executor,
           progress=None, batch: int = BATCH, extra_spreads: dict | None = None, stages=None) -> dict:
    """robust.json for ``candidates`` (``pick_designs``'s, or results.json
    records). ``extra_spreads``:
    tolerances added to (and overriding) the requirements' ones, e.g. the
    Bouc-Wen spreads of a fit (``io.fit_spreads``). ``stages``: the solve's
    records (``SolveOutput.stages``), whose designs are taken as sized instead of being read back from results.json."""
    candidates = [as_candidate(c) for c in candidates]
    tols = tolerances_of({**req.tolerance_spreads, **(extra_spreads or {})})
    loads = [c["load_N"] for c in load_cases(req.load)]
    designs = study_designs(req, catalog, candidates, stages)
    tasks = []
    for d, (cand, design) in enumerate(zip(candidates, designs)):
        for b, start in enumerate(range(0, samples, batch)):
            tasks.append(BatchTask(req, catalog, design, cand.id, tols, seed, d, b,
                                   min(batch, samples - start), loads, cand.technology))
    done = executor.map(run_batch, tasks, progress=progress)
    out_designs = []
    for d, cand in enumerate(candidates):
        parts = [r for t, r in zip(tasks, done) if t.design_index == d]
        out_designs.append(_summarise(cand, parts, seed))
    _robust_front(out_designs)
    return {"samples": samples, "seed": seed, "tolerances": {t.key: t.spread for t in tols},
            "tolerances_source": "requirements [tolerances]" if req.tolerances is not None else "defaults",
            "sensitivity_method": "RBD-FAST first-order index (SALib rbd_fast) of the worst margin, "
                                  "on the Monte Carlo samples",
            "interval": "Wilson score, 95 %",
            "load_cases_N": loads, "where": executor.where,
            "simulated_candidate_s": float(sum(r["simulated_s"] for r in done)),
            "designs": out_designs}


def _summarise(cand: Candidate, parts: list[dict], seed: int) -> dict:
    """The design's figures over its samples; its sensitivity indices are
    over the tolerances that apply to it (``tolerances.applicable``)."""
    names = parts[0]["keys"]
    z = np.concatenate([p["z"] for p in parts])
    feasible = np.concatenate([p["feasible"] for p in parts])
    keys = sorted({k for p in parts for k in p["margins"]})
    margins = {k: np.concatenate([p["margins"].get(k, np.full(len(p["z"]), math.inf)) for p in parts]) for k in keys}
    n = len(feasible)
    ok = int(feasible.sum())
    worst = np.clip(np.min(np.vstack([margins[k] for k in keys]), axis=0), WORST_FLOOR, None)
    sens = sensitivity(names, z, worst, seed=seed)
    p_req = {k: float(np.mean(margins[k] >= 0)) for k in keys}
    failing = sorted((k for k in keys if p_req[k] < 1.0), key=p_req.get)
    return {"id": cand.id, "name": cand.name or cand.id, "technology": cand.technology,
            "rank": cand.rank,
            "nominal_feasible": cand.feasible, "nominal_driver": cand.driver,
            "p_compliance": ok / n, "p_ci95": list(wilson(ok, n)),
            "p_requirement": p_req,
            "p_requirement_ci95": {k: list(wilson(int(np.sum(margins[k] >= 0)), n)) for k in keys},
            "failing_requirements": failing,
            "sensitivity": sens,
            "driving_tolerance": max(sens, key=sens.get) if any(v > 0 for v in sens.values()) else None,
            "nominal_margins": {k: cand.margins[k] for k in keys if k in cand.margins},
            "margin_quantiles": {k: _quantiles(margins[k]) for k in keys},
            "metrics": {k: cand.metrics[k] for k in ("mass_kg", "cost_usd") if k in cand.metrics}}


def _quantiles(x: np.ndarray) -> dict:
    """5, 50 and 95 % quantiles of a margin; None where it is not finite
    (a failed simulation's margin is -inf)."""
    with np.errstate(invalid="ignore"):
        q = np.quantile(x, [0.05, 0.5, 0.95])
    return {k: (float(v) if np.isfinite(v) else None) for k, v in zip(("p05", "p50", "p95"), q)}


def _robust_front(designs: list[dict]) -> None:
    """Non-dominated over (mass, cost, 1 - P): ``robust_pareto``."""
    if not designs:
        return
    F = np.array([[d["metrics"].get("mass_kg", math.inf), d["metrics"].get("cost_usd", math.inf),
                   1.0 - d["p_compliance"]] for d in designs])
    level = nondominated_levels(F)
    for d, lv in zip(designs, level):
        d["robust_pareto"] = bool(lv == 1)
