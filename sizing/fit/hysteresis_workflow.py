"""``sizing fit hysteresis`` end to end: read runs, split off the holdout,
fit Bouc-Wen (plain and regularised toward the catalog prior) and
Prandtl-Ishlinskii, choose the model on the holdout, render the TOML, the
HTML report and optionally a catalog entry, write them atomically.

Defaults for real records: a sensor offset and an initial state
per run are fitted, the input filter's cut-off follows each record's sample
rate and excitation, and ``model="auto"`` carries the model with the lower
mean holdout NRMSE.
"""
from __future__ import annotations

import tempfile
import warnings
from pathlib import Path

import numpy as np

from ..errors import InputError
from ..io.catalog import load_catalog
from ..io.atomic import check_files
from ..io.catalog_import import entry_toml
from ..io.runs import read_runs, split_holdout
from ..io.schema import load_toml
from ..sim.signals import nrmse
from .bouc_wen import PARAM_NAMES, BoucWenEstimator
from .catalog_entry import stack_entry, stack_sheet
from .common import Z95, HysteresisRecord, check_hysteresis_records
from .output import render_toml
from .prandtl_ishlinskii import PrandtlIshlinskiiEstimator
from .prior import combinations, transfer_prior

MODELS = ("bouc-wen", "prandtl-ishlinskii")
MODEL_CHOICES = ("auto",) + MODELS
DEFAULT_PRIOR_STACK = "thorlabs-pk4ga7p1"     # the seed's Table 1 stack
FROM_PRIOR_SHARE = 0.5                        # posterior/prior variance above which a value "comes from the prior"


def _mean(values):
    values = list(values)
    return float(np.mean(values)) if values else None


def _prior(catalog_dir, prior_stack, train):
    """(physical prior (6,), source text, raw base entry, base named?)."""
    catalog = load_catalog(catalog_dir)
    stack_id = prior_stack or DEFAULT_PRIOR_STACK
    if stack_id not in catalog.stacks:
        field = "--prior-stack" if prior_stack else "--prior-stack (default)"
        raise InputError(str(catalog.folder), field, f"no stack {stack_id!r} in the catalog")
    stack = catalog.stacks[stack_id]
    seed = catalog.stacks.get(DEFAULT_PRIOR_STACK)
    if prior_stack and stack.bouc_wen is not None:
        bw = stack.bouc_wen
        prior = np.array([bw.d33, bw.alpha, bw.beta, bw.gamma, bw.delta, bw.n])
        text = f"catalog stack {stack_id}: its [stack.bouc_wen] values"
    else:
        if seed is None or seed.bouc_wen is None:
            raise InputError(str(catalog.folder), "--prior-stack",
                             f"the default prior needs {DEFAULT_PRIOR_STACK} with [stack.bouc_wen] in the catalog")
        from ..physics.bouc_wen import BoucWen
        table1 = BoucWen(seed.bouc_wen.d33, seed.bouc_wen.alpha, seed.bouc_wen.beta, seed.bouc_wen.gamma,
                         seed.bouc_wen.delta, seed.bouc_wen.n)
        if prior_stack:
            target = (stack.stroke, stack.max_voltage)
            text = (f"catalog stack {stack_id} (stroke {stack.stroke:.4g} m at {stack.max_voltage:g} V) with the seed's "
                    f"Table 1 loop ({DEFAULT_PRIOR_STACK}) in normalised form")
        else:
            target = (max(float(np.ptp(r.position)) for r in train), max(float(np.ptp(r.voltage)) for r in train))
            text = (f"seed Table 1 ({DEFAULT_PRIOR_STACK}) normalised groups rescaled to the record "
                    f"(displacement range {target[0]:.4g} m over a voltage range {target[1]:.4g} V); "
                    "no --prior-stack given")
        prior = transfer_prior(table1, seed.stroke, seed.max_voltage, *target)
    raw = next(e for e in load_toml(catalog.folder / "stacks.toml")["stack"] if e.get("id") == stack_id)
    return prior, text, raw, bool(prior_stack)


def _record(run):
    return HysteresisRecord(run.name, run.time, run["voltage_V"], run["position_m"], source=str(run.path))


def fit_hysteresis(paths, holdout=None, model: str = "auto", out=None, report=None,
                   cutoff_hz: float | None = None, fit_offset: bool = True, n_starts: int = 4,
                   seed: int = 0, n_operators: int = 16, prior_stack: str | None = None,
                   prior_sigma: float = 0.5, catalog_entry: str | None = None, catalog=None,
                   progress=None) -> dict:
    """Fit Bouc-Wen and Prandtl-Ishlinskii to runs (CSV paths). ``model``:
    "auto" (the better on the holdout), "bouc-wen" or "prandtl-ishlinskii".
    Returns {"toml", "warnings", "result", "written"}."""
    from .workflow import _targets, _write

    if model not in MODEL_CHOICES:
        raise InputError("command line", "--model", f"expected one of {', '.join(MODEL_CHOICES)}, got {model!r}")
    if not prior_sigma > 0:
        raise InputError("command line", "--prior-sigma", f"expected a positive relative sd, got {prior_sigma!r}")
    if catalog_entry is not None:
        _check_entry_id(catalog_entry, catalog)
    check_files(_targets(out, report), inputs=paths)     # before any work: never over an input
    runs = read_runs(paths, kind="piezohydraulic")
    train, hold = split_holdout(runs, holdout, ", ".join(str(p) for p in paths))
    train_rec, hold_rec = [_record(r) for r in train], [_record(r) for r in hold]
    check_hysteresis_records(train_rec + hold_rec)   # every run, held out or not, needs a reversal
    prior, prior_text, base_raw, base_named = _prior(catalog, prior_stack, train_rec)
    with warnings.catch_warnings(record=True) as log:
        warnings.simplefilter("always")
        tick = progress or (lambda fraction, message: None)
        bw = BoucWenEstimator(n_starts=n_starts, random_state=seed, cutoff_hz=cutoff_hz, fit_offset=fit_offset,
                              prior=prior, prior_sigma=prior_sigma,
                              progress=lambda f, m: tick(0.8 * f, f"Bouc-Wen: {m}")).fit(train_rec)
        tick(0.8, "Prandtl-Ishlinskii")
        pi = PrandtlIshlinskiiEstimator(n_operators=n_operators, cutoff_hz=cutoff_hz,
                                        fit_offset=fit_offset).fit(train_rec)
        fitted = {"bouc-wen": bw.regularised_.estimator, "prandtl-ishlinskii": pi, "bouc-wen-plain": bw}
        traces, per_model = [], {m: {"train": {}, "holdout": {}} for m in fitted}
        states = {"h0_m": {}, "offset_m": {}}
        tick(0.9, "predictions and holdout states")
        for role, recs in (("train", train_rec), ("holdout", hold_rec)):
            for rec in recs:
                xs = {}
                for m, est in fitted.items():
                    if m == "prandtl-ishlinskii":
                        xs[m] = est.predict(rec)
                        continue
                    h0, off = (est.h0_[rec.name], est.offset_[rec.name]) if role == "train" else est.initial_state(rec)
                    xs[m] = est.predict(rec, h0=h0, offset=off)
                    if m == "bouc-wen":
                        states["h0_m"][rec.name], states["offset_m"][rec.name] = h0, off
                for m, x in xs.items():
                    per_model[m][role][rec.name] = nrmse(rec.position, x)
                traces.append({"name": rec.name, "role": role, "time": rec.time, "voltage": rec.voltage,
                               "voltage_filtered": rec.voltage_filtered, "measured": rec.position,
                               "fitted": {m: xs[m] for m in MODELS}})
    caught = [str(w.message) for w in log]
    summary = {m: {"nrmse_train": _mean(per_model[m]["train"].values()),
                   "nrmse_holdout": _mean(per_model[m]["holdout"].values()),
                   "nrmse_runs": {**per_model[m]["train"], **per_model[m]["holdout"]}} for m in fitted}
    choice = _choose(summary)
    carried = choice["winner"] if model == "auto" else model
    fit_table = _fit_table(carried, model, choice, summary, bw, pi, train_rec, hold_rec, states,
                           prior_text, prior_sigma, fit_offset)
    tables = _stack_tables(bw)
    if carried == "prandtl-ishlinskii":
        tables = {"prandtl_ishlinskii": {"thresholds_V": [float(x) for x in pi.thresholds_],
                                         "weights_m_V": [float(x) for x in pi.weights_]}, **tables}
    tables["fit"] = fit_table
    comments = {"stack": ("sizing fit hysteresis: seed eq. 1-2, SI (paste into rig.toml); values the data leave "
                          "free come from the prior, see [fit.prior]"),
                "prandtl_ishlinskii": "the model this fit carries (see [fit.model_choice]); [stack] below is the Bouc-Wen form a rig.toml takes",
                "fit": "not part of a rig: fit figures (NRMSE per docs/formats.md)"}
    toml = render_toml(tables, comments)
    files: dict[Path, str] = {}
    if catalog_entry is not None:
        files.update(_catalog_entry(catalog_entry, base_raw, base_named, bw, paths, prior_text, out, catalog))
    result = {"model": carried, "summary": {m: summary[m] for m in MODELS}, "traces": traces, "fit": fit_table,
              "bouc_wen": {"params": dict(zip(PARAM_NAMES, bw.regularised_.params.as_array().tolist())),
                           "ci95": fit_table["ci95"], "plain": dict(zip(PARAM_NAMES, bw.params_.as_array().tolist())),
                           "plain_ci95": bw.ci95_, "corr": bw.corr_, "warnings": bw.warnings_,
                           "combinations": fit_table["combinations"], "prior": fit_table["prior"],
                           "message": bw.message_},
              "prandtl_ishlinskii": {"thresholds_V": pi.thresholds_, "weights_m_V": pi.weights_},
              "model_choice": choice, "filter": fit_table["input_filter"], "sources": [str(p) for p in paths]}
    written = _write(out, report, toml, result, kind="hysteresis", inputs=paths, extra=files)
    return {"toml": toml, "warnings": list(dict.fromkeys(caught)), "result": result, "written": written}


def _choose(summary: dict) -> dict:
    """Which model wins: lower mean holdout NRMSE (training NRMSE when
    nothing is held out), and by how much."""
    key = "nrmse_holdout" if summary["bouc-wen"]["nrmse_holdout"] is not None else "nrmse_train"
    scores = {m: summary[m][key] for m in MODELS}
    winner = min(MODELS, key=lambda m: scores[m])
    loser = MODELS[1 - MODELS.index(winner)]
    return {"winner": winner, "criterion": f"mean {key.removeprefix('nrmse_')} NRMSE" +
            ("" if key == "nrmse_holdout" else " (nothing held out)"),
            "bouc_wen": scores["bouc-wen"], "prandtl_ishlinskii": scores["prandtl-ishlinskii"],
            "margin": scores[loser] - scores[winner],
            "margin_relative": (scores[loser] - scores[winner]) / scores[loser] if scores[loser] else 0.0}


def _stack_tables(bw) -> dict:
    th = bw.regularised_.params.as_array()
    return {"stack": {"d33": th[0]}, "stack.bouc_wen": dict(zip(PARAM_NAMES[1:], th[1:]))}


def _fit_table(carried, requested, choice, summary, bw, pi, train_rec, hold_rec, states, prior_text,
               prior_sigma, fit_offset) -> dict:
    reg = bw.regularised_
    cutoffs = sorted(set(round(c, 3) for c in bw.cutoff_hz_.values()))
    filter_note = ("voltage low-passed before it drives the models: 4th-order Butterworth, zero phase "
                   f"(forwards and backwards), cut-off {', '.join(f'{c:g}' for c in cutoffs)} Hz, chosen per run "
                   "from its sample rate and excitation (20 x the dominant frequency, 3 x the band holding 99 % of "
                   "the excitation's energy, at least 5 Hz, at most a quarter of the Nyquist frequency), so sensor "
                   "noise cannot ratchet the hysteresis state" if any(cutoffs)
                   else "voltage used unfiltered (--cutoff-hz 0)")
    half = Z95 * np.sqrt(np.clip(np.diag(reg.cov), 0, None))
    th = reg.params.as_array()
    other = MODELS[1 - MODELS.index(carried)]
    table = {
        "model": carried,
        "model_requested": requested,
        "nrmse_train": summary[carried]["nrmse_train"],
        "nrmse_holdout": summary[carried]["nrmse_holdout"],
        "train_runs": [r.name for r in train_rec],
        "holdout_runs": [r.name for r in hold_rec],
        "sensor_offset": ("fitted per run (default; --no-offset holds it at 0)" if fit_offset
                          else "held at 0 (--no-offset)"),
        "initial_state_note": ("fitted per run: Bouc-Wen h0, Prandtl-Ishlinskii the last turning point u of the "
                          "input before the record; holdout runs get theirs with the model held"),
        "input_filter": filter_note,
        "cutoff_Hz": cutoffs[0] if len(cutoffs) == 1 else cutoffs,
        "warnings": list(bw.warnings_),
        "nrmse_runs": summary[carried]["nrmse_runs"],
        "model_choice": choice,
        "ci95": {n: [float(th[i] - half[i]), float(th[i] + half[i])] for i, n in enumerate(PARAM_NAMES)},
        "residual_lag1_correlation": bw.residual_correlation_,
        "interval_inflation": bw.interval_inflation_,
        "combinations": combinations(bw.params_.as_array(), bw.cov_),
        "prior": {"source": prior_text, "sigma_relative": prior_sigma,
                  "weight": (f"Gaussian prior on each dimensionless group, 1-sigma {prior_sigma:g} x its prior value "
                             "(at least 0.1), against the data's white-noise chi^2 at the plain fit's residual "
                             "level; intervals and prior shares count the data with the interval inflation"),
                  "values": dict(zip(PARAM_NAMES, reg.prior.tolist())),
                  "prior_share": dict(zip(PARAM_NAMES, reg.prior_share.tolist())),
                  "from_prior": [n for n, s in zip(PARAM_NAMES, reg.prior_share) if s > FROM_PRIOR_SHARE]},
        "unregularised": {"nrmse_train": summary["bouc-wen-plain"]["nrmse_train"],
                          "nrmse_holdout": summary["bouc-wen-plain"]["nrmse_holdout"],
                          "values": dict(zip(PARAM_NAMES, bw.params_.as_array().tolist())),
                          "ci95": {n: list(bw.ci95_[n]) for n in PARAM_NAMES}},
        "initial_state": {"h0_m": states["h0_m"], "offset_m": states["offset_m"],
                           "prandtl_ishlinskii_u_V": {k: "steady-state guess" if u is None else float(u)
                                                      for k, u in pi.memory_.items()},
                           "prandtl_ishlinskii_offset_m": dict(pi.offset_)},
    }
    table[other.replace("-", "_")] = {"nrmse_train": summary[other]["nrmse_train"],
                                      "nrmse_holdout": summary[other]["nrmse_holdout"],
                                      "nrmse_runs": summary[other]["nrmse_runs"]}
    return table


def _check_entry_id(entry_id: str, catalog) -> None:
    """Before any fit: a well-formed id the catalog does not have yet
    (``sizing catalog add`` would refuse a duplicate)."""
    from ..io.catalog import ID_PATTERN

    if not ID_PATTERN.match(entry_id):
        raise InputError("command line", "--catalog-entry",
                         f"expected lower case letters, digits, '.' and '-', got {entry_id!r}")
    if entry_id in load_catalog(catalog).stacks:
        raise InputError("command line", "--catalog-entry", f"id {entry_id!r} is already in the catalog; choose a new one")


def _catalog_entry(entry_id, base_raw, base_named, bw, paths, prior_text, out, catalog) -> dict:
    """{path: text} of the catalog entry (TOML block and CSV sheet),
    validated as a catalog would be."""
    from ..io.validate import validate_catalog

    raw = stack_entry(base_raw, entry_id, bw.regularised_.params.as_array(), [Path(p).name for p in paths],
                      base_named, f"regularised toward {prior_text}")
    text = entry_toml("stack", raw)
    with tempfile.TemporaryDirectory(prefix="sizing-entry-") as tmp:
        (Path(tmp) / "stacks.toml").write_text(text, encoding="utf-8")
        try:
            validate_catalog(tmp)
        except InputError as exc:
            raise InputError("command line", "--catalog-entry",
                             f"the entry would not validate: {exc.field}: {exc.message}") from None
    folder = Path(out).parent if out is not None else Path(".")
    return {folder / f"{entry_id}.toml": text, folder / f"{entry_id}.csv": stack_sheet(raw)}
