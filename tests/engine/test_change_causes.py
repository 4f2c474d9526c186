"""What changed, by cause: the requirement values, catalog entries and tool
version that differ between two runs, before the designs that moved."""
from __future__ import annotations

from sizing.engine.changes import change_causes, rank_changes

from ..conftest import FAST_REQUIREMENTS, run_cli


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
    assert summary["text"].startswith("1 requirement value changed (duty.strokes_per_second 1 -> 0.1)")
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
    code, _, err = run_cli("solve", req, "--out", tmp_path / "a", "--quiet")
    assert code == 0, err
    req.write_text(FAST_REQUIREMENTS + "\n[duty]\nstrokes_per_second = 0.1\n")
    code, out, err = run_cli("solve", req, "--out", tmp_path / "b", "--baseline", tmp_path / "a" / "results.json")
    assert code == 0, err
    first = out.strip().splitlines()[0]
    assert first.startswith("what changed: 1 requirement value changed (duty.strokes_per_second 1 -> 0.1)"), first


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
    code, _, err = run_cli("solve", req, "--out", tmp_path / "out", "--robust", tmp_path / "rob" / "robust.json", "--quiet")
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
