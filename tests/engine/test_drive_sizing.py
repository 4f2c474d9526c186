"""The piezohydraulic drive sized as amplifier units, the stacks' self-heating,
a leaking compensator's creep over the hold, the sized oil gap, the envelope,
and their bad inputs. Each figure recomputed by hand in the docstring."""
from __future__ import annotations

import json
import math

import pytest

from sizing.technologies.piezohydraulic.designs import compensator_creep, effective_gap
from sizing.technologies.piezohydraulic.records import PiezoBrief
from sizing.io.requirements import load_requirements
from sizing.physics import amplifier, stack

from ..conftest import FAST_REQUIREMENTS, STUDIES, run_cli

C_P05690 = 31e-6            # F, small-signal, catalogs/stacks.toml pi-p-056.90


def test_amplifier_units_for_the_reviewers_fifteen_stacks():
    """15 x P-056.90 at 1000 V, one stroke a second, a 0.2 s ramp, PI E-481
    units (2 A for 5 ms, 0.2 A continuous). By hand: C_L = 15 x 31 uF x 1.7 =
    790.5 uF; mean 2 C V f = 1.581 A (the reviewer's 1.58 A); ramp current
    C V / t = 3.9525 A, held for 0.2 s >> 5 ms, so on the continuous rating:
    19.76 -> 20 units; rms 3.9525 x sqrt(2 x 0.2 x 1) = 2.4998 A -> 13 units."""
    C = 15 * C_P05690 * stack.LARGE_SIGNAL_CAPACITANCE_FACTOR
    assert C == pytest.approx(790.5e-6)
    assert amplifier.mean_current(C, 1000.0, 1.0) == pytest.approx(1.581, rel=1e-4)
    assert amplifier.ramp_current(C, 1000.0, 0.2) == pytest.approx(3.9525, rel=1e-4)
    assert amplifier.rms_current(C, 1000.0, 0.2, 1.0) == pytest.approx(2.4998, rel=1e-4)
    assert amplifier.units_needed(C, 1000.0, 0.2, 1.0, 2.0, 0.2, 5e-3) == 20
    # a ramp inside the rated pulse may use the peak: 3 ms -> C V / t = 263.5 A / 2 A -> 132 units
    # for the ramp, against rms 263.5 x sqrt(0.006) = 20.41 A / 0.2 A -> 103 units
    assert amplifier.units_needed(C, 1000.0, 3e-3, 1.0, 2.0, 0.2, 5e-3) == 132
    # at a tenth of the duty and a slow ramp a single unit does: 0.79 mC over 4 s = 0.198 A
    assert amplifier.units_needed(C, 1000.0, 4.0, 0.1, 2.0, 0.2, 5e-3) == 1


def test_amplifier_heat_with_energy_recovery():
    """C V^2 f = 790.5 uF x 1e6 V^2 x 1 Hz = 790.5 W shed by a linear stage;
    80 % recovered leaves 158.1 W."""
    C = 790.5e-6
    assert amplifier.dissipated_power(C, 1000.0, 1.0) == pytest.approx(790.5)
    assert amplifier.dissipated_power(C, 1000.0, 1.0, 0.8) == pytest.approx(158.1)


def test_stack_self_heating_by_hand():
    """P-056.90, tan(delta) 0.02, 31 uF, 1000 V, one cycle a second:
    P = pi/4 x 7 x 0.02 x 31e-6 x 1e6 x 1 = 3.409 W a stack (the reviewer's
    'very roughly 4-7 W'); side pi x 0.056 x 0.150 = 0.02639 m^2;
    rise 3.409 / (10 x 0.02639) = 12.92 K."""
    heat = stack.heat_per_stack(0.02, C_P05690, 1000.0, 1.0)
    assert heat == pytest.approx(3.409, rel=1e-3)
    area = stack.side_area(0.150, 0.056)
    assert area == pytest.approx(0.02639, rel=1e-3)
    assert stack.temperature_rise(heat, area) == pytest.approx(12.92, rel=1e-3)
    assert stack.side_area(0.036, 0.010, square=True) == pytest.approx(4 * 0.010 * 0.036)


def test_compensator_creep_over_the_hold():
    """The reviewer's orifice reservoir: 64 um/s at the load -> 3.84 mm a
    minute. With G = 3e-15 m^3/(s Pa) (catalog) and a 16 mm narrow bore under
    1210 N: p = 1210 / (pi 0.008^2) = 6.018 MPa; Q = G p = 1.805e-8 m^3/s;
    over the bore's 2.011e-4 m^2: 89.8 um/s, 5.39 mm in 60 s, 89.8 um in 1 s."""
    d = 0.016
    p = 1210 / (math.pi * 0.008**2)
    assert p == pytest.approx(6.018e6, rel=1e-3)
    assert compensator_creep(3e-15, p, 1.0, d) == pytest.approx(89.8e-6, rel=2e-3)
    assert compensator_creep(3e-15, p, 60.0, d) == pytest.approx(5.39e-3, rel=2e-3)


def test_gap_floor_is_the_stack_stroke_plus_clearance_and_tolerance():
    """180 um of stack stroke + 0.5 mm clearance + 0.1 mm tolerance = 0.78 mm
    (the reviewer's 0.68 mm covers the stroke with 0.5 mm): far below the
    3 mm the sizing used to fix; a floor in the requirements still holds."""
    req, _ = load_requirements(STUDIES / "seed-requirements.toml")
    assert effective_gap(PiezoBrief.of(req), 180e-6) == pytest.approx(0.78e-3)
    floored = req.model_copy(update={"options": req.options.model_copy(update={"wide_gap": 3e-3})})
    assert effective_gap(PiezoBrief.of(floored), 180e-6) == pytest.approx(3e-3)


def _fast(tmp_path, extra: str) -> tuple:
    req = tmp_path / "req.toml"
    req.write_text(FAST_REQUIREMENTS.replace("max_stacks = 2", "max_stacks = 12") + extra)
    out = tmp_path / "out"
    return run_cli("solve", req, "--out", out, "--quiet", "--fast"), out      # verdicts and ranks, no flips


def test_an_envelope_rules_designs_out_and_none_is_ranked(tmp_path):
    (code, _, stderr), out = _fast(tmp_path, '\n[envelope]\nmax_mass = "150 kg"\n')
    assert code == 0, stderr
    r = json.loads((out / "results.json").read_text())
    reasons = [x["reason"] for x in r["ruled_out"]]
    assert "envelope" in reasons and set(reasons) <= {"envelope", "structure_out_of_range"}
    assert all(c["metrics"]["mass_kg"] <= 150 * (1 + 1e-9) for c in r["candidates"] if c["metrics"].get("mass_kg"))
    assert r["summary"]["ruled_out"]["envelope"] == reasons.count("envelope")
    # robust picks only ranked designs: none ruled out, none outside the envelope
    from sizing.studies.robust import pick_designs
    picked = pick_designs(r, 10, "piezohydraulic")
    assert not {c.id for c in picked} & {x["id"] for x in r["ruled_out"]}
    assert all(c.metrics["mass_kg"] <= 150 * (1 + 1e-9) for c in picked)


@pytest.mark.parametrize("extra, field", [
    ('\n[envelope]\nmax_length = "10 mm"\n', "[envelope].max_length"),      # shorter than any stack
    ('\n[envelope]\nmax_diameter = "1 mm"\n', "[envelope].max_diameter"),
    ('\n[duty]\nhold_time = "-5 s"\n', "hold_time"),
])
def test_bad_envelope_and_hold_exit_2_with_one_line(tmp_path, extra, field):
    (code, _, stderr), out = _fast(tmp_path, extra)
    assert code == 2
    assert field in stderr and len(stderr.strip().splitlines()) == 1
    assert not out.exists()


def test_an_amplifier_without_a_pulse_rating_exits_2(tmp_path, catalog_copy):
    path = catalog_copy / "amplifiers.toml"
    path.write_text(path.read_text().replace('peak_duration = "5 ms"\n', "", 1))
    req = tmp_path / "req.toml"
    req.write_text(FAST_REQUIREMENTS)
    out = tmp_path / "out"
    code, _, stderr = run_cli("solve", req, "--out", out, "--quiet", "--catalog", catalog_copy)
    assert code == 2 and "peak_duration" in stderr and len(stderr.strip().splitlines()) == 1
    assert not out.exists()


def test_compensator_time_constant_and_the_share_it_takes_in_time():
    """The reviewer's figure: the seed solve's best design (504 mm bore,
    force path 3.476e9 N/m) behind the 3e-15 m^3/(s Pa) restrictor:
    C_h = A_w^2 / k = 0.19946^2 / 3.476e9 = 1.1446e-11 m^3/Pa, and
    tau = C_h / G = 3815 s, 63.6 min (not the 1 min its entry was sized
    for). Ramped over a 60 s warm-up and held 60 s it has taken up
    1 - (3815/60)(1 - exp(-60/3815)) exp(-60/3815) = 2.33 % of the thermal
    volume; an instant one all of it, one that never acts none."""
    from sizing.physics import thermal
    A = math.pi * 0.252**2
    tau = thermal.compensator_time_constant(A, 3.476e9, 3e-15)
    assert tau == pytest.approx(A**2 / 3.476e9 / 3e-15, rel=1e-12)
    assert tau / 60 == pytest.approx(63.6, abs=0.05)
    share = thermal.compensated_share(tau, 60.0, 60.0)
    x = 60 / tau
    assert share == pytest.approx(1 - (1 - math.exp(-x)) / x * math.exp(-x), rel=1e-9)
    assert share == pytest.approx(0.0233, abs=2e-4)
    assert thermal.compensated_share(0.0, 60.0, 60.0) == 1.0
    assert thermal.compensated_share(math.inf, 60.0, 60.0) == 0.0
    # a first-order lag driven by a ramp, integrated numerically, agrees
    t, dt, y = 0.0, 0.01, 0.0
    tau_small = 40.0
    while t < 120.0:
        u = min(t / 60.0, 1.0)
        y += dt * (u - y) / tau_small
        t += dt
    assert thermal.compensated_share(tau_small, 60.0, 60.0) == pytest.approx(y, rel=2e-3)
