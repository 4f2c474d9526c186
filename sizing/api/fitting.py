"""``sizing fit hysteresis`` and ``sizing fit dc-motor``: read runs, split
off the holdout, fit with the estimators of ``sizing.fit``, build the TOML
(``api.fit_tables``) and the HTML report; ``api.output`` writes them.

Defaults for real records (hysteresis): a sensor offset and an initial state
per run are fitted, the input filter's cut-off follows each record's sample
rate and excitation, and ``model="auto"`` carries the model with the lower
mean holdout NRMSE.
"""
from __future__ import annotations

import dataclasses
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar

import numpy as np

from ..errors import InputError
from ..io.catalog import load_catalog
from ..io.rig import DC_KIND, STACK_KIND
from ..io.runs import read_runs, split_holdout
from ..report.fit_toml import render_toml
from . import output
from .output import PLOTLY_FILE, Payload, plotly_js

# The fits' modules (numba, scipy.signal) are imported inside the functions,
# once the inputs are read: a bad file answers before they load.
DEFAULT_PRIOR_STACK = "thorlabs-pk4ga7p1"     # the seed's Table 1 stack


@dataclass(frozen=True)
class FitResult(Payload):
    """A fit: the TOML it carries, the figures its report plots (``result``),
    the warnings the estimators raised, and where it goes: ``out`` (the
    TOML), ``report`` (the HTML page) and ``extra`` ({path: text}, the
    catalog entry). Reads as {"toml", "warnings", "result", "written"}."""

    kind: str            # "hysteresis" or "dc-motor"
    toml: str
    result: dict
    warnings: tuple = ()
    out: Path | None = None
    report: Path | None = None
    extra: dict = dataclasses.field(default_factory=dict)
    inputs: tuple = ()
    written: tuple = ()
    layout: ClassVar[str] = "files"

    def _payload(self) -> dict:
        return {"toml": self.toml, "warnings": list(self.warnings), "result": self.result,
                "written": list(self.written)}

    def summary(self) -> str:
        """What the fit found, as the terminal shows it before any warning:
        the model carried, its held-out NRMSE, the parameters with intervals."""
        from ..report.text import fit_summary
        return fit_summary(self.kind, self.result)

    def files(self) -> dict:
        """{path: content}: the TOML, the report with the plotly bundle beside it, the extra files."""
        from ..report.fit_html import render
        files: dict = {} if self.out is None else {self.out: self.toml}
        if self.report is not None:
            files[self.report] = lambda: render(self.result, kind=self.kind, toml=self.toml)
            files[self.report.parent / PLOTLY_FILE] = plotly_js
        files.update(self.extra)
        return files


def targets(out, report) -> tuple[Path | None, Path | None]:
    """(TOML path, report path) of ``--out`` and ``--report`` (the report
    defaults to OUT.html)."""
    out = Path(out) if out is not None else None
    if report is None and out is not None:
        report = out.with_suffix(".html")
    if report is not None and out is not None and Path(report).absolute() == out.absolute():
        raise InputError(str(report), "--report", "the report would overwrite the --out file; give another name")
    return out, Path(report) if report is not None else None


def _finish(result: FitResult) -> FitResult:
    """Write the result's files; the result with the paths written."""
    return dataclasses.replace(result, written=tuple(output.write(result)))


def _checked_targets(out, report, inputs) -> tuple[Path | None, Path | None]:
    """The targets, checked before any work: files, writable, never an input."""
    out, report = targets(out, report)
    output.check(None, [p for p in (out, report) if p is not None], inputs, layout="files")
    return out, report


# --- sizing fit hysteresis ---------------------------------------------------

def fit_hysteresis(paths, holdout=None, model: str = "auto", out=None, report=None,
                   cutoff_hz: float | None = None, fit_offset: bool = True, n_starts: int = 4,
                   seed: int = 0, n_operators: int = 16, prior_stack: str | None = None,
                   prior_sigma: float = 0.5, catalog_entry: str | None = None, catalog=None,
                   progress=None) -> FitResult:
    """Fit Bouc-Wen (seed eq. 1-2; plain and regularised toward the catalog
    prior) and Prandtl-Ishlinskii to run CSVs. ``model``: "auto" (the
    better on the holdout), "bouc-wen" or "prandtl-ishlinskii": the one the
    TOML carries. Writes OUT, the report (OUT.html unless ``report``) and,
    with ``catalog_entry``, ID.toml and ID.csv beside OUT."""
    from . import fit_tables as tables
    choices = ("auto", *tables.MODELS)
    if model not in choices:
        raise InputError("command line", "--model", f"expected one of {', '.join(choices)}, got {model!r}")
    if not prior_sigma > 0:
        raise InputError("command line", "--prior-sigma", f"expected a positive relative sd, got {prior_sigma!r}")
    if catalog_entry is not None:
        _check_entry_id(catalog_entry, catalog)
    out, report = _checked_targets(out, report, paths)
    train, hold = _hysteresis_records(paths, holdout)
    prior, prior_text, base_raw, base_named = _prior(catalog, prior_stack, train)
    with warnings.catch_warnings(record=True) as log:
        warnings.simplefilter("always")
        bw, pi = _fit_hysteresis_models(train, prior, prior_sigma, cutoff_hz, fit_offset, n_starts, seed,
                                        n_operators, progress)
        fitted = {"bouc-wen": bw.regularised_.estimator, "prandtl-ishlinskii": pi, "bouc-wen-plain": bw}
        traces, per_model, states = _hysteresis_predictions(fitted, train, hold)
    summary = {m: tables.nrmse_summary(per_model[m]) for m in fitted}
    choice = tables.choose(summary)
    carried = choice["winner"] if model == "auto" else model
    fit_table = tables.hysteresis_fit_table(carried, model, choice, summary, bw, pi, (train, hold), states,
                                            prior_text, prior_sigma, fit_offset)
    toml = render_toml(tables.hysteresis_tables(carried, bw, pi, fit_table), tables.HYSTERESIS_COMMENTS)
    extra = {} if catalog_entry is None else _catalog_entry(catalog_entry, base_raw, base_named, bw, paths,
                                                            prior_text, out)
    result = _hysteresis_result(carried, summary, traces, fit_table, bw, pi, choice, paths)
    plain = set(bw.warnings_)
    said = tuple(tables.plain_warnings([w])[0] if w in plain else w for w in _unique(log))
    return _finish(FitResult("hysteresis", toml, result, said, out, report, extra, tuple(paths)))


def _unique(log) -> tuple[str, ...]:
    return tuple(dict.fromkeys(str(w.message) for w in log))


def _hysteresis_records(paths, holdout):
    """(training, holdout) HysteresisRecords of the run CSVs; every run needs a reversal."""
    runs = read_runs(paths, kind=STACK_KIND)
    train, hold = split_holdout(runs, holdout, ", ".join(str(p) for p in paths))
    from ..fit.common import HysteresisRecord, check_hysteresis_records

    def record(run):
        return HysteresisRecord(run.name, run.time, run["voltage_V"], run["position_m"], source=str(run.path))

    train, hold = [record(r) for r in train], [record(r) for r in hold]
    check_hysteresis_records(train + hold)
    return train, hold


def _fit_hysteresis_models(train, prior, prior_sigma, cutoff_hz, fit_offset, n_starts, seed, n_operators,
                           progress):
    """The fitted BoucWenEstimator (with its regularised fit) and PrandtlIshlinskiiEstimator."""
    from ..fit.bouc_wen import BoucWenEstimator
    from ..fit.prandtl_ishlinskii import PrandtlIshlinskiiEstimator

    tick = progress or (lambda fraction, message: None)
    bw = BoucWenEstimator(n_starts=n_starts, random_state=seed, cutoff_hz=cutoff_hz, fit_offset=fit_offset,
                          prior=prior, prior_sigma=prior_sigma,
                          progress=lambda f, m: tick(0.8 * f, f"Bouc-Wen: {m}")).fit(train)
    tick(0.8, "Prandtl-Ishlinskii")
    pi = PrandtlIshlinskiiEstimator(n_operators=n_operators, cutoff_hz=cutoff_hz, fit_offset=fit_offset).fit(train)
    tick(0.9, "predictions and holdout states")
    return bw, pi


def _hysteresis_predictions(fitted: dict, train, hold):
    """Each model's prediction of each run: (traces, {model: {role: {run:
    NRMSE}}}, the carried Bouc-Wen's initial states)."""
    from ..sim.signals import nrmse
    from . import fit_tables as tables
    traces, per_model = [], {m: {"train": {}, "holdout": {}} for m in fitted}
    states = {"h0_m": {}, "offset_m": {}}
    for role, recs in (("train", train), ("holdout", hold)):
        for rec in recs:
            xs = {m: _predict(m, est, rec, role, states) for m, est in fitted.items()}
            for m, x in xs.items():
                per_model[m][role][rec.name] = nrmse(rec.position, x)
            traces.append({"name": rec.name, "role": role, "time": rec.time, "voltage": rec.voltage,
                           "voltage_filtered": rec.voltage_filtered, "measured": rec.position,
                           "fitted": {m: xs[m] for m in tables.MODELS}})
    return traces, per_model, states


def _predict(model: str, est, rec, role: str, states: dict):
    """One model's prediction of one run; a Bouc-Wen model takes the run's
    fitted initial state (training) or finds it with the model held
    (holdout), recorded in ``states`` for the carried one."""
    if model == "prandtl-ishlinskii":
        return est.predict(rec)
    h0, off = (est.h0_[rec.name], est.offset_[rec.name]) if role == "train" else est.initial_state(rec)
    if model == "bouc-wen":
        states["h0_m"][rec.name], states["offset_m"][rec.name] = h0, off
    return est.predict(rec, h0=h0, offset=off)


def _hysteresis_result(carried, summary, traces, fit_table, bw, pi, choice, paths) -> dict:
    """The figures the report plots."""
    from ..fit.bouc_wen import PARAM_NAMES
    from . import fit_tables as tables
    return {"model": carried, "summary": {m: summary[m] for m in tables.MODELS}, "traces": traces,
            "fit": fit_table,
            "bouc_wen": {"params": dict(zip(PARAM_NAMES, bw.regularised_.params.as_array().tolist())),
                         "ci95": fit_table["ci95"], "plain": dict(zip(PARAM_NAMES, bw.params_.as_array().tolist())),
                         "plain_ci95": bw.ci95_, "corr": bw.corr_, "warnings": bw.warnings_,
                         "combinations": fit_table["combinations"], "prior": fit_table["prior"],
                         "message": bw.message_},
            "prandtl_ishlinskii": {"thresholds_V": pi.thresholds_, "weights_m_V": pi.weights_},
            "model_choice": choice, "filter": fit_table["input_filter"], "sources": [str(p) for p in paths]}


def _prior(catalog_dir, prior_stack, train):
    """(physical prior (6,), source text, raw base entry, base named?)."""
    from ..io.schema import load_toml
    catalog = load_catalog(catalog_dir)
    stack_id = prior_stack or DEFAULT_PRIOR_STACK
    if stack_id not in catalog.stacks:
        field = "--prior-stack" if prior_stack else "--prior-stack (default)"
        raise InputError(str(catalog.folder), field, f"no stack {stack_id!r} in the catalog")
    stack = catalog.stacks[stack_id]
    if prior_stack and stack.bouc_wen is not None:
        bw = stack.bouc_wen
        prior = np.array([bw.d33, bw.alpha, bw.beta, bw.gamma, bw.delta, bw.n])
        text = f"catalog stack {stack_id}: its [stack.bouc_wen] values"
    else:
        prior, text = _transferred_prior(catalog, stack_id, stack, prior_stack, train)
    raw = next(e for e in load_toml(catalog.folder / "stacks.toml")["stack"] if e.get("id") == stack_id)
    return prior, text, raw, bool(prior_stack)


def _transferred_prior(catalog, stack_id, stack, prior_stack, train):
    """The seed's Table 1 loop in normalised form, carried to the named
    stack or, when none is named, to the record's ranges: (prior, text)."""
    from ..physics.bouc_wen import BoucWen, transfer
    seed = catalog.stacks.get(DEFAULT_PRIOR_STACK)
    if seed is None or seed.bouc_wen is None:
        raise InputError(str(catalog.folder), "--prior-stack",
                         f"the default prior needs {DEFAULT_PRIOR_STACK} with [stack.bouc_wen] in the catalog")
    b = seed.bouc_wen
    table1 = BoucWen(b.d33, b.alpha, b.beta, b.gamma, b.delta, b.n)
    if prior_stack:
        target = (stack.stroke, stack.max_voltage)
        text = (f"catalog stack {stack_id} (stroke {stack.stroke:.4g} m at {stack.max_voltage:g} V) with the seed's "
                f"Table 1 loop ({DEFAULT_PRIOR_STACK}) in normalised form")
    else:
        target = (max(float(np.ptp(r.position)) for r in train), max(float(np.ptp(r.voltage)) for r in train))
        text = (f"seed Table 1 ({DEFAULT_PRIOR_STACK}) normalised groups rescaled to the record "
                f"(displacement range {target[0]:.4g} m over a voltage range {target[1]:.4g} V); "
                "no --prior-stack given")
    return transfer(table1, seed.stroke, seed.max_voltage, *target).as_array(), text


def _check_entry_id(entry_id: str, catalog) -> None:
    """Before any fit: a well-formed id the catalog does not have yet
    (``sizing catalog add`` would refuse a duplicate)."""
    from ..io.catalog import ID_PATTERN

    if not ID_PATTERN.match(entry_id):
        raise InputError("command line", "--catalog-entry",
                         f"expected lower case letters, digits, '.' and '-', got {entry_id!r}")
    if entry_id in load_catalog(catalog).stacks:
        raise InputError("command line", "--catalog-entry", f"id {entry_id!r} is already in the catalog; choose a new one")


def _catalog_entry(entry_id, base_raw, base_named, bw, paths, prior_text, out) -> dict:
    """{path: text} of the catalog entry (TOML block and CSV sheet),
    validated as a catalog would be."""
    from ..io.atomic import scratch_folder
    from ..io.catalog_import import entry_toml
    from ..io.validate import validate_catalog
    from .fit_entry import stack_entry, stack_sheet

    raw = stack_entry(base_raw, entry_id, bw.regularised_.params.as_array(), [Path(p).name for p in paths],
                      base_named, f"regularised toward {prior_text}")
    text = entry_toml("stack", raw)
    with scratch_folder({"stacks.toml": text}, prefix="sizing-entry-") as tmp:
        try:
            validate_catalog(tmp)
        except InputError as exc:
            raise InputError("command line", "--catalog-entry",
                             f"the entry would not validate: {exc.field}: {exc.message}") from None
    folder = out.parent if out is not None else Path(".")
    return {folder / f"{entry_id}.toml": text, folder / f"{entry_id}.csv": stack_sheet(raw)}


# --- sizing fit dc-motor -----------------------------------------------------

def fit_dc_motor(paths, rig, holdout=None, out=None, report=None, fit_gains: bool = False,
                 n_starts: int = 3, seed: int = 0, progress=None) -> FitResult:
    """Fit c1, c2 (seed eq. 13-14; with ``fit_gains`` the rig's nonzero PID
    gains too) of a DC rig (``io.rig.DC_KIND``) to reference/position run CSVs."""
    inputs = (*paths, rig)
    out, report = _checked_targets(out, report, inputs)
    rig_file, rig = rig, _dc_rig(rig)
    train, hold = _dc_records(paths, holdout, rig, rig_file)
    from ..fit import DCMotorEstimator
    from ..sim.rigs import dc_model
    from . import fit_tables as tables
    with warnings.catch_warnings(record=True) as log:
        warnings.simplefilter("always")
        est = DCMotorEstimator(dc_model(rig), fit_gains=fit_gains, n_starts=n_starts, random_state=seed,
                               progress=progress).fit(train)
    traces, per_role = _dc_predictions(est, train, hold)
    fit_table = tables.dc_fit_table(est, (train, hold), per_role)
    toml = render_toml(tables.dc_tables(est, fit_table), tables.DC_COMMENTS)
    result = {"model": "dc-motor", "traces": traces, "fit": fit_table, "params": est.params_,
              "ci95": est.ci95_, "warnings": est.warnings_, "sources": [str(p) for p in paths],
              "summary": {"dc-motor": {k: fit_table[k] for k in ("nrmse_train", "nrmse_holdout", "nrmse_runs")}}}
    return _finish(FitResult("dc-motor", toml, result, _unique(log), out, report, {}, inputs))


def _dc_rig(rig_path):
    from ..io.rig import DCRig, load_rig
    rig = load_rig(rig_path)
    if not isinstance(rig, DCRig):
        raise InputError(str(rig_path), "kind", f'expected "{DC_KIND}" for sizing fit dc-motor')
    return rig


def _dc_records(paths, holdout, rig, rig_path):
    """(training, holdout) DCRecords of the run CSVs, within the step limit."""
    from ..limits import check_steps, dc_steps

    runs = read_runs(paths, kind=DC_KIND)
    check_steps(dc_steps(sum(float(r.time[-1] - r.time[0]) for r in runs), rig.controller.rate),
                str(rig_path), "[controller].rate", "controller steps per simulation of the runs")
    train, hold = split_holdout(runs, holdout, ", ".join(str(p) for p in paths))
    from ..fit import DCRecord

    def record(run):
        return DCRecord(run.name, run.time, run["reference_m"], run["position_m"], source=str(run.path))

    return [record(r) for r in train], [record(r) for r in hold]


def _dc_predictions(est, train, hold):
    """(traces, {role: {run: NRMSE}}) of the fitted model on every run."""
    from ..sim.signals import nrmse
    traces, per_role = [], {"train": {}, "holdout": {}}
    for role, recs in (("train", train), ("holdout", hold)):
        for rec in recs:
            x = est.predict(rec)
            per_role[role][rec.name] = nrmse(rec.position, x)
            traces.append({"name": rec.name, "role": role, "time": rec.time, "reference": rec.reference,
                           "measured": rec.position, "fitted": {"dc-motor": x}})
    return traces, per_role
