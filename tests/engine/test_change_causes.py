"""What changed, by cause: the requirement values, catalog entries and tool
version that differ between two runs, before the designs that moved."""
from __future__ import annotations

import pytest

from sizing.engine.changes import change_causes, rank_changes

from ..conftest import FAST_REQUIREMENTS, STUDIES, run_cli


def _results(duty: float, version: str = "0.1.0", ranks=(1, 2)) -> dict:
    return {"tool_version": version,
            "requirements": {"stroke_m": 0.04, "duty": {"strokes_per_second": duty}, "options": {"max_stacks": 20}},
            "candidates": [{"id": f"d{i}", "technology": "dc_motor", "feasible": True, "pareto": i == 0, "rank": r}
                           for i, r in enumerate(ranks)]}


def test_a_duty_change_is_named_as_the_cause():
    old, new = _results(1.0), _results(0.1, ranks=(2, 1))
    changes = rank_changes(old, new, None)
    summary = change_causes(old, new, changes, None)
    assert summary["requirements"] == [{"field": "duty.strokes_per_second", "old": 1.0, "new": 0.1}]
    assert summary["designs_moved"] == 2 and summary["tool_version"] is None
    assert summary["text"].startswith("Recommendation unchanged: none")
    assert "1 requirement value changed (duty.strokes_per_second 1 -> 0.1)" in summary["text"]
    assert all("the requirements did" in c["summary"] for c in changes)
    # a value only one run records (an older results.json) is not a change
    older = _results(1.0)
    del older["requirements"]["duty"]
    assert change_causes(older, new, changes, None)["requirements"] == []
    # a new tool version is named
    assert "tool version 0.1.0 -> 0.2.0" in change_causes(old, _results(1.0, "0.2.0"), [], None)["text"]


def test_baseline_run_prints_the_cause_first(tmp_path):
    req = tmp_path / "req.toml"
    req.write_text(FAST_REQUIREMENTS)
    code, _, err = run_cli("solve", req, "--out", tmp_path / "a", "--quiet", "--fast")
    assert code == 0, err
    req.write_text(FAST_REQUIREMENTS + "\n[duty]\nstrokes_per_second = 0.1\n")
    code, out, err = run_cli("solve", req, "--out", tmp_path / "b", "--baseline", tmp_path / "a" / "results.json",
                             "--fast")
    assert code == 0, err
    first = out.strip().splitlines()[0]
    assert first.startswith("what changed: Recommendation "), first
    assert "1 requirement value changed (duty.strokes_per_second 1 -> 0.1)" in first


def _answer_results(temperature, dc_feasible):
    tech = {"dc_motor": {"best": "dc-a", "name": "DC A", "feasible": dc_feasible, "metrics": {"mass_kg": 1.5}},
            "piezohydraulic": {"best": "ph-b", "name": "PH B", "feasible": False, "metrics": {"mass_kg": 500.0}}}
    return {"objectives": ["mass"], "requirements": {"max_temperature_degC": temperature, "max_thermal_drift_m": 0.004,
                                                     "stroke_m": 0.04},
            "summary": {"comparison": {"technologies": tech}}, "candidates": []}


def test_what_changed_leads_with_the_recommendation():
    """The recommendation first (from which design to which), then each
    technology's best and verdict, then the requirement in people's units;
    a derived SI value never leads."""
    old, new = _answer_results(100.0, True), _answer_results(150.0, False)
    new["requirements"]["max_thermal_drift_m"] = 0.0044
    out = change_causes(old, new, [], None)
    assert out["answer"] == ("Recommendation changed: DC A (DC motor, 1.5 kg) -> none (no technology meets every "
                             "requirement)")
    assert out["technologies"][0] == "DC motor: DC A infeasible (was DC A feasible)"
    assert out["text"].startswith(out["answer"])
    assert "max temperature 100 -> 150 degC" in out["text"]
    assert out["text"].index("max temperature") < out["text"].index("max_thermal_drift_m")
    same = change_causes(old, _answer_results(100.0, True), [], None)
    assert same["answer"].startswith("Recommendation unchanged: DC A")


@pytest.mark.slow
def test_the_seed_at_150_degc_names_the_change_of_recommendation_first(tmp_path):
    """The seed solved at 100 degC, then at 150 degC with --baseline: the
    first line of What changed (terminal and report) names the change of
    recommendation."""
    seed = (STUDIES / "seed-requirements.toml").read_text()
    req = tmp_path / "req.toml"
    req.write_text(seed)
    code, _, err = run_cli("solve", req, "--out", tmp_path / "a", "--quiet", "--fast")
    assert code == 0, err
    req.write_text(seed.replace('max_temperature = "100 degC"', 'max_temperature = "150 degC"'))
    code, out, err = run_cli("solve", req, "--out", tmp_path / "b", "--fast", "--baseline", tmp_path / "a" / "results.json")
    assert code == 0, err
    first = out.strip().splitlines()[0]
    assert first.startswith("what changed: Recommendation changed: DC "), first
    html = (tmp_path / "b" / "report.html").read_text()
    section = html[html.index("<h2>What changed</h2>"):]
    assert section.index("Recommendation changed") < section.index("max temperature 100 -&gt; 150 degC")


def test_solve_with_robust_gives_the_probability_of_compliance(tmp_path):
    """sizing robust, then sizing solve --robust robust.json: the studied
    best design carries its p_compliance in results.json and the report."""
    import json
    req = tmp_path / "req.toml"
    req.write_text(FAST_REQUIREMENTS.replace("max_stacks = 2", "max_stacks = 12").replace("max_simulated = 2", "max_simulated = 4"))
    code, _, err = run_cli("robust", req, "--samples", "4", "--designs", "2", "--workers", "0", "--out",
                           tmp_path / "rob", "--quiet")
    assert code == 0, err
    studied = json.loads((tmp_path / "rob" / "robust.json").read_text())["designs"]
    code, _, err = run_cli("solve", req, "--out", tmp_path / "out", "--robust", tmp_path / "rob" / "robust.json", "--quiet",
                           "--fast")       # the studied designs' figures are attached with or without flips
    assert code == 0, err
    r = json.loads((tmp_path / "out" / "results.json").read_text())
    by_id = {c["id"]: c for c in r["candidates"]}
    for d in studied:
        assert by_id[d["id"]]["p_compliance"] == d["p_compliance"]
    tech = r["summary"]["comparison"]["technologies"]["piezohydraulic"]
    studied_ids = {d["id"] for d in studied}
    assert ("p_compliance" in tech) == (tech["best"] in studied_ids)
    # the answer section shows it where known
    from sizing.report.html import _answer
    summary = {"comparison": {"technologies": {"dc_motor": dict(
        best="dc-x", name="DC X", feasible=True, metrics={"mass_kg": 1.5}, binding="temperature",
        binding_margin=0.01, rests_on_assumed=[], deciding_assumed=[], flip=None, p_compliance=0.45,
        p_ci95=[0.41, 0.49])}}}
    assert "complies in 45% [41%, 49%] of robust samples" in _answer(summary)
    bad = tmp_path / "bad.json"
    bad.write_text('{"designs": 3}')
    code, _, err = run_cli("solve", req, "--out", tmp_path / "out2", "--robust", bad, "--quiet")
    assert code == 2 and "bad.json" in err and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "out2").exists()
