"""Command line: parse, call ``sizing.api``, print. InputError -> exit 2 with
one line on stderr; any other exception is a bug -> traceback, exit 1.
SIGINT exits 130 and SIGTERM 143, with one line (outputs are written by
``io.atomic``, so they are either complete or untouched). Every numeric
option is checked here (``number_option``): finite, in range, an integer
where it counts something.

The annotations are evaluated when the module loads (no ``from __future__
import annotations``): typer reads every command's signature each time it
builds the command line, and strings it would evaluate twice a parameter
(``inspect.signature(eval_str=True)``, then ``get_type_hints``): 0.04-0.09 s
a build, 0.003-0.008 s without them."""

import signal
import sys
import threading

from .errors import HOLDING_SIGNALS, RECEIVED_SIGNALS


def _record_interrupt(signum, frame):
    """Until ``main`` takes over: note the signal, then interrupt as Python
    would (the imports below take seconds; a library that turns the
    interrupt into an ImportError still leaves the note)."""
    RECEIVED_SIGNALS.append(signum)
    raise KeyboardInterrupt


def _one_line_on_interrupt(kind, value, tb, _default=sys.excepthook):
    """An interrupt that arrives outside ``main`` (while the command line
    loads, or as it exits): one line and exit 128 + signal, not a traceback."""
    if RECEIVED_SIGNALS or issubclass(kind, KeyboardInterrupt):
        import os
        signum = RECEIVED_SIGNALS[0] if RECEIVED_SIGNALS else signal.SIGINT
        sys.stderr.write(f"error: interrupted by {signal.Signals(signum).name}; {INTERRUPTED_OUTPUTS}\n")
        sys.stderr.flush()
        os._exit(128 + signum)
    _default(kind, value, tb)


INTERRUPTED_OUTPUTS = "outputs are complete or untouched"
if signal.getsignal(signal.SIGINT) is signal.default_int_handler and \
        threading.current_thread() is threading.main_thread():      # not when a host program set its own
    signal.signal(signal.SIGINT, _record_interrupt)
    signal.signal(signal.SIGTERM, _record_interrupt)
    if sys.excepthook is sys.__excepthook__:
        sys.excepthook = _one_line_on_interrupt

from .threads import single_threaded_blas  # noqa: E402

single_threaded_blas()   # before numpy loads (sizing/threads.py)

import json  # noqa: E402
import math  # noqa: E402
from pathlib import Path  # noqa: E402
from typing import List, Optional  # noqa: E402

import typer  # noqa: E402

from . import __version__  # noqa: E402
from .errors import FitError, InputError, Interrupted, raise_if_interrupted  # noqa: E402
from .limits import use_limits  # noqa: E402


class _DeferredApi:
    """``sizing.api``, imported when a command first calls it: ``--help``,
    ``--version`` and a mistyped option answer before numpy, scipy, numba,
    cvxpy and plotly load (about 1.5 s of imports)."""

    def __getattr__(self, name):
        from . import api as loaded
        return getattr(loaded, name)


api = _DeferredApi()

app = typer.Typer(help="Size smart-material actuators for glide-body control surfaces, "
                       "fit their models to test data and diagnose the sim-to-real gap.",
                  no_args_is_help=True, add_completion=False, pretty_exceptions_enable=False)
catalog_app = typer.Typer(help="List, show, validate and compare the parts catalog.", no_args_is_help=True)
fit_app = typer.Typer(help="Estimate model parameters from measured runs.", no_args_is_help=True)
app.add_typer(catalog_app, name="catalog")
app.add_typer(fit_app, name="fit")

CatalogOpt = typer.Option(None, "--catalog", help="Catalog folder (default: the catalogs/ that ships with sizing).")


def _in_range(name: str, low: float | None, high: float | None, integer: bool):
    """A typer callback: the option's value must be finite and within
    [low, high] (None: unbounded); exit 2 with one line otherwise."""
    def check(value):
        if value is None:
            return value
        bounds = (f" between {low:g} and {high:g}" if low is not None and high is not None
                  else f" >= {low:g}" if low is not None else f" <= {high:g}" if high is not None else "")
        word = "an integer" if integer else "a finite number"
        if isinstance(value, float) and not math.isfinite(value) or \
                (low is not None and value < low) or (high is not None and value > high):
            raise typer.BadParameter(f"expected {word}{bounds}, got {value!r}", param_hint=name)
        return value
    return check


def number_option(default, name: str, help: str, low: float | None = None, high: float | None = None):
    """A numeric option checked by ``_in_range`` (int default: a count or a
    seed, float default: a finite value). For other commands to reuse."""
    integer = isinstance(default, int) and not isinstance(default, bool)
    return typer.Option(default, name, help=help, callback=_in_range(name, low, high, integer))


SEED_MAX = 2**32 - 1
MaxSamplesOpt = number_option(None, "--max-samples", "Raise the limit on measured samples read from run CSVs "
                              "(default 1,000,000, about 3 GB while fitting).", low=1)
MaxStepsOpt = number_option(None, "--max-steps", "Raise the limit on simulation steps of one pass "
                            "(default 1e8, about a minute).", low=1)


def _version(value: bool):
    if value:
        typer.echo(f"sizing {__version__}")
        raise typer.Exit()


@app.callback()
def main_options(version: bool = typer.Option(False, "--version", callback=_version, is_eager=True,
                                              help="Print the version and exit.")):
    """sizing: smart-material and motor actuators, from requirements to hardware."""


def _print_json(data) -> None:
    typer.echo(json.dumps(data, indent=2, default=_jsonable))


def _jsonable(value):
    import numpy as np
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, (np.floating, np.integer)):
        return value.item()
    return str(value)


@app.command()
def evaluate(design: Path = typer.Argument(..., help="design.toml (docs/formats.md)."),
             json_out: bool = typer.Option(False, "--json", help="Print one JSON object instead of a summary."),
             catalog: Optional[Path] = CatalogOpt,
             requirements: Optional[Path] = typer.Option(
                 None, "--requirements", help="requirements.toml: judge the design with the checks of sizing solve "
                                              "(margins and feasibility)."),
             max_steps: Optional[float] = MaxStepsOpt):
    """Static and simulated figures of one design; with --requirements, its margins and verdict."""
    with use_limits(steps=max_steps):
        result = api.evaluate(design, catalog, requirements)
    for warning in result.warnings:
        typer.echo(f"warning: {design}: {warning}", err=True)
    if json_out:
        _print_json(result.figures)
        return
    typer.echo(result.summary())


@app.command()
def solve(requirements: Path = typer.Argument(..., help="requirements.toml (docs/formats.md)."),
          out: Path = typer.Option(Path("sizing-out"), "--out", help="Folder for results.json, candidates.csv and report.html."),
          catalog: Optional[Path] = CatalogOpt,
          baseline: Optional[Path] = typer.Option(None, "--baseline", help="An earlier results.json: report what changed."),
          quiet: bool = typer.Option(False, "--quiet", help="No progress bar and no summary."),
          robust: Optional[Path] = typer.Option(None, "--robust",
                                                help="A robust.json of these requirements: the report gives each "
                                                     "studied design's probability of compliance."),
          detail: str = typer.Option("summary", "--detail",
                                     help="summary: combinations ruled out before sizing counted by reason; "
                                          "full: a record of each in results.json."),
          max_steps: Optional[float] = MaxStepsOpt,
          fast: bool = typer.Option(False, "--fast", help="Skip what would flip each verdict and the probability of "
                                                          "compliance (flips and compliance null in results.json; the "
                                                          "nominal recommendation): quicker iterations on the requirements.")):
    """Size, verify by simulation and rank every design for the requirements."""
    with use_limits(steps=max_steps):
        results = _solve(requirements, out, catalog, baseline, quiet, detail, robust, fast)
    if not quiet:
        if results.get("changes_summary"):
            typer.echo(f"what changed: {results['changes_summary']['text']}")
        for group in results["summary"]["groups"]:
            typer.echo(f"{group['label']}: {group['text']}")
        typer.echo(results["summary"]["thermal"])
        if results["summary"].get("comparison", {}).get("text"):
            typer.echo(results["summary"]["comparison"]["text"])
        if results["summary"].get("comparison", {}).get("recommendation"):
            typer.echo(results["summary"]["comparison"]["recommendation"])
        knife = results.knife_edges()
        if knife:
            typer.echo(knife)
        for line in results.flip_lines():
            typer.echo(line)
        typer.echo(f"{out}/report.html, results.json, candidates.csv written "
                   f"({results['runtime_s']:.1f} s"
                   + (f", and {results['compliance_s']:.1f} s for the probability of compliance"
                      if results.get("compliance_s") is not None else "") + ")")


def _solve(requirements, out, catalog, baseline, quiet, detail="summary", robust=None, fast=False):
    with _StageBars(quiet) as bars:          # the same bars as robust and sweep (below)
        return api.solve(requirements, out, catalog, baseline,
                         progress=lambda stage, done, total: bars(f"{stage} candidates", done, total), detail=detail,
                         robust=robust, fast=fast)


@catalog_app.command("list")
def catalog_list(catalog: Optional[Path] = CatalogOpt):
    """List every catalog entry: id, kind, name and source."""
    typer.echo(api.catalog_table(catalog))


@catalog_app.command("show")
def catalog_show(entry_id: str = typer.Argument(..., help="Catalog id, e.g. pi-p-056.90."),
                 json_out: bool = typer.Option(False, "--json", help="Print JSON."),
                 catalog: Optional[Path] = CatalogOpt):
    """Show every field of one entry with its unit and provenance."""
    found = api.catalog_entry(entry_id, catalog)
    if json_out:
        _print_json(found.to_dict())
        return
    typer.echo(found.details())


@catalog_app.command("validate")
def catalog_validate(folder: Optional[Path] = typer.Argument(None, help="Catalog folder to check (default: the shipped one)."),
                     max_age_days: int = number_option(730, "--max-age-days", "Flag entries retrieved longer ago than this.", low=0, high=100_000),
                     catalog: Optional[Path] = CatalogOpt):
    """Check schema, units, ids and physical plausibility; exit 2 on errors."""
    report = api.catalog_validate(folder or catalog, max_age_days=max_age_days)
    for line in report.warnings:
        typer.echo(f"warning: {line}", err=True)
    typer.echo(f"{report.folder}: {report.n_entries} entries valid ({report.n_warnings} warnings)")


@catalog_app.command("diff")
def catalog_diff(old: str = typer.Argument(..., help="Old catalog: a folder, or a git revision (HEAD~3, a tag; REV:DIR for another folder)."),
                 new: Optional[str] = typer.Argument(None, help="New catalog: a folder or a git revision, as OLD (default: --catalog, else the shipped catalog)."),
                 json_out: bool = typer.Option(False, "--json", help="Print JSON (added, removed, changed with each field's old and new value and unit)."),
                 catalog: Optional[Path] = CatalogOpt):
    """Added, removed and changed entries between two catalogs, field by field."""
    diff = api.catalog_diff(old, new if new is not None else catalog)
    if json_out:
        _print_json(diff.to_dict())
        return
    typer.echo(diff.text())


@catalog_app.command("add")
def catalog_add(kind: str = typer.Argument(..., help="Part kind: stack, fluid, seal, amplifier, dc_actuator, motor, screw, gear or drive."),
                sheet: Path = typer.Argument(..., help="CSV of new parts, one per row; header = field names, units in the header or the cells."),
                catalog: Optional[Path] = CatalogOpt):
    """Validate a vendor sheet (CSV) and append its parts to the kind's catalog file."""
    added = api.catalog_add(kind, sheet, catalog).added
    ids = added["ids"]
    typer.echo(f"{added['file']}: added {len(ids)} {added['kind']} entr{'y' if len(ids) == 1 else 'ies'}: {', '.join(ids)}")


@catalog_app.command("import-mgdb")
def catalog_import_mgdb(tables: Path = typer.Argument(..., help="Folder of the makers' motor and gearhead tables (MGDB CSVs: maxon_*, faulhaber_*, allied_motion_motors.csv)."),
                        screws: Optional[Path] = typer.Option(None, "--screws", help="CSV of makers' ball screws with load ratings (screws-sourced.csv)."),
                        catalog: Optional[Path] = CatalogOpt):
    """Import brushless motors, their mountable gearheads and ball screws from makers' tables, each value with its provenance."""
    done = api.catalog_import_mgdb(tables, screws, catalog).added
    skipped = ", ".join(f"{n} {what}" for what, n in done["skipped"].items() if n)
    typer.echo(f"imported {done['motors']} motors, {done['gears']} gearheads, {done['screws']} screws into "
               f"{', '.join(done['files'])}" + (f" (skipped: {skipped})" if skipped else ""))


@app.command()
def diagnose(campaign: Path = typer.Argument(..., help="Campaign folder: rig.toml and runs/NAME.csv (docs/formats.md)."),
             holdout: Optional[List[str]] = typer.Option(None, "--holdout", help="Run (CSV name without .csv) never used for fitting; repeatable. Required unless --check."),
             out: Path = typer.Option(Path("diagnose-out"), "--out", help="Folder for diagnosis.json and diagnosis.html."),
             recalibrate: Optional[List[str]] = typer.Option(None, "--recalibrate", help="Re-fit this nominal parameter on the training runs first, and jointly with every effect (piezo: d33, wide_friction, narrow_friction; DC: c1, c2); repeatable. Default: d33 (piezo), c1 and c2 (DC)."),
             no_recalibrate: bool = typer.Option(False, "--no-recalibrate", help="Judge the effects against the stated nominal, without re-calibration."),
             check: bool = typer.Option(False, "--check", help="Inject each library effect into the campaign's own excitations, diagnose each without using the injected truth and print the confusion matrix."),
             seed: int = number_option(0, "--seed", "Seed of the screening and of --check's noise.", low=0, high=SEED_MAX),
             workers: Optional[int] = number_option(None, "--workers", "--check: cases diagnosed at once, each in a process of its own (the verdicts do not depend on it). Default: the machine's cores, at most 4.", low=1),
             max_samples: Optional[int] = MaxSamplesOpt,
             max_steps: Optional[float] = MaxStepsOpt):
    """Say where the model and the hardware disagree, which unmodelled effect explains it, and how far the gap shrinks."""
    with use_limits(samples=max_samples, steps=max_steps):
        _diagnose(campaign, holdout, out, recalibrate, no_recalibrate, check, seed, workers)


def _diagnose(campaign, holdout, out, recalibrate, no_recalibrate, check, seed, workers=None) -> None:
    if check:
        def progress(case):
            typer.echo(f"  {case.truth:>22} size {case.size} -> {case.predicted} ({case.seconds:.1f} s)", err=True)
        result = api.diagnose_check(campaign, holdout, seed=seed, progress=progress, workers=_workers(workers))
        typer.echo(result.table())
        typer.echo(f"right effect first: {100 * result.accuracy:.0f} %, null cases naming an effect: "
                   f"{100 * result.null_false_positive:.0f} %, median holdout shrink when right: "
                   f"{100 * result.median_shrink:.0f} %")
        return
    if not holdout:
        raise InputError(str(campaign), "--holdout", "expected at least one --holdout RUN (the runs never used for fitting)")
    result = api.diagnose(campaign, holdout, out, recalibrate=[] if no_recalibrate else (recalibrate or None), seed=seed)
    v = result.verdict_dict
    typer.echo(f"baseline holdout NRMSE {result.baseline_holdout:.4f} (noise floor {result.noise_floor_holdout:.4f})")
    for f in result.fits[:5]:
        typer.echo(f"  {f.name + ' (' + f.form + ')':<48} holdout NRMSE {f.nrmse_holdout:.4f}  shrink {100 * (1 - f.nrmse_holdout / result.baseline_holdout):5.1f} %")
    if v["effect"]:
        typer.echo(f"verdict: {v['status']}: {v['effect']} ({v.get('form')} form; holdout shrink {100 * v['shrink_holdout']:.0f} %): {v['reason']}")
    else:
        typer.echo(f"verdict: {v['status']}: {v['reason']}")
    typer.echo(f"wrote {out / 'diagnosis.json'} and {out / 'diagnosis.html'}")


class _LazyProgress:
    """A rich progress bar on stderr that appears only once a fit has run
    for more than a second (the library reports fractions done)."""

    def __init__(self, label: str):
        import time
        self.label, self.start, self.bar, self.task = label, time.monotonic(), None, None

    def __call__(self, fraction: float, message: str = "") -> None:
        import time
        if self.bar is None:
            if time.monotonic() - self.start < 1.0:
                return
            from rich.console import Console
            from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn
            console = Console(stderr=True)
            self.bar = Progress(TextColumn("{task.description}"), BarColumn(), TimeElapsedColumn(),
                                console=console, transient=True, disable=not console.is_terminal)
            self.bar.start()
            self.task = self.bar.add_task(self.label, total=1.0)
        self.bar.update(self.task, completed=fraction, description=f"{self.label}: {message}")

    def close(self) -> None:
        if self.bar is not None:
            self.bar.stop()


def _fit_output(result, out: Optional[Path]) -> None:
    """The result first (on stderr when stdout carries the TOML), then the warnings."""
    typer.echo(result.summary(), err=out is None)
    for warning in result.warnings:
        typer.echo(f"warning: {warning}", err=True)
    if out is None:
        typer.echo(result.toml)
    for path in result.written:
        typer.echo(f"wrote {path}", err=True)


@fit_app.command("hysteresis")
def fit_hysteresis(data: List[Path] = typer.Argument(..., help="Run CSVs (time_s,voltage_V,position_m), one run each; position is the stack's displacement."),
                   holdout: Optional[List[str]] = typer.Option(None, "--holdout", help="Run (CSV name without .csv) kept out of the fit for validation; repeatable."),
                   out: Optional[Path] = typer.Option(None, "--out", help="TOML file to write (tables stack, stack.bouc_wen and fit); the HTML report goes beside it (OUT.html). Default: print the TOML."),
                   model: str = typer.Option("auto", "--model", help="Model the TOML carries: auto (the one with the lower holdout NRMSE), bouc-wen or prandtl-ishlinskii (both are always fitted and compared)."),
                   report: Optional[Path] = typer.Option(None, "--report", help="HTML report path (default: OUT with .html; none without --out)."),
                   cutoff_hz: Optional[float] = number_option(None, "--cutoff-hz", "Low-pass cut-off of the measured voltage, Hz (default: per run from its sample rate and excitation, at most a quarter of Nyquist; 0: no filter).", low=0, high=1e6),
                   offset: bool = typer.Option(True, "--offset/--no-offset", help="Fit a constant sensor offset per run (default) beside each run's initial hysteresis state."),
                   starts: int = number_option(4, "--starts", "Starting points refined by least squares (best of a seeded random screen).", low=1, high=1000),
                   operators: int = number_option(16, "--operators", "Play operators of the Prandtl-Ishlinskii model.", low=1, high=1000),
                   seed: int = number_option(0, "--seed", "Seed of the random starting points.", low=0, high=SEED_MAX),
                   prior_stack: Optional[str] = typer.Option(None, "--prior-stack", help="Catalog stack id whose datasheet (and Bouc-Wen values, if any) regularise the parameters the data leave free. Default: the seed's Table 1 loop rescaled to the record."),
                   prior_sigma: float = typer.Option(0.5, "--prior-sigma", help="Relative 1-sigma of the prior on each dimensionless Bouc-Wen group (positive; the library checks it)."),
                   catalog_entry: Optional[str] = typer.Option(None, "--catalog-entry", help="Also write ID.toml and ID.csv beside --out: a stack catalog entry (for a stacks.toml, or for sizing catalog add stack ID.csv) with the fitted Bouc-Wen values under status measured."),
                   catalog: Optional[Path] = CatalogOpt,
                   max_samples: Optional[int] = MaxSamplesOpt):
    """Fit the seed's Bouc-Wen model (d33, alpha, beta, gamma, delta, n) and a Prandtl-Ishlinskii model to voltage/displacement runs."""
    progress = _LazyProgress("fit hysteresis")
    try:
        with use_limits(samples=max_samples):
            result = api.fit_hysteresis(data, holdout, model=model, out=out, report=report, cutoff_hz=cutoff_hz,
                                        fit_offset=offset, n_starts=starts, n_operators=operators, seed=seed,
                                        prior_stack=prior_stack, prior_sigma=prior_sigma,
                                        catalog_entry=catalog_entry, catalog=catalog, progress=progress)
    finally:
        progress.close()
    _fit_output(result, out)


@fit_app.command("dc-motor")
def fit_dc_motor(data: List[Path] = typer.Argument(..., help="Run CSVs (time_s,reference_m,position_m), one run each."),
                 rig: Path = typer.Option(..., "--rig", help="rig.toml of a DC rig (its kind in docs/formats.md): screw, controller, current limit, load."),
                 holdout: Optional[List[str]] = typer.Option(None, "--holdout", help="Run (CSV name without .csv) kept out of the fit for validation; repeatable."),
                 out: Optional[Path] = typer.Option(None, "--out", help="TOML file to write (tables motor and fit); the HTML report goes beside it. Default: print the TOML."),
                 report: Optional[Path] = typer.Option(None, "--report", help="HTML report path (default: OUT with .html; none without --out)."),
                 gains: bool = typer.Option(False, "--gains", help="Also fit the rig's nonzero PID gains (kp, ki, kd)."),
                 starts: int = number_option(3, "--starts", "Starting points refined by least squares.", low=1, high=1000),
                 seed: int = number_option(0, "--seed", "Seed of the random starting points.", low=0, high=SEED_MAX),
                 max_samples: Optional[int] = MaxSamplesOpt,
                 max_steps: Optional[float] = MaxStepsOpt):
    """Identify c1, c2 of the seed's eq. 13-14 (optionally the PID gains) through the rig's closed loop."""
    progress = _LazyProgress("fit dc-motor")
    try:
        with use_limits(samples=max_samples, steps=max_steps):
            result = api.fit_dc_motor(data, rig, holdout, out=out, report=report, fit_gains=gains,
                                      n_starts=starts, seed=seed, progress=progress)
    finally:
        progress.close()
    _fit_output(result, out)


class _StageBars:
    """Rich progress bars on stderr, one per stage of ``progress(stage, done, total)``."""

    def __init__(self, quiet: bool = False):
        self.quiet, self.bar, self.tasks = quiet, None, {}

    def __enter__(self):
        return self

    def _start(self) -> None:
        """Start the bars at the first report of work, so input errors found
        before any work print their one line and nothing else."""
        from rich.console import Console
        from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn
        console = Console(stderr=True)      # bars only on a terminal: a log file gets no blank line
        self.bar = Progress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
                            TimeElapsedColumn(), console=console, transient=True, disable=not console.is_terminal)
        self.bar.start()

    def __call__(self, stage: str, done: int, total: int) -> None:
        if self.quiet:
            return
        if self.bar is None:
            self._start()
        if stage not in self.tasks:
            self.tasks[stage] = self.bar.add_task(stage, total=total)
        self.bar.update(self.tasks[stage], completed=done, total=total)

    def note(self, text: str) -> None:
        """A line above the bars (e.g. the Dask dashboard's address)."""
        if self.quiet:
            return
        if self.bar is None:
            self._start()
        self.bar.console.print(text)

    def __exit__(self, *exc):
        if self.bar is not None:
            self.bar.stop()


def _workers(workers: Optional[int]) -> int:
    """``--workers``, or by default the machine's cores, at most 4."""
    import os
    return max(1, min(4, os.cpu_count() or 1)) if workers is None else workers


def _run_study(fn, quiet: bool, workers: Optional[int], *args, **kwargs):
    """Run api.robust or api.sweep with progress bars and the --workers default
    (the number of cores, at most 4)."""
    if workers is not None and workers < 0:
        raise InputError(None, "--workers", f"expected 0 or more, got {workers}")
    n = _workers(workers)
    with _StageBars(quiet) as bars:
        return fn(*args, workers=n, progress=bars, **kwargs)


SchedulerOpt = typer.Option(None, "--scheduler", help="Address of a running Dask scheduler (tcp://HOST:8786). "
                                                      "Default: a local cluster of --workers processes.")
WorkersOpt = number_option(None, "--workers", "Worker processes of the local Dask cluster "
                                               "(default: the number of cores, at most 4; 0: run serially here).", low=0, high=256)


@app.command()
def robust(requirements: Path = typer.Argument(..., help="requirements.toml (docs/formats.md), with an optional tolerances table."),
           samples: int = number_option(1000, "--samples", "Monte Carlo samples per design (>= 1).", low=1, high=10**7),
           seed: int = number_option(0, "--seed", "Random seed; the same seed gives the same numbers wherever the work runs.", low=0, high=SEED_MAX),
           designs: int = number_option(10, "--designs", "How many of the best designs of sizing solve to study.", low=1, high=10**4),
           out: Path = typer.Option(Path("robust-out"), "--out", help="Folder for robust.json and robust.html."),
           scheduler: Optional[str] = SchedulerOpt, workers: Optional[int] = WorkersOpt,
           catalog: Optional[Path] = CatalogOpt,
           bouc_wen_fit: Optional[Path] = typer.Option(None, "--bouc-wen-fit", help="Output of sizing fit hysteresis: "
                                                       "its standard errors become tolerances of the stacks' Bouc-Wen parameters."),
           technology: Optional[str] = typer.Option(None, "--technology", help="Study only the best designs of this "
                                                    "technology (a folder name of sizing/technologies; default: every one whose parts have a tolerance model)."),
           quiet: bool = typer.Option(False, "--quiet", help="No progress bar and no summary.")):
    """Probability of compliance of the best designs under part tolerances (Monte Carlo, full simulations)."""
    data = _run_study(api.robust, quiet, workers, requirements, out, catalog, samples=samples, seed=seed,
                      designs=designs, scheduler=scheduler, bouc_wen_fit=bouc_wen_fit, technology=technology)
    if not quiet:
        for d in data["designs"]:
            lo, hi = d["p_ci95"]
            typer.echo(f"{d.get('name') or d['id']}: P(compliance) {d['p_compliance']:.3f} (95 % interval {lo:.3f} to {hi:.3f}), "
                       f"driven by {d['driving_tolerance'] or '-'}")
        typer.echo(f"{out}/robust.json, robust.html written ({data['where']})")


@app.command()
def sweep(requirements: Path = typer.Argument(..., help="requirements.toml (docs/formats.md)."),
          vary: List[str] = typer.Option(..., "--vary", help="FIELD=FROM..TO:N, units as in the file, e.g. "
                                                              "stroke=35mm..50mm:4 or max_temperature=80degC..120degC:3. Repeat for a grid."),
          out: Path = typer.Option(Path("sweep-out"), "--out", help="Folder for sweep.json and sweep.html."),
          scheduler: Optional[str] = SchedulerOpt, workers: Optional[int] = WorkersOpt,
          catalog: Optional[Path] = CatalogOpt,
          quiet: bool = typer.Option(False, "--quiet", help="No progress bar and no summary.")):
    """A full solve at every point of a grid over requirement fields."""
    data = _run_study(api.sweep, quiet, workers, requirements, vary, out, catalog, scheduler=scheduler)
    if not quiet:
        for line in data.point_lines():
            typer.echo(line)
        typer.echo(f"{out}/sweep.json, sweep.html written ({data['where']})")


def _interrupt(signum, frame):
    RECEIVED_SIGNALS.append(signum)
    if HOLDING_SIGNALS:             # outputs being swapped in: the writer raises once they are whole
        return
    raise Interrupted(signum)


def _handle_signals() -> dict:
    """SIGINT and SIGTERM raise Interrupted (main thread only); returns the
    previous handlers."""
    if threading.current_thread() is not threading.main_thread():
        return {}
    return {sig: signal.signal(sig, _interrupt) for sig in (signal.SIGINT, signal.SIGTERM)}


def _one_line(text: str) -> str:
    return " ".join(str(text).split())


def main(argv: Optional[List[str]] = None) -> None:
    """Console entry point: maps errors to exit codes (docs/formats.md): 0 done,
    2 bad input (one line), 130 SIGINT, 143 SIGTERM, 1 a bug (traceback)."""
    from typer._click.exceptions import ClickException   # typer bundles its own click

    previous = _handle_signals()
    try:
        raise_if_interrupted()        # one that arrived while the command line loaded
        code = app(args=argv, standalone_mode=False, prog_name="sizing")
        raise_if_interrupted()        # a signal some library swallowed still ends the run as interrupted
    except Interrupted as exc:
        typer.echo(f"error: interrupted by {signal.Signals(exc.signum).name}; {INTERRUPTED_OUTPUTS}", err=True)
        sys.exit(128 + exc.signum)
    except (InputError, FitError) as exc:
        typer.echo(f"error: {_one_line(exc)}", err=True)
        sys.exit(2)
    except typer.Exit as exc:
        sys.exit(exc.exit_code)
    except typer.Abort:
        # click turns a KeyboardInterrupt it sees into Abort
        typer.echo("error: interrupted by SIGINT", err=True)
        sys.exit(130)
    except ClickException as exc:
        # usage errors of typer's bundled click (bad option, missing argument,
        # an option value out of range): one line, exit 2
        where = f"{exc.ctx.command_path}: " if getattr(exc, "ctx", None) is not None else ""
        typer.echo(f"error: {where}{_one_line(exc.format_message())}", err=True)
        sys.exit(exc.exit_code)
    except SystemExit:
        raise
    except RecursionError:
        typer.echo("error: input nested too deeply", err=True)
        sys.exit(2)
    except OSError as exc:
        # a path the user gave that the system refuses (a loop, no permission)
        # and that no reader turned into an InputError yet: still one line
        if exc.filename is None:
            raise
        typer.echo(f"error: {exc.filename}: {exc.strerror or exc}", err=True)
        sys.exit(2)
    finally:
        for sig, handler in previous.items():
            signal.signal(sig, handler)
        RECEIVED_SIGNALS.clear()
    if isinstance(code, int) and code:
        sys.exit(code)


if __name__ == "__main__":
    main()
