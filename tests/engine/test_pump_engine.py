"""The piezo pump in the seed solve (technologies/piezo_pump/designs.py, pump_screen.py): the
designs it verifies, the contract's fields, the bound no design beats, the
agreement of the two models and the three-technology verdict."""
from __future__ import annotations


import numpy as np
import pytest

from sizing.engine.candidate import Candidate
from sizing.technologies.piezo_pump import designs as pump_engine
from sizing.engine.evaluate import load_cases
from sizing.technologies.piezo_pump.record import pump_candidate
from sizing.io.catalog import load_catalog
from sizing.io.requirements import load_requirements

from ..conftest import STUDIES

DESIGN_KEYS = {"pump_frequency", "pump_diameter", "cylinder_diameter", "bias_pressure", "valve", "stack", "n_stacks",
               "voltage", "fluid", "seal", "amplifier"}
STATIC_KEYS = {"swept_volume_m3", "output_power_W", "amplifier_power_VA", "mean_speed_m_s"}


def _pumps(req, catalog, loads) -> tuple:
    """The pump stage's outcome and its designs' results.json records."""
    out = pump_engine.pump_designs(req, catalog, loads)
    return out, [pump_candidate(req, d) for d in out.designs]


@pytest.fixture(scope="module")
def seed_pumps():
    req, _ = load_requirements(STUDIES / "seed-requirements.toml")
    loads = [c["load_N"] for c in load_cases(req.load)]
    return req, _pumps(req, load_catalog(), loads)


def test_the_seed_sizes_and_simulates_at_least_20_pump_designs(seed_pumps):
    _, (out, candidates) = seed_pumps
    sims = [c for c in candidates if c["stage"] == "simulated"]
    assert len(sims) >= 20
    assert out.counts["simulated"] == len(sims)
    # every screened row is either simulated or counted by reason
    assert (sum(out.ruled_out.values()) + len(sims) + out.counts["outside_envelope"]
            == out.counts["combinations"])
    for c in sims:
        assert DESIGN_KEYS <= c["design"].keys(), c["id"]
        assert STATIC_KEYS <= c["static"].keys(), c["id"]
        assert all("mean_speed_m_s" in k for k in c["simulated"]["cases"])
        assert c["static"]["amplifier_power_VA"] > c["static"]["output_power_W"] > 0


def test_no_pump_design_delivers_more_oil_than_it_pumps_and_draws(seed_pumps):
    """The outlet passes what the pump sweeps plus what the ringing load draws
    from the accumulator through both valves (the inlet's flow beyond the
    pump's); the output moves no more oil than the outlet passed, within the
    high side's compression (its pressure at the end of the stroke differs
    from the start's by up to a few MPa: V_h / beta x dp, under 1 %)."""
    _, (_, candidates) = seed_pumps
    for c in candidates:
        s = c["static"]
        for case in c["simulated"]["cases"]:
            moved = case["stroke_m"] * s["cylinder_area_m2"]
            assert moved <= case["delivered_volume_m3"] * 1.01, c["id"]
            assert case["delivered_volume_m3"] > 0.5 * moved, c["id"]


def test_cycle_averaged_model_agrees_with_the_simulation_within_the_stated_tolerance(seed_pumps):
    """docs/models.md: on the verified designs the simulated mean speed lies
    within AGREEMENT_TOLERANCE of the cycle-averaged one, on the fast side
    (the averaged model omits the load ringing on the high-side oil)."""
    _, (_, candidates) = seed_pumps
    low, high = pump_engine.AGREEMENT_TOLERANCE
    for c in candidates:
        for case in c["simulated"]["cases"]:
            assert low <= case["agreement"] <= high, (c["id"], case["agreement"])


def test_an_envelope_rules_pump_designs_out_with_one_line_per_body():
    req, _ = load_requirements(STUDIES / "seed-requirements.toml")
    req = req.model_copy(update={"envelope": req.envelope.model_copy(update={"max_mass": 100.0})})
    loads = [c["load_N"] for c in load_cases(req.load)]
    out, candidates = _pumps(req, load_catalog(), loads)
    assert out.records and all(r["reason"] == "envelope" for r in out.records)
    assert sum(r["designs"] for r in out.records) == out.counts["outside_envelope"] > 0
    assert all(c["metrics"]["mass_kg"] <= 100.0 for c in candidates)


def test_the_speed_margin_is_the_simulated_one(seed_pumps):
    req, (_, candidates) = seed_pumps
    for c in candidates:
        assert c["margins"]["speed"] == pytest.approx(c["simulated"]["speed_m_s"] / req.requirements.speed - 1)


def test_design_frequency_stays_below_the_valve_rating_and_resonance(seed_pumps):
    _, (_, candidates) = seed_pumps
    cat = load_catalog()
    for c in candidates:
        valve = cat.valves[c["design"]["valve"]]
        assert c["design"]["pump_frequency"] <= valve.max_frequency < c["valve_resonance_Hz"]


def test_the_solve_ranks_three_technologies_and_states_the_pump_power(seed_solve_fast):
    r, html = seed_solve_fast.results, (seed_solve_fast.out / "report.html").read_text()
    techs = r["summary"]["comparison"]["technologies"]
    assert {"piezohydraulic", "dc_motor", "piezo_pump"} <= techs.keys()
    pp = techs["piezo_pump"]
    assert pp["best_demonstrated_power_W"] == pump_engine.BEST_DEMONSTRATED_POWER_W
    loads = [c["load_N"] for c in r["load_cases"]]
    assert pp["required_output_power_W"] == pytest.approx(max(loads) * r["requirements"]["speed_m_s"])
    assert "best demonstrated piezo pump" in r["summary"]["comparison"]["recommendation"]
    assert "piezo pump" in html
    assert any(c["technology"] == "piezo_pump" for c in r["candidates"])
    assert all(len(c["name"]) <= 32 for c in r["candidates"])
    assert "piezo_pump" in r["summary"]["ruled_out_by_technology"]


def test_a_catalog_without_valves_sizes_no_pump(tmp_path):
    from sizing.io.catalog import load_catalog as load
    cat = load()
    cat.valves.clear()
    req, _ = load_requirements(STUDIES / "seed-requirements.toml")
    out = pump_engine.pump_designs(req, cat, [500.0])
    assert out.designs == () and out.records == () and out.counts["combinations"] == 0


def test_a_diverged_cycle_simulation_is_a_failure_not_a_figure():
    from sizing.technologies.piezo_pump.designs import DIVERGED_FACTOR, diverged
    case = {"load_N": 1210.0, "stroke_m": 0.04, "mean_speed_m_s": 0.1, "delivered_volume_m3": 1e-5,
            "peak_cylinder_pressure_Pa": 5e6}
    swept = 0.12                                   # m/s the pump sweeps (swept volume x f / bore)
    assert diverged([case], swept) == ""
    # some through-flow from the accumulator is physics; several times the pump is not
    assert diverged([dict(case, mean_speed_m_s=1.5 * swept)], swept) == ""
    assert "diverged under 1210 N" in diverged([dict(case, mean_speed_m_s=-2e6)], swept)
    assert "diverged" in diverged([dict(case, mean_speed_m_s=(DIVERGED_FACTOR + 0.1) * swept)], swept)
    assert "non-finite" in diverged([case, dict(case, peak_cylinder_pressure_Pa=float("nan"))], swept)


def test_every_seed_design_keeps_to_the_stacks_work(seed_pumps):
    """No simulated design delivers more work to the load than its stacks
    put in (the integral of p dV). The seed's designs ring (the line's oil
    puts their output resonance at 2.5-7 x the pumping frequency), so the
    quasi-static bound K x_f^2 / 4 a cycle is checked where it holds: each
    design re-simulated with a light load (its output resonance over 10 x the
    pumping frequency) stays below it, summed over the cycles it ran with its
    own Bouc-Wen strokes."""
    req, (_, candidates) = seed_pumps
    for c in candidates:
        for case in c["simulated"]["cases"]:
            assert case["output_work_J"] <= case["stack_work_J"], c["id"]
    models = []
    original = pump_engine.simulate

    def keep(model, step_factor=1.0):
        models.append(model)
        return original(model, step_factor)

    pump_engine.simulate = keep
    try:
        pump_engine.pump_designs(req, load_catalog(), [c["load_N"] for c in load_cases(req.load)][-1:])
    finally:
        pump_engine.simulate = original
    m = models[0]
    light = m.replace(load_mass=1e-3, line_mass=0.0, line_volume=0.0, line_damping=0.0,
                      load_force=0.5 * np.asarray(m.load_force))
    omega = np.sqrt(m.bulk_modulus * m.cylinder_area / (m.dead_length * 1e-3))
    assert np.all(omega / (2 * np.pi) > 10 * np.asarray(m.frequency))
    s = original(light)
    assert np.all(s["output_work_J"] > 0)
    assert np.all(s["output_work_J"] <= s["stack_work_J"])
    assert np.all(s["output_work_J"] <= s["quasi_static_bound_J"]), s["output_work_J"] / s["quasi_static_bound_J"]
    # and no more oil than the pump sweeps
    swept_speed = light.pump_area * s["free_stroke_m"] * light.frequency / light.cylinder_area
    assert np.all(s["mean_speed_m_s"] <= swept_speed)


def test_seed_designs_converge_when_the_step_halves(seed_pumps):
    """The closest design (and every other simulated one): the mean speed
    within 1 % when the simulation's step halves."""
    req, (out, _) = seed_pumps
    loads = [c["load_N"] for c in load_cases(req.load)]
    half = pump_engine.pump_designs(req, load_catalog(), loads, step_factor=0.5)
    assert [d.id for d in half.designs] == [d.id for d in out.designs]
    closest = max(out.designs, key=lambda d: min(d.margins.values()))
    for d, h in zip(out.designs, half.designs):
        for a, b in zip(d.simulation.cases, h.simulation.cases):
            assert abs(a["mean_speed_m_s"] / b["mean_speed_m_s"] - 1) < 0.01, (d.id, d is closest)


def test_the_closest_design_block_round_trips_through_evaluate(seed_pumps):
    """The closest pump's results.json ``design`` block, evaluated on its
    own (technologies/piezo_pump/evaluate.py), reproduces its metrics and margins."""
    from sizing.technologies.piezo_pump.evaluate import evaluate_pump
    from sizing.technologies.piezo_pump.design_file import PumpDesignFile
    req, (out, candidates) = seed_pumps
    closest = max(candidates, key=lambda c: min(c["margins"].values()))
    r = evaluate_pump(PumpDesignFile.model_validate(closest["design"]), load_catalog(), "design.toml")
    for k, v in closest["metrics"].items():
        assert r["metrics"][k] == pytest.approx(v, rel=5e-3), k
    for k, v in closest["margins"].items():
        assert r["margins"][k] == pytest.approx(v, rel=5e-3, abs=1e-9), k


def test_robust_studies_a_pump_design(seed_pumps):
    """``sizing robust --technology piezo_pump``: the closest pump's parts
    perturbed by the tolerances (stack stroke and stiffness, bulk modulus,
    seal friction, air), each sample judged by the screen's checks and the
    cycle simulation. With every spread 0 the samples are the nominal
    design: its margins, the amplifier count missed in every sample."""
    from sizing.studies.executor import Executor
    from sizing.studies.robust import pick_designs, robust
    req, (_, candidates) = seed_pumps
    results = {"candidates": sorted(candidates, key=lambda c: -min(c["margins"].values()))}
    assert pick_designs(results, 3) == []                     # pumps only when asked for
    picked = pick_designs(results, 1, "piezo_pump")
    zero = req.model_copy(update={"tolerances": {"stack.stroke": 0.0, "stack.stiffness": 0.0}})
    out = robust(zero, load_catalog(), picked, samples=4, seed=1, executor=Executor(0))["designs"][0]
    assert out["technology"] == "piezo_pump" and out["p_compliance"] == 0.0
    assert out["failing_requirements"] == ["amplifier_units"]
    for k, q in out["margin_quantiles"].items():
        assert q["p50"] == pytest.approx(picked[0].margins[k], rel=5e-3, abs=1e-9), k
    spread = robust(req, load_catalog(), picked, samples=8, seed=1, executor=Executor(0))["designs"][0]
    assert len(set(round(spread["margin_quantiles"]["blocked_force"][q], 9) for q in ("p05", "p95"))) == 2


@pytest.mark.parametrize("capacitance", [3.1e-5, 1.55e-5])
def test_the_flips_pump_re_solve_gives_the_stage_s_verdict_and_lightest(capacitance):
    """``pump.complying_designs`` (what the flips' re-solves simulate)
    against the whole pump stage: the same verdict and the same lightest
    complying design, at the seed's stack capacitance (no pump complies)
    and at half of it (one does), while simulating fewer rows."""
    from sizing.engine import resolve
    req, _ = load_requirements(STUDIES / "seed-requirements.toml")
    catalog = resolve.with_value(load_catalog(None), "pi-p-056.90", "capacitance", capacitance)
    loads = [c["load_N"] for c in load_cases(req.load)]
    whole = pump_engine.pump_designs(req, catalog, loads).designs
    few = pump_engine.complying_designs(req, catalog, loads)
    a = resolve.verdict_of(req, [Candidate.from_dict(pump_candidate(req, d)) for d in whole])
    b = resolve.verdict_of(req, [Candidate.from_dict(pump_candidate(req, d)) for d in few])
    assert (a.feasible, a.best) == (b.feasible, b.best) and a.objective == pytest.approx(b.objective, rel=1e-9)
    assert a.feasible == (capacitance < 3e-5) and len(few) < len(whole)
