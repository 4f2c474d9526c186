"""The noise floor where the output is at rest (floor.rest_noise): not
inflated by a stick-slip's sample-scale staircase during motion."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from sizing.diagnose import synth
from sizing.diagnose.diagnosis import diagnose_runs
from sizing.diagnose.floor import rest_noise
from sizing.diagnose.inputs import noise_sigma
from sizing.io.rig import load_rig
from .excitations import trapezoids

ROOT = Path(__file__).resolve().parents[2]


def _staircase(h: float):
    """Stick-slip at a fixed slip length: the output sticks and advances in jumps of h."""
    return lambda t, y, rng: h * np.round(y / h)


def test_rest_noise_of_a_staircase_during_ramps_is_the_sensor_noise():
    """A ramp-and-hold output read with white noise sigma, advancing in
    jumps of 5 sigma while it moves: the second differences of the whole
    run take the jumps for noise (more than 1.5 sigma), those where the
    nominal is at rest do not (within 10 % of sigma)."""
    rng = np.random.default_rng(3)
    t, u = trapezoids(0.01)["up"]
    sigma = 1e-5
    measured = 5 * sigma * np.round(u / (5 * sigma)) + rng.normal(0.0, sigma, len(t))
    estimate, where = rest_noise(measured - u, u, float(np.ptp(u)))
    assert where.startswith("at rest")
    assert estimate == pytest.approx(sigma, rel=0.1)
    assert noise_sigma(measured - u) > 1.5 * sigma


def test_rest_noise_falls_back_to_the_whole_run_without_rest():
    t = np.arange(0.0, 1.0, 1e-3)
    u = np.sin(2 * np.pi * 3 * t)
    e = np.random.default_rng(0).normal(0.0, 1e-3, len(t))
    assert rest_noise(e, u, 2.0) == (noise_sigma(e), "whole run")


def test_stick_slip_gap_of_1_3_times_the_noise_is_a_gap():
    """A DC campaign whose output sticks and advances in jumps (stick-slip)
    while it moves, read with white noise of 0.1 % of the span: the
    stick-slip's own gap is 1.3 x the true noise (hand-set slip length
    h = 1.3 sqrt(12) sigma, checked on the noise-free runs). The noise
    floor is estimated within 20 % of the true noise, and the verdict is
    not "no_significant_gap"."""
    rig = load_rig(ROOT / "studies/campaigns/dc-motor/rig.toml")
    inputs = trapezoids(0.01)
    sigma_rel = 1e-3
    h = 1.3 * np.sqrt(12.0) * sigma_rel * 0.01
    clean = synth.synthesize("dc_motor", rig, inputs, hidden=_staircase(h), noise=synth.Noise(position=0.0))
    smooth = synth.synthesize("dc_motor", rig, inputs, noise=synth.Noise(position=0.0))
    ratio = [np.sqrt(np.mean((a["position_m"] - b["position_m"]) ** 2)) / (sigma_rel * np.ptp(a["position_m"]))
             for a, b in zip(clean, smooth)]
    assert np.mean(ratio) == pytest.approx(1.3, abs=0.1)
    runs = synth.synthesize("dc_motor", rig, inputs, hidden=_staircase(h), noise=synth.Noise(position=sigma_rel, seed=4))
    d = diagnose_runs("dc_motor", rig, runs, ["down"])
    assert d.noise_floor_holdout == pytest.approx(sigma_rel, rel=0.2)
    assert d.verdict["status"] != "no_significant_gap", d.verdict["reason"]
