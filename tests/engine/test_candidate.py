"""A ranked design is a frozen ``Candidate`` from the ranking to the
written results: built from its technology's record, it gives that record
back field for field and in the same key order, and every change to it
(its standing, its name, its probability of compliance) makes a new one."""
from __future__ import annotations

import dataclasses
import json

import pytest

from sizing.engine.candidate import TYPED, Candidate

from ..conftest import STUDIES, run_cli

PRUNED = {"id": "ph-x", "technology": "piezohydraulic", "variant": "uncompensated", "stage": "pruned",
          "components": {"stack": "s", "n_stacks": 2, "ratio": None}, "stack_params": {"d33_m_V": 1e-9},
          "static": {"work_J": 1.0}, "simulated": {}, "margins": {"stroke": -0.2},
          "metrics": {"mass_kg": 3.0}, "metrics_lower_bound": True, "reason": "ruled out before sizing: stroke"}


def _round_trips(records: list[dict]) -> None:
    for d in records:
        back = Candidate.from_dict(d).to_dict()
        assert back == d, d["id"]
        assert list(back) == list(d), d["id"]                   # the key order too
        assert json.dumps(back) == json.dumps(d)


def test_every_candidate_of_the_seed_round_trips(seed_solve_fast):
    cands = seed_solve_fast.results["candidates"]
    assert {c["technology"] for c in cands} >= {"piezohydraulic", "dc_motor", "piezo_pump"}
    _round_trips(cands)


@pytest.mark.slow
def test_every_candidate_of_the_low_duty_solve_round_trips(tmp_path):
    code, _, err = run_cli("solve", STUDIES / "seed-requirements-low-duty.toml", "--fast", "--detail", "full",
                           "--out", tmp_path / "out")
    assert code == 0, err
    cands = json.loads((tmp_path / "out" / "results.json").read_text())["candidates"]
    assert any(c["stage"] == "pruned" for c in cands)           # records without a design block too
    _round_trips(cands)


def test_a_record_reads_as_typed_fields_and_its_own():
    c = Candidate.from_dict(PRUNED)
    assert (c.id, c.technology, c.stage, c.margins["stroke"], c.metrics["mass_kg"]) == (
        "ph-x", "piezohydraulic", "pruned", -0.2, 3.0)
    assert c.design is None and "design" not in c.order and "design" not in c.to_dict()    # absent, not null
    assert dict(c.own) == {"stack_params": {"d33_m_V": 1e-9}, "metrics_lower_bound": True}
    assert c.own["metrics_lower_bound"] is True and c.rank is None and c.to_dict() == PRUNED
    assert {f for f in PRUNED if f in TYPED} == {"id", "technology", "variant", "stage", "components", "static",
                                                 "simulated", "margins", "metrics", "reason"}


def test_a_candidate_reads_by_attribute_not_as_its_record():
    """The record is made only where results are written (``to_dict``):
    code that read a candidate as a dict fails here, not in a file."""
    c = Candidate.from_dict(PRUNED)
    with pytest.raises(TypeError):
        c["id"]
    with pytest.raises(TypeError):
        dict(c)
    assert not hasattr(c, "get") and not hasattr(c, "keys")


def test_a_candidate_is_frozen_and_changes_make_new_ones():
    c = Candidate.from_dict(PRUNED)
    with pytest.raises(dataclasses.FrozenInstanceError):
        c.rank = 1
    with pytest.raises(TypeError):
        c["rank"] = 1
    ranked = c.with_fields(feasible=False, driver="stroke", rank=4, pareto=False, pareto_level=None)
    named = ranked.with_fields(rank=2, name="2xP056", extra_figure=1.5)
    assert c.rank is None and "rank" not in c.order and ranked.rank == 4 and named.rank == 2
    # as dict(record, **fields) would: new fields after the others, a given one in its place
    assert list(named.to_dict()) == [*PRUNED, "feasible", "driver", "rank", "pareto", "pareto_level", "name",
                                     "extra_figure"]
    assert named.to_dict() == dict(PRUNED, feasible=False, driver="stroke", rank=2, pareto=False,
                                   pareto_level=None, name="2xP056", extra_figure=1.5)
    assert named.own["extra_figure"] == 1.5 and "extra_figure" not in c.own


def test_a_solve_hands_out_its_technologies_records_ranked_and_named():
    """The candidates of a solve are built once from each technology's
    records: each gives back its technology's record field for field (JSON
    safe), then its standing, the assumed values it rests on and its name."""
    import tomllib

    from sizing.engine.loads import load_cases
    from sizing.engine.solve import solve
    from sizing.engine.solve_summary import _clean
    from sizing.io.requirements import parse_requirements
    from sizing.technologies.registry import technologies

    from ..conftest import FAST_REQUIREMENTS, ONE_DESIGN, subset_catalog
    req = parse_requirements(tomllib.loads(FAST_REQUIREMENTS), "req.toml")
    catalog = subset_catalog(**ONE_DESIGN)
    out = solve(req, "x", catalog, detail="full", fast=True)
    loads = [c["load_N"] for c in load_cases(req.load)]
    own = {r["id"]: _clean(r) for t in technologies() for r in t.solve(req, catalog, loads, None, "full")[0].candidates}
    cands = out.results["candidates"]
    assert cands and all(isinstance(c, Candidate) for c in cands)
    assert {c.id for c in cands} == set(own)
    added = ["feasible", "driver", "rank", "pareto", "pareto_level", "rests_on_assumed", "name"]
    for c in cands:
        record, theirs = c.to_dict(), own[c.id]
        assert list(record) == list(theirs) + [k for k in added if k not in theirs]
        assert {k: record[k] for k in theirs} == theirs
        assert [c.rank, c.name] == [record["rank"], record["name"]] and c.name
    assert [c.rank for c in cands] == list(range(1, len(cands) + 1))
