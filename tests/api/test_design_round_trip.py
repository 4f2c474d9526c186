"""Designs that evaluate to themselves: the ``design`` block of every ranked
piezohydraulic, DC and piezo pump candidate of a solve, written as a design.toml and
judged with the same requirements (``sizing evaluate --requirements``),
reproduces the candidate's mass, feasibility and every margin within 0.5 %.
The solve's figures are the reference; the evaluation rebuilds the design
from the file alone."""
from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from sizing import api
from sizing.io.design import design_toml

from ..conftest import run_cli

REPO = Path(__file__).resolve().parents[2]
TOLERANCE = 0.005
TECHNOLOGIES = ("piezohydraulic", "dc_motor", "piezo_pump")


def _close(a, b) -> bool:
    """Two margins agree: both missing, or within 0.5 % (of 1 for a margin near 0)."""
    if a is None or b is None:
        return a is None and b is None
    return abs(a - b) <= TOLERANCE * max(1.0, abs(a))


@pytest.fixture(scope="module")
def fast_solves(seed_solve_fast) -> dict:
    """The seed solves with --fast (no compliance: the design blocks are the
    same); the seed's own is computed once per test run (conftest)."""
    return {"seed-requirements.toml": seed_solve_fast.results}


def _solve(study: str, cache: dict) -> dict:
    if study not in cache:
        cache[study] = api.run_solve(REPO / "studies" / study, fast=True).records      # as results.json holds them
    return cache[study]


def _round_trip(study: str, tmp_path: Path, cache: dict) -> list[str]:
    requirements = REPO / "studies" / study
    results = _solve(study, cache)
    cands = [c for c in results["candidates"] if c["technology"] in TECHNOLOGIES and "design" in c]
    assert len(cands) > 50
    paths = []
    for i, c in enumerate(cands):
        path = tmp_path / f"{i}.toml"
        path.write_text(design_toml(c["design"]))
        paths.append(path)
    judged = api.judge_designs(paths, requirements)
    misses = []
    for c, j in zip(cands, judged):
        simulated = c.get("stage") == "simulated"     # an unsimulated candidate states its static margins
        ref = c["margins"] if simulated else c.get("static_margins", c["margins"])
        got = j["margins"] if simulated else j["judged"]["static_margins"]
        wrong = [k for k in set(ref) | set(got) if not _close(ref.get(k), got.get(k, math.nan))]
        mass = j["judged"]["metrics"]["mass_kg"] / c["metrics"]["mass_kg"] - 1
        if wrong or j["feasible"] != c["feasible"] or abs(mass) > TOLERANCE:
            misses.append(f"{c['id']}: {wrong} feasible {c['feasible']}->{j['feasible']} mass {mass:+.2%}")
    return misses


@pytest.mark.parametrize("study", ["seed-requirements.toml",
                                   pytest.param("seed-requirements-low-duty.toml", marks=pytest.mark.slow)])  # a solve of its own
def test_every_ranked_design_evaluates_to_itself(study, tmp_path, fast_solves):
    assert _round_trip(study, tmp_path, fast_solves) == []


def test_fast_solve_states_no_compliance(fast_solves):
    """solve --fast: the nominal recommendation, every compliance null."""
    comp = _solve("seed-requirements.toml", fast_solves)["summary"]["comparison"]
    assert all(t["compliance"] is None for t in comp["technologies"].values())
    assert comp["recommended"]["compliance"] is None
    assert comp["recommended"]["id"] in {t["best"] for t in comp["technologies"].values()}


def test_evaluate_carries_the_amplifier_units_and_ramp(tmp_path, fast_solves):
    """The best piezohydraulic design of the seed: ``sizing evaluate`` on its
    design block (no requirements) gives the solve's mass and ramp, where
    one amplifier unit would give a lighter actuator and a ramp many times
    longer; with --requirements the JSON adds the margins and the verdict."""
    requirements = REPO / "studies" / "seed-requirements.toml"
    results = _solve("seed-requirements.toml", fast_solves)
    best_id = results["summary"]["comparison"]["technologies"]["piezohydraulic"]["best"]
    best = next(c for c in results["candidates"] if c["id"] == best_id)
    assert best["design"]["amplifier_units"] > 1
    path = tmp_path / "best.toml"
    path.write_text(design_toml(best["design"]))
    code, out, err = run_cli("evaluate", path, "--requirements", requirements, "--json")
    assert code == 0, err
    figures = json.loads(out)
    assert figures["metrics"]["mass_kg"] == pytest.approx(best["metrics"]["mass_kg"], rel=TOLERANCE)
    assert figures["design"]["ramp_time_s"] == pytest.approx(best["design"]["ramp_time"], rel=TOLERANCE)
    assert figures["static"]["blocked_force_N"] == pytest.approx(best["static"]["blocked_force_N"], rel=TOLERANCE)
    assert figures["feasible"] is best["feasible"]
    assert set(figures["margins"]) == set(best["margins"])
    one_unit = path.read_text().replace(f"amplifier_units = {best['design']['amplifier_units']}\n", "")
    path.write_text(one_unit.replace(f"ramp_time = {best['design']['ramp_time']!r}\n", ""))
    lone = api.evaluate(path).figures
    assert lone["design"]["amplifier_units"] == 1
    assert lone["metrics"]["mass_kg"] < best["metrics"]["mass_kg"] - 0.9 * best["design"]["amplifier_units"]
    assert lone["design"]["ramp_time_s"] > 3 * best["design"]["ramp_time"]


def test_evaluate_requirements_bad_input_exits_2(tmp_path):
    """A design judged against requirements needs every part; a missing
    requirements file is named. One line each, exit 2."""
    design = tmp_path / "design.toml"
    design.write_text('technology = "piezohydraulic"\nstack = "pi-p-056.90"\nn_stacks = 10\nratio = 277\n')
    code, _, err = run_cli("evaluate", design, "--requirements", REPO / "studies" / "seed-requirements.toml")
    assert code == 2 and len(err.strip().splitlines()) == 1 and "design.toml" in err and "fluid" in err
    code, _, err = run_cli("evaluate", design, "--requirements", tmp_path / "missing.toml")
    assert code == 2 and len(err.strip().splitlines()) == 1 and "missing.toml" in err
