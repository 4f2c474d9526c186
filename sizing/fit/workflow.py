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
from .bouc_wen import PARAM_NAMES, BoucWenEstimator
from .common import HysteresisRecord
from .dc_motor import DCMotorEstimator, DCRecord
from .output import render_toml
from .prandtl_ishlinskii import PrandtlIshlinskiiEstimator

MODELS = ("bouc-wen", "prandtl-ishlinskii")


def _mean(values):
    values = list(values)
    return float(np.mean(values)) if values else None


def _source(paths) -> str:
    return ", ".join(str(p) for p in paths)


def fit_hysteresis(paths, holdout=None, model: str = "bouc-wen", out=None, report=None,
                   cutoff_hz: float | None = None, fit_offset: bool = False, n_starts: int = 4,
                   seed: int = 0, n_operators: int = 16, progress=None) -> dict:
    """Fit Bouc-Wen and Prandtl-Ishlinskii to runs (CSV paths); ``model``
    chooses which one the TOML carries. Returns {"toml", "warnings",
    "result", "written"}."""
    if model not in MODELS:
        raise InputError("command line", "--model", f"expected one of {', '.join(MODELS)}, got {model!r}")
    check_files(_targets(out, report), inputs=paths)
    runs = read_runs(paths, kind="piezohydraulic")
    train, hold = split_holdout(runs, holdout, _source(paths))

    def record(run):
        return HysteresisRecord(run.name, run.time, run["voltage_V"], run["position_m"], source=str(run.path))

    train_rec, hold_rec = [record(r) for r in train], [record(r) for r in hold]
    caught: list[str] = []
    with warnings.catch_warnings(record=True) as log:
        warnings.simplefilter("always")
        bw = BoucWenEstimator(n_starts=n_starts, random_state=seed, cutoff_hz=cutoff_hz,
                              fit_offset=fit_offset, progress=progress).fit(train_rec)
        pi = PrandtlIshlinskiiEstimator(n_operators=n_operators, cutoff_hz=cutoff_hz).fit(train_rec)
    caught = [str(w.message) for w in log]

    traces = []
    per_model = {"bouc-wen": {"train": {}, "holdout": {}}, "prandtl-ishlinskii": {"train": {}, "holdout": {}}}
    for role, recs in (("train", train_rec), ("holdout", hold_rec)):
        for rec in recs:
            x_bw, x_pi = bw.predict(rec), pi.predict(rec)
            per_model["bouc-wen"][role][rec.name] = nrmse(rec.position, x_bw)
            per_model["prandtl-ishlinskii"][role][rec.name] = nrmse(rec.position, x_pi)
            traces.append({"name": rec.name, "role": role, "time": rec.time, "voltage": rec.voltage,
                           "voltage_filtered": rec.voltage_filtered, "measured": rec.position,
                           "fitted": {"bouc-wen": x_bw, "prandtl-ishlinskii": x_pi}})
    summary = {m: {"nrmse_train": _mean(per_model[m]["train"].values()),
                   "nrmse_holdout": _mean(per_model[m]["holdout"].values()),
                   "nrmse_runs": {**per_model[m]["train"], **per_model[m]["holdout"]}} for m in MODELS}
    other = MODELS[1 - MODELS.index(model)]
    cutoffs = sorted(set(round(c, 3) for c in bw.cutoff_hz_.values()))
    filter_note = ("voltage low-passed before it drives the models: 4th-order Butterworth, zero phase "
                   f"(forwards and backwards), cut-off {', '.join(f'{c:g}' for c in cutoffs)} Hz "
                   "(20 x the excitation frequency, at least 5 Hz), so sensor noise cannot ratchet the "
                   "hysteresis state" if any(cutoffs) else "voltage used unfiltered (--cutoff-hz 0)")
    th = bw.params_.as_array()
    fit_table = {
        "model": model,
        "nrmse_train": summary[model]["nrmse_train"],
        "nrmse_holdout": summary[model]["nrmse_holdout"],
        "train_runs": [r.name for r in train_rec],
        "holdout_runs": [r.name for r in hold_rec],
        "input_filter": filter_note,
        "cutoff_Hz": cutoffs[0] if len(cutoffs) == 1 else cutoffs,
        "warnings": list(bw.warnings_) if model == "bouc-wen" else [],
    }
    fit_table["nrmse_runs"] = summary[model]["nrmse_runs"]
    if model == "bouc-wen":
        fit_table["ci95"] = {n: [bw.ci95_[n][0], bw.ci95_[n][1]] for n in PARAM_NAMES}
        fit_table["stderr"] = {n: float(s) for n, s in zip(PARAM_NAMES, bw.stderr_)}
        fit_table["initial_state"] = {"h0_m": {**bw.h0_, **{r.name: bw.initial_state(r)[0] for r in hold_rec}},
                                      "offset_m": {**bw.offset_, **{r.name: bw.initial_state(r)[1] for r in hold_rec}}}
        if fit_offset is False:
            fit_table["initial_state"].pop("offset_m")
    fit_table[other.replace("-", "_")] = {"nrmse_train": summary[other]["nrmse_train"],
                                           "nrmse_holdout": summary[other]["nrmse_holdout"]}
    tables: dict = {}
    if model == "bouc-wen":
        tables["stack"] = {"d33": th[0]}
        tables["stack.bouc_wen"] = dict(zip(PARAM_NAMES[1:], th[1:]))
    else:
        tables["prandtl_ishlinskii"] = {"thresholds_V": [float(x) for x in pi.thresholds_],
                                        "weights_m_V": [float(x) for x in pi.weights_]}
    tables["fit"] = fit_table
    comments = {"stack": "sizing fit hysteresis: seed eq. 1-2, SI (paste into rig.toml)",
                "fit": "not part of a rig: fit figures (NRMSE per CONTRACTS.md)"}
    toml = render_toml(tables, comments)
    result = {"model": model, "summary": summary, "traces": traces, "fit": fit_table,
              "bouc_wen": {"params": dict(zip(PARAM_NAMES, th.tolist())), "ci95": bw.ci95_,
                           "corr": bw.corr_, "warnings": bw.warnings_, "h0": bw.h0_, "message": bw.message_},
              "prandtl_ishlinskii": {"thresholds_V": pi.thresholds_, "weights_m_V": pi.weights_},
              "filter": filter_note, "sources": [str(p) for p in paths]}
    warn = list(dict.fromkeys(caught))
    written = _write(out, report, toml, result, kind="hysteresis", inputs=paths)
    return {"toml": toml, "warnings": warn, "result": result, "written": written}


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
                                "fit": "not part of a rig: fit figures (NRMSE per CONTRACTS.md)"})
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


def _write(out, report, toml, result, kind, inputs=()) -> list[str]:
    from ..report.fit_html import render
    targets = _targets(out, report)
    files: dict[Path, object] = {path: toml for path in targets[:1 if out is not None else 0]}
    files.update({path: render(result, kind=kind, toml=toml) for path in targets[1 if out is not None else 0:]})
    write_files(files, inputs=inputs)
    return [str(p) for p in files]
