"""The recommendation that complies (studies/compliance.py): its
probability of compliance against an independent ``sizing robust`` run of
1000 samples, the min_compliance policy, and the knife edges."""
from __future__ import annotations

from pathlib import Path

import pytest

from sizing import api
from sizing.io.catalog import load_catalog
from sizing.io.requirements import load_requirements
from sizing.studies import compliance
from sizing.studies.executor import Executor
from sizing.studies.robust import robust

REPO = Path(__file__).resolve().parents[2]
SEED = REPO / "studies" / "seed-requirements.toml"


# seed_solve: the seed's full solve, once per test run (conftest); every
# test here checks figures of the probability of compliance: the slow tier
pytestmark = pytest.mark.slow


def _within_wider(a: dict, b: dict) -> bool:
    """Each estimate lies inside the wider of the two 95 % intervals."""
    low, high = max(((a["low"], a["high"]), (b["low"], b["high"])), key=lambda iv: iv[1] - iv[0])
    return low <= a["p"] <= high and low <= b["p"] <= high


def test_recommendation_agrees_with_robust(seed_solve):
    """The recommended design's probability, estimated inside solve, against
    sizing robust's 1000 samples of another random stream on that design."""
    results = seed_solve.results
    rec = results["summary"]["comparison"]["recommended"]
    cand = next(c for c in results["candidates"] if c["id"] == rec["id"])
    req, _ = load_requirements(SEED)
    with Executor(0) as ex:
        study = robust(req, load_catalog(None), [cand], 1000, 7, ex)["designs"][0]
    other = {"p": study["p_compliance"], "low": study["p_ci95"][0], "high": study["p_ci95"][1]}
    assert rec["compliance"]["samples"] >= compliance.REPORTED_SAMPLES
    assert _within_wider(rec["compliance"], other), (rec["compliance"], other)


def test_default_policy_meets_the_minimum_or_says_none_does(seed_solve):
    comp = seed_solve.results["summary"]["comparison"]
    rec = comp["recommended"]
    assert rec["min_compliance"] == 0.9
    if rec["meets_min_compliance"]:
        assert rec["compliance"]["p"] >= 0.9
    else:
        assert "no design meets min_compliance 90%" in comp["recommendation"]
        assert len(rec["examined"]) == compliance.MAX_EXAMINED or all(e["p"] < 0.9 for e in rec["examined"])
    # every technology's best carries its estimate or says why it has none
    for t in comp["technologies"].values():
        assert set(t["compliance"]) == {"p", "low", "high", "samples", "method"}
        assert t["compliance"]["p"] is not None or t["compliance"]["method"].startswith("not estimated")


def test_policy_picks_a_heavier_design_that_complies(seed_solve, tmp_path):
    """A minimum above the nominal lightest design's probability but within
    reach of the designs after it: the policy picks another, heavier design
    whose estimate reaches it, and names the nominal lightest with its own."""
    nominal = seed_solve.results["summary"]["comparison"]["recommended"]
    target = round(nominal["compliance"]["high"] + 0.02, 2)
    path = tmp_path / "requirements.toml"
    path.write_text(SEED.read_text().replace('minimize = ["mass", "cost"]',
                                             f'minimize = ["mass", "cost"]\nmin_compliance = {target}'))
    comp = api.run_solve(path).results["summary"]["comparison"]
    rec = comp["recommended"]
    assert rec["meets_min_compliance"], rec
    assert rec["id"] != nominal["id"] and rec["compliance"]["p"] >= target
    assert rec["nominal_lightest"]["id"] == nominal["id"]
    assert rec["nominal_lightest"]["compliance"]["p"] < target
    assert rec["name"] in comp["recommendation"] and nominal["name"] in comp["recommendation"]
    # the recommendation's flips are searched anew for the design picked, under its technology
    flips = [e for t in comp["technologies"].values() for e in t["flips"] if e["changes"] == "recommendation"]
    assert flips and all(e["design"] == rec["id"] and e["held"].startswith("the policy's pick") for e in flips)
    assert all(e in comp["technologies"][rec["technology"]]["flips"] for e in flips)


def test_report_and_terminal_flag_knife_edges(seed_solve):
    """The seed's nominal answer binds on temperature at +0.0 %: the terminal
    line and the report's answer section both name it, with the probability."""
    from sizing.report.text import knife_edge_text
    comp = seed_solve.results["summary"]["comparison"]
    rec = comp["recommended"]
    assert "temperature" in rec["knife_edges"]
    line = knife_edge_text(comp)
    assert line.startswith("knife edges") and rec["name"] in line and "temperature +0.00%" in line
    page = (seed_solve.out / "report.html").read_text()
    assert "knife edge" in page and f"of {rec['compliance']['samples']} samples under tolerance" in page


def test_knife_edges_are_the_margins_under_one_percent():
    from sizing.engine.candidate import Candidate
    cand = Candidate("ph-x", "piezohydraulic",
                     margins={"a": 0.0, "b": 0.0099, "c": 0.01, "d": -0.2, "e": None, "f": float("inf")})
    assert compliance.knife_edges(cand) == {"a": 0.0, "b": 0.0099}
    assert compliance.knife_edges(None) == {}
