"""Every piezohydraulic variant sized on its own, the drive sized with it,
and the geometric program's direct re-solve against cvxpy's own."""
from __future__ import annotations

import dataclasses
import math

import pytest

from sizing.technologies.piezohydraulic import designs as piezo_designs
from sizing.technologies.piezohydraulic.convex import GPSizer, SizingInput
from sizing.technologies.piezohydraulic.records import PiezoBrief
from sizing.technologies.piezohydraulic.search import enumerate_combos
from sizing.io.catalog import load_catalog
from sizing.io.requirements import load_requirements
from sizing.physics import amplifier, stack

from ..conftest import STUDIES

# the seed's full-scale stack (Table 2), a 21 MPa seal, the PI E-481's ratings per unit
BASE = SizingInput(
    n_stiffness=17 * 4.33e8, stack_stroke=180e-6, rated_voltage=1000.0, max_fraction=1.0, force=2500.0,
    stroke=0.04, bulk_modulus=1.5e9, wide_gap=1e-9, pressure_rating=21e6, natural_frequency=25.0,
    stroke_time=0.4, n_capacitance=17 * 31e-6, max_current=16 * 0.2, margin=0.05, fixed_mass=50.0,
    fixed_cost=300_000.0, fixed_volume=0.01, oil_density=850.0, oil_cost=10_000.0,
    amp_unit_mass=10.0, amp_unit_cost=10_000.0, amp_unit_current=0.2, amp_unit_continuous=0.2,
    strokes_per_second=1.0)


def test_drive_for_the_reviewers_seventeen_stacks():
    """17 x P-056.90 at 1 kV: C_L = 17 x 31 uF x 1.7 = 895.9 uF, 0.8959 C a
    ramp. Reaching a 42 mm free stroke at 100 mm/s allows a 0.42 s ramp:
    0.8959 / 0.42 = 2.133 A (the reviewer's 2.13 A), far beyond the 5 ms
    pulse, so on the 0.2 A continuous rating: 10.67 -> 11 units; the rms
    2.133 x sqrt(2 x 0.42 x 1) = 1.955 A needs only 10. Within the pulse
    (5 ms) it would take 179.2 A / 2 A -> 90 units. Eleven units then ramp
    in 0.8959 / 2.2 = 0.4072 s (rms 2 f (C V / (11 x 0.2))^2 = 0.332 s is
    shorter). Capped at 8: 0.8959 / 1.6 = 0.560 s, and the rms needs
    2 x 0.560^2 = 0.627 s: the capped drive ramps in 0.627 s."""
    C = 17 * 31e-6 * stack.LARGE_SIGNAL_CAPACITANCE_FACTOR
    assert C == pytest.approx(895.9e-6)
    assert amplifier.ramp_current(C, 1000.0, 0.42) == pytest.approx(2.133, rel=1e-3)
    d = amplifier.drive_for_speed(C, 1000.0, 0.42, 1.0, 2.0, 0.2, 5e-3, 16)
    assert d["needed"] == 11 and d["units"] == 11
    assert d["ramp"] == pytest.approx(0.8959 / 2.2, rel=1e-4)
    capped = amplifier.drive_for_speed(C, 1000.0, 0.42, 1.0, 2.0, 0.2, 5e-3, 8)
    assert capped["needed"] == 11 and capped["units"] == 8
    assert capped["ramp"] == pytest.approx(2 * (0.8959 / 1.6) ** 2, rel=1e-4)
    # a small group ramped within the pulse: 1 stack, 52.7 uF, 1 kV in 30 ms allowed:
    # continuous 52.7e-3 / 0.03 / 0.2 = 8.8 -> 9 units; on the peak within 5 ms:
    # 10.54 A / 2 A -> 6 units (rms 10.54 x sqrt(0.01) = 1.054 A / 0.2 -> 6), ramp
    # 52.7e-3 / 12 A = 4.39 ms, the rms asking 2 x (52.7e-3 / 1.2)^2 = 3.86 ms
    one = amplifier.drive_for_speed(31e-6 * 1.7, 1000.0, 0.03, 1.0, 2.0, 0.2, 5e-3)
    assert one["units"] == 6 and one["ramp"] == pytest.approx(52.7e-3 / 12.0, rel=1e-3)


def test_the_program_sizes_the_units_against_the_speed():
    """The program's continuous count: the ramp at the required speed over
    the free stroke, R x0 v / u, carried at 0.2 A a unit, the rms and mean
    below it; the count is within the cap and pays for itself in mass."""
    res = GPSizer(("mass", "cost")).solve(BASE)
    assert res.success
    C = 17 * 31e-6 * 1.7
    free = res.ratio * 180e-6 * res.voltage_fraction
    ramp = free / 0.1
    needs = max(C * 1000 * res.voltage_fraction / ramp / 0.2,
                amplifier.rms_current(C, 1000 * res.voltage_fraction, ramp, 1.0) / 0.2,
                2 * C * 1000 * res.voltage_fraction / 0.2)
    assert res.amplifier_units_sized == pytest.approx(needs, rel=1e-4)
    assert res.amplifier_units_sized <= 16 * (1 + 1e-6)
    # a cap below what the speed needs makes the drive the binding requirement
    capped = GPSizer(("mass", "cost")).solve(dataclasses.replace(BASE, max_current=4 * 0.2))
    assert not capped.success and capped.driver == "drive_current"


def test_direct_re_solve_agrees_with_cvxpy():
    """The direct path (the compiled cone program filled and solved) gives
    cvxpy's own solution, feasible and infeasible, within the solver's
    tolerance."""
    inputs = [BASE, dataclasses.replace(BASE, n_stiffness=12 * 4.33e8, n_capacitance=12 * 31e-6),
              dataclasses.replace(BASE, youngs_modulus=205e9, poisson=0.29, material_density=7850.0,
                                  allowable_stress=417e6),
              dataclasses.replace(BASE, n_stiffness=5 * 4.33e8, n_capacitance=5 * 31e-6)]     # below the work bound
    fast, plain = GPSizer(), GPSizer()
    for run in plain._runs.values():
        run.direct = False
    fast.solve(BASE)                                   # compiles
    for s in inputs:
        a, b = fast.solve(s), plain.solve(s)
        assert a.success == b.success and a.binding == b.binding
        for name in ("ratio", "wide_area", "voltage_fraction", "cap_thickness", "frame_area", "wide_gap",
                     "amplifier_units_sized"):
            assert getattr(a, name) == pytest.approx(getattr(b, name), rel=1e-3), name
    assert all(run.compiled is not None for run in (fast._runs[id(fast.problem)],))


@pytest.fixture(scope="module")
def sized_seed():
    req, _ = load_requirements(STUDIES / "seed-requirements.toml")
    catalog = load_catalog()
    brief = PiezoBrief.of(req)
    combo = next(c for c in enumerate_combos(req, catalog)
                 if not c.pruned and c.stack.id == "pi-p-056.90" and c.n == 16 and c.seal.id == "ptfe-spring-energised"
                 and c.fluid.id == "mil-prf-87257" and c.amplifier.id == "pi-e-481")
    return brief, catalog, combo, piezo_designs.size(brief, catalog, [combo])


def test_every_material_and_compensator_gets_its_own_geometry(sized_seed):
    """Each variant's geometry is the program's optimum for that variant's
    own material and compensator (re-solved here from its own input), and
    the steel variant's bore is far smaller than aluminium's (the
    reviewer's hand re-sizing: 504 mm -> about 275 mm for 16 stacks)."""
    brief, catalog, combo, sized = sized_seed
    assert len(sized) == len(piezo_designs.variants(brief, catalog))
    sizer = GPSizer(list(brief.objectives))
    for _, v, res in sized:
        own = sizer.solve(piezo_designs.sizing_input(brief, combo, v.material, v.compensator))
        assert res.wide_area == pytest.approx(own.wide_area, rel=1e-3), v.suffix()
        assert res.cap_thickness == pytest.approx(own.cap_thickness, rel=1e-3), v.suffix()
    bore = {(v.material.id, v.compensator.id if v.compensator else None): 2 * math.sqrt(res.wide_area / math.pi)
            for _, v, res in sized}
    al, steel = bore[("al-6061-t6", None)], bore[("steel-4340", None)]
    assert steel < 0.7 * al
    assert steel == pytest.approx(0.275, rel=0.1)


def test_a_design_held_at_the_units_cap_says_so(sized_seed):
    """Built with the options' cap below what the speed needs, a design
    carries the cap, ramps slower, misses the speed and says so."""
    brief, catalog, combo, sized = sized_seed
    capped = dataclasses.replace(brief, max_amplifier_units=6)
    d = next(x for x in piezo_designs.designs(capped, catalog, sized[:1]) if x.built)
    free = piezo_designs.designs(brief, catalog, sized[:1])[0]
    assert free.static["amplifier_units_at_cap"] == 0.0 and free.static["amplifier_units"] < 16
    assert d.static["amplifier_units"] == 6 and d.static["amplifier_units_at_cap"] == 1.0
    assert d.static_margins["amplifier_units"] < 0 and d.static_margins["speed"] < 0
    assert d.amplifier_units == 6 and d.ramp_time > free.ramp_time


def test_direct_re_solves_find_cvxpy_s_optimum_on_seed_inputs():
    """Seed programs (every 40th of the search's combinations and variants,
    feasible and not) re-solved by handing the compiled cone data to
    Clarabel against cvxpy's own ``problem.solve(gp=True)`` of the same
    program: the same feasibility and binding requirements, the same
    optimum (mass x cost at the point each returns) and the same point,
    within the solver's tolerance."""
    req, _ = load_requirements(STUDIES / "seed-requirements.toml")
    catalog = load_catalog()
    brief = PiezoBrief.of(req)
    vs = piezo_designs.variants(brief, catalog)
    inputs = [piezo_designs.sizing_input(brief, c, v.material, v.compensator)
              for c in enumerate_combos(req, catalog) if not c.pruned for v in vs][::40]
    fast, plain = GPSizer(brief.objectives), GPSizer(brief.objectives)
    for run in plain._runs.values():
        run.direct = False
    for s in inputs:                   # compile first, so that the comparison below is of direct re-solves
        fast.solve(s)
    infeasible = 0
    for s in inputs:
        a = fast.solve(s)
        optimum = fast.problem.objective.value if a.success else None
        b = plain.solve(s)
        assert a.success == b.success and a.binding == b.binding
        infeasible += not a.success
        if a.success:
            assert optimum == pytest.approx(plain.problem.value, rel=1e-6)
        for name in ("ratio", "wide_area", "voltage_fraction", "cap_thickness", "frame_area", "wide_gap",
                     "amplifier_units_sized"):
            assert getattr(a, name) == pytest.approx(getattr(b, name), rel=1e-3), name
    assert infeasible and infeasible < len(inputs)
    assert all(run.compiled is not None and run.cone_data is not None for run in fast._runs.values())
