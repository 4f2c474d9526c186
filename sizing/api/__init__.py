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
from .catalogs import (CatalogEntry, CatalogUpdate, catalog, catalog_add, catalog_diff, catalog_entry,
                       catalog_import_mgdb, catalog_table, catalog_validate)
from .checks import check_envelope, check_evaluate_steps, check_solve_steps
from .diagnosis import DIAGNOSE_OUTPUTS, DiagnoseResult, diagnose, diagnose_check, run_diagnose
from .evaluation import EvaluateResult, evaluate, judge_designs
from .fitting import FitResult, fit_dc_motor, fit_hysteresis
from .output import PLOTLY_FILE, plotly_js, write
from .solution import SOLVE_OUTPUTS, SolveResult, results_json, run_solve, solve
from .studies import ROBUST_OUTPUTS, SWEEP_OUTPUTS, StudyResult, robust, run_robust, run_sweep, sweep

from ..threads import one_blas_thread

# every computing entry point runs with one BLAS thread (sizing/threads.py)
(catalog_add, catalog_import_mgdb, diagnose, diagnose_check, evaluate, fit_dc_motor, fit_hysteresis,
 judge_designs, robust, run_diagnose, run_robust, run_solve, run_sweep, solve, sweep) = map(one_blas_thread, (
    catalog_add, catalog_import_mgdb, diagnose, diagnose_check, evaluate, fit_dc_motor, fit_hysteresis,
    judge_designs, robust, run_diagnose, run_robust, run_solve, run_sweep, solve, sweep))

__all__ = [
    "CatalogEntry", "CatalogUpdate", "DIAGNOSE_OUTPUTS", "DiagnoseResult", "EvaluateResult", "FitResult",
    "PLOTLY_FILE", "ROBUST_OUTPUTS", "SOLVE_OUTPUTS", "SWEEP_OUTPUTS", "SolveResult", "StudyResult",
    "catalog", "catalog_add", "catalog_diff", "catalog_entry", "catalog_import_mgdb", "catalog_table",
    "catalog_validate", "check_envelope", "check_evaluate_steps", "check_solve_steps", "diagnose",
    "diagnose_check", "evaluate", "judge_designs", "fit_dc_motor", "fit_hysteresis", "plotly_js", "results_json", "robust",
    "run_diagnose", "run_robust", "run_solve", "run_sweep", "solve", "sweep", "write",
]
