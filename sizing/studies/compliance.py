"""Probability of compliance inside ``sizing solve``, and the recommendation
that complies (docs/formats.md: ``summary.comparison.technologies.T.compliance``
and ``summary.comparison.recommended``).

The estimate is the Monte Carlo of ``sizing robust`` (``robust.run_batch``:
the tolerated catalog fields of ``[tolerances]``, or the defaults, drawn per
sample, each sample re-verified by the solve's own checks and simulated in
full under every load case), run in process and sequentially: batches of
``SCHEDULE`` samples until the 95 % Wilson interval lies wholly above or
below ``[objectives] min_compliance``, or ``MAX_SAMPLES`` are spent
(the sequential stop is accounted for only by the interval's width). A
design whose chance is plainly short of the minimum is dropped after the
first 20 samples; a design the report states (each technology's best, the
recommendation, the nominal lightest) gets at least ``REPORTED_SAMPLES``.
Every design is drawn from the same random stream (common random numbers),
so two designs are compared on the same parts.

The policy: the feasible designs in order of the first objective (the
nominal recommendation first), each examined in turn, at most
``MAX_EXAMINED``; the first whose estimate reaches ``min_compliance`` is
recommended. ``min_compliance = 0``: the nominal answer, its probability
stated. Designs whose parts carry no tolerance model (catalog DC actuators,
piezo pumps: ``studied``) are stated without a probability and are not
picked by a policy above 0.
"""
from __future__ import annotations

import math
import time
from typing import TYPE_CHECKING

import numpy as np

from ..engine.comparison import OBJECTIVE_KEYS, recommendation_sentence
from ..engine.loads import load_cases
from ..engine.sized import study_designs
from .robust import BatchTask, run_batch
from .stats import wilson
from .tolerances import tolerances_of

if TYPE_CHECKING:
    from ..engine.candidate import Candidate

SCHEDULE = (20, 180, 300, 500)     # batch sizes: 20, 200, 500, 1000 samples in all
MAX_SAMPLES = sum(SCHEDULE)
from ..settings import KNIFE_EDGE, MAX_EXAMINED, REPORTED_SAMPLES  # noqa: E402  (sizing/settings.py)
SEED = 0
METHOD = ("Monte Carlo over the tolerances through the solve's checks and simulation (sizing robust's samples), "
          "sequential: 20, 200, 500, 1000 samples until the 95 % Wilson interval excludes min_compliance")


def studied(cand: Candidate) -> bool:
    """Whether the tolerances can perturb the candidate's parts, as its
    technology says (``Technology.perturbable``: ``sizing robust``'s scope
    when no technology is named)."""
    from ..technologies.registry import get
    tech = get(cand.technology)
    return cand.design is not None and tech is not None and tech.perturbable(cand, None)


def not_estimated(cand: Candidate) -> dict:
    what = "a catalog actuator" if cand.variant == "catalog" else f"a {cand.technology} design"
    return {"p": None, "low": None, "high": None, "samples": 0,
            "method": f"not estimated: {what} has no tolerance model of its parts"}


class Study:
    """The sequential estimates of one solve, kept per design so a design
    examined by the policy and then stated continues its own samples."""

    def __init__(self, req, catalog, stages=None):
        self.req, self.catalog, self.stages = req, catalog, stages
        self.tols = tolerances_of(req.tolerance_spreads)
        self.loads = [c["load_N"] for c in load_cases(req.load)]
        self.target = float(req.objectives.min_compliance)
        self.tally: dict[str, list] = {}          # id -> [successes, samples, batches, design]
        self.simulated_s = 0.0

    def compliance(self, cand: Candidate, least: int = REPORTED_SAMPLES) -> dict:
        """The candidate's estimate, sampled until decided against the
        minimum (and at least ``least`` samples)."""
        if not studied(cand):
            return not_estimated(cand)
        t = self.tally.get(cand.id)
        if t is None:
            t = self.tally[cand.id] = [0, 0, 0, study_designs(self.req, self.catalog, [cand], self.stages)[0]]
        while t[2] < len(SCHEDULE) and not (t[1] >= least and self._decided(t[0], t[1])):
            task = BatchTask(self.req, self.catalog, t[3], cand.id, self.tols, SEED, 0, t[2], SCHEDULE[t[2]],
                             self.loads, cand.technology)
            out = run_batch(task)
            t[0] += int(np.sum(out["feasible"]))
            t[1] += len(out["feasible"])
            t[2] += 1
            self.simulated_s += out["simulated_s"]
        low, high = wilson(t[0], t[1])
        return {"p": t[0] / t[1], "low": low, "high": high, "samples": t[1], "method": METHOD}

    def _decided(self, ok: int, n: int) -> bool:
        if self.target <= 0:
            return True
        low, high = wilson(ok, n)
        return low >= self.target or high < self.target

    def meets(self, estimate: dict) -> bool:
        return estimate["p"] is not None and estimate["p"] >= self.target


def knife_edges(cand: Candidate | None) -> dict:
    """The margins of a design that are met by less than KNIFE_EDGE (none
    without a design)."""
    return {k: v for k, v in (cand.margins if cand is not None else {}).items()
            if v is not None and math.isfinite(v) and 0 <= v < KNIFE_EDGE}


def _with_comparison(results: dict, comp: dict, **fields) -> dict:
    """New results with the comparison ``comp`` (and ``fields``)."""
    return dict(results, summary=dict(results["summary"], comparison=comp), **fields)


def _comparison_copy(results: dict) -> tuple[dict, dict]:
    """A copy of the results' comparison to state the policy in, and its
    technologies' entries (copies too)."""
    comp = dict(results["summary"]["comparison"])
    comp["technologies"] = {name: dict(t) for name, t in comp["technologies"].items()}
    return comp, comp["technologies"]


def attach(req, catalog, results: dict, stages=None) -> dict:
    """New results in which each technology's best design has its
    ``compliance``, the summary its ``recommended`` design under the policy,
    and the one-sentence answer says what the policy changed."""
    start = time.perf_counter()
    comp, techs = _comparison_copy(results)
    cands = results["candidates"]
    by_id = {c.id: c for c in cands}
    study = Study(req, catalog, stages)
    nominal = _nominal(techs, by_id, req)
    chosen, examined = _policy(study, cands, nominal, req)
    for t in techs.values():
        t["compliance"] = study.compliance(by_id[t["best"]]) if t["best"] in by_id else None
        t["knife_edges"] = knife_edges(by_id.get(t["best"]))
    comp["recommended"] = _recommended(study, nominal, chosen, examined)
    _restate_flips(req, catalog, cands, techs, chosen, nominal, study.target)
    comp["recommendation"] = _sentence(techs, req, comp["recommended"], chosen, nominal, study)
    return _with_comparison(results, comp, compliance_s=time.perf_counter() - start)


def attach_fast(results: dict, req) -> dict:
    """``--fast``: new results with the nominal recommendation, every
    ``compliance`` null."""
    comp, techs = _comparison_copy(results)
    by_id = {c.id: c for c in results["candidates"]}
    for t in techs.values():
        t["compliance"] = None
        t["knife_edges"] = knife_edges(by_id.get(t["best"]))
    nominal = _nominal(techs, by_id, req)
    comp["recommended"] = None if nominal is None else dict(_entry(nominal, None), knife_edges=knife_edges(nominal))
    return _with_comparison(results, comp)


def _nominal(techs: dict, by_id: dict, req) -> Candidate | None:
    """The design the nominal answer names: the feasible technology's best
    that is best in the first objective (``comparison._recommendation``)."""
    key = OBJECTIVE_KEYS[req.objectives.minimize[0]]
    bests = [by_id[t["best"]] for t in techs.values() if t["feasible"] and t["best"] in by_id]
    return min(bests, key=lambda c: c.metrics.get(key, math.inf), default=None)


def _policy(study: Study, cands: list[Candidate], nominal: Candidate | None, req) -> tuple[Candidate | None, list]:
    """(the first design, in order of the first objective, whose estimate
    reaches the minimum, or None; those examined, with their estimates)."""
    if nominal is None or study.target <= 0:
        return nominal, []
    key = OBJECTIVE_KEYS[req.objectives.minimize[0]]
    order = [nominal] + sorted((c for c in cands if c.feasible and c is not nominal and studied(c)
                                and c.metrics.get(key) is not None), key=lambda c: (c.metrics[key], c.rank))
    examined = []
    for c in order:
        if not studied(c):
            continue
        if len(examined) == MAX_EXAMINED:
            break
        estimate = study.compliance(c, least=SCHEDULE[0])
        examined.append({"id": c.id, "name": c.name or c.id, "p": estimate["p"],
                         "samples": estimate["samples"]})
        if study.meets(estimate):
            return c, examined
    return None, examined


def _restate_flips(req, catalog, candidates, techs: dict, chosen, nominal, target: float) -> None:
    """The recommendation's flips made those of the design recommended
    under the policy (``flip.restate``, in ``techs``, the copy ``attach``
    states the policy in): searched anew when the policy picked another
    design than the nominal lightest they were searched for."""
    from ..engine import flip
    pick = chosen or nominal
    if pick is None:
        flip.restate(techs, None, flip.held_text(target, None, False))
        return
    redo = None
    if pick is not nominal:
        def redo():
            from ..engine.solve import technology_stages
            return flip.policy_flips(req, catalog, candidates, techs, pick, technology_stages())
    flip.restate(techs, pick, flip.held_text(target, chosen is not None, pick is nominal), redo)


def _entry(cand: Candidate, compliance) -> dict:
    return {"technology": cand.technology, "id": cand.id, "name": cand.name or cand.id,
            "compliance": compliance}


def _recommended(study: Study, nominal, chosen, examined: list) -> dict | None:
    if nominal is None:
        return None
    pick = chosen or nominal
    out = dict(_entry(pick, study.compliance(pick)), min_compliance=study.target,
               meets_min_compliance=chosen is not None, examined=examined, knife_edges=knife_edges(pick))
    if pick is not nominal:
        out["nominal_lightest"] = {"id": nominal.id, "name": nominal.name or nominal.id,
                                   "compliance": study.compliance(nominal)}
    return out


def _sentence(techs, req, rec, chosen, nominal, study: Study) -> str:
    """The one-sentence answer under the policy."""
    if rec is None:
        return recommendation_sentence(techs, [OBJECTIVE_KEYS[k] for k in req.objectives.minimize])
    keys = [OBJECTIVE_KEYS[k] for k in req.objectives.minimize]
    pick = chosen or nominal
    clause = f"; it complies in {_p(rec['compliance'])} of samples under tolerance"
    if chosen is None and not rec["examined"]:
        clause = (f"; min_compliance {study.target:.0%} cannot be checked: no feasible design's parts carry a "
                  "tolerance model")
    elif chosen is None:
        clause = (f"; no design meets min_compliance {study.target:.0%}: under tolerance this one complies in "
                  f"{_p(rec['compliance'])} of samples, and none of the {len(rec['examined'])} lightest examined "
                  f"reaches {study.target:.0%}")
    elif "nominal_lightest" in rec:
        n = rec["nominal_lightest"]
        clause += (f" (min_compliance {study.target:.0%}); the nominal lightest, {n['name']}, complies in only "
                   f"{_p(n['compliance'])}")
    return recommendation_sentence(techs, keys, pick, clause)


def _p(estimate: dict) -> str:
    if estimate is None or estimate.get("p") is None:
        return "an unestimated share"
    return f"{estimate['p']:.0%} [{estimate['low']:.0%}, {estimate['high']:.0%}]"
