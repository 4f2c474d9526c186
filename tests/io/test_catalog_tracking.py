"""Catalog provenance, validation, diffs, import, and what a catalog
change does to the ranking. The first test is the issue's acceptance test."""
from __future__ import annotations

import datetime as dt
import json
import re
import shutil
import subprocess

import pytest

from sizing import api
from sizing.engine.changes import rank_changes
from sizing.io.catalog import load_catalog
from sizing.io.catalog_diff import CatalogDiff, diff_catalogs, format_diff
from sizing.io.provenance import assumed_values, status_counts
from sizing.io.validate import stale_entries, validate_catalog

from ..conftest import CATALOGS, run_cli

STACK = "pi-p-056.90"


def _set_field(folder, file, entry_id, field, value):
    """Set ``field = value`` in the entry ``entry_id`` of a catalog file."""
    path = folder / file
    text = path.read_text()
    start = text.index(f'id = "{entry_id}"')
    pattern = re.compile(rf'^{field} = .*$', re.MULTILINE)
    match = pattern.search(text, start)
    assert match, f"{field} not found after {entry_id}"
    path.write_text(text[:match.start()] + f"{field} = {value}" + text[match.end():])


def _drop_line(folder, file, entry_id, field):
    path = folder / file
    text = path.read_text()
    start = text.index(f'id = "{entry_id}"')
    match = re.compile(rf'^{field} = .*\n', re.MULTILINE).search(text, start)
    path.write_text(text[:match.start()] + text[match.end():])


# --- acceptance: diff ----------------------------------------------------------

def test_acceptance_stiffness_change_shows_in_diff(tmp_path):
    """Change one stack's stiffness in a copy of the catalog: `sizing catalog
    diff` shows that field, with old and new value and unit."""
    old, new = tmp_path / "old", tmp_path / "new"
    shutil.copytree(CATALOGS, old)
    shutil.copytree(CATALOGS, new)
    before = load_catalog(old).stacks[STACK].stiffness
    _set_field(new, "stacks.toml", STACK, "stiffness", '"5.0e8 N/m"')

    code, out, err = run_cli("catalog", "diff", old, new)
    assert code == 0, err
    assert f"~ stack {STACK}" in out and "stiffness:" in out
    assert f"{before:.6g} N/m" in out and "5e+08 N/m" in out
    assert "0 added, 0 removed, 1 changed" in out

    code, out, err = run_cli("catalog", "diff", old, new, "--json")
    assert code == 0, err
    data = json.loads(out)
    assert data["added"] == [] and data["removed"] == []
    (entry,) = data["changed"]
    assert entry["id"] == STACK and entry["kind"] == "stack" and entry["file"] == "stacks.toml"
    (change,) = entry["fields"]
    assert change["field"] == "stiffness" and change["unit"] == "N/m"
    assert change["old"] == pytest.approx(before) and change["new"] == pytest.approx(5.0e8)
    assert change["new_text"] == "5.0e8 N/m"


def test_equal_values_in_other_units_are_not_a_change(tmp_path):
    old, new = tmp_path / "old", tmp_path / "new"
    shutil.copytree(CATALOGS, old)
    shutil.copytree(CATALOGS, new)
    k = load_catalog(old).stacks["pi-p-888.91"].stiffness
    _set_field(new, "stacks.toml", "pi-p-888.91", "stiffness", f'"{k / 1e6:g} N/um"')
    _set_field(old, "stacks.toml", "pi-p-888.91", "stiffness", f'"{k:g} N/m"')
    assert diff_catalogs(old, new).empty


def test_diff_added_entry_and_git_revisions(tmp_path, monkeypatch):
    """OLD and NEW as git revisions of a repository; an added part shows as added."""
    repo = tmp_path / "repo"
    shutil.copytree(CATALOGS, repo / "catalogs")
    git = ["git", "-c", "user.name=t", "-c", "user.email=t@example.com", "-c", "commit.gpgsign=false"]
    subprocess.run(git + ["init", "-q"], cwd=repo, check=True)
    subprocess.run(git + ["add", "."], cwd=repo, check=True)
    subprocess.run(git + ["commit", "-qm", "catalog"], cwd=repo, check=True)
    sheet = tmp_path / "new.csv"
    sheet.write_text(_SHEET)
    code, out, err = run_cli("catalog", "add", "stack", sheet, "--catalog", repo / "catalogs")
    assert code == 0, err
    _set_field(repo / "catalogs", "stacks.toml", STACK, "cost_usd", "25000")
    subprocess.run(git + ["commit", "-qam", "new stack, new price"], cwd=repo, check=True)
    subprocess.run(git + ["tag", "v2"], cwd=repo, check=True)

    monkeypatch.chdir(repo)
    diff = diff_catalogs("HEAD~1", "v2")
    assert [e.id for e in diff.added] == ["pi-p-888.31"] and diff.removed == []
    (changed,) = diff.changed
    assert changed.id == STACK and [f.field for f in changed.fields] == ["cost_usd"]
    assert changed.fields[0].new == 25000
    assert diff.old_sha256 != diff.new_sha256
    assert "+ stack pi-p-888.31" in format_diff(diff)
    # the JSON form reads back
    assert CatalogDiff.from_dict(json.loads(json.dumps(diff.to_dict()))).to_dict() == diff.to_dict()

    code, _, err = run_cli("catalog", "diff", "no-such-rev", "HEAD")
    assert code == 2 and "no-such-rev" in err and "Traceback" not in err


# --- acceptance: validate --------------------------------------------------------

def _validate_fails(folder, *expected):
    code, out, err = run_cli("catalog", "validate", folder)
    assert code == 2, (out, err)
    assert "Traceback" not in err and len(err.strip().splitlines()) == 1, err
    for text in expected:
        assert text in err, (text, err)
    return err


def test_unit_error_fails_validate(catalog_copy):
    _set_field(catalog_copy, "seals.toml", "fkm-o-ring", "pressure_rating", '"10 MN"')
    _validate_fails(catalog_copy, "seals.toml", "[[seal]] fkm-o-ring", "pressure_rating", "expected a pressure")


def test_duplicate_id_across_files_fails_validate(catalog_copy):
    path = catalog_copy / "fluids.toml"
    text = path.read_text()
    first_id = re.search(r'^id = "([^"]+)"', text, re.MULTILINE).group(1)
    path.write_text(text.replace(f'id = "{first_id}"', f'id = "{STACK}"', 1))
    _validate_fails(catalog_copy, "fluids.toml", f"[[fluid]] {STACK}", "id", "duplicate id", "stacks.toml")


def test_implausible_value_fails_validate(catalog_copy):
    # kg/m^3 mistyped as g/m^3: a density of 0.87 kg/m^3 is a gas, not an oil
    _set_field(catalog_copy, "fluids.toml", "iso-vg-15-mineral", "density", '"870 g/m^3"')
    _validate_fails(catalog_copy, "fluids.toml", "[[fluid]] iso-vg-15-mineral", "density", "implausible value")


def test_inconsistent_stack_fails_validate(catalog_copy):
    _set_field(catalog_copy, "stacks.toml", "pi-p-888.91", "blocked_force", '"32 N"')
    _validate_fails(catalog_copy, "stacks.toml", "[[stack]] pi-p-888.91", "blocked_force", "stiffness x stroke")


def test_unordered_temperature_range_fails_validate(catalog_copy):
    _set_field(catalog_copy, "seals.toml", "ptfe-o-ring", "min_temperature", '"300 degC"')
    _validate_fails(catalog_copy, "seals.toml", "[[seal]] ptfe-o-ring", "max_temperature", "above min_temperature")


def test_seal_without_pressure_rating_fails_validate(catalog_copy):
    _drop_line(catalog_copy, "seals.toml", "ptfe-o-ring", "pressure_rating")
    _drop_line(catalog_copy, "seals.toml", "ptfe-o-ring", "pressure_rating")   # its status line
    _validate_fails(catalog_copy, "seals.toml", "[[seal]] ptfe-o-ring", "pressure_rating", "required")


def test_shipped_catalog_validates_and_stale_entries_are_flagged():
    report = validate_catalog()
    assert report.n_entries == len(load_catalog().entries())
    cat = load_catalog()
    newest = max(e.retrieved for _, e in cat.entries())
    later = newest + dt.timedelta(days=400)
    stale = stale_entries(cat, 365, today=later)
    assert len(stale) == report.n_entries and all("older than 365" in s for s in stale)
    oldest = min(e.retrieved for _, e in cat.entries())
    assert stale_entries(cat, 365, today=oldest) == []
    code, _, err = run_cli("catalog", "validate", "--max-age-days", "0")
    assert code == 0
    code, _, err = run_cli("catalog", "validate", "--max-age-days", "-1")
    assert code == 2 and "--max-age-days" in err


def test_future_retrieval_date_fails(catalog_copy):
    _set_field(catalog_copy, "stacks.toml", STACK, "retrieved", "2999-01-01")
    _validate_fails(catalog_copy, f"[[stack]] {STACK}", "retrieved", "not in the future")


# --- import ------------------------------------------------------------------

_SHEET = (
    "id,name,manufacturer,source,retrieved,stiffness [N/um],stroke_per_volt,max_voltage [V],stroke [um],"
    "blocked_force [N],capacitance [uF],mass [g],length [mm],diameter [mm],section,max_temperature [degC],"
    "cost_usd,status,status.cost_usd\n"
    'pi-p-888.31,"PI P-888.31 PICMA Stack, 10 x 10 x 9 mm",Physik Instrumente (PI),'
    '"PI datasheet P-882 - P-888, row P-888.31",2026-11-01,300,6.5e-8 m/V,100,6.5,1950,3.1,7,9,10,square,150,'
    '250,datasheet,"assumed: list price not retrieved"\n'
)


def test_catalog_add_writes_valid_entries(catalog_copy, tmp_path):
    sheet = tmp_path / "parts.csv"
    sheet.write_text(_SHEET)
    code, out, err = run_cli("catalog", "add", "stack", sheet, "--catalog", catalog_copy)
    assert code == 0, err
    assert "pi-p-888.31" in out
    stack = load_catalog(catalog_copy).stacks["pi-p-888.31"]
    assert stack.stiffness == pytest.approx(3e8) and stack.mass == pytest.approx(0.007)
    assert stack.stroke == pytest.approx(6.5e-6) and stack.section == "square"
    assert stack.status["stiffness"] == "datasheet" and stack.assumed() == {"cost_usd": "list price not retrieved"}
    assert validate_catalog(catalog_copy).n_entries == len(load_catalog(CATALOGS).entries()) + 1
    # adding the same sheet again: the id exists
    code, _, err = run_cli("catalog", "add", "stack", sheet, "--catalog", catalog_copy)
    assert code == 2 and "line 2" in err and "already in the catalog" in err


@pytest.mark.parametrize("old, new, column", [
    (",300,", ",300 kg,", "column 6 (stiffness)"),                 # unit error
    (",1950,", ",1.95,", "column 10 (blocked_force)"),             # implausible: 1000x too small
    (",square,", ",squared,", "column 15 (section)"),              # bad choice
    ("2026-11-01", "01/11/2026", "column 5 (retrieved)"),          # bad date
])
def test_catalog_add_bad_row_exits_2_and_writes_nothing(catalog_copy, tmp_path, old, new, column):
    lines = _SHEET.splitlines()
    sheet = tmp_path / "parts.csv"
    sheet.write_text("\n".join([lines[0], lines[1].replace("pi-p-888.31", "ok-part"), lines[1].replace(old, new, 1)]) + "\n")
    before = (catalog_copy / "stacks.toml").read_bytes()
    code, _, err = run_cli("catalog", "add", "stack", sheet, "--catalog", catalog_copy)
    assert code == 2 and "parts.csv" in err and "line 3" in err and column in err, err
    assert (catalog_copy / "stacks.toml").read_bytes() == before


def test_catalog_add_unknown_column_and_kind(catalog_copy, tmp_path):
    sheet = tmp_path / "parts.csv"
    sheet.write_text(_SHEET.replace("stroke_per_volt", "strok_per_volt"))
    code, _, err = run_cli("catalog", "add", "stack", sheet, "--catalog", catalog_copy)
    assert code == 2 and "line 1" in err and "strok_per_volt" in err
    code, _, err = run_cli("catalog", "add", "widget", sheet, "--catalog", catalog_copy)
    assert code == 2 and "widget" in err


# --- provenance --------------------------------------------------------------

def test_assumed_values_of_a_design():
    cat = load_catalog()
    components = {"stack": STACK, "n_stacks": 10, "ratio": 277.0, "fluid": "no-such-fluid"}
    assumed = assumed_values(cat, components)
    assert set(assumed) == {STACK}
    assert assumed[STACK] == cat.stacks[STACK].assumed() and assumed[STACK]
    counts = status_counts(cat, [STACK])
    assert sum(counts.values()) == len(cat.stacks[STACK].status) and counts["assumed"] == len(assumed[STACK])


# --- rank changes ----------------------------------------------------------------

def _cand(cid, rank, feasible, pareto, stack=STACK, **extra):
    return {"id": cid, "technology": "piezohydraulic", "rank": rank, "feasible": feasible, "pareto": pareto,
            "components": {"stack": stack, "n_stacks": 10, "ratio": 277.0, "fluid": "iso-vg-15-mineral"},
            "stack_params": {"stiffness_N_m": 4.33e8, "d33_m_V": 1.8e-7, "max_voltage_V": 1000.0},
            "margins": {"stroke": 0.1}, "driver": "stroke", **extra}


def _results(*cands):
    return {"tool_version": "0.1.0", "catalog_sha256": "x", "candidates": list(cands)}


def test_rank_changes_hand_made():
    baseline = _results(_cand("a", 1, True, True), _cand("b", 2, True, False, stack="pi-p-888.91"),
                        _cand("c", 3, False, False, stack="pi-p-888.51"), _cand("gone", 4, False, False))
    new_c = _cand("c", 1, True, True, stack="pi-p-888.51")
    results = _results(new_c, _cand("a", 2, True, False), _cand("b", 3, True, False, stack="pi-p-888.91"),
                       _cand("new", 4, False, False))
    diff = {"old": "o", "new": "n", "added": [], "removed": [],
            "changed": [{"kind": "stack", "id": "pi-p-888.51", "file": "stacks.toml",
                         "fields": [{"field": "stiffness", "old": 2e8, "new": 2.5e8, "unit": "N/m"}]}]}
    changes = rank_changes(baseline, results, diff)
    by_id = {c["id"]: c for c in changes}
    assert set(by_id) == {"a", "b", "c", "gone", "new"}
    assert changes[0]["id"] == "c"                     # entering the feasible set comes first
    c = by_id["c"]
    assert c["events"] == ["entered_feasible", "entered_pareto", "rank_up"]
    assert c["rank"] == [3, 1] and c["rank_move"] == 2 and c["feasible"] == [False, True]
    assert c["causes"] == [{"entry": "pi-p-888.51", "kind": "stack", "field": "stiffness", "old": 2e8,
                            "new": 2.5e8, "unit": "N/m", "relative_change": None}]
    assert "pi-p-888.51.stiffness" in c["summary"] and "rank 3 -> 1" in c["summary"]
    assert by_id["a"]["events"] == ["left_pareto", "rank_down"] and by_id["a"]["causes"] == []
    assert "other designs moved" in by_id["a"]["summary"]
    assert by_id["b"]["events"] == ["rank_down"] and by_id["b"]["rank_move"] == -1
    assert by_id["gone"]["events"] == ["dropped_candidate"] and by_id["gone"]["rank"] == [4, None]
    assert by_id["new"]["events"] == ["new_candidate"] and by_id["new"]["rank_move"] is None
    # nothing changed: nothing listed
    assert rank_changes(baseline, baseline, None) == []


def test_rank_changes_without_diff_uses_stack_params():
    baseline = _results(_cand("a", 1, True, True), _cand("b", 2, True, True, stack="pi-p-888.91"))
    moved = _cand("a", 2, False, False)
    moved["stack_params"] = dict(moved["stack_params"], stiffness_N_m=3.0e8)
    results = _results(_cand("b", 1, True, True, stack="pi-p-888.91"), moved)
    (a, b) = rank_changes(baseline, results, None)
    assert a["id"] == "a" and a["events"] == ["left_feasible", "left_pareto", "rank_down"]
    assert [(x["entry"], x["field"], x["old"], x["new"]) for x in a["causes"]] == [(STACK, "stiffness_N_m", 4.33e8, 3.0e8)]
    assert b["events"] == ["rank_up"] and b["causes"] == []


def test_rank_changes_accepts_a_diff_object(tmp_path):
    """The acceptance chain without `sizing solve`: a real diff names the field
    responsible for a design that moved."""
    old, new = tmp_path / "old", tmp_path / "new"
    shutil.copytree(CATALOGS, old)
    shutil.copytree(CATALOGS, new)
    _set_field(new, "stacks.toml", STACK, "stiffness", '"3.0e8 N/m"')
    diff = diff_catalogs(old, new)
    baseline = _results(_cand("ph-a", 1, True, True))
    results = _results(_cand("ph-a", 1, False, False))
    (change,) = rank_changes(baseline, results, diff)
    assert change["events"] == ["left_feasible", "left_pareto"]
    assert [(c["entry"], c["field"], c["unit"]) for c in change["causes"]] == [(STACK, "stiffness", "N/m")]
    assert change["causes"][0]["new"] == pytest.approx(3.0e8)


def test_solve_with_baseline_names_the_field(tmp_path, seed_solve_fast):
    """Acceptance, second half: `sizing solve --baseline` after the stiffness
    change lists the designs that moved and blames the stack's stiffness."""
    new = tmp_path / "new"
    shutil.copytree(CATALOGS, new)
    _set_field(new, "stacks.toml", STACK, "stiffness", '"2.0e8 N/m"')
    req = CATALOGS.parent / "studies" / "seed-requirements.toml"
    # the baseline: the seed solved with the shipped catalog (once per test run, conftest)
    code, _, err = run_cli("solve", req, "--out", tmp_path / "after", "--catalog", new,
                           "--baseline", seed_solve_fast.out / "results.json", "--quiet", "--fast")
    assert code == 0, err
    results = json.loads((tmp_path / "after" / "results.json").read_text())
    assert results["changes"], "halving the PI stack's stiffness must move the designs built on it"
    causes = [c for ch in results["changes"] for c in ch.get("causes", [])]
    blamed = [c for c in causes if c["entry"] == STACK and c["field"] == "stiffness"]
    assert blamed, causes[:5]
    assert "What changed" in (tmp_path / "after" / "report.html").read_text()


# --- golden reasons ----------------------------------------------------------

def test_golden_failure_names_the_catalog_field(catalog_copy):
    from ..project import test_golden as golden_module

    golden = golden_module._design("seed-table2-full-scale")
    _set_field(catalog_copy, "stacks.toml", STACK, "stiffness", '"3.0e8 N/m"')
    result = api.evaluate(CATALOGS.parent / golden["study"], catalog_copy)
    failures = golden_module.check_design(golden, result)
    # the seed's published 2.81 kN is now checked as the ideal figure
    assert any(f.startswith("static.blocked_force_ideal_N") for f in failures)
    message = golden_module.explain(golden, result, failures, load_catalog(catalog_copy))
    assert "the catalog changed" in message and f"{STACK}.stiffness" in message


def test_evaluate_marks_assumed_values():
    """Reports mark results that rest on assumed values."""
    result = api.evaluate(CATALOGS.parent / "studies" / "seed-table3-prototype.toml")
    cat = load_catalog()
    assert result["assumed"]["thorlabs-pk4ga7p1"] == cat.stacks["thorlabs-pk4ga7p1"].assumed()
    from sizing.report.text import evaluation_summary
    assert "rests on assumed catalog values" in evaluation_summary(result)


def test_snapshot_beside_results_is_the_baseline_catalog(tmp_path, catalog_copy):
    """What `sizing solve --baseline OLD/results.json` diffs against."""
    from sizing.io.catalog_diff import baseline_catalog, snapshot_files

    out = tmp_path / "run"
    for name, content in snapshot_files(CATALOGS).items():      # as sizing solve writes them
        (out / name).parent.mkdir(parents=True, exist_ok=True)
        (out / name).write_bytes(content)
    (out / "results.json").write_text("{}")
    assert baseline_catalog(out / "results.json") == out / "catalog"
    _set_field(catalog_copy, "stacks.toml", STACK, "stiffness", '"4.0e8 N/m"')
    diff = diff_catalogs(baseline_catalog(out / "results.json"), catalog_copy)
    assert [(c.id, [f.field for f in c.fields]) for c in diff.changed] == [(STACK, ["stiffness"])]
    # without a snapshot: the catalog_dir recorded in results.json, if unchanged since
    bare = tmp_path / "bare" / "results.json"
    bare.parent.mkdir()
    assert baseline_catalog(bare, {"catalog_dir": str(CATALOGS), "catalog_sha256": load_catalog().sha256}) == CATALOGS
    assert baseline_catalog(bare, {"catalog_dir": str(CATALOGS), "catalog_sha256": "stale"}) is None
