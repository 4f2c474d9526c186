"""One BLAS thread for every call into sizing.api, also for a Python user
who imported numpy first; the user's own threads come back afterwards."""
import pytest

threadpoolctl = pytest.importorskip("threadpoolctl")

from sizing import threads  # noqa: E402


def _blas_threads() -> list[int]:
    return [lib["num_threads"] for lib in threadpoolctl.threadpool_info() if lib["user_api"] == "blas"]


def test_an_api_call_runs_with_one_blas_thread_and_restores_the_rest(monkeypatch):
    import numpy  # noqa: F401  (the BLAS library is loaded before the limit)
    if not _blas_threads():
        pytest.skip("no BLAS library found by threadpoolctl")
    monkeypatch.setattr(threads, "USER_SETTING", {name: None for name in threads.BLAS_THREAD_VARIABLES})
    seen = []
    with threadpoolctl.threadpool_limits(limits=2, user_api="blas"):
        before = _blas_threads()
        threads.one_blas_thread(lambda: seen.extend(_blas_threads()))()
        after = _blas_threads()
    assert seen and set(seen) == {1}
    assert after == before


def test_a_user_setting_is_kept(monkeypatch):
    monkeypatch.setattr(threads, "USER_SETTING", {"OPENBLAS_NUM_THREADS": "2", "MKL_NUM_THREADS": None})
    seen = []
    with threadpoolctl.threadpool_limits(limits=2, user_api="blas"):
        before = _blas_threads()
        threads.one_blas_thread(lambda: seen.extend(_blas_threads()))()
    assert seen == before


def test_the_api_entry_points_are_limited():
    from sizing import api
    for name in ("solve", "run_solve", "evaluate", "fit_hysteresis", "fit_dc_motor", "diagnose", "robust", "sweep"):
        assert getattr(getattr(api, name), "__wrapped__", None) is not None, name
