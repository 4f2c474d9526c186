"""Fitting that holds on real records by default (sensor offset and
initial state per run, input filter from the record, catalog prior,
identifiable combinations, model choice on the holdout, catalog entry,
cross-excitation)."""
import os
import shutil
import tomllib
import warnings

from pathlib import Path

import numpy as np
import pytest

from sizing import api
from sizing.fit.bouc_wen import BoucWenEstimator
from sizing.fit.common import HysteresisRecord, fit_cutoff
from sizing.fit.prandtl_ishlinskii import PrandtlIshlinskiiEstimator
from sizing.fit.prior import combinations
from sizing.physics.bouc_wen import BoucWen, free_displacement
from sizing.sim.signals import nrmse

from ..conftest import CATALOGS, run_cli

# a stack that is NOT the seed's Table 1 (the default prior), so a fit that
# only returned the prior would fail the 5 % check
TRUTH = BoucWen(d33=9.0e-7, alpha=-3.0e-7, beta=0.2, gamma=0.05, delta=-4.0e-8, n=1.2)
OFFSET = 3e-6           # sensor offset, m (about 3 % of the stroke)


def write_csv(path, t, v, x):
    rows = "\n".join(f"{a:.9g},{b:.9g},{c:.9g}" for a, b, c in zip(t, v, x))
    path.write_text("time_s,voltage_V,position_m\n" + rows + "\n")
    return path


def quiet(est, records):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return est.fit(records)


def test_fit_cutoff_follows_excitation_and_sample_rate():
    # hand values: 1 Hz sine at 5 kHz -> 20 x 1 Hz; the same sine at 40 Hz
    # sampling -> capped at a quarter of Nyquist, 0.25 x 20 Hz = 5 Hz; a
    # 0.5 Hz carrier with 8 Hz minor loops -> 3 x the 99 % band (>= 8 Hz)
    t = np.arange(0, 4, 1 / 5000)
    assert fit_cutoff(t, np.sin(2 * np.pi * t)) == pytest.approx(20.0, rel=0.02)
    # white noise of 10 % of the amplitude is floor, not excitation: unchanged
    noisy = np.sin(2 * np.pi * t) + 0.1 * np.random.default_rng(0).standard_normal(len(t))
    assert fit_cutoff(t, noisy) == pytest.approx(20.0, rel=0.02)
    t40 = np.arange(0, 4, 1 / 40)
    assert fit_cutoff(t40, np.sin(2 * np.pi * t40)) == pytest.approx(5.0)
    t200 = np.arange(0, 8, 1 / 200)
    v = np.sin(np.pi * t200) + 0.3 * np.sin(2 * np.pi * 8 * t200)
    assert 24.0 <= fit_cutoff(t200, v) <= 25.0


@pytest.fixture(scope="module")
def offset_runs(tmp_path_factory):
    """Three amplitudes at three sample rates for training and a fourth held
    out, each with a sensor offset and cut from a longer record so it starts
    mid-loop (h != 0). Three cycles each: two amplitudes of two cycles leave
    beta, gamma and delta 5-13 % off at this noise (tried, seeds 12-13)."""
    folder = tmp_path_factory.mktemp("offset")
    rng = np.random.default_rng(12)
    paths, starts = [], {}
    for a, rate in ((50.0, 500), (100.0, 400), (150.0, 250), (120.0, 300)):
        t = np.arange(0.0, 3.6, 1 / rate)
        v = a / 2 * (1 - np.cos(2 * np.pi * t))
        x = free_displacement(t, v, TRUTH)
        cut = int(0.6 * rate)                      # 0.6 s: on the falling branch
        starts[f"a{int(a)}"] = x[cut] - TRUTH.d33 * v[cut]
        noisy = x + OFFSET + 1e-3 * np.ptp(x) * rng.standard_normal(len(t))
        paths.append(write_csv(folder / f"a{int(a)}.csv", t[cut:], v[cut:], noisy[cut:]))
    return paths, starts


@pytest.fixture(scope="module")
def default_fit(offset_runs, tmp_path_factory):
    paths, _ = offset_runs
    # the default command, plus a catalog entry (written to the working
    # folder without --out); no HTML, the slow part
    here = os.getcwd()
    os.chdir(tmp_path_factory.mktemp("out"))
    try:
        result = dict(api.fit_hysteresis(paths, holdout=["a120"], catalog_entry="fitted-stack"))
        result["cwd"] = Path(os.getcwd())
        return result
    finally:
        os.chdir(here)


def test_default_command_recovers_parameters_offsets_and_states(default_fit, offset_runs):
    result = default_fit
    _, starts = offset_runs
    data = tomllib.loads(result["toml"])
    stack = {"d33": data["stack"]["d33"], **data["stack"]["bouc_wen"]}
    err = {k: stack[k] / getattr(TRUTH, k) - 1 for k in stack}
    assert all(abs(e) < 0.05 for e in err.values()), str(err)
    fit = data["fit"]
    assert "fitted per run" in fit["sensor_offset"] and "fitted per run" in fit["initial_state_note"]
    for name in starts:              # training and holdout runs: offset and h0 as simulated
        assert fit["initial_state"]["offset_m"][name] == pytest.approx(OFFSET, rel=0.01)
        assert fit["initial_state"]["h0_m"][name] == pytest.approx(starts[name], rel=0.02)
    # the data determine every group: the prior's share stays small
    assert max(fit["prior"]["prior_share"].values()) < 0.2 and fit["prior"]["from_prior"] == []
    # d33 + alpha, hand value 9e-7 - 3e-7 = 6e-7 m/V
    slope = fit["combinations"]["small_signal_slope_m_V"]
    assert slope["ci95"][0] < 6e-7 < slope["ci95"][1] and slope["value"] == pytest.approx(6e-7, rel=0.01)
    choice = fit["model_choice"]
    assert fit["model"] == choice["winner"] == "bouc-wen"    # data from eq. 2 itself
    assert choice["margin"] == pytest.approx(choice["prandtl_ishlinskii"] - choice["bouc_wen"], rel=1e-4)
    assert fit["nrmse_holdout"] < 0.01


def test_catalog_entry_validates_and_adds(default_fit, tmp_path):
    result = default_fit
    [entry_path] = [p for p in result["written"] if p.endswith("fitted-stack.toml")]
    entry_path = result["cwd"] / entry_path if not os.path.isabs(entry_path) else entry_path
    entry = tomllib.loads(open(entry_path).read())["stack"][0]
    assert entry["status"]["bouc_wen"].startswith("measured")
    assert entry["bouc_wen"]["d33"] == pytest.approx(TRUTH.d33, rel=0.05)
    # appended to a copy of the shipped catalog, `sizing catalog validate` accepts it
    catalog = tmp_path / "catalogs"
    shutil.copytree(CATALOGS, catalog)
    with open(catalog / "stacks.toml", "a") as f:
        f.write("\n" + open(entry_path).read())
    code, stdout, stderr = run_cli("catalog", "validate", catalog)
    assert code == 0, stderr
    code, stdout, _ = run_cli("catalog", "show", "fitted-stack", "--catalog", catalog)
    assert code == 0 and "measured" in stdout
    # the CSV sheet beside it goes through `sizing catalog add` unchanged
    [sheet] = [result["cwd"] / p for p in result["written"] if p.endswith("fitted-stack.csv")]
    fresh = tmp_path / "fresh"
    shutil.copytree(CATALOGS, fresh)
    code, stdout, stderr = run_cli("catalog", "add", "stack", sheet, "--catalog", fresh)
    assert code == 0 and "fitted-stack" in stdout, stderr
    code, stdout, _ = run_cli("catalog", "show", "fitted-stack", "--catalog", fresh)
    assert code == 0 and "measured" in stdout


def test_two_amplitudes_separate_d33_and_alpha_and_the_prior_fills_what_one_leaves_free():
    # n = 2: at 20 V the |h|^n term is ~3 % of alpha, so the small loop is
    # almost linear and fixes only d33 + alpha; 150 V bends it and separates them
    truth = BoucWen(d33=8.0e-7, alpha=-2.0e-7, beta=300.0, gamma=150.0, delta=-3e-8, n=2.0)
    prior = BoucWen(d33=1.0e-6, alpha=-3.0e-7, beta=250.0, gamma=120.0, delta=-3e-8, n=2.0)   # a "datasheet" guess
    t = np.arange(0, 2.0, 1 / 500)
    rng = np.random.default_rng(4)

    def run(a):
        v = a / 2 * (1 - np.cos(2 * np.pi * t))
        x = free_displacement(t, v, truth)
        return HysteresisRecord(f"a{a}", t[130:], v[130:], (x + 2e-6 + 3e-3 * np.ptp(x) * rng.standard_normal(len(t)))[130:])

    small, large = run(20), run(150)
    one = quiet(BoucWenEstimator(prior=prior.as_array()), [small])
    half = {k: (hi - lo) / 2 / abs(getattr(truth, k)) for k, (lo, hi) in one.ci95_.items()}
    assert abs(one.corr_[0, 1]) > 0.999 and half["d33"] > 0.2 and half["alpha"] > 0.5
    combo = combinations(one.params_.as_array(), one.cov_)["small_signal_slope_m_V"]
    assert combo["value"] == pytest.approx(6.0e-7, rel=0.01) and combo["relative_half_width"] < 0.01
    # the plain fit runs off along the free directions (n at its bound);
    # the regularised one keeps d33 + alpha and stays within 3 prior sigma
    assert any(one.at_bound_.values())
    reg = one.regularised_
    assert reg.params.d33 + reg.params.alpha == pytest.approx(6.0e-7, rel=0.01)
    sd = 0.5 * np.maximum(np.abs(prior.as_array()), 1e-300)
    assert np.all(np.abs(reg.params.as_array() - prior.as_array()) < 3 * sd)
    assert max(reg.prior_share) > 0.5 and reg.nrmse["a20"] < 1.1 * one.nrmse_["a20"]
    two = quiet(BoucWenEstimator(), [small, large])
    for k in ("d33", "alpha"):
        assert getattr(two.params_, k) == pytest.approx(getattr(truth, k), rel=0.05)
        lo, hi = two.ci95_[k]
        assert (hi - lo) / 2 < 0.05 * abs(getattr(truth, k))


def duhem(v, a=0.03, c1=6e-7, c2=-5e-10, g=3.5e-7):
    """Coleman-Hodgdon (Duhem) hysteresis, written here and outside both
    fitted families: dx = a |dv| (f(v) - x) + g dv with a curved anhysteretic
    f(v) = c1 v + c2 v^2 (Coleman and Hodgdon 1986; Jiles-Atherton-like)."""
    x = np.zeros_like(v)
    for k in range(len(v) - 1):
        dv = v[k + 1] - v[k]
        x[k + 1] = x[k] + a * abs(dv) * (c1 * v[k] + c2 * v[k] ** 2 - x[k]) + g * dv
    return x


def test_cross_excitation_on_a_model_outside_both_families():
    # fit a full 0-150 V sine, judge a decaying carrier with 3 Hz minor loops
    rng = np.random.default_rng(5)
    t1, t2 = np.arange(0, 3.0, 1 / 500), np.arange(0, 4.0, 1 / 500)
    v1 = 75 * (1 - np.cos(2 * np.pi * t1))
    v2 = 70 + 55 * np.exp(-t2 / 3) * np.sin(2 * np.pi * 0.75 * t2 - np.pi / 2) + 20 * np.sin(2 * np.pi * 3 * t2)
    v2 -= v2[0]
    x1, x2 = duhem(v1), duhem(v2)
    fit_on = HysteresisRecord("sine", t1, v1, x1 + 1e-6 + 1e-3 * np.ptp(x1) * rng.standard_normal(len(t1)))
    judge = HysteresisRecord("minor", t2, v2, x2 - 2e-6 + 1e-3 * np.ptp(x2) * rng.standard_normal(len(t2)))
    scores = {}
    for name, est in (("bouc-wen", BoucWenEstimator(n_starts=2)), ("pi", PrandtlIshlinskiiEstimator())):
        quiet(est, [fit_on])
        scores[name] = (nrmse(fit_on.position, est.predict(fit_on)), nrmse(judge.position, est.predict(judge)))
    # the aim: one model within 1 % on both (Bouc-Wen here;
    # measured 0.58 % / 0.65 %); Prandtl-Ishlinskii fits the sine as well
    # but misses the minor loops (~1.9 %)
    assert max(scores["bouc-wen"]) < 0.01, scores
    assert scores["pi"][0] < 0.01 and scores["pi"][1] > scores["bouc-wen"][1], scores


def test_record_shorter_than_one_reversal_exits_2_in_a_joint_fit(offset_runs, tmp_path):
    paths, _ = offset_runs
    t = np.arange(0, 0.3, 1 / 500)
    short = write_csv(tmp_path / "ramp-up.csv", t, 100 * t, 1e-6 * t)
    code, stdout, stderr = run_cli("fit", "hysteresis", paths[0], short, "--out", tmp_path / "x.toml")
    assert code == 2 and stdout == ""
    lines = stderr.strip().splitlines()
    assert len(lines) == 1 and "ramp-up.csv" in lines[0] and "shorter than one reversal" in lines[0]
    assert not (tmp_path / "x.toml").exists()
    # held out, it is refused as well: its initial state could not be told from its offset
    code, _, stderr = run_cli("fit", "hysteresis", paths[0], short, "--holdout", "ramp-up")
    assert code == 2 and "ramp-up.csv" in stderr and "shorter than one reversal" in stderr


def test_prior_transfer_hand_values():
    # Table 1 (100 um at 150 V) carried to 50 um over 150 V: d = H/V halves,
    # so d33 and alpha halve; beta H^n / d is kept, so beta' = beta x 0.5 /
    # 0.5^1.14 = 0.134 x 0.5^-0.14 = 0.134 x 1.10190 = 0.147655 (hand)
    from sizing.fit.prior import transfer_prior
    seed = BoucWen(d33=8.15e-7, alpha=-2.23e-7, beta=0.134, gamma=0.0755, delta=-5.46e-8, n=1.14)
    p = transfer_prior(seed, 100e-6, 150.0, 50e-6, 150.0)
    np.testing.assert_allclose(p, [4.075e-7, -1.115e-7, 0.147655, 0.0755 * 1.10190, -2.73e-8, 1.14], rtol=1e-4)


def test_prandtl_ishlinskii_initial_state_is_fitted():
    # PI data whose operators remember a trip to 150 V before the record
    # starts at 60 V rising: y_r(0) = clip(150, 60 - r, 60 + r) = 60 + r for
    # every threshold (r <= 37.5 V here). The steady-state guess assumes the
    # input came from the record's own minimum (20 V) and misses the first cycle.
    from sizing.physics import prandtl_ishlinskii as pi
    t = np.arange(0, 2.0, 1 / 500)
    v = 60 + 40 * np.sin(2 * np.pi * t)
    r = np.arange(16) * 0.5 * np.ptp(v) / 16
    w = 1e-7 * np.exp(-r / 20)
    x = pi.displacement(v, r, w, y0=np.clip(150.0, v[0] - r, v[0] + r))
    x = x + 2e-6 + 1e-3 * np.ptp(x) * np.random.default_rng(6).standard_normal(len(t))
    rec = [HysteresisRecord("mid", t, v, x)]
    fitted = PrandtlIshlinskiiEstimator(cutoff_hz=0).fit(rec)
    guessed = PrandtlIshlinskiiEstimator(cutoff_hz=0, fit_state=False).fit(rec)
    assert fitted.nrmse_["mid"] < 0.0015 and guessed.nrmse_["mid"] > 3 * fitted.nrmse_["mid"]
    assert fitted.memory_["mid"] >= 60 + r[-1] and fitted.offset_["mid"] == pytest.approx(2e-6, rel=0.05)
    # single weights trade off with their neighbours under noise; their sum
    # (the slope after a reversal larger than every threshold) does not
    assert fitted.weights_.sum() == pytest.approx(w.sum(), rel=0.01)


@pytest.mark.parametrize("option, value, message", [
    ("--catalog-entry", "Bad Id", "lower case"),
    ("--catalog-entry", "pi-p-056.90", "already in the catalog"),
    ("--prior-stack", "no-such-stack", "no stack 'no-such-stack'"),
    ("--prior-sigma", "0", "positive"),
])
def test_bad_fit_options_exit_2_before_fitting(offset_runs, tmp_path, option, value, message):
    paths, _ = offset_runs
    code, stdout, stderr = run_cli("fit", "hysteresis", *paths[:2], option, value, "--out", tmp_path / "x.toml")
    lines = stderr.strip().splitlines()
    assert code == 2 and stdout == "" and len(lines) == 1 and option in lines[0] and message in lines[0], stderr
    assert not list(tmp_path.iterdir())
