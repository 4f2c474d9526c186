"""``sizing robust``: probability of compliance of the best designs under
part tolerances (docs/formats.md, robust.json).

For each of the K best designs of ``sizing solve`` (piezohydraulic, and DC
designs sized from parts), N samples of the tolerated catalog fields that
apply to the design (``tolerances.py``) are drawn, and every sample is
re-verified by the solve's own checks (piezohydraulic:
``piezohydraulic.stage.verify_sized``; DC: ``technologies.dc_motor.from_parts.verify_parts``, with
the controller and drive limits kept as designed on the nominal parts:
static figures, margins and a full dynamic simulation under every load
case). Work is split into tasks of one design x
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

from ..engine.loads import load_cases
from ..technologies.piezohydraulic.parts import reference_bouc_wen, stack_bouc_wen
from ..engine.rank import nondominated_levels
from ..technologies.dc_motor.catalog_actuators import dc_duration
from ..technologies.dc_motor.from_parts import verify_parts
from ..engine.sized import DCPartsDesign, study_designs
from ..technologies.piezohydraulic.stage import verify_sized
from ..technologies.piezohydraulic.verify import SETTLE_TIME_S
from ..io.design import PumpDesignFile
from .executor import Executor, task_seed
from .stats import sensitivity, wilson
from .tolerances import (BOUC_WEN_PREFIX, Tolerance, applicable, factors, operating_temperatures, perturbed_combo,
                         perturbed_parts, tolerances_of)

BATCH = 250                 # samples per task: one vectorised simulation per load case
WORST_FLOOR = -1.0          # worst margin of a failed simulation, for the sensitivity


@dataclass
class BatchTask:
    req: object
    catalog: object
    design: object          # (Combo, Variant, SizingResult), or engine.sized.DCPartsDesign
    variant_id: str         # the candidate id to read
    tolerances: list[Tolerance]     # all of them: run_batch keeps those that apply to the design
    seed: int
    design_index: int
    batch_index: int
    size: int
    loads: list[float]


def run_batch(task: BatchTask) -> dict:
    """One design x one batch: perturb the tolerances that apply to the
    design, re-verify, return margins per sample."""
    tols = applicable(task.tolerances, task.design)
    rng = task_seed(task.seed, task.design_index, task.batch_index)
    z = rng.standard_normal((task.size, len(tols)))
    f = factors(tols, z)
    r, o = task.req.requirements, task.req.options
    temps = operating_temperatures(tols, f, o.drift_reference_temperature, r.max_temperature)
    verify = (_verify_dc if isinstance(task.design, DCPartsDesign)
              else _verify_pump if isinstance(task.design, PumpDesignFile) else _verify_piezo)
    picked, sim_s = verify(task, tols, f, temps)
    keys = sorted({k for c in picked for k in c["margins"]})
    margins = {k: np.array([_finite(c["margins"].get(k)) for c in picked]) for k in keys}
    return {"keys": [t.key for t in tols], "z": z, "margins": margins,
            "feasible": np.array([c["feasible"] for c in picked]), "simulated_s": float(sim_s)}


def _verify_piezo(task: BatchTask, tols: list[Tolerance], f: np.ndarray, temps) -> tuple[list[dict], float]:
    """The solve's own checks (``verify_sized``) of each perturbed sample;
    (the design's candidate per sample, simulated seconds)."""
    combo, variant, res = task.design
    bw = None
    if any(t.key.startswith(BOUC_WEN_PREFIX) for t in tols):
        bw = stack_bouc_wen(combo.stack, reference_bouc_wen(task.catalog.stacks))[0]
    sized = [(perturbed_combo(combo, tols, row, bw), variant, res) for row in f]
    verified = verify_sized(task.req, task.catalog, sized, task.loads, chunk=task.size, temperatures=temps)
    picked = [_pick(cands, task.variant_id) for cands in verified]
    sim_s = sum(sum(case["ramp_time_s"] + SETTLE_TIME_S for case in c["simulated"].get("cases", []))
                for c in picked)
    return picked, sim_s


def _verify_dc(task: BatchTask, tols: list[Tolerance], f: np.ndarray, temps) -> tuple[list[dict], float]:
    """The DC solve's checks (``dc_sizing.verify_parts``) of each perturbed
    sample, with the controller and drive limits as designed on the nominal
    parts; (per sample its verdict, simulated seconds)."""
    d = task.design
    n = f.shape[0]
    settings = {k: np.full(n, v) for k, v in d.settings.items()}
    duration = d.duration if d.duration is not None else dc_duration(task.req)
    picked = verify_parts(task.req, perturbed_parts(d.parts, tols, f), task.loads, settings,
                          ambient=temps, duration=duration)
    return picked, n * len(task.loads) * duration


def _verify_pump(task: BatchTask, tols: list[Tolerance], f: np.ndarray, temps) -> tuple[list[dict], float]:
    """The pump's screen checks and cycle simulation (``pump_evaluate.verify_samples``)
    on each sample's perturbed parts, at the required maximum temperature;
    (per sample its verdict, simulated seconds)."""
    from ..technologies.piezo_pump import screen as pump_screen
    from ..technologies.piezo_pump.evaluate import verify_samples
    d, cat = task.design, task.catalog
    group = pump_screen.Group(cat.stacks[d.stack], d.n_stacks, cat.amplifiers[d.amplifier], cat.valves[d.valve],
                              cat.accumulators[d.accumulator], cat.fluids[d.fluid], cat.seals[d.seal])
    bw = None
    if any(t.key.startswith(BOUC_WEN_PREFIX) for t in tols):
        bw = stack_bouc_wen(group.stack, reference_bouc_wen(cat.stacks))[0]
    groups = [perturbed_combo(group, tols, row, bw) for row in f]
    picked = verify_samples(d, cat, groups, task.loads)
    return picked, f.shape[0] * len(task.loads) * 2.0 * d.stroke / d.speed


def _pick(cands: list[dict], variant_id: str) -> dict:
    """The sample's candidate of the design under study. A passive design
    ("-pc") whose sample does not drift beyond the allowance needs no spacer:
    its as-built candidate stands for it."""
    by_id = {c["id"]: c for c in cands}
    return by_id.get(variant_id) or by_id[variant_id.removesuffix("-pc")]


def _finite(v) -> float:
    return -math.inf if v is None or (isinstance(v, float) and math.isnan(v)) else float(v)


def pick_designs(results: dict, k: int, technology: str | None = None) -> list[dict]:
    """The K best candidates robust can perturb, in rank order: sized
    piezohydraulic designs, DC designs from parts (not the catalog's
    ready-made DC actuators); only ``technology``'s when given, and the
    simulated pumps only when asked for (``technology`` "piezo_pump")."""
    from ..technologies.registry import get
    out = [c for c in results["candidates"] if "design" in c and (tech := get(c["technology"])) is not None
           and tech.perturbable(c, technology) and technology in (None, c["technology"])]
    return out[:k]


def robust(req, catalog, candidates: list[dict], samples: int, seed: int, executor: Executor,
           progress=None, batch: int = BATCH, extra_spreads: dict | None = None, stages=None) -> dict:
    """robust.json for ``candidates`` (results.json entries). ``extra_spreads``:
    tolerances added to (and overriding) the requirements' ones, e.g. the
    Bouc-Wen spreads of a fit (``io.fit_spreads``). ``stages``: the solve's
    records (``SolveOutput.stages``), whose piezohydraulic and DC designs
    are taken as sized instead of being read back from results.json."""
    tols = tolerances_of({**req.tolerance_spreads, **(extra_spreads or {})})
    loads = [c["load_N"] for c in load_cases(req.load)]
    designs = study_designs(req, catalog, candidates, stages)
    tasks = []
    for d, (cand, design) in enumerate(zip(candidates, designs)):
        for b, start in enumerate(range(0, samples, batch)):
            tasks.append(BatchTask(req, catalog, design, cand["id"], tols, seed, d, b,
                                   min(batch, samples - start), loads))
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


def _summarise(cand: dict, parts: list[dict], seed: int) -> dict:
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
    return {"id": cand["id"], "name": cand.get("name", cand["id"]), "technology": cand["technology"],
            "rank": cand.get("rank"),
            "nominal_feasible": cand.get("feasible"), "nominal_driver": cand.get("driver"),
            "p_compliance": ok / n, "p_ci95": list(wilson(ok, n)),
            "p_requirement": p_req,
            "p_requirement_ci95": {k: list(wilson(int(np.sum(margins[k] >= 0)), n)) for k in keys},
            "failing_requirements": failing,
            "sensitivity": sens,
            "driving_tolerance": max(sens, key=sens.get) if any(v > 0 for v in sens.values()) else None,
            "nominal_margins": {k: cand["margins"][k] for k in keys if k in cand.get("margins", {})},
            "margin_quantiles": {k: _quantiles(margins[k]) for k in keys},
            "metrics": {k: cand["metrics"][k] for k in ("mass_kg", "cost_usd") if k in cand.get("metrics", {})}}


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
