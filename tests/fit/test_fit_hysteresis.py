"""Bouc-Wen and Prandtl-Ishlinskii estimators (sizing.fit) on data simulated
with the seed's Table 1 parameters (ARL-TR-10251, Table 1)."""
import warnings

import numpy as np
import pytest

from sizing.errors import FitError
from sizing.fit.bouc_wen import PARAM_NAMES, BoucWenEstimator, groups_to_params, params_to_groups
from sizing.fit.common import HysteresisRecord, count_reversals, padded_lowpass
from sizing.fit.prandtl_ishlinskii import PrandtlIshlinskiiEstimator
from sizing.physics import prandtl_ishlinskii as pi
from sizing.physics.bouc_wen import BoucWen, free_displacement

from ..conftest import SEED_BOUC_WEN

SEED = BoucWen(**SEED_BOUC_WEN)
TRUE = SEED.as_array()


def table1_runs(noise, rate, duration, seed, amplitudes=(50.0, 100.0, 150.0)):
    """Unipolar 1 Hz sines from rest (0 -> A -> 0), noise on the displacement
    as a fraction of the largest run's range."""
    rng = np.random.default_rng(seed)
    t = np.arange(0.0, duration, 1.0 / rate)
    clean = [(a, a / 2 * (1 - np.cos(2 * np.pi * t))) for a in amplitudes]
    xs = [free_displacement(t, v, SEED) for _, v in clean]
    span = max(np.ptp(x) for x in xs)
    return [HysteresisRecord(f"a{int(a)}", t, v, x + noise * span * rng.standard_normal(len(t)))
            for (a, v), x in zip(clean, xs)]


def fit_quiet(est, records):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return est.fit(records)


@pytest.fixture(scope="module")
def runs_03():
    # 3 runs x 3 s at 5 kHz (the real measurement's rate), noise 0.3 % of range
    return table1_runs(0.003, 5000, 3.0, seed=20251201)


def test_table1_recovered_within_5_percent(runs_03):
    est = fit_quiet(BoucWenEstimator(random_state=0), runs_03)
    err = est.params_.as_array() / TRUE - 1
    assert np.all(np.abs(err) < 0.05), dict(zip(PARAM_NAMES, err))
    assert est.success_
    # residual at the noise floor: 0.3 % of the largest run's range
    assert est.residual_rms_ == pytest.approx(0.003 * max(np.ptp(r.position) for r in runs_03), rel=0.05)


def test_confidence_intervals_cover_truth_at_1_percent_noise():
    # linearised 95 % intervals (Jacobian covariance); same design as above.
    # On shorter records (3 x 2.5 s at 2 kHz) 2 of 8 seeds put a parameter
    # of the beta-gamma-n ridge at 2.2-2.7 sigma: the intervals are somewhat
    # optimistic there (the model is strongly nonlinear along that ridge).
    est = fit_quiet(BoucWenEstimator(random_state=1), table1_runs(0.01, 5000, 3.0, seed=20251202))
    for name, true in zip(PARAM_NAMES, TRUE):
        lo, hi = est.ci95_[name]
        assert lo <= true <= hi, (name, lo, true, hi)


def test_noise_free_fit_is_exact_and_h0_free():
    # cross-check: no noise, no filter -> the simulator's own parameters back
    runs = table1_runs(0.0, 1000, 2.0, seed=0)
    est = fit_quiet(BoucWenEstimator(random_state=0, cutoff_hz=0), runs)
    np.testing.assert_allclose(est.params_.as_array(), TRUE, rtol=1e-4)
    assert max(abs(h) for h in est.h0_.values()) < 1e-9


def test_run_cut_mid_loop_gets_its_initial_state():
    t = np.arange(0.0, 3.0, 1 / 1000)
    v = 75 * (1 - np.cos(2 * np.pi * t))
    x = free_displacement(t, v, SEED)
    cut = slice(1300, None)                      # starts on the falling branch, h != 0
    rec = HysteresisRecord("cut", t[cut] - t[cut][0], v[cut], x[cut])
    full = [HysteresisRecord("full", t, v, x)]
    est = fit_quiet(BoucWenEstimator(random_state=0, cutoff_hz=0), full + [rec])
    h_true = x[1300] - SEED.d33 * v[1300]
    assert est.h0_["cut"] == pytest.approx(h_true, rel=1e-3)


def test_identifiability_warnings_and_groups_round_trip():
    H, V = 1.07e-4, 150.0
    np.testing.assert_allclose(groups_to_params(params_to_groups(TRUE, H, V), H, V), TRUE, rtol=1e-12)
    # one small run: parameters correlate strongly -> IdentifiabilityWarning
    runs = table1_runs(0.01, 500, 1.0, seed=3, amplitudes=(150.0,))
    with pytest.warns(UserWarning, match="correlated|confidence interval|bound"):
        BoucWenEstimator(random_state=0, n_starts=1).fit(runs)


@pytest.mark.parametrize("voltage, message", [
    (lambda t: np.full_like(t, 40.0), "constant input"),
    (lambda t: 150 * t / t[-1], "no reversal"),
])
def test_unsupported_data_raise_fit_error(voltage, message):
    t = np.linspace(0, 1, 200)
    rec = HysteresisRecord("bad", t, voltage(t), 1e-6 * np.sin(t), source="bad.csv")
    with pytest.raises(FitError, match=f"bad.csv.*{message}"):
        BoucWenEstimator().fit([rec])


def test_too_short_raises_fit_error():
    t = np.linspace(0, 1, 10)
    rec = HysteresisRecord("short", t, np.sin(6 * t), np.sin(6 * t), source="short.csv")
    with pytest.raises(FitError, match="short.csv: too short"):
        PrandtlIshlinskiiEstimator().fit([rec])


def test_filter_keeps_clean_excitation_and_removes_noise():
    t = np.arange(0, 2.5, 1 / 2000)
    v = 75 * (1 - np.cos(2 * np.pi * t))
    noisy = v + 0.5 * np.random.default_rng(0).standard_normal(len(t))
    assert np.max(np.abs(padded_lowpass(t, v, 20.0) - v)) < 2e-4 * 150
    filtered = padded_lowpass(t, noisy, 20.0)
    assert count_reversals(noisy, 0.0) > 100 and count_reversals(filtered, 0.0) == 4   # peaks at 0.5, 1.5 s, troughs at 1, 2 s


def test_play_operator_hand_values():
    # threshold 1: input 0 -> 2 -> 1.5 -> -1 gives 0, 1, 1, 0 (backlash of half-width 1)
    y = pi.play_operators(np.array([0.0, 2.0, 1.5, -1.0]), np.array([0.0, 1.0]), y0=np.zeros(2))
    np.testing.assert_allclose(y[:, 0], [0, 2, 1.5, -1])
    np.testing.assert_allclose(y[:, 1], [0, 1, 1, 0])


def test_prandtl_ishlinskii_weights_nonnegative_and_fit_good(runs_03):
    est = PrandtlIshlinskiiEstimator().fit(runs_03)
    assert np.all(est.weights_ >= 0) and est.weights_.sum() > 0
    assert est.success_
    # the symmetric PI model cannot follow the seed's non-symmetric loop
    # exactly; it stays within 5 % of the range on every run
    assert max(est.nrmse_.values()) < 0.05
    assert est.nrmse_["a150"] < 0.02


def test_a_vibration_the_model_lacks_is_named_and_a_clean_fit_is_not():
    """A 37 Hz vibration of 2 % of the range on the displacement of every
    run (a sensor mount the Bouc-Wen model cannot represent): the fit
    warns of a spectral line near 37 Hz; the same runs without it raise no
    such warning."""
    clean = table1_runs(0.002, 2000, 2.0, seed=7)
    span = max(np.ptp(r.position) for r in clean)
    shaken = [HysteresisRecord(r.name, r.time, r.voltage, r.position + 0.02 * span * np.sin(2 * np.pi * 37.0 * r.time))
              for r in clean]
    lines = [m for m in fit_quiet(BoucWenEstimator(random_state=0), shaken).warnings_ if "spectral line" in m]
    assert len(lines) == 1 and "at 37." in lines[0], lines
    assert not [m for m in fit_quiet(BoucWenEstimator(random_state=0), clean).warnings_ if "spectral line" in m]
