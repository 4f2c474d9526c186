"""The best DC design on sourced parts, recomputed by hand from its parts'
catalog values: blocked force, top speed under each load case and winding
temperature within 2 %; and the summary entry beside the best on any parts."""
from __future__ import annotations

import math
from pathlib import Path

import pytest

from sizing.technologies.dc_motor import from_parts as dc_sizing
from sizing.technologies.dc_motor import verdict as dc_verdict
from sizing.technologies.dc_motor.record import actuator_candidate, parts_candidate
from sizing.engine.candidate import Candidate
from sizing.engine.evaluate import load_cases
from sizing.engine.rank import verdict
from sizing.io.catalog import load_catalog
from sizing.io.requirements import load_requirements

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def solved():
    req, _ = load_requirements(ROOT / "studies" / "seed-requirements.toml")
    cat = load_catalog()
    loads = [c["load_N"] for c in load_cases(req.load)]
    cands = [parts_candidate(req, cat, d) for d in dc_sizing.dc_parts_designs(req, cat, loads).designs]
    for c in cands:
        c["feasible"], c["driver"] = verdict(c["margins"])
    return req, cat, loads, cands, dc_verdict.dc_sourced(cat, [Candidate.from_dict(c) for c in cands])


def _hot(m, ambient, torque):
    """Winding temperature and k_t with the magnets at the winding, by plain iteration."""
    Tw = ambient
    for _ in range(60):
        kt = m.torque_constant * (1 + m.torque_constant_temperature_coefficient * (Tw - 25))
        i = torque / kt
        Tw = ambient + m.thermal_resistance * m.winding_resistance * (1 + m.resistance_temperature_coefficient * (Tw - 25)) * i**2
    return Tw, m.torque_constant * (1 + m.torque_constant_temperature_coefficient * (Tw - 25))


def test_best_on_sourced_parts_by_hand(solved):
    req, cat, loads, cands, summary = solved
    best = summary["best_on_sourced_parts"]
    assert best is not None and summary["feasible_on_sourced_parts"] >= 1
    cand = next(c for c in cands if c["id"] == best["id"])
    comp = cand["components"]
    m, s, d = cat.motors[comp["motor"]], cat.screws[comp["screw"]], cat.drives[comp["drive"]]
    g = cat.gears[comp["gear"]] if comp["gear"] else None
    for part in (m, s, d) + ((g,) if g else ()):
        assert dc_verdict.is_real(part)
    N, eta_g = (g.ratio, g.efficiency) if g else (1.0, 1.0)
    eta, lead = s.efficiency * eta_g, s.lead
    T = req.requirements.max_temperature
    # holding the worst load case heats the winding; k_t at that temperature
    F_hold = max(loads)
    Tw_hold, kt = _hot(m, T, F_hold * lead / (2 * math.pi * eta * N))
    # blocked force: the drive's peak current (or the motor's peak torque) through gear and screw
    i_max = min(d.peak_current, m.peak_torque / kt)
    F = 2 * math.pi * eta * N * kt * i_max / lead
    if g:
        F = min(F, 2 * math.pi * s.efficiency * g.max_output_torque / lead)
    assert cand["static"]["blocked_force_N"] == pytest.approx(F, rel=0.02)
    assert F >= req.requirements.blocked_force
    # top speed under each load: (U - R_hot i_load) / k_e through the screw, U capped by the ratings
    R_hot = m.winding_resistance * (1 + m.resistance_temperature_coefficient * (Tw_hold - 25))
    w_mech = min(m.max_speed, s.max_speed * N, g.max_input_speed if g else math.inf)
    U = min(d.bus_voltage, m.back_emf_constant * w_mech)
    for case in cand["simulated"]["cases"]:
        i_load = case["load_N"] * lead / (2 * math.pi * eta * kt * N)
        v = min((U - R_hot * i_load) / m.back_emf_constant, w_mech) * lead / (2 * math.pi * N)
        assert case["peak_speed_m_s"] == pytest.approx(v, rel=0.02)
        assert req.requirements.speed <= case["speed_m_s"] <= v
    # winding temperature at the simulated duty's RMS torque
    torque_rms = kt * max(c["rms_current_A"] for c in cand["simulated"]["cases"])
    Tw, _ = _hot(m, T, torque_rms)
    assert cand["simulated"]["winding_temperature_degC"] == pytest.approx(Tw, rel=0.02)
    assert Tw <= m.max_winding_temperature


def test_summary_sets_the_two_side_by_side(solved):
    *_, summary = solved
    any_, real = summary["best_on_any_parts"], summary["best_on_sourced_parts"]
    assert any_["mass_kg"] <= real["mass_kg"]
    assert summary["feasible_on_any_parts"] >= summary["feasible_on_sourced_parts"]
    assert isinstance(any_["rests_on_assumed"], list) and any_["rests_on_assumed"]
    label = lambda e: e.get("name") or e["id"]  # noqa: E731  (what people read)
    assert label(any_) in summary["text"] and label(real) in summary["text"]


def test_a_generic_part_is_not_real(solved):
    _, cat, *_ = solved
    assert not dc_verdict.is_real(cat.motors["gen-bldc42-28v-h"])
    assert not dc_verdict.is_real(cat.drives["servo-48v-10a"])        # only its loop rate is the seed's
    assert dc_verdict.is_real(cat.drives["tgdrives-tgz-d-48-13-26"])
    assert dc_verdict.is_real(cat.motors["maxon-597974"])


def test_the_lowest_ambient_rating_decides(solved):
    """A design bound by the ambient margin rests on the rating of the part
    rated lowest, not on every part's rating."""
    from sizing.technologies.dc_motor import assumed as dc_assumed
    _, cat, *_ = solved
    parts = {"motor": cat.motors["allied-mf0127008-48v"], "screw": cat.screws["ball-12x2"], "gear": None,
             "drive": cat.drives["servo-48v-10a"]}
    out = dc_assumed.rests_on(parts, "temperature")
    deciding = {(x["part"], x["field"]) for x in out if x["decides"]}
    assert deciding == {("allied-mf0127008-48v", "max_temperature")}     # 100 degC, below the screw's 120
    assert ("ball-12x2", "max_temperature") in {(x["part"], x["field"]) for x in out}
    rules = dc_assumed.rests_on({"motor": cat.motors["maxon-597974"]}, "temperature", "rule")
    assert {"part": "maxon-597974", "field": "max_temperature", "decides": True} in rules


def test_every_dc_candidate_says_what_it_rests_on(solved):
    """Catalog actuators too: a list, never null; each entry names a field of
    the part with an assumed status."""
    from sizing.technologies.dc_motor.catalog_actuators import actuator_designs
    req, cat, loads, cands, _ = solved
    for c in [actuator_candidate(req, cat, d) for d in actuator_designs(req, cat, loads)] + cands:
        assert isinstance(c["rests_on_assumed"], list), c["id"]
        for x in c["rests_on_assumed"]:
            assert cat.get(x["part"])[1].status[x["field"]].startswith("assumed"), (c["id"], x)
            assert isinstance(x["decides"], bool)


def test_evaluate_reproduces_the_best_real_design(solved, tmp_path):
    """Its `design` entry through `sizing evaluate` (a one-design catalog of
    makers' parts) gives the same speeds, winding and margins."""
    from sizing import api
    *_, cands, summary = solved
    best = next(c for c in cands if c["id"] == summary["best_on_sourced_parts"]["id"])
    d = best["design"]
    lines = ['technology = "dc_motor"'] + [f'{k} = "{d[k]}"' for k in ("motor", "screw", "drive")]
    lines += [f'gear = "{d["gear"]}"'] if d["gear"] else []
    lines += [f"{k} = {d[k]!r}" for k in ("step", "duration", "temperature", "speed", "strokes_per_second",
                                          "electronics_bay_temperature")]
    lines += [f'amplifier_location = "{d["amplifier_location"]}"', "[load]", 'dynamic_pressure = ["10 kPa", "25 kPa"]']
    path = tmp_path / "dc.toml"
    path.write_text("\n".join(lines) + "\n")
    ev = api.evaluate(path)
    assert ev["margins"] == pytest.approx({k: v for k, v in best["margins"].items() if k != "blocked_force"}, rel=1e-9)
    for a, b in zip(ev["simulated"]["cases"], best["simulated"]["cases"]):
        assert a["speed_m_s"] == pytest.approx(b["speed_m_s"], rel=1e-9)
