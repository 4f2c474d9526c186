"""The library's front door: one function per command, returning plain
result objects (dicts of SI floats). ``cli.py`` is a thin layer over this."""
from __future__ import annotations

from pathlib import Path

from .io.catalog import Catalog, load_catalog
from .io.design import PiezoDesignFile, load_design
from .report.bundle import PLOTLY_FILE       # a constant; the bundle itself loads only when written


def catalog(folder: str | Path | None = None) -> Catalog:
    return load_catalog(folder)


def evaluate(design_path: str | Path, catalog_dir: str | Path | None = None) -> dict:
    """Static and simulated figures of one design file (docs/formats.md)."""
    from .engine.evaluate import evaluate_dc, evaluate_piezo

    design = load_design(design_path)
    cat = load_catalog(catalog_dir)
    check_evaluate_steps(design, cat, str(design_path))
    if isinstance(design, PiezoDesignFile):
        result = evaluate_piezo(design, cat, str(design_path))
    else:
        result = evaluate_dc(design, cat, str(design_path))
    # provenance: the catalog values this result rests on that are assumed
    from .io.provenance import assumed_values
    parts = {k: v for k, v in result["design"].items() if k in ("stack", "fluid", "seal", "amplifier", "actuator",
                                                                 "motor", "screw", "gear", "drive")}
    result["assumed"] = assumed_values(cat, parts)
    return result


def solve(requirements_path: str | Path, out_dir: str | Path | None = "sizing-out",
          catalog_dir: str | Path | None = None, baseline: str | Path | None = None,
          progress=None, detail: str = "summary", robust: str | Path | None = None) -> dict:
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
    Raises InputError for bad input before writing anything.
    """
    import json

    from .engine.solve import solve as run
    from .io.atomic import check_folder, write_folder
    from .io.requirements import load_requirements
    from .report.csv_table import candidates_csv
    from .report.html import render

    inputs = [requirements_path, catalog_dir, baseline, robust]
    if out_dir is not None:
        check_folder(out_dir, SOLVE_OUTPUTS, inputs=inputs)
    req, sha = load_requirements(requirements_path)
    cat = load_catalog(catalog_dir)
    check_solve_steps(req, cat, str(requirements_path))
    old = _load_baseline(baseline) if baseline is not None else None
    studied = _load_robust(robust) if robust is not None else None
    if detail not in ("summary", "full"):
        from .errors import InputError
        raise InputError(None, "--detail", f'expected "summary" or "full", got {detail!r}')
    output = run(req, sha, cat, progress=progress, detail=detail)
    results = output.results
    results["catalog_dir"] = str(cat.folder.resolve())
    if studied is not None:
        _attach_compliance(results, studied)
    if old is not None:
        results["changes"], results["changes_summary"] = _rank_changes(old, results, baseline, cat.folder)
        results["baseline_sha256"] = old.get("requirements_sha256")
    if out_dir is not None:
        files = {"results.json": results_json(results),
                 "candidates.csv": candidates_csv(results),
                 "report.html": render(results, output.traces), PLOTLY_FILE: plotly_js}
        # the catalog these results rest on, so a later --baseline can diff it
        files.update(_catalog_snapshot(cat.folder))
        write_folder(out_dir, files, inputs=inputs)
    return results


# What ``solve --out DIR`` holds (check_folder needs it before any work).
# plotly.js once per output folder, beside the pages that use it (report/bundle.py)
def plotly_js() -> str:
    """The folder's plotly bundle (report/bundle.py), made only when written."""
    from .report.bundle import plotly_js as bundle
    return bundle()

SOLVE_OUTPUTS = ("results.json", "candidates.csv", "report.html", "catalog/", PLOTLY_FILE)
ROBUST_OUTPUTS = ("robust.json", "robust.html", PLOTLY_FILE)
SWEEP_OUTPUTS = ("sweep.json", "sweep.html", PLOTLY_FILE)


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


def _catalog_snapshot(folder: Path) -> dict[str, bytes]:
    from .io.catalog import KINDS
    from .io.catalog_diff import SNAPSHOT_DIR
    from .io.schema import read_input_bytes
    return {f"{SNAPSHOT_DIR}/{name}": read_input_bytes(folder / name)
            for name in KINDS if (folder / name).exists()}


def _n_loads(load) -> int:
    return len(load.force) if load.force is not None else len(load.dynamic_pressure)


def check_evaluate_steps(design, cat: Catalog, file: str) -> None:
    """Refuse (exit 2) a design whose simulation would need more steps than
    the limit (``sizing.limits``): duration x rate x load cases."""
    from .engine.dc import OUTPUT_RATE_HZ
    from .engine.verify import SETTLE_TIME_S
    from .limits import check_steps, dc_steps, piezo_steps
    if isinstance(design, PiezoDesignFile):
        check_steps(piezo_steps(design.rise_time + SETTLE_TIME_S, _n_loads(design.load)), file, "rise_time",
                    "simulation steps (rise time x 20 kHz x load cases)")
    elif design.actuator in cat.dc_actuators:
        rate = cat.dc_actuators[design.actuator].pid.rate
        check_steps(dc_steps(design.duration, rate, _n_loads(design.load), OUTPUT_RATE_HZ), file, "duration",
                    f"simulation steps (duration x {max(rate, OUTPUT_RATE_HZ):g} Hz x load cases)")


def check_solve_steps(req, cat: Catalog, file: str) -> None:
    """Refuse (exit 2) requirements whose verification would need more
    steps than the limit: simulated candidates x load cases x stroke time."""
    from .engine.dc import OUTPUT_RATE_HZ
    from .engine.dc_candidates import dc_duration
    from .engine.verify import SETTLE_TIME_S
    from .limits import check_steps, dc_steps, piezo_steps
    n = _n_loads(req.load)
    steps = piezo_steps(req.stroke_time + SETTLE_TIME_S, n * req.options.max_simulated)
    if req.options.dc_motors:
        steps += sum(dc_steps(dc_duration(req), act.pid.rate, n, OUTPUT_RATE_HZ) for act in cat.dc_actuators.values())
    check_steps(steps, file, "[requirements].stroke",
                "simulation steps (candidates x load cases x stroke / speed)")
    check_envelope(req, cat, file)


def check_envelope(req, cat: Catalog, file: str) -> None:
    """Refuse (exit 2) an envelope that no stack fits in: shorter than the
    shortest stack or narrower than the thinnest one."""
    from .errors import InputError
    env, stacks = req.envelope, list(cat.stacks.values())
    if not stacks:
        return
    for field, limit, need, what in (("max_length", env.max_length, min(s.length for s in stacks), "length"),
                                     ("max_diameter", env.diameter, min(s.diameter for s in stacks), "diameter")):
        if limit is not None and limit < need:
            raise InputError(file, f"[envelope].{field}",
                             f"expected room for at least one stack: the smallest stack {what} is "
                             f"{need * 1e3:g} mm, the envelope gives {limit * 1e3:g} mm")


def _read_json(path: Path, what: str, writer: str):
    """A JSON file a command wrote (exit 2, one line, when it is not JSON)."""
    import json

    from .errors import InputError
    from .io.schema import read_input_bytes
    try:
        return json.loads(read_input_bytes(path, f"a {what}").decode("utf-8"))
    except (json.JSONDecodeError, UnicodeDecodeError, RecursionError) as exc:
        raise InputError(str(path), None, f"expected a {what} written by {writer} ({exc})") from None


def _load_robust(path: str | Path) -> dict[str, dict]:
    """{design id: its robust.json entry} of a robust.json (exit 2 when it is not one)."""
    from .errors import InputError
    path = Path(path)
    data = _read_json(path, "robust.json", "sizing robust")
    designs = data.get("designs") if isinstance(data, dict) else None
    if not isinstance(designs, list) or not all(isinstance(d, dict) and "id" in d and "p_compliance" in d
                                                for d in designs):
        raise InputError(str(path), "designs", "expected a robust.json with designs and their p_compliance")
    return {d["id"]: d for d in designs}


def _attach_compliance(results: dict, studied: dict[str, dict]) -> None:
    """Each studied candidate, and each technology's best, carries its
    probability of compliance under tolerances and its 95 % interval."""
    for c in results["candidates"]:
        if c["id"] in studied:
            c["p_compliance"] = studied[c["id"]]["p_compliance"]
            c["p_ci95"] = studied[c["id"]].get("p_ci95")
    for tech in results["summary"]["comparison"]["technologies"].values():
        entry = studied.get(tech["best"])
        if entry is not None:
            tech["p_compliance"], tech["p_ci95"] = entry["p_compliance"], entry.get("p_ci95")


def _load_baseline(path: str | Path) -> dict:
    from .errors import InputError
    path = Path(path)
    data = _read_json(path, "results.json", "sizing solve")
    if not isinstance(data, dict) or not isinstance(data.get("candidates"), list):
        raise InputError(str(path), "candidates", "expected a results.json with a list of candidates")
    return data


def _rank_changes(baseline: dict, results: dict, baseline_path, catalog_folder: Path) -> tuple[list[dict], dict]:
    """Designs whose standing changed (engine/changes.py), with the
    catalog fields responsible when the baseline's catalog is known (the
    snapshot ``sizing solve`` writes beside its results.json)."""
    from .engine.changes import change_causes, rank_changes
    from .io.catalog_diff import baseline_catalog, diff_catalogs
    old_catalog = baseline_catalog(baseline_path, baseline)
    diff = diff_catalogs(old_catalog, catalog_folder) if old_catalog is not None else None
    changes = rank_changes(baseline, results, diff)
    return changes, change_causes(baseline, results, changes, diff)


def diagnose(campaign_dir: str | Path, holdout: list[str], out_dir: str | Path | None = None,
             recalibrate: list[str] | None = None, seed: int = 0):
    """Diagnose the sim-to-real gap of a campaign (docs/formats.md). Writes
    diagnosis.json and diagnosis.html into ``out_dir`` when given; returns
    the Diagnosis (``.to_json()`` is diagnosis.json)."""
    import json

    from .diagnose.diagnosis import diagnose_runs
    from .io.atomic import check_folder, write_folder
    from .io.campaign import campaign_split, load_campaign

    if out_dir is not None:
        check_folder(out_dir, DIAGNOSE_OUTPUTS, inputs=[campaign_dir])
    campaign = load_campaign(campaign_dir)
    campaign_split(campaign, holdout)
    result = diagnose_runs(campaign.kind, campaign.rig, campaign.runs, list(holdout), recalibrate=recalibrate,
                           seed=seed)
    if out_dir is not None:
        from .report.diagnose_html import render
        files = {"diagnosis.json": json.dumps(result.to_json(), indent=2),
                 "diagnosis.html": render(result, f"Sim-to-real gap: {Path(campaign_dir).name}"),
                 PLOTLY_FILE: plotly_js}
        write_folder(out_dir, files, inputs=[campaign_dir])
    return result


DIAGNOSE_OUTPUTS = ("diagnosis.json", "diagnosis.html", PLOTLY_FILE)


def diagnose_check(campaign_dir: str | Path, holdout: list[str] | None = None, seed: int = 0, progress=None):
    """The withheld-effect check on a campaign's own excitations and rig."""
    from .diagnose.bench import Bench
    from .diagnose.check import campaign_noise, check_runs, clean_inputs
    from .io.campaign import campaign_split, load_campaign

    campaign = load_campaign(campaign_dir)
    holdout = list(holdout) if holdout else [campaign.runs[-1].name]
    campaign_split(campaign, holdout)
    bench = Bench(campaign.kind, campaign.rig, campaign.runs, holdout)
    return check_runs(campaign.kind, campaign.rig, clean_inputs(bench), holdout, campaign_noise(bench, seed),
                      seed=seed, progress=progress)


def fit_hysteresis(paths, holdout=None, model: str = "auto", out=None, **options) -> dict:
    """Fit Bouc-Wen (seed eq. 1-2) and Prandtl-Ishlinskii to run CSVs; the
    TOML carries ``model`` ("auto": the better on the holdout). Writes OUT and OUT.html when ``out`` is given.
    Returns {"toml", "warnings", "result", "written"}."""
    from .fit.workflow import fit_hysteresis as run

    return run(paths, holdout=holdout, model=model, out=out, **options)


def fit_dc_motor(paths, rig, holdout=None, out=None, **options) -> dict:
    """Fit c1, c2 (optionally the PID gains) of a dc_motor rig to run CSVs."""
    from .fit.workflow import fit_dc_motor as run

    return run(paths, rig, holdout=holdout, out=out, **options)


# --- studies: sizing robust, sizing sweep ------------------------
def _executor(scheduler: str | None, workers: int, cluster=None, progress=None):
    """The study executor; tells ``progress.note`` (when it has one) where the
    Dask dashboard shows the tasks."""
    from .studies.executor import Executor
    ex = Executor(workers=workers, scheduler=scheduler, cluster=cluster)
    if ex.dashboard and hasattr(progress, "note"):
        progress.note(f"Dask dashboard: {ex.dashboard}")
    return ex


def robust(requirements_path: str | Path, out_dir: str | Path | None = "robust-out", catalog_dir=None,
           samples: int = 1000, seed: int = 0, designs: int = 10, scheduler: str | None = None,
           workers: int = 0, cluster=None, progress=None, bouc_wen_fit: str | Path | None = None,
           technology: str | None = None) -> dict:
    """Probability of compliance of the ``designs`` best designs of ``solve``
    (piezohydraulic and DC from parts; only ``technology``'s when given)
    under the [tolerances] (docs/formats.md). ``workers`` > 0: a
    local Dask cluster of that many processes; ``scheduler``: a running one;
    ``cluster``: a dask cluster object. ``bouc_wen_fit``: a ``sizing fit
    hysteresis`` output whose standard errors become Bouc-Wen tolerances. Writes robust.json and robust.html
    into ``out_dir`` when given. ``progress(stage, done, total)``."""
    import json

    from .errors import InputError
    from .io.atomic import check_folder, write_folder
    from .io.requirements import load_requirements

    inputs = [requirements_path, catalog_dir, bouc_wen_fit]
    if out_dir is not None:
        check_folder(out_dir, ROBUST_OUTPUTS, inputs=inputs)
    if samples < 1:
        raise InputError(None, "--samples", f"expected at least 1 sample, got {samples}")
    if designs < 1:
        raise InputError(None, "--designs", f"expected at least 1 design, got {designs}")
    if technology not in (None, "piezohydraulic", "dc_motor"):
        raise InputError(None, "--technology", f'expected "piezohydraulic" or "dc_motor", got {technology!r}')
    req, sha = load_requirements(requirements_path)
    cat = load_catalog(catalog_dir)
    extra = None
    if bouc_wen_fit is not None:        # the stack was fitted: its Bouc-Wen spreads from the fit
        from .io.fit_spreads import bouc_wen_spreads
        extra = bouc_wen_spreads(bouc_wen_fit)
    with _executor(scheduler, workers, cluster, progress) as ex:        # an unreachable scheduler fails here, first
        from .engine.solve import solve as run                # (the engine's imports take seconds)
        from .studies.robust import pick_designs, robust as run_robust
        results = run(req, sha, cat, progress=progress).results
        picked = pick_designs(results, designs, technology)
        if not picked:
            raise InputError(str(requirements_path), None, "no sized design (piezohydraulic, or DC from parts) "
                                                           f"to study{'' if technology is None else ' of ' + technology}")
        data = run_robust(req, cat, picked, samples, seed, ex, extra_spreads=extra,
                          progress=(lambda d, t: progress("sampling", d, t)) if progress else None)
    data["requirements_sha256"] = sha
    data["catalog_sha256"] = cat.sha256
    if out_dir is not None:
        from .report.robust_html import render
        write_folder(out_dir, {"robust.json": json.dumps(data, indent=1, allow_nan=False) + "\n",
                               "robust.html": render(data), PLOTLY_FILE: plotly_js}, inputs=inputs)
    return data


def sweep(requirements_path: str | Path, vary: list[str], out_dir: str | Path | None = "sweep-out",
          catalog_dir=None, scheduler: str | None = None, workers: int = 0, cluster=None, progress=None) -> dict:
    """A full solve per point of the grid ``vary`` (``FIELD=FROM..TO:N``
    each); writes sweep.json and sweep.html into ``out_dir`` when given."""
    import json

    from .io.atomic import check_folder, write_folder
    from .io.schema import load_toml
    from .studies.sweep import sweep as run_sweep

    inputs = [requirements_path, catalog_dir]
    if out_dir is not None:
        check_folder(out_dir, SWEEP_OUTPUTS, inputs=inputs)
    data = load_toml(requirements_path)
    cat = load_catalog(catalog_dir)
    from .studies.sweep import parse_vary
    for v in vary:                          # bad --vary before any cluster starts
        parse_vary(v, data, requirements_path)
    with _executor(scheduler, workers, cluster, progress) as ex:
        result = run_sweep(data, requirements_path, cat, vary, ex,
                           progress=(lambda d, t: progress("solving", d, t)) if progress else None)
    if out_dir is not None:
        from .report.sweep_html import render
        write_folder(out_dir, {"sweep.json": json.dumps(result, indent=1, allow_nan=False) + "\n",
                               "sweep.html": render(result), PLOTLY_FILE: plotly_js}, inputs=inputs)
    return result
