"""``sizing solve``: enumerate, size, verify by simulation, rank.

Every registered technology (``technologies.registry``, one folder of
``sizing/technologies`` each) enumerates, sizes and verifies its own
designs in its ``solve`` stage; their candidates are then ranked in one
list, named, summarised and compared.
"""
from __future__ import annotations

import contextvars
import threading
import time
from collections import Counter
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from types import SimpleNamespace

from .. import __version__
from ..settings import FAR_MISS
from ..io.catalog import Catalog
from ..io.requirements import RequirementsFile
from ..technologies.registry import technologies
from ..threads import core_to_spare
from . import assumed, names, stage_cache
from .candidate import Candidate, records
from .comparison import technology_comparison
from .flip import flips
from .loads import load_cases
from .rank import OBJECTIVE_KEYS, standings
from .records import Stages, stages_of
from .solve_summary import _assumptions, _clean, _requirements_si, _summary, _traces


@dataclass(frozen=True)
class SolveOutput:
    results: dict                                  # results.json, its candidates ``Candidate``s (``api`` writes it)
    traces: list = field(default_factory=list)     # time traces of the top designs, for the report
    stages: Stages = Stages()                      # the records behind the results (robust takes them)


def solve(req: RequirementsFile, requirements_sha256: str, catalog: Catalog, progress=None,
          detail: str = "summary", fast: bool = False) -> SolveOutput:
    """Run the whole search: each technology enumerates, sizes and verifies
    its designs (its ``solve`` stage, ``technologies.registry``), then all are ranked in
    one list. ``progress(stage, done, total)`` is called while candidates are
    sized and simulated. ``detail``: "summary" counts the combinations ruled
    out before sizing by reason; "full" also keeps a record of each, with the
    nominal figures of its parts. ``fast``: no flips (``flips`` null)."""
    start = time.perf_counter()
    cases = load_cases(req.load)
    loads = [c["load_N"] for c in cases]
    solved = _stages(req, catalog, loads, progress, detail)
    outcomes = tuple(outcome for outcome, _ in solved.values())
    unranked = [Candidate.from_dict(c) for o in outcomes for c in o.candidates]
    ranking = standings([c.margins for c in unranked], [c.metrics for c in unranked],
                        [OBJECTIVE_KEYS[k] for k in req.objectives.minimize])
    ranked = sorted((c.with_fields(**s.fields()) for c, s in zip(unranked, ranking)), key=lambda c: c.rank)
    candidates = [c.with_fields(rests_on_assumed=rests, name=n)
                  for c, rests, n in zip(ranked, assumed.of_candidates(catalog, ranked), names.unique(ranked))]
    stages = stages_of({name: records for name, (_, records) in solved.items()})
    names_by_id = {c.id: c.name for c in candidates}
    results = _results(req, requirements_sha256, catalog, cases, candidates, outcomes,
                       [d for t in technologies() for d in t.disagreements(solved[t.name][1], names_by_id)])
    results["flips_cost"] = None if fast else _with_flips(req, catalog, loads, candidates, results["summary"])
    traces = _traces(req, candidates, stages, loads)
    if detail != "full":
        results = _keep_verified(results)
    results["summary"]["counts"] = summary_counts(results)
    results["runtime_s"] = time.perf_counter() - start
    return SolveOutput(results=_json_safe(results), traces=traces, stages=stages)


def _stages(req, catalog, loads, progress, detail) -> dict:
    """Each technology's ``solve`` stage, by name, in the registry's order:
    those that may (``Technology.alongside``) run one after another in a
    worker thread while the others run here, one after another (on two
    cores a serial simulation kernel then overlaps the other stages'
    sizing), when the machine has a core to spare (``threads.core_to_spare``).
    Each stage reads only the inputs, so its answer does not depend on what
    runs beside it."""
    techs = technologies()
    aside = [t for t in techs if t.alongside] if len(techs) > 1 and core_to_spare() else []
    if not aside:
        return {t.name: t.solve(req, catalog, loads, progress, detail) for t in techs}
    if progress is not None:
        progress = _one_at_a_time(progress)
    with ThreadPoolExecutor(max_workers=1, thread_name_prefix="sizing-stage") as pool:     # two cores: one beside
        running = {t.name: pool.submit(contextvars.copy_context().run, t.solve, req, catalog, loads, progress, detail)
                   for t in aside}        # the context: the limits (``limits.current``) hold in the threads
        here = {t.name: t.solve(req, catalog, loads, progress, detail) for t in techs if t.name not in running}
        done = {name: future.result() for name, future in running.items()}
    return {t.name: here[t.name] if t.name in here else done[t.name] for t in techs}


def _one_at_a_time(progress):
    """``progress`` called by one thread at a time."""
    lock = threading.Lock()

    def report(stage, done, total):
        with lock:
            progress(stage, done, total)
    return report


def _json_safe(results: dict) -> dict:
    """The results with every figure as results.json holds it (numpy to
    Python, non-finite floats null), the candidates still ``Candidate``s."""
    clean = _clean(dict(results, candidates=records(results["candidates"])))
    return dict(clean, candidates=[Candidate.from_dict(c) for c in clean["candidates"]])


def _results(req, requirements_sha256, catalog, cases, candidates, outcomes, disagreements) -> dict:
    """results.json from the ranked candidates and each technology's outcome."""
    techs = {t.name: t for t in technologies()}
    ruled_out = sum((o.ruled_out_all for o in outcomes), Counter())
    counts = {}
    for o in outcomes:
        key = techs[o.technology].counts_key
        if key is None:
            counts.update(o.counts)
        else:
            counts[key or o.technology] = o.counts
    pruned = {o.technology: o.ruled_out for o in outcomes if techs[o.technology].prunes_before_sizing}
    own = {k: v for t in techs.values() for k, v in t.results_fields(catalog).items()}
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
        "summary": dict(_summary(req, candidates, catalog, pruned), ruled_out=dict(ruled_out.most_common()),
                        ruled_out_by_technology={o.technology: dict(o.ruled_out_all.most_common()) for o in outcomes}),
        "disagreements": disagreements,
        **own,
        "counts": counts,
    }


def technology_stages() -> SimpleNamespace:
    """Each technology's stages of the solve, for the re-solves of the flips
    (``resolve.py``), by technology name."""
    return SimpleNamespace(**{t.name: t.solve for t in technologies()})


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


# --- candidates -------------------------------------------------------------
UNVERIFIED = ("sized", "gp_infeasible")
UNVERIFIED_REASON = "not simulated: misses a static check"
# a simulated design that misses a check by more than FAR_MISS is counted, not recorded
FAR_MISS_REASON = "simulated: misses {} by more than " + f"{-100 * FAR_MISS:g} %"


def _dropped_reason(c: Candidate, named: set) -> str | None:
    """Why a candidate's record is left out of the default results.json
    (None: it is kept)."""
    if c.feasible or c.id in named:
        return None
    if c.stage in UNVERIFIED:
        return UNVERIFIED_REASON
    worst = c.margins.get(c.driver) if c.driver else None
    if worst is not None and worst < FAR_MISS:
        return FAR_MISS_REASON.format(c.driver)
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
            dropped[(c.technology, why)] += 1
    ruled = dict(summary["ruled_out"])
    by_tech = {t: dict(counts) for t, counts in summary["ruled_out_by_technology"].items()}
    for (tech, why), n in dropped.items():
        ruled[why] = ruled.get(why, 0) + n
        counts = by_tech.setdefault(tech, {})
        counts[why] = counts.get(why, 0) + n
    return dict(results, candidates=[c.with_fields(rank=rank) for rank, c in enumerate(kept, start=1)],
                summary=dict(summary, ruled_out=ruled, ruled_out_by_technology=by_tech))


def summary_counts(results: dict) -> dict:
    """Every count the terminal and the report show, in one place
    (results.json ``summary.counts``): per technology the combinations
    enumerated, those ruled out before sizing, the designs left out
    before ranking (by reason in ``summary.ruled_out_by_technology``), those
    ranked in ``candidates`` and the feasible ones, the designs simulated
    and the counts of its own a technology names (``extra_counts``); totals."""
    raw, by_tech = results["counts"], results["summary"]["ruled_out_by_technology"]
    cands = results["candidates"]
    out = {}
    for technology in technologies():
        tech, own = technology.name, technology.counts_of(raw)
        ranked = [c for c in cands if c.technology == tech]
        catalog_units = sum(1 for c in ranked if "actuator" in c.components)
        before = int(own.get("pruned", 0)) if technology.prunes_before_sizing else 0
        out[tech] = {"combinations": int(own.get("combinations", 0)) + catalog_units,
                     "ruled_out_before_sizing": before,
                     "left_out": int(sum(by_tech.get(tech, {}).values())) - before,
                     "simulated": int(own.get("simulated", 0)),
                     "ranked": len(ranked), "feasible": sum(1 for c in ranked if c.feasible)}
        out[tech].update({k: int(own.get(k, 0)) for k in technology.extra_counts})
    out["ranked"] = len(cands)
    out["feasible"] = sum(1 for c in cands if c.feasible)
    return out
