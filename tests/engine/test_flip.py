"""What would flip each verdict, found by re-solving (engine/flip.py):
bisection on a known predicate, and for the seed requirements each
reported flip checked by re-solving on both sides of it, and against
``sizing sweep``'s own grid points."""
from __future__ import annotations

import pytest

from sizing.engine import flip
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
    return req, cat, [c["load_N"] for c in load_cases(req.load)], seed_solve.results


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
