"""The application layer: one function per command, each computing a typed
result and writing its files as a separate, shared step (``api.output``).
``cli.py`` is a thin layer over this; from Python::

    from sizing import api
    result = api.solve("requirements.toml", out_dir=None)   # compute only
    api.write(result, "sizing-out")                          # then write

One module per command family: ``solution`` (solve), ``evaluation``
(evaluate), ``fitting`` (fit hysteresis, fit dc-motor), ``diagnosis``
(diagnose, diagnose --check), ``studies`` (robust, sweep), ``catalogs``
(catalog list, show, validate, diff, add, import-mgdb).
"""
from __future__ import annotations

import importlib

# {public name: the module of this package that defines it}. Each module is
# imported when one of its names is first used, so that ``sizing --help``
# and an input error answer before numpy, scipy, cvxpy, numba and plotly
# load (``from sizing import api`` alone costs nothing).
_WHERE = {
    **dict.fromkeys(("CatalogEntry", "CatalogUpdate", "catalog", "catalog_add", "catalog_diff", "catalog_entry",
                     "catalog_import_mgdb", "catalog_table", "catalog_validate"), "catalogs"),
    **dict.fromkeys(("check_envelope", "check_evaluate_steps", "check_solve_steps"), "checks"),
    **dict.fromkeys(("DIAGNOSE_OUTPUTS", "DiagnoseResult", "diagnose", "diagnose_check", "run_diagnose"), "diagnosis"),
    **dict.fromkeys(("EvaluateResult", "evaluate", "judge_designs"), "evaluation"),
    **dict.fromkeys(("FitResult", "fit_dc_motor", "fit_hysteresis"), "fitting"),
    **dict.fromkeys(("PLOTLY_FILE", "plotly_js", "write"), "output"),
    **dict.fromkeys(("SOLVE_OUTPUTS", "SolveResult", "results_json", "run_solve", "solve"), "solution"),
    **dict.fromkeys(("ROBUST_OUTPUTS", "SWEEP_OUTPUTS", "StudyResult", "robust", "run_robust", "run_sweep", "sweep"),
                    "studies"),
}

# every computing entry point runs with one BLAS thread (sizing/threads.py)
_ONE_BLAS_THREAD = {"catalog_add", "catalog_import_mgdb", "diagnose", "diagnose_check", "evaluate", "fit_dc_motor",
                    "fit_hysteresis", "judge_designs", "robust", "run_diagnose", "run_robust", "run_solve",
                    "run_sweep", "solve", "sweep"}


def __getattr__(name: str):
    """A public name, loaded from its module on first use and kept."""
    if name not in _WHERE:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(f"{__name__}.{_WHERE[name]}"), name)
    if name in _ONE_BLAS_THREAD:
        from ..threads import one_blas_thread
        value = one_blas_thread(value)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_WHERE))


__all__ = [
    "CatalogEntry", "CatalogUpdate", "DIAGNOSE_OUTPUTS", "DiagnoseResult", "EvaluateResult", "FitResult",
    "PLOTLY_FILE", "ROBUST_OUTPUTS", "SOLVE_OUTPUTS", "SWEEP_OUTPUTS", "SolveResult", "StudyResult",
    "catalog", "catalog_add", "catalog_diff", "catalog_entry", "catalog_import_mgdb", "catalog_table",
    "catalog_validate", "check_envelope", "check_evaluate_steps", "check_solve_steps", "diagnose",
    "diagnose_check", "evaluate", "judge_designs", "fit_dc_motor", "fit_hysteresis", "plotly_js", "results_json", "robust",
    "run_diagnose", "run_robust", "run_solve", "run_sweep", "solve", "sweep", "write",
]
