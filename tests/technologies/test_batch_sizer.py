"""The batch sizer (every combination's geometric program at once, in
numpy) against Clarabel through cvxpy, the reference: the expanded
posynomials against cvxpy's own expressions, a few hand-made inputs, the
fallback, and every combination the seed and low-duty solves size."""
from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from sizing.technologies.piezohydraulic.records import PiezoBrief
from sizing.io.catalog import load_catalog
from sizing.io.requirements import load_requirements
from sizing.technologies.piezohydraulic import batch_gp, batch_sizer
from sizing.technologies.piezohydraulic import designs as piezo_designs
from sizing.technologies.piezohydraulic.batch_sizer import BatchSizer
from sizing.technologies.piezohydraulic.convex import (CONSTRAINTS, PARAMETERS, POINT, VARIABLES, GPSizer, Program,
                                                       parameter_values)
from sizing.technologies.piezohydraulic.posynomial import Posynomial
from sizing.technologies.piezohydraulic.search import enumerate_combos

from ..conftest import STUDIES
from ..engine.test_variant_sizing import BASE

POINT_FIELDS = ("ratio", "wide_area", "voltage_fraction", "cap_thickness", "frame_area", "wide_gap",
                "amplifier_units_sized")
INPUTS = [BASE, dataclasses.replace(BASE, n_stiffness=12 * 4.33e8, n_capacitance=12 * 31e-6),
          dataclasses.replace(BASE, youngs_modulus=205e9, poisson=0.29, material_density=7850.0,
                              allowable_stress=417e6),
          dataclasses.replace(BASE, n_stiffness=5 * 4.33e8, n_capacitance=5 * 31e-6),      # below the work bound
          dataclasses.replace(BASE, max_current=4 * 0.2)]                                  # the drive binds


def _objective(objectives, inputs, results) -> np.ndarray:
    """log of the objective (the product of the objectives) at each result's point."""
    layout = BatchSizer(objectives).problem.objective
    theta = np.log([[parameter_values(s)[k] for k in PARAMETERS] for s in inputs])
    y = np.zeros((len(results), len(VARIABLES)))
    y[:, :len(POINT)] = np.log([[getattr(r, f) for f in POINT_FIELDS] for r in results])
    b = theta @ layout.parameter_powers.T + layout.log_coefficient
    return batch_gp._Posynomials(layout).evaluate(y, b)[0].sum(axis=1)


def test_the_expanded_posynomials_are_cvxpy_s_expressions():
    """Every constraint term and objective, expanded into monomials, has
    the value cvxpy's expression has at the reference's optimum."""
    ref = GPSizer(("mass", "cost"))
    res = ref.solve(BASE)
    assert res.success
    values = {n: float(v.value) for n, v in zip(VARIABLES, (ref.R, ref.A, ref.v, ref.t, ref.Af, ref.g, ref.U,
                                                            ref.C, ref.Fs, ref.M))}
    values.update({k: float(p.value) for k, p in ref.par.items()})
    mine = Program(("mass", "cost"), Posynomial.symbol, Posynomial.symbol)

    def value(posy: Posynomial) -> float:
        return sum(c * math.prod(values[s] ** a for s, a in key) for key, c in posy.terms.items())

    for k, expr in ref._constraint_terms().items():
        assert value(mine._constraint_terms()[k]) == pytest.approx(float(expr.value), rel=1e-12), k
    assert value(mine._objective_factors()[0] * mine._objective_factors()[1]) == pytest.approx(
        float(ref._objective().value), rel=1e-12)


def test_hand_made_inputs_agree_with_clarabel():
    """Feasible inputs: the same optimum (objective within 1e-9 relative);
    infeasible ones: the same binding requirements."""
    got = BatchSizer(("mass", "cost")).solve(INPUTS)
    ref = GPSizer(("mass", "cost"))
    want = [ref.solve(s) for s in INPUTS]
    for a, b in zip(got, want):
        assert a.success == b.success and a.binding == b.binding
    ok = [i for i, r in enumerate(want) if r.success]
    assert len(ok) == 3
    diff = (_objective(("mass", "cost"), [INPUTS[i] for i in ok], [got[i] for i in ok])
            - _objective(("mass", "cost"), [INPUTS[i] for i in ok], [want[i] for i in ok]))
    assert np.all(np.abs(diff) < 1e-7)
    assert got[4].driver == "drive_current" and got[3].status == "infeasible"


def test_rows_the_batch_does_not_certify_go_to_clarabel(monkeypatch):
    """With no iteration allowed nothing is certified: every row is
    Clarabel's own answer, field for field."""
    monkeypatch.setattr(batch_gp.solve, "__defaults__", (0,))
    monkeypatch.setattr(batch_sizer, "OPTIMUM_ITERATIONS", 0)
    sizer = BatchSizer(("mass", "cost"))
    got = sizer.solve(INPUTS)
    ref = GPSizer(("mass", "cost"))
    assert [dataclasses.asdict(r) for r in got] == [dataclasses.asdict(ref.solve(s)) for s in INPUTS]


def _seed_inputs(study: str) -> tuple[tuple, list]:
    """Every program input the piezohydraulic stage sizes for a study
    (the variants, then the passive designs re-sized with their spacer)."""
    req, _ = load_requirements(STUDIES / study)
    catalog = load_catalog()
    brief = PiezoBrief.of(req)
    seen = []
    solved = piezo_designs._solved

    def record(objectives, inputs):
        seen.extend(inputs)
        return solved(objectives, inputs)

    combos = [c for c in enumerate_combos(req, catalog) if not c.pruned]
    try:
        piezo_designs._solved = record
        sized = piezo_designs.size(brief, catalog, combos)
        piezo_designs.resize_passive(brief, catalog, piezo_designs.designs(brief, catalog, sized))
    finally:
        piezo_designs._solved = solved
    return tuple(brief.objectives), seen


@pytest.mark.slow
@pytest.mark.parametrize("study", ["seed-requirements.toml", "seed-requirements-low-duty.toml"])
def test_every_seed_combination_agrees_with_clarabel(study):
    """On every combination (about a thousand each): the same feasibility;
    the feasible ones' objective within 1e-6 relative of Clarabel's and
    their geometry within 1e-3 (the optimum is flat in some directions:
    Clarabel stops at its 1e-8 gap, the batch at 1e-10); the infeasible
    ones' driver the same and phase 1's total miss (the product of the
    slacks) within 1e-6."""
    objectives, inputs = _seed_inputs(study)
    assert len(inputs) > 1000
    got = BatchSizer(objectives).solve(inputs)
    ref = GPSizer(objectives)
    want = [ref.solve(s) for s in inputs]
    assert [r.success for r in got] == [r.success for r in want]
    ok = [i for i, r in enumerate(want) if r.success]
    diff = (_objective(objectives, [inputs[i] for i in ok], [got[i] for i in ok])
            - _objective(objectives, [inputs[i] for i in ok], [want[i] for i in ok]))
    assert np.abs(diff).max() < 1e-6
    for i in ok:
        for f in POINT_FIELDS:
            assert getattr(got[i], f) == pytest.approx(getattr(want[i], f), rel=1e-3), (i, f)
    bad = [i for i, r in enumerate(want) if not r.success]
    assert bad
    for i in bad:
        assert got[i].driver == want[i].driver, i
        total = [math.prod(r.slack[k] for k in CONSTRAINTS) for r in (got[i], want[i])]
        assert total[0] == pytest.approx(total[1], rel=1e-6), i
    assert batch_sizer.INFEASIBLE in {r.status for r in want}


def test_inside_a_reuse_block_only_new_inputs_are_solved(monkeypatch):
    """The flips' re-solves (``stage_cache.reuse()``) read back what was
    sized before and send only the new inputs to the batch."""
    from sizing.engine import stage_cache
    sizes = []
    solve = BatchSizer.solve
    monkeypatch.setattr(BatchSizer, "solve", lambda self, inputs: sizes.append(len(inputs)) or solve(self, inputs))
    with stage_cache.reuse():
        first = piezo_designs._solved(("mass", "cost"), INPUTS[:3])
        again = piezo_designs._solved(("mass", "cost"), INPUTS)
    assert sizes == [3, 2]
    assert all(a is b for a, b in zip(first, again[:3]))
