"""``sizing robust`` and ``sizing sweep``: studies that run many solves,
serially or on Dask (``studies.executor``)."""
from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar

from ..errors import InputError
from ..io.catalog import load_catalog
from . import output
from .checks import one_of
from .output import PLOTLY_FILE, Payload, plotly_js

ROBUST_OUTPUTS = ("robust.json", "robust.html", PLOTLY_FILE)
SWEEP_OUTPUTS = ("sweep.json", "sweep.html", PLOTLY_FILE)


@dataclass(frozen=True)
class StudyResult(Payload):
    """A robust or sweep study: ``data`` (robust.json or sweep.json,
    docs/formats.md) and which it is. Reads as the ``data`` mapping."""

    kind: str          # "robust" or "sweep"
    data: dict
    inputs: tuple = ()
    layout: ClassVar[str] = "folder"

    def _payload(self) -> dict:
        return self.data

    def point_lines(self) -> list[str]:
        """A sweep's grid points as the terminal shows them: the varied values
        with units, the feasible count per technology, the best by name."""
        from ..report.words import sweep_point_line
        return [sweep_point_line(g) for g in self.data.get("grid", [])]

    def files(self) -> dict:
        if self.kind == "robust":
            from ..report.robust_html import render
        else:
            from ..report.sweep_html import render
        return {f"{self.kind}.json": json.dumps(self.data, indent=1, allow_nan=False) + "\n",
                f"{self.kind}.html": render(self.data), PLOTLY_FILE: plotly_js}


def _executor(scheduler: str | None, workers: int, cluster=None, progress=None):
    """The study executor; tells ``progress.note`` (when it has one) where the
    Dask dashboard shows the tasks."""
    from ..studies.executor import Executor
    ex = Executor(workers=workers, scheduler=scheduler, cluster=cluster)
    if ex.dashboard and hasattr(progress, "note"):
        progress.note(f"Dask dashboard: {ex.dashboard}")
    return ex


def _stage(progress, stage: str):
    """``progress(stage, done, total)`` as the ``progress(done, total)`` a study reports."""
    return (lambda done, total: progress(stage, done, total)) if progress else None


def robust(requirements_path: str | Path, out_dir: str | Path | None = "robust-out", catalog_dir=None,
           samples: int = 1000, seed: int = 0, designs: int = 10, scheduler: str | None = None,
           workers: int = 0, cluster=None, progress=None, bouc_wen_fit: str | Path | None = None,
           technology: str | None = None) -> StudyResult:
    """Probability of compliance of the ``designs`` best designs of ``solve``
    (those whose parts robust can perturb; only ``technology``'s when given)
    under the [tolerances] (docs/formats.md). ``workers`` > 0: a
    local Dask cluster of that many processes; ``scheduler``: a running one;
    ``cluster``: a dask cluster object. ``bouc_wen_fit``: a ``sizing fit
    hysteresis`` output whose standard errors become Bouc-Wen tolerances. Writes robust.json and robust.html
    into ``out_dir`` when given. ``progress(stage, done, total)``."""
    def compute():
        return run_robust(requirements_path, catalog_dir, samples, seed, designs, scheduler, workers, cluster,
                          progress, bouc_wen_fit, technology)
    return output.produce(ROBUST_OUTPUTS, out_dir, (requirements_path, catalog_dir, bouc_wen_fit), compute)


def run_robust(requirements_path, catalog_dir=None, samples: int = 1000, seed: int = 0, designs: int = 10,
               scheduler=None, workers: int = 0, cluster=None, progress=None, bouc_wen_fit=None,
               technology=None) -> StudyResult:
    """The robust study without writing anything (``robust``'s arguments)."""
    from ..io.requirements import load_requirements

    if samples < 1:
        raise InputError(None, "--samples", f"expected at least 1 sample, got {samples}")
    if designs < 1:
        raise InputError(None, "--designs", f"expected at least 1 design, got {designs}")
    from ..technologies.registry import names
    one_of(technology, (None, *names()), "--technology")
    req, sha = load_requirements(requirements_path)
    cat = load_catalog(catalog_dir)
    extra = None
    if bouc_wen_fit is not None:        # the stack was fitted: its Bouc-Wen spreads from the fit
        from ..io.fit_spreads import bouc_wen_spreads
        extra = bouc_wen_spreads(bouc_wen_fit)
    with _executor(scheduler, workers, cluster, progress) as ex:        # an unreachable scheduler fails here, first
        from ..engine.solve import solve as run                # (the engine's imports take seconds)
        from ..studies.robust import pick_designs, robust as study
        solved = run(req, sha, cat, progress=progress, fast=True)      # the designs to study, not their flips
        results = solved.results
        picked = pick_designs(results, designs, technology)
        if not picked:
            raise InputError(str(requirements_path), None, "no sized design whose parts have a tolerance model "
                                                           f"to study{'' if technology is None else ' of ' + technology}")
        data = study(req, cat, picked, samples, seed, ex, extra_spreads=extra, progress=_stage(progress, "sampling"),
                     stages=solved.stages)        # the solve's own records, not re-read from results
    data["requirements_sha256"] = sha
    data["catalog_sha256"] = cat.sha256
    return StudyResult("robust", data, (requirements_path, catalog_dir, bouc_wen_fit))


def sweep(requirements_path: str | Path, vary: list[str], out_dir: str | Path | None = "sweep-out",
          catalog_dir=None, scheduler: str | None = None, workers: int = 0, cluster=None,
          progress=None) -> StudyResult:
    """A full solve per point of the grid ``vary`` (``FIELD=FROM..TO:N``
    each); writes sweep.json and sweep.html into ``out_dir`` when given."""
    def compute():
        return run_sweep(requirements_path, vary, catalog_dir, scheduler, workers, cluster, progress)
    return output.produce(SWEEP_OUTPUTS, out_dir, (requirements_path, catalog_dir), compute)


def run_sweep(requirements_path, vary, catalog_dir=None, scheduler=None, workers: int = 0, cluster=None,
              progress=None) -> StudyResult:
    """The sweep without writing anything (``sweep``'s arguments)."""
    from ..io.schema import load_toml
    from ..studies.sweep import parse_vary, sweep as study

    data = load_toml(requirements_path)
    cat = load_catalog(catalog_dir)
    for v in vary:                          # bad --vary before any cluster starts
        parse_vary(v, data, requirements_path)
    with _executor(scheduler, workers, cluster, progress) as ex:
        grid = study(data, requirements_path, cat, vary, ex, progress=_stage(progress, "solving"))
    return StudyResult("sweep", grid, (requirements_path, catalog_dir))
