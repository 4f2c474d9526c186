"""Vibration: the additive-sinusoid form of
sensor_vibration (frequency from the residual spectrum, amplitude and
phase by linear least squares) and the spectral start of the mount form,
against hand-computed numbers."""
from __future__ import annotations

import numpy as np
import pytest

from sizing import spectrum
from sizing.diagnose.effects import library
from sizing.diagnose.effects.sensor_vibration import SINUSOID, mount_response


def _residual(seed=0, freq=37.3, amp=2e-5, phase=0.7, n=2000, fs=1000.0):
    """A smooth model-form error (a slow bump) + white noise + a sinusoid."""
    rng = np.random.default_rng(seed)
    t = np.arange(n) / fs
    smooth = 1e-4 * np.exp(-((t - 0.8) / 0.3) ** 2)
    e = smooth + 1e-5 * rng.normal(size=n) + amp * np.sin(2 * np.pi * freq * t + phase)
    return t, e


def test_sinusoid_recovered_from_a_synthetic_residual():
    """37.3 Hz, 20 um, 0.7 rad in 10 um white noise on top of a 100 um slow
    bump: the line is found from the spectrum (bins 0.5 Hz apart), refined
    to the frequency within 0.02 Hz, amplitude within 3 % and phase within
    0.05 rad (least squares: the standard error of the amplitude is
    sigma sqrt(2 / n) = 0.32 um, 1.6 %)."""
    t, e = _residual()
    found = spectrum.lines([(t, e)])
    assert found and abs(found[0][0] - 37.3) <= 0.5
    freq = spectrum.refine([(t, e)], found[0][0])
    assert freq == pytest.approx(37.3, abs=0.02)
    amp, phase, fit = spectrum.sinusoid(t, e, 37.3)
    assert amp == pytest.approx(2e-5, rel=0.03)
    assert phase == pytest.approx(0.7, abs=0.05)
    # by hand: a sinusoid alone is recovered exactly
    pure = 3.0 * np.sin(2 * np.pi * 5.0 * t - 1.2)
    a, p, _ = spectrum.sinusoid(t, pure, 5.0)
    assert a == pytest.approx(3.0, rel=1e-9) and p == pytest.approx(-1.2, abs=1e-9)


def test_no_line_in_a_smooth_residual_with_noise():
    """A slow bump and white noise: no bin 20 x above its local median."""
    rng = np.random.default_rng(3)
    t = np.arange(2000) / 1000.0
    for _ in range(5):
        e = 1e-4 * np.exp(-((t - 0.8) / 0.3) ** 2) + 1e-5 * rng.normal(size=t.size)
        assert spectrum.lines([(t, e)]) == []


def test_line_of_the_simulated_output_is_not_a_gap_line():
    """A periodic excitation (5 Hz) leaves its harmonics in the residual of
    a nominal of another form: those bins are not lines of the gap."""
    rng = np.random.default_rng(1)
    t = np.arange(2000) / 1000.0
    sim = np.sin(2 * np.pi * 5.0 * t)
    e = 0.01 * np.sin(2 * np.pi * 5.0 * t + 0.3) + 1e-4 * rng.normal(size=t.size)
    assert spectrum.lines([(t, e)]) and spectrum.lines([(t, e)], [sim]) == []


def test_sinusoid_form_fits_per_run_and_sits_in_the_dc_library():
    forms = [(e.name, e.form) for e in library("dc_motor")]
    assert ("sensor_vibration", "mount") in forms and ("sensor_vibration", "sinusoid") in forms
    t, e = _residual(freq=50.0, phase=-2.0)
    y = np.linspace(0, 1e-3, t.size)
    out = SINUSOID.fit_run(t, y, y + e, {"frequency_Hz": 50.0})
    amp, phase, _ = spectrum.sinusoid(t, out - y, 50.0)
    assert amp == pytest.approx(2e-5, rel=0.03) and phase == pytest.approx(-2.0, abs=0.05)


def test_mount_start_gain_by_least_squares():
    """The mount's ringing is proportional to its gain: the least-squares
    gain of a noiseless response is the true one."""
    t = np.arange(2000) / 1000.0
    y = 1e-3 * (t > 0.5)
    z = mount_response(t, y, 20.0, 0.02, 0.3)
    z1 = mount_response(t, y, 20.0, 0.02, 1.0)
    assert float(z @ z1 / (z1 @ z1)) == pytest.approx(0.3, rel=1e-9)


def test_white_noise_gives_no_line():
    """100 runs of white noise, 2000 samples each: no bin reaches
    LINE_FACTOR x its local median (README: the false-line rate)."""
    rng = np.random.default_rng(7)
    t = np.arange(2000) / 1000.0
    assert sum(bool(spectrum.lines([(t, rng.normal(size=t.size))])) for _ in range(100)) == 0


def test_line_rule_names_a_mount_inside_the_model_form_floor(tmp_path):
    """A 35 Hz mount of gain 0.15 on the second generator's DC rig (a gap
    within 1.5 x the model-form floor): the holdout gap has a line near
    35 Hz that the mount form removes, so sensor_vibration is named by the
    line rule."""
    from benchmarks.crossform import cases, dc
    from benchmarks.crossform.common import write_campaign
    from sizing import api

    rig, runs = dc.campaign({"mount": cases.find("dc-mount-b").effects["mount"]}, seed=17)
    d = api.diagnose(write_campaign(tmp_path / "c", rig, runs), ["stairs_b"])
    assert d.verdict["effect"] == "sensor_vibration"
    line = d.verdict["line"]
    assert any(abs(f - 35.0) < 1.0 for f in line["frequencies_Hz"]) and 0 < line["share"] <= 1
    assert line["removed"] > 0.75
