"""``sizing solve``: size, verify and rank designs for a requirements file,
compared with a baseline and carrying robust-study figures when asked.
``run_solve`` computes a ``SolveResult``; ``solve`` also writes it."""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from pathlib import Path
from typing import ClassVar

from ..io.catalog import load_catalog
from . import output
from .checks import check_solve_steps, one_of, read_json
from .output import PLOTLY_FILE, Payload, plotly_js

# What ``solve --out DIR`` holds (checked before any work).
SOLVE_OUTPUTS = ("results.json", "candidates.csv", "report.html", "catalog/", PLOTLY_FILE)


@dataclass(frozen=True)
class SolveResult(Payload):
    """A solve: ``results`` (results.json, docs/formats.md, its candidates
    ``engine.candidate.Candidate``s), the simulated ``traces`` the report
    plots, and the catalog folder it rests on. Reads as results.json
    (``records``)."""

    results: dict
    traces: list
    catalog_folder: Path
    inputs: tuple = ()
    layout: ClassVar[str] = "folder"

    @cached_property
    def records(self) -> dict:
        """results.json as written: the results with each candidate its record."""
        from ..engine.candidate import records
        return dict(self.results, candidates=records(self.results["candidates"]))

    def _payload(self) -> dict:
        return self.records

    def knife_edges(self) -> str:
        """The terminal line of the checks met by less than ``KNIFE_EDGE``
        (sizing/settings.py; "" when none)."""
        from ..report.text import knife_edge_text
        return knife_edge_text(self.results["summary"].get("comparison", {}))

    def flip_lines(self) -> list[str]:
        """What would flip each technology's verdict, re-solved, in the
        user's units: one terminal line per technology (none with --fast)."""
        from ..engine.comparison import actuator_noun
        from ..engine.flip import flip_text
        from ..settings import FLIP_TOLERANCE
        lines = []
        for tech, t in self.results["summary"].get("comparison", {}).get("technologies", {}).items():
            flips = t.get("flips")
            if flips is None:
                continue
            shown = sorted(flips, key=lambda f: (f["to"] is None, f["changes"] != "feasibility"))
            lines.append(f"what would flip the {actuator_noun(tech)} (re-solved, to {100 * FLIP_TOLERANCE:g} %): " + "; ".join(flip_text(f) for f in shown))
        return lines

    def files(self) -> dict:
        """results.json, candidates.csv, report.html, plotly.js and the
        catalog snapshot a later ``--baseline`` diffs against."""
        from ..io.catalog_diff import snapshot_files
        from ..report.csv_table import candidates_csv
        from ..report.html import render
        files = {"results.json": results_json(self.records), "candidates.csv": candidates_csv(self.records),
                 "report.html": render(self.results, self.traces), PLOTLY_FILE: plotly_js}
        files.update(snapshot_files(self.catalog_folder))
        return files


def solve(requirements_path: str | Path, out_dir: str | Path | None = "sizing-out",
          catalog_dir: str | Path | None = None, baseline: str | Path | None = None,
          progress=None, detail: str = "summary", robust: str | Path | None = None,
          fast: bool = False) -> SolveResult:
    """Size, verify and rank designs for a requirements file (docs/formats.md).

    Writes results.json, candidates.csv and report.html into ``out_dir``
    (atomically, after everything is computed and rendered; nothing when
    ``out_dir`` is None). ``baseline``: an earlier results.json to compare
    with ("changes" in the results, "What changed" in the report).
    ``progress(stage, done, total)`` is called while candidates are sized and
    simulated. ``detail``: "summary" counts the combinations ruled out before
    sizing by reason (``summary.ruled_out``); "full" also records each one.
    ``robust``: a robust.json of these requirements; each design it studied
    gets its probability of compliance (``p_compliance``, ``p_ci95``).
    ``fast``: skip the probability of compliance (``compliance`` null; the
    nominal recommendation) and what would flip each verdict (``flips``
    null), for quick iterations on the requirements.
    Raises InputError for bad input before writing anything.
    """
    def compute():
        return run_solve(requirements_path, catalog_dir, baseline, progress, detail, robust, fast)
    return output.produce(SOLVE_OUTPUTS, out_dir, (requirements_path, catalog_dir, baseline, robust), compute)


def run_solve(requirements_path, catalog_dir=None, baseline=None, progress=None, detail: str = "summary",
              robust=None, fast: bool = False) -> SolveResult:
    """The solve without writing anything (``solve``'s arguments)."""
    from ..io.requirements import load_requirements

    one_of(detail, ("summary", "full"), "--detail")
    req, sha = load_requirements(requirements_path)
    cat = load_catalog(catalog_dir)
    check_solve_steps(req, cat, str(requirements_path))
    old = _load_baseline(baseline) if baseline is not None else None
    studied = _load_robust(robust) if robust is not None else None
    from ..engine.solve import solve as run      # cvxpy and numba load once the inputs are known good
    out = run(req, sha, cat, progress=progress, detail=detail, fast=fast)
    results = dict(out.results, catalog_dir=str(cat.folder.resolve()))
    from ..studies import compliance
    if fast:
        results = compliance.attach_fast(results, req)
    else:
        results = compliance.attach(req, cat, results, out.stages)
    if studied is not None:
        results = _with_compliance(results, studied)
    if old is not None:
        changes, changes_summary = _rank_changes(old, results, baseline, cat.folder)
        results = dict(results, changes=changes, changes_summary=changes_summary,
                       baseline_sha256=old.get("requirements_sha256"))
    return SolveResult(results, out.traces, cat.folder, (requirements_path, catalog_dir, baseline, robust))


def results_json(results: dict) -> str:
    """results.json as people read it: the top level indented, each candidate
    (and each ruled-out record) one compact line, so a candidate is one line
    of a diff and the file stays a few MB."""
    import json
    head = {k: v for k, v in results.items() if k not in ("candidates", "ruled_out")}
    text = json.dumps(head, indent=1, allow_nan=False)[:-2]
    for key in ("candidates", "ruled_out"):
        rows = ",\n".join(json.dumps(c, separators=(",", ":"), allow_nan=False) for c in results.get(key, []))
        text += f',\n "{key}": [\n{rows}\n ]'
    return text + "\n}\n"


def _load_robust(path: str | Path) -> dict[str, dict]:
    """{design id: its robust.json entry} of a robust.json (exit 2 when it is not one)."""
    from ..errors import InputError
    path = Path(path)
    data = read_json(path, "robust.json", "sizing robust")
    designs = data.get("designs") if isinstance(data, dict) else None
    if not isinstance(designs, list) or not all(isinstance(d, dict) and "id" in d and "p_compliance" in d
                                                for d in designs):
        raise InputError(str(path), "designs", "expected a robust.json with designs and their p_compliance")
    return {d["id"]: d for d in designs}


def _with_compliance(results: dict, studied: dict[str, dict]) -> dict:
    """New results in which each studied candidate, and each technology's
    best, carries its probability of compliance under tolerances and its
    95 % interval."""
    def given(ident: str) -> dict:
        entry = studied.get(ident)
        return {} if entry is None else {"p_compliance": entry["p_compliance"], "p_ci95": entry.get("p_ci95")}
    summary, comparison = results["summary"], results["summary"]["comparison"]
    techs = {name: dict(t, **given(t["best"])) for name, t in comparison["technologies"].items()}
    return dict(results, candidates=[c.with_fields(**g) if (g := given(c.id)) else c for c in results["candidates"]],
                summary=dict(summary, comparison=dict(comparison, technologies=techs)))


def _load_baseline(path: str | Path) -> dict:
    from ..errors import InputError
    path = Path(path)
    data = read_json(path, "results.json", "sizing solve")
    if not isinstance(data, dict) or not isinstance(data.get("candidates"), list):
        raise InputError(str(path), "candidates", "expected a results.json with a list of candidates")
    return data


def _rank_changes(baseline: dict, results: dict, baseline_path, catalog_folder: Path) -> tuple[list[dict], dict]:
    """Designs whose standing changed (engine/changes.py), with the
    catalog fields responsible when the baseline's catalog is known (the
    snapshot ``sizing solve`` writes beside its results.json)."""
    from ..engine.changes import change_causes, rank_changes
    from ..io.catalog_diff import baseline_catalog, diff_catalogs
    old_catalog = baseline_catalog(baseline_path, baseline)
    diff = diff_catalogs(old_catalog, catalog_folder) if old_catalog is not None else None
    changes = rank_changes(baseline, results, diff)
    return changes, change_causes(baseline, results, changes, diff)
