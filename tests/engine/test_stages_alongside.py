"""The solve's stages side by side (``engine/solve.py`` ``_stages``): a
technology marked ``Technology.alongside`` runs in a worker thread under the
caller's limits, the others in the calling thread, and the outcomes come
back by name in the registry's order whatever finishes first; an error in
a worker's stage reaches the caller. With no core to spare every stage runs
in the calling thread."""
from __future__ import annotations

import threading
import time

import pytest

from sizing import limits
from sizing.engine import solve as solve_module
from sizing.technologies import registry


def _technology(name: str, order: int, alongside: bool, seen: dict, delay: float = 0.0, fails: bool = False):
    def stage(req, catalog, loads, progress, detail="summary"):
        time.sleep(delay)                    # the worker's stage finishes last
        if fails:
            raise ValueError(f"{name} failed")
        seen[name] = (threading.current_thread() is threading.main_thread(), limits.current().steps)
        if progress is not None:
            progress(name, 1, 1)
        return f"{name} outcome", (name,)
    return registry.Technology(name=name, label=name, order=order, part_kinds=(), solve=stage, groups=(),
                               short_name=lambda c: name, describe=lambda c, catalog: name, alongside=alongside)


@pytest.fixture(autouse=True)
def core_to_spare(monkeypatch):
    monkeypatch.setattr(solve_module, "core_to_spare", lambda: True)


@pytest.fixture
def three(monkeypatch):
    seen: dict = {}
    techs = (_technology("first", 0, False, seen), _technology("second", 1, True, seen, delay=0.2),
             _technology("third", 2, False, seen))
    monkeypatch.setattr(solve_module, "technologies", lambda: techs)
    return seen


def test_an_alongside_stage_runs_in_a_worker_under_the_callers_limits(three):
    reports = []
    with limits.use_limits(steps=1234.0):
        out = solve_module._stages(None, None, [1.0], lambda *a: reports.append(a), "summary")
    assert list(out) == ["first", "second", "third"]                 # the registry's order
    assert out["second"] == ("second outcome", ("second",))
    assert three == {"first": (True, 1234.0), "second": (False, 1234.0), "third": (True, 1234.0)}
    assert sorted(r[0] for r in reports) == ["first", "second", "third"]


def test_a_single_technology_runs_in_the_calling_thread(monkeypatch):
    seen: dict = {}
    only = (_technology("only", 0, True, seen),)
    monkeypatch.setattr(solve_module, "technologies", lambda: only)
    solve_module._stages(None, None, [1.0], None, "summary")
    assert seen == {"only": (True, limits.current().steps)}


def test_a_worker_stages_error_reaches_the_caller(monkeypatch):
    seen: dict = {}
    techs = (_technology("first", 0, False, seen), _technology("second", 1, True, seen, fails=True))
    monkeypatch.setattr(solve_module, "technologies", lambda: techs)
    with pytest.raises(ValueError, match="second failed"):
        solve_module._stages(None, None, [1.0], lambda *a: None, "summary")
    assert "first" in seen


def test_with_no_core_to_spare_every_stage_runs_in_the_calling_thread(three, monkeypatch):
    monkeypatch.setattr(solve_module, "core_to_spare", lambda: False)
    out = solve_module._stages(None, None, [1.0], None, "summary")
    assert list(out) == ["first", "second", "third"]
    assert all(in_main for in_main, _ in three.values())


def test_one_core_has_none_to_spare(monkeypatch):
    from sizing import threads
    monkeypatch.setattr(threads.os, "sched_getaffinity", lambda pid: {0}, raising=False)
    assert threads.core_to_spare() is False


def test_the_solve_gives_the_same_results_with_or_without_a_core_to_spare(monkeypatch):
    """The real stages (the seed's requirements on one piezohydraulic
    design's parts and three catalog DC actuators, simulated, ``fast``):
    results.json and the traces are the same, field by field and to the
    bit, whether the DC stage runs in a worker thread beside the others or
    every stage in turn here; only the time taken depends on the load."""
    import json
    from dataclasses import replace

    from sizing.engine.candidate import records
    from sizing.io.requirements import load_requirements
    from tests.conftest import ONE_DESIGN, STUDIES, subset_catalog

    catalog = subset_catalog(**ONE_DESIGN, dc_actuators=3)
    req, sha = load_requirements(STUDIES / "seed-requirements.toml")
    ran_in = {}

    def recorded(t):
        def stage(*args):
            ran_in[t.name] = threading.current_thread().name
            return t.solve(*args)
        return replace(t, solve=stage)
    techs = tuple(recorded(t) for t in registry.technologies())
    monkeypatch.setattr(solve_module, "technologies", lambda: techs)

    def written(spare: bool) -> tuple[str, set]:
        monkeypatch.setattr(solve_module, "core_to_spare", lambda: spare)
        out = solve_module.solve(req, sha, catalog, fast=True)
        results = dict(out.results, candidates=records(out.results["candidates"]), runtime_s=None)
        designed = {c["technology"] for c in results["candidates"]}
        return json.dumps([results, out.traces], sort_keys=True, default=lambda a: a.tolist()), designed

    beside, designed = written(True)
    assert all(ran_in[t.name].startswith("sizing-stage") == t.alongside for t in techs)
    assert designed & {t.name for t in techs if t.alongside}         # a worker's stage gave designs
    in_turn, _ = written(False)
    assert set(ran_in.values()) == {"MainThread"}
    assert beside == in_turn
