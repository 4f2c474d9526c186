"""A technology added from outside the package: one registered object, no
edit elsewhere in ``sizing/``, and the solve ranks it, the comparison
compares it, the report shows it and the sweep counts it.

The technology is the least one can be: catalog actuators with a fixed
stroke and a linear force-speed line (free speed at no load, stall force
at zero speed), judged at the largest load case."""
from __future__ import annotations

from collections import Counter

import pytest

from sizing.engine.loads import load_cases
from sizing.engine.rank import floor_margin
from sizing.engine.records import Outcome
from sizing.engine.solve import solve
from sizing.io.requirements import parse_requirements
from sizing.io.schema import load_toml
from sizing.studies.executor import Executor
from sizing.studies.sweep import sweep
from sizing.technologies import registry

from ..conftest import ONE_DESIGN, STUDIES, subset_catalog

NAME = "linear_line"
# (id, stroke m, stall force N, free speed m/s, mass kg, cost USD): made-up units for a mechanism test
UNITS = (("line-a", 0.060, 9000.0, 0.40, 2.0, 900.0),
         ("line-b", 0.030, 9000.0, 0.40, 1.0, 500.0))


def speed_under(load: float, stall: float, free: float) -> float:
    """The linear force-speed line: v = v_free (1 - F / F_stall)."""
    return free * max(0.0, 1.0 - load / stall)


def _solve(req, catalog, loads, progress, detail="summary"):
    r, worst = req.requirements, max(loads)
    candidates = []
    for ident, stroke, stall, free, mass, cost in UNITS:
        v = speed_under(worst, stall, free)
        margins = {"stroke": floor_margin(stroke, r.stroke), "blocked_force": floor_margin(stall, r.blocked_force),
                   "speed": floor_margin(v, r.speed)}
        candidates.append({"id": ident, "technology": NAME, "variant": "catalog", "stage": "simulated",
                           "components": {"unit": ident}, "stack_params": {},
                           "static": {"stroke_m": stroke, "blocked_force_N": stall, "speed_m_s": v},
                           "simulated": {"stroke_m": stroke, "speed_m_s": v, "load_N": worst},
                           "margins": margins, "metrics": {"mass_kg": mass, "cost_usd": cost},
                           "temperatures": {}, "design": {"technology": NAME, "unit": ident}, "reason": ""})
    return Outcome(NAME, candidates, Counter(), (), {"combinations": len(UNITS), "simulated": len(UNITS)}), ()


LINE = registry.Technology(
    name=NAME, label="linear line", order=9, part_kinds=(), solve=_solve,
    groups=(registry.Group("catalog", "linear force-speed catalog actuators"),),
    short_name=lambda c: f"LL {c.components['unit']}",
    describe=lambda c, catalog: f"catalog unit {c.components['unit']} on a linear force-speed line",
)


@pytest.fixture
def fourth():
    registry.register(LINE)
    yield LINE
    registry.unregister(NAME)


@pytest.fixture(scope="module")
def small_catalog():
    return subset_catalog(**ONE_DESIGN, dc_actuators=1)


@pytest.fixture(scope="module")
def seed_data():
    data = load_toml(STUDIES / "seed-requirements.toml")
    data["options"] = {"max_stacks": 11, "max_simulated": 6}
    return data


def test_the_line_is_the_hand_figure():
    # 9 kN stall, 0.4 m/s free: at 4.5 kN half the free speed
    assert speed_under(4500.0, 9000.0, 0.40) == pytest.approx(0.20)
    assert speed_under(9000.0, 9000.0, 0.40) == 0.0


def test_a_registered_technology_is_solved_compared_and_reported(fourth, seed_data, small_catalog):
    from sizing.report.html import render
    req = parse_requirements(seed_data, STUDIES / "seed-requirements.toml")
    out = solve(req, "0" * 64, small_catalog, fast=True)
    results = out.results
    ours = [c for c in results["candidates"] if c.technology == NAME]
    assert {c.id for c in ours} == {"line-a", "line-b"}
    loads = [c["load_N"] for c in load_cases(req.load)]
    expected = speed_under(max(loads), 9000.0, 0.40) / req.requirements.speed - 1
    assert next(c for c in ours if c.id == "line-a").margins["speed"] == pytest.approx(expected)
    # line-b is short of the stroke (30 mm against the seed's), line-a is not
    assert next(c for c in ours if c.id == "line-b").driver == "stroke"
    assert {c.name for c in ours} == {"LL line-a", "LL line-b"}
    entry = results["summary"]["comparison"]["technologies"][NAME]
    assert entry["description"].startswith("catalog unit")
    assert "linear line" in results["summary"]["comparison"]["text"]
    assert results["summary"]["counts"][NAME]["ranked"] == 2
    assert [g for g in results["summary"]["groups"] if g["technology"] == NAME][0]["n_candidates"] == 2
    page = render(results, out.traces)
    assert "linear line" in page and "LL line-a" in page


def test_a_registered_technology_is_counted_by_the_sweep(fourth, seed_data, small_catalog):
    out = sweep(seed_data, "req.toml", small_catalog, ["stroke=38mm..44mm:2"], Executor(0))
    for point in out["grid"]:
        assert NAME in point["feasible"]
        assert point["best_by_technology"][NAME]["id"] in {"line-a", "line-b"}


def test_unregistered_it_is_gone(seed_data, small_catalog):
    assert registry.get(NAME) is None
    assert NAME not in {t.name for t in registry.technologies()}
