"""What would flip each verdict, found by re-solving (engine/flip.py):
bisection on a known predicate, and for the seed requirements each
reported flip checked by re-solving on both sides of it, and against
``sizing sweep``'s own grid points."""
from __future__ import annotations

import math

import pytest

from sizing.engine import flip
from sizing.engine.candidate import Candidate
from sizing.engine.flip import TOLERANCE, Probe, bisect

from ..conftest import STUDIES


def _probe(value=40.0, stricter=+1, linear=False):
    return Probe("requirement stroke", "stroke", value, stricter, linear, None)


def test_bisection_finds_a_known_threshold_to_the_tolerance():
    """A verdict that changes above 61.3: found within 1 % on the side that
    changes; nothing changes within the range: None, one evaluation."""
    calls = []

    def changed(x):
        calls.append(x)
        return x > 61.3
    to = bisect(changed, _probe(), _probe().end(+1))
    assert 61.3 < to <= 61.3 * (1 + TOLERANCE) and changed(to * (1 + TOLERANCE)) and not changed(to * (1 - TOLERANCE))
    assert len(calls) <= 12              # log2(ln 4 / ln 1.01) = 7.1 halvings, the end, the checks
    calls.clear()
    assert bisect(lambda x: calls.append(x) or x > 1e9, _probe(), 160.0) is None and calls == [160.0]


def test_a_temperature_is_searched_in_degc_within_its_span():
    """100 degC: 150 degC either side, never below -55 degC; 1 degC steps."""
    p = _probe(100.0, +1, linear=True)
    assert p.end(+1) == 250.0 and p.end(-1) == -50.0 and _probe(20.0, -1, True).end(-1) == flip.COLD_LIMIT
    to = bisect(lambda x: x > 120.2, p, p.end(+1))
    assert 120.2 < to <= 121.2


class _Rivals:
    """A search over two technologies whose best designs' masses are known
    functions of the stroke: the recommended "a" (today 2 kg) and "b"."""

    def __init__(self, a, b):
        self.mass, self.calls = {"a": a, "b": b}, []
        self.today = {"a": flip.resolve.Verdict(True, "a1", a(40.0)), "b": flip.resolve.Verdict(True, "b1", b(40.0))}

    def recommended(self):
        return "a", {"id": "a1"}

    def touches(self, tech, probe):
        return True

    def best_at(self, tech, probe, x):
        self.calls.append((tech, x))
        return self.mass[tech](x)

    def no_lighter(self, tech, probe, x, today):
        return self.best_at(tech, probe, x) >= today

    def design_at(self, tech, probe, x, c):
        mass = self.mass[tech](x)
        return math.isfinite(mass), mass

    def floor_at(self, tech, probe, x):
        return -math.inf


def test_a_looser_value_that_lets_another_technology_lead_is_found_to_the_tolerance():
    """"a" gets lighter at a shorter stroke (1.6 + 0.01 x kg), "b" faster
    (2 + 0.5 (x - 23.7) kg): "b" leads below x = 11.45 / 0.49 = 23.37 mm.
    The flip is found within 1 %, and re-evaluated at the flip plus and
    minus the tolerance the recommendation changes on one side only."""
    s = _Rivals(lambda x: 1.6 + 0.01 * x, lambda x: 2.0 + 0.5 * (x - 23.7))
    p = _probe()
    to = flip.loosening_flip(s, p, p.end(-1))
    assert 11.45 / 0.49 * (1 - TOLERANCE) <= to < 11.45 / 0.49

    def leads_b(x):
        return s.best_at("b", p, x) < s.best_at("a", p, x)
    assert leads_b(to * (1 - TOLERANCE)) and not leads_b(to * (1 + TOLERANCE))


def test_nothing_flips_looser_when_no_rival_gets_under_today_at_the_end_of_the_range():
    """Every rival no lighter at the loosest value than the recommendation
    today: nothing flips in the range, one re-solve per rival, none of the
    recommended technology."""
    s = _Rivals(lambda x: 2.0, lambda x: 2.5 + x)
    p = _probe()
    assert flip.loosening_flip(s, p, p.end(-1)) is None and s.calls == [("b", 10.0)]


def test_a_looser_value_the_recommended_technology_cannot_meet_changes_the_recommendation():
    """"a" stops complying below a 20 mm stroke (a DC motor must reach the
    mean speed over a shorter stroke in less time), "b" stays heavier: the
    recommendation passes on there, found within 1 %."""
    s = _Rivals(lambda x: 2.0 if x >= 20.0 else math.inf, lambda x: 400.0)
    p = _probe()
    to = flip.loosening_flip(s, p, p.end(-1))
    assert 20.0 * (1 - TOLERANCE) <= to < 20.0


def test_the_recommendation_flips_follow_the_design_the_policy_picks():
    """The min_compliance policy picked a DC design over the nominal
    piezohydraulic one: the entries searched for the nominal are replaced
    by those of the pick, under its technology, each naming the design and
    what is held; with the nominal picked they are kept and annotated."""
    def techs():
        rec = {"what": "requirement stroke", "field": "stroke", "from": 0.04, "to": 0.05,
               "changes": "recommendation", "tolerance": TOLERANCE, "within": [0.04, 0.16]}
        feas = dict(rec, changes="feasibility", to=0.08)
        return {"piezohydraulic": {"flips": [feas, rec]}, "dc_motor": {"flips": [dict(feas, to=None)]}}
    pick = Candidate(id="dc-1", technology="dc_motor")
    out = techs()
    flip.restate(out, pick, flip.held_text(0.9, True, False), lambda: [
        {"what": "requirement stroke", "field": "stroke", "from": 0.04, "to": 0.06, "changes": "recommendation",
         "tolerance": TOLERANCE, "within": [0.04, 0.16]}])
    assert [e["changes"] for e in out["piezohydraulic"]["flips"]] == ["feasibility"]
    rec = [e for e in out["dc_motor"]["flips"] if e["changes"] == "recommendation"]
    assert len(rec) == 1 and rec[0]["to"] == 0.06 and rec[0]["design"] == "dc-1" and "held" in rec[0]
    assert out["dc_motor"]["flip"]["to"] == 0.06
    out = techs()
    flip.restate(out, Candidate(id="ph-1", technology="piezohydraulic"), flip.held_text(0.9, False, True))
    rec = out["piezohydraulic"]["flips"][1]
    assert rec["to"] == 0.05 and rec["design"] == "ph-1" and "no design meets" in rec["held"]


# --- the seed: each flip re-solved on both sides ------------------------------
@pytest.fixture(scope="module")
def seed(seed_solve):
    """The seed's requirements, catalog, load cases and full solve (computed
    once per test run, conftest)."""
    from sizing.engine.loads import load_cases
    from sizing.io.catalog import load_catalog
    from sizing.io.requirements import load_requirements
    req, _ = load_requirements(STUDIES / "seed-requirements.toml")
    cat = load_catalog(None)
    results = seed_solve.results          # read from results.json: its candidates made candidates once
    return req, cat, [c["load_N"] for c in load_cases(req.load)], dict(
        results, candidates=[Candidate.from_dict(c) for c in results["candidates"]])


def _feasible(tech, req, cat, loads, field, value) -> bool:
    """The technology re-solved whole (every combination, not only those
    the flip search narrowed to) with one requirement changed."""
    from sizing.engine import resolve
    from sizing.engine.solve import technology_stages
    changed = req.model_copy(update={"requirements": req.requirements.model_copy(update={field: value})})
    return resolve.verdict_of(changed, resolve.whole(technology_stages(), tech, changed, cat, loads)).feasible


@pytest.mark.slow
@pytest.mark.parametrize("tech", ["piezohydraulic", "dc_motor"])
@pytest.mark.parametrize("field", ["stroke", "blocked_force"])
def test_each_seed_flip_holds_on_one_side_and_not_the_other(seed, tech, field):
    """Both technologies are feasible for the seed: at the flip plus the
    tolerance the technology is infeasible, at the flip minus the tolerance
    it is feasible; where nothing flips it is still feasible at the end of
    the range."""
    req, cat, loads, results = seed
    t = results["summary"]["comparison"]["technologies"][tech]
    assert t["feasible"]
    entry = next(f for f in t["flips"] if f["field"] == field and f["changes"] == "feasibility")
    assert entry["method"] == "re-solve" and entry["tolerance"] == TOLERANCE
    if entry["to"] is None:
        assert _feasible(tech, req, cat, loads, field, entry["within"][1])
        return
    assert entry["within"][0] <= entry["to"] <= entry["within"][1]
    assert not _feasible(tech, req, cat, loads, field, entry["to"] * (1 + TOLERANCE))
    assert _feasible(tech, req, cat, loads, field, entry["to"] * (1 - TOLERANCE))


@pytest.mark.slow
def test_the_dc_verdict_does_not_depend_on_the_simulation_budget(seed):
    """At a 160 mm stroke the DC search's first 300 simulated designs held
    none of those that comply, while 158 and 161.6 mm found some: the
    verdict then read infeasible between two feasible strokes, and the
    stroke's flip stopped at the end of its range. Designs that pass the
    static screen beyond the budget are simulated while none complies:
    feasible at all three."""
    req, cat, loads, _ = seed
    for stroke in (0.158, 0.160, 0.1616):
        assert _feasible("dc_motor", req, cat, loads, "stroke", stroke), stroke


@pytest.mark.slow
def test_the_seed_flips_agree_with_sweep(seed):
    """``sizing sweep``'s own grid points (a full solve each) on either side
    of the piezohydraulic stroke flip, and at the end of the DC motor's
    stroke range where nothing flips: the same feasibility."""
    import tomllib
    from sizing.studies.sweep import PointTask, run_point
    req, cat, loads, results = seed
    techs = results["summary"]["comparison"]["technologies"]
    data = tomllib.loads((STUDIES / "seed-requirements.toml").read_text())

    def point(stroke):
        d = dict(data, requirements=dict(data["requirements"], stroke=stroke))
        return run_point(PointTask(d, "seed-requirements.toml", cat, {"stroke": stroke}))["feasible"]
    ph = next(f for f in techs["piezohydraulic"]["flips"] if f["field"] == "stroke" and f["changes"] == "feasibility")
    dc = next(f for f in techs["dc_motor"]["flips"] if f["field"] == "stroke" and f["changes"] == "feasibility")
    if ph["to"] is not None:
        assert point(ph["to"] * (1 - TOLERANCE))["piezohydraulic"] > 0
        assert point(ph["to"] * (1 + TOLERANCE))["piezohydraulic"] == 0
    if dc["to"] is None:
        assert point(dc["within"][1])["dc_motor"] > 0


@pytest.mark.slow
def test_the_seed_recommendation_stroke_flips_agree_with_sweep(seed):
    """``sizing sweep``'s own grid points a tolerance either side of each
    stroke flip of the recommendation: past the flip its best design is
    another, short of it the recommended one."""
    import tomllib
    from sizing.studies.sweep import PointTask, run_point
    req, cat, loads, results = seed
    comp = results["summary"]["comparison"]
    data = tomllib.loads((STUDIES / "seed-requirements.toml").read_text())

    def best(stroke):
        d = dict(data, requirements=dict(data["requirements"], stroke=stroke))
        return run_point(PointTask(d, "seed-requirements.toml", cat, {"stroke": stroke}))["best"]["id"]
    entries = [f for f in comp["technologies"][comp["recommended"]["technology"]]["flips"]
               if f["field"] == "stroke" and f["changes"] == "recommendation" and f["to"] is not None]
    assert entries
    for e in entries:
        away = 1 + TOLERANCE if e["direction"] == "stricter" else 1 - TOLERANCE
        assert best(e["to"] * away) != comp["recommended"]["id"]
        assert best(e["to"] / away) == comp["recommended"]["id"]


def _recommended(req, cat, loads, field, value) -> tuple:
    """(first objective, technology, id) of the lightest technology's best,
    every technology re-solved whole with one requirement changed."""
    from sizing.engine import resolve
    from sizing.engine.solve import technology_stages
    changed = req.model_copy(update={"requirements": req.requirements.model_copy(update={field: value})})
    stages, found = technology_stages(), []
    for tech in ("piezohydraulic", "dc_motor"):
        v = resolve.verdict_of(changed, resolve.whole(stages, tech, changed, cat, loads))
        if v.feasible:
            found.append((v.objective, tech, v.best))
    pump = resolve.pump_lightest(stages, changed, cat, loads)
    if pump is not None:
        found.append((pump[1], "piezo_pump", pump[0]))
    return min(found, default=(None, None, None))


@pytest.mark.slow
@pytest.mark.parametrize("direction", ["stricter", "looser"])
@pytest.mark.parametrize("field", ["stroke", "blocked_force"])
def test_each_seed_recommendation_flip_holds_on_one_side_and_not_the_other(seed, field, direction):
    """The recommendation's flips, stricter and looser: a tolerance past the
    flip (away from today) the recommended design is no longer recommended,
    a tolerance short of it it is; where nothing flips, it still is at the
    end of the range. Stricter: the lightest technology's best is another
    design (designs only drop out); looser: it stops complying or another
    technology's best, re-solved whole, is lighter than it."""
    req, cat, loads, results = seed
    comp = results["summary"]["comparison"]
    lead = comp["recommended"]["technology"]
    entries = [f for f in comp["technologies"][lead]["flips"] if f["field"] == field and f["changes"] == "recommendation"]
    assert {e["direction"] for e in entries} == {"stricter", "looser"}
    assert all(e["design"] == comp["recommended"]["id"] and e["held"] for e in entries)
    d0 = next(c for c in results["candidates"] if c.id == comp["recommended"]["id"])
    for e in (e for e in entries if e["direction"] == direction):
        stricter = e["direction"] == "stricter"

        def kept(x):
            if stricter:
                return _recommended(req, cat, loads, field, x)[2] == d0.id
            return _kept_looser(req, cat, loads, d0, field, x)
        if e["to"] is None:
            assert kept(e["within"][1] if stricter else e["within"][0])
            continue
        away = 1 + TOLERANCE if stricter else 1 - TOLERANCE
        assert not kept(e["to"] * away) and kept(e["to"] / away)


def _kept_looser(req, cat, loads, d0, field, value) -> bool:
    """The recommended design ``d0`` (its row re-solved) still complies with
    one requirement changed and no other technology's best (re-solved whole)
    is lighter than it."""
    from sizing.engine import resolve
    from sizing.engine.rank import verdict
    from sizing.engine.solve import technology_stages
    changed = req.model_copy(update={"requirements": req.requirements.model_copy(update={field: value})})
    stages = technology_stages()
    fresh = next((f for f in resolve.units(stages, d0.technology, changed, cat, loads, [d0]) if f.id == d0.id), None)
    if fresh is None or not verdict(fresh.margins)[0]:
        return False
    mass = fresh.metrics["mass_kg"]
    rivals = [resolve.verdict_of(changed, resolve.whole(stages, t, changed, cat, loads)).objective
              for t in ("piezohydraulic", "dc_motor") if t != d0.technology]
    pump = resolve.pump_lightest(stages, changed, cat, loads)
    return all(r >= mass for r in rivals + [pump[1] if pump else math.inf])


@pytest.mark.slow
def test_the_piezohydraulic_mass_floor_bounds_every_design(seed):
    """The floor the looser search settles on without sizing (n stacks and
    one amplifier unit of each combination kept) is below the mass of
    every piezohydraulic design the seed's solve sized, and none is known
    for the DC motor."""
    from sizing.engine import resolve
    req, cat, _, results = seed
    floor = resolve.mass_floor("piezohydraulic", req, cat)
    masses = [c.metrics["mass_kg"] for c in results["candidates"]
              if c.technology == "piezohydraulic" and c.stage != "pruned" and c.metrics]
    assert masses and 0 < floor <= min(masses) and resolve.mass_floor("dc_motor", req, cat) is None


def _design_complies(req, cat, loads, c, field, value) -> bool:
    """Design ``c`` (its part combination re-solved) with one requirement changed."""
    from sizing.engine import resolve
    from sizing.engine.rank import verdict
    from sizing.engine.solve import technology_stages
    changed = req.model_copy(update={"requirements": req.requirements.model_copy(update={field: value})})
    fresh = resolve.units(technology_stages(), c.technology, changed, cat, loads, [c])
    return any(f.id == c.id and verdict(f.margins)[0] for f in fresh)


@pytest.mark.slow
@pytest.mark.parametrize("field", ["stroke", "blocked_force"])
def test_a_design_the_policy_picks_gets_its_own_recommendation_flips(seed, field):
    """Had the policy picked the seed's second DC design from parts instead
    of the nominal lightest, its stroke and blocked-force flips are where
    it stops complying: re-solved a tolerance past the flip it fails, a
    tolerance short of it it complies (or still complies at the end of the
    range when nothing flips)."""
    import copy
    req, cat, loads, results = seed
    comp = results["summary"]["comparison"]
    pick = next(c for c in results["candidates"] if c.feasible and c.technology == "dc_motor"
                and c.id != comp["recommended"]["id"] and "actuator" not in c.components)
    from sizing.engine.solve import technology_stages
    entries = flip.policy_flips(req, cat, results["candidates"], copy.deepcopy(comp["technologies"]), pick,
                                technology_stages())
    e = next(e for e in entries if e["field"] == field)
    assert e["changes"] == "recommendation" and e["direction"] == "stricter"
    if e["to"] is None:
        assert _design_complies(req, cat, loads, pick, field, e["within"][1])
        return
    assert not _design_complies(req, cat, loads, pick, field, e["to"] * (1 + TOLERANCE))
    assert _design_complies(req, cat, loads, pick, field, e["to"] / (1 + TOLERANCE))
