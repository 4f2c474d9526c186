"""What changed, by cause: the requirement values, catalog entries and tool
version that differ between two runs, before the designs that moved."""
from __future__ import annotations

from sizing.engine.changes import change_causes, rank_changes

from .conftest import FAST_REQUIREMENTS, run_cli


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
