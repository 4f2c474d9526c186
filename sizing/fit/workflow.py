"""The fit commands end to end: read runs, split off the holdout, fit, render
the TOML and the HTML report, write both atomically. ``sizing.api`` calls
these; the CLI only prints."""
from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np

from ..errors import InputError
from ..io.atomic import check_files, write_files
from ..io.rig import DCRig, load_rig
from ..io.runs import read_runs, split_holdout
from ..limits import check_steps, dc_steps
from ..sim.signals import nrmse
from .dc_motor import DCMotorEstimator, DCRecord
from .output import render_toml



def _mean(values):
    values = list(values)
    return float(np.mean(values)) if values else None


def _source(paths) -> str:
    return ", ".join(str(p) for p in paths)


def fit_hysteresis(paths, holdout=None, model: str = "auto", out=None, report=None, **options) -> dict:
    """Fit Bouc-Wen and Prandtl-Ishlinskii to runs (CSV paths); see
    ``hysteresis_workflow.fit_hysteresis``."""
    from .hysteresis_workflow import fit_hysteresis as run

    return run(paths, holdout=holdout, model=model, out=out, report=report, **options)


def fit_dc_motor(paths, rig_path, holdout=None, out=None, report=None, fit_gains: bool = False,
                 n_starts: int = 3, seed: int = 0, progress=None) -> dict:
    """Fit c1, c2 (and gains) of the rig's DC motor to reference/position runs."""
    from ..sim.rigs import dc_model

    check_files(_targets(out, report), inputs=[*paths, rig_path])
    rig = load_rig(rig_path)
    if not isinstance(rig, DCRig):
        raise InputError(str(rig_path), "kind", 'expected "dc_motor" for sizing fit dc-motor')
    runs = read_runs(paths, kind="dc_motor")
    check_steps(dc_steps(sum(float(r.time[-1] - r.time[0]) for r in runs), rig.controller.rate),
                str(rig_path), "[controller].rate", "controller steps per simulation of the runs")
    train, hold = split_holdout(runs, holdout, _source(paths))

    def record(run):
        return DCRecord(run.name, run.time, run["reference_m"], run["position_m"], source=str(run.path))

    train_rec, hold_rec = [record(r) for r in train], [record(r) for r in hold]
    with warnings.catch_warnings(record=True) as log:
        warnings.simplefilter("always")
        est = DCMotorEstimator(dc_model(rig), fit_gains=fit_gains, n_starts=n_starts, random_state=seed,
                               progress=progress).fit(train_rec)
    caught = [str(w.message) for w in log]
    traces, runs_nrmse = [], {"train": {}, "holdout": {}}
    for role, recs in (("train", train_rec), ("holdout", hold_rec)):
        for rec in recs:
            x = est.predict(rec)
            runs_nrmse[role][rec.name] = nrmse(rec.position, x)
            traces.append({"name": rec.name, "role": role, "time": rec.time, "reference": rec.reference,
                           "measured": rec.position, "fitted": {"dc-motor": x}})
    fit_table = {"model": "dc-motor", "nrmse_train": _mean(runs_nrmse["train"].values()),
                 "nrmse_holdout": _mean(runs_nrmse["holdout"].values()),
                 "train_runs": [r.name for r in train_rec], "holdout_runs": [r.name for r in hold_rec],
                 "warnings": list(est.warnings_),
                 "nrmse_runs": {**runs_nrmse["train"], **runs_nrmse["holdout"]},
                 "ci95": {n: list(v) for n, v in est.ci95_.items()},
                 "stderr": {n: float(s) for n, s in zip(est.names_, est.stderr_)}}
    tables = {"motor": {"c1": est.params_["c1"], "c2": est.params_["c2"]}}
    gains = {k: v for k, v in est.params_.items() if k in ("kp", "ki", "kd")}
    if gains:
        tables["controller"] = gains
    tables["fit"] = fit_table
    toml = render_toml(tables, {"motor": "sizing fit dc-motor: seed eq. 13-14, SI (paste into rig.toml)",
                                "fit": "not part of a rig: fit figures (NRMSE per docs/formats.md)"})
    result = {"model": "dc-motor", "traces": traces, "fit": fit_table, "params": est.params_,
              "ci95": est.ci95_, "warnings": est.warnings_, "sources": [str(p) for p in paths],
              "summary": {"dc-motor": {"nrmse_train": fit_table["nrmse_train"],
                                       "nrmse_holdout": fit_table["nrmse_holdout"],
                                       "nrmse_runs": fit_table["nrmse_runs"]}}}
    written = _write(out, report, toml, result, kind="dc-motor", inputs=[*paths, rig_path])
    return {"toml": toml, "warnings": list(dict.fromkeys(caught)), "result": result, "written": written}


def _targets(out, report) -> list[Path]:
    """The files ``--out`` and ``--report`` name (the report defaults to OUT.html)."""
    targets = [Path(out)] if out is not None else []
    if report is None and out is not None:
        report = Path(out).with_suffix(".html")
    if report is not None:
        if targets and Path(report).absolute() == targets[0].absolute():
            raise InputError(str(report), "--report", "the report would overwrite the --out file; give another name")
        targets.append(Path(report))
    return targets


def _write(out, report, toml, result, kind, inputs=(), extra: dict | None = None) -> list[str]:
    """Write the TOML, the report and any ``extra`` files (path -> text) as
    one set (``io.atomic.write_files``), never over an input."""
    from ..report.bundle import PLOTLY_FILE, plotly_js
    from ..report.fit_html import render
    targets = _targets(out, report)
    files: dict[Path, object] = {path: toml for path in targets[:1 if out is not None else 0]}
    pages = targets[1 if out is not None else 0:]
    files.update({path: render(result, kind=kind, toml=toml) for path in pages})
    files.update({path.parent / PLOTLY_FILE: plotly_js for path in pages})
    files.update(extra or {})
    write_files(files, inputs=inputs)
    return [str(p) for p in files]
