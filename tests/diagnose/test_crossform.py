"""Diagnosis on campaigns from the second, independent generator
(benchmarks/crossform: RK4 on its own state forms, LuGre friction, a
mis-stated nominal, white + 1/f + quantisation noise), judged on every
logged channel; bad input. A few short DC campaigns (the full cross-form
set is the benchmark, not a test)."""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from sizing import api
from sizing.errors import InputError

from benchmarks.crossform import cases, dc
from benchmarks.crossform.common import write_campaign

from ..conftest import run_cli

ROOT = Path(__file__).resolve().parents[2]


def _campaign(tmp_path, effects, seed, **options):
    rig, runs = dc.campaign(effects, seed, **options)
    return write_campaign(tmp_path / "c", rig, runs)


@pytest.mark.slow
def test_lugre_friction_in_a_stiff_loop_is_named_from_the_current(tmp_path):
    """LuGre friction with a Stribeck rise (a form the library does not use:
    it holds Karnopp-Coulomb) under a stiff position loop that logs its
    current: the diagnosis names coulomb_friction, and the current channel
    shrinks more than the position does (the loop hides friction in the
    position)."""
    folder = _campaign(tmp_path, {"friction": cases.find("dc-lugre-b").effects["friction"]}, seed=7)
    d = api.diagnose(folder, ["stairs_b"], tmp_path / "out")
    assert d.bench.channels == ("position_m", "current_A")
    assert d.verdict["effect"] == "coulomb_friction"
    assert d.verdict["status"] in ("explained", "partial")
    c = d.to_json()["candidates"][0]
    assert set(c["shrink_holdout_channels"]) == {"position_m", "current_A"}
    assert c["shrink_holdout_channels"]["current_A"] > 0.3
    data = json.loads((tmp_path / "out" / "diagnosis.json").read_text())
    assert data["verdict"]["status"] == d.verdict["status"] and data["verdict"]["remaining"]
    assert {w["channel"] for w in data["where"]} == {"position_m", "current_A"}
    page = (tmp_path / "out" / "diagnosis.html").read_text()
    assert "current, A" in page and "Separation test" in page and "Runner-up" in page


@pytest.mark.slow
def test_null_campaign_from_the_second_generator_names_nothing(tmp_path):
    folder = _campaign(tmp_path, {}, seed=11)
    d = api.diagnose(folder, ["stairs_b"])
    assert d.verdict["effect"] is None
    assert d.verdict["status"] in ("no_significant_gap", "unexplained", "undetectable")


@pytest.mark.slow
def test_outside_effect_is_not_explained(tmp_path):
    """Cogging (a force ripple with the motor angle) is not in the library:
    no library effect is named for it, neither explained nor partial."""
    folder = _campaign(tmp_path, {"cogging": dict(amp_N=40.0, pitch_m=2e-3 / 6)}, seed=13)
    d = api.diagnose(folder, ["stairs_b"])
    assert d.verdict["effect"] is None, d.verdict["reason"]
    assert d.verdict["status"] in ("no_significant_gap", "unexplained", "undetectable")


def test_pade_delay_by_hand():
    # a second-order Pade of a 10 ms delay passes a slow ramp late by 10 ms
    # (its group delay at low frequency is tau)
    from benchmarks.crossform.common import pade_delay
    t = np.arange(0.0, 1.0, 1e-3)
    y = np.where(t > 0.1, t - 0.1, 0.0)
    out = pade_delay(t, y, 0.01)
    np.testing.assert_allclose(out[500:], y[500:] - 0.01, atol=1e-6)


def _write_runs(folder: Path, kind_rig: Path, columns: dict):
    folder.mkdir(parents=True)
    (folder / "rig.toml").write_text(kind_rig.read_text())
    (folder / "runs").mkdir()
    for name in ("a", "b"):
        keys = list(columns)
        rows = [",".join(keys)] + [",".join(str(columns[k][i]) for k in keys) for i in range(len(columns["time_s"]))]
        (folder / "runs" / f"{name}.csv").write_text("\n".join(rows) + "\n")


@pytest.mark.parametrize("rig,columns,match", [
    ("piezo-prototype", {"time_s": np.arange(2000) / 1e3, "voltage_V": np.zeros(2000),
                         "position_m": np.zeros(2000), "current_A": np.zeros(2000)}, "current_A: a current channel"),
    ("piezo-prototype", {"time_s": np.arange(300) / 1e3, "voltage_V": np.linspace(0, 100, 300),
                         "position_m": np.linspace(0, 1e-3, 300)}, "time_s: the run lasts"),
    ("dc-motor", {"time_s": np.arange(2000) / 1e3, "reference_m": np.zeros(2000),
                  "position_m": np.zeros(2000), "current_A": np.r_[np.zeros(1000), np.nan, np.zeros(999)]},
     "column current_A"),
])
def test_bad_input_exits_2_with_one_line(tmp_path, rig, columns, match):
    folder = tmp_path / "bad"
    _write_runs(folder, ROOT / "studies/campaigns" / rig / "rig.toml", columns)
    with pytest.raises(InputError, match=match):
        api.diagnose(folder, ["b"])
    code, _, err = run_cli("diagnose", folder, "--holdout", "b", "--out", tmp_path / "out")
    assert code == 2
    assert len(err.strip().splitlines()) == 1 and match.split(":")[0] in err
    assert not (tmp_path / "out").exists()


@pytest.mark.slow
def test_drive_current_limit_is_named_with_its_form(tmp_path):
    """A drive that limits the actual current to 4.5 A behind the
    controller's back (the logged command is not clipped, the loop winds up):
    current_saturation in its ``drive`` form, the limit found within 10 %."""
    folder = _campaign(tmp_path, {"current_limit": 4.5}, seed=23)
    d = api.diagnose(folder, ["stairs_b"])
    assert d.verdict["effect"] == "current_saturation" and d.verdict["form"] == "drive"
    assert d.verdict["status"] == "explained"
    best = d.fits[0]
    assert best.params["current_limit_A"] == pytest.approx(4.5, rel=0.1)


@pytest.mark.slow
def test_lugre_seal_from_the_second_generator_is_named_as_seal_stick_slip(tmp_path):
    """Acceptance (piezo): the second generator's output seal is
    LuGre with a Stribeck rise (3 N running, 6 N breakaway, 1 mm/s, 10 um
    presliding), its own RK4 with the oil pressure as a state, a mis-stated
    nominal, white + 1/f + quantisation noise, a seed other than the
    benchmark's. The diagnosis names seal_stick_slip. With this seed the
    pair test may keep stack_creep next to it (the pair is significantly better than the seal alone: the
    creep takes up part of the model-form difference of the hysteresis), so
    the name is checked as a member of the verdict, not as the whole of it;
    on the benchmark's own seed (pz-seal-b) the seal alone is named.
    Since the voltage is read piecewise linear (its noise floor fell from
    0.55 % to 0.32 % of the span here) this seed's seal is named but
    ``partial``: the library's seal leaves 0.85 %, 2.6 x the floor, the
    stick-slip phase difference between the two simulators' seals (see the
    README's misses), and the Karnopp form ranks above the LuGre one; the
    dev set's two seal cases are ``explained``."""
    from benchmarks.crossform import piezo
    rig, runs = piezo.campaign({"seal": cases.find("pz-seal-b").effects["seal"]}, seed=17)
    folder = write_campaign(tmp_path / "c", rig, runs)
    d = api.diagnose(folder, ["stairs_b"])
    assert d.verdict["status"] in ("explained", "partial"), d.verdict["reason"]
    assert "seal_stick_slip" in d.verdict["effect"].split("+")


@pytest.mark.slow
def test_a_small_backlash_behind_a_large_delay_is_named_as_the_pair(tmp_path):
    """A 10 ms Pade delay that alone removes nearly all of the gap above the
    model-form floor, and a 0.2 mm backlash with contact stiffness behind it
    (the loop closed on the motor): the delay alone still leaves several
    times the noise floor, so pairs are tried and the pair is named, each
    size within 20 % of the generator's."""
    folder = _campaign(tmp_path, {"delay_s": 0.010, "backlash": dict(gap_m=2e-4, k_N_m=3e6, zeta=0.25, m_kg=1.0,
                                                                      c_ground=300.0)}, seed=29)
    d = api.diagnose(folder, ["stairs_b"])
    assert set(d.verdict["effect"].split("+")) == {"sensor_delay", "backlash"}, d.verdict["reason"]
    params = d.fits[0].params
    assert params["sensor_delay.delay_s"] == pytest.approx(0.010, rel=0.2)
    assert params["backlash.backlash_m"] == pytest.approx(2e-4, rel=0.2)


@pytest.mark.slow
def test_a_seal_masked_by_a_large_delay_is_named_with_it(tmp_path):
    """A 12 ms Pade delay over a LuGre output seal (2 N running, 3.3 N
    breakaway) on four stacks. Against the nominal the delay screens first
    and the seal below the top three families, so the pairs of the top
    families never held it (the fourth held-out set's pz-h4-seal+pade: the
    delay alone, partial). Screened again with the delay held at its fit,
    the seal ranks first and the pair is named."""
    from benchmarks.crossform import piezo
    rig, runs = piezo.campaign({"seal": dict(fc=2.0, fs=3.3, vs=2.6e-3, sigma2=0.0), "delay_s": 0.012}, seed=31,
                               n_stacks=4)
    folder = write_campaign(tmp_path / "c", rig, runs)
    d = api.diagnose(folder, ["stairs_b"])
    assert set(d.verdict["effect"].split("+")) == {"seal_stick_slip", "sensor_delay"}, d.verdict["reason"]
    assert d.verdict["status"] in ("explained", "partial")
    assert d.fits[0].params["sensor_delay.delay_s"] == pytest.approx(0.012, rel=0.2)


@pytest.mark.slow
def test_an_output_lag_is_not_taken_for_an_amplifier_bandwidth(tmp_path):
    """Viscous damping of 180 N s/m on the output of a 3.5 in rig: a
    first-order lag of c R^2 / (n k_s), about 20 ms. An amplifier
    bandwidth of 7 Hz fitted it as well (pz-h3-viscous named the
    amplifier); no piezo amplifier is that slow on small signals into
    these stacks (amplifier_slew_limit's docstring), so the bandwidth is
    bounded at 20 Hz and the lag is the output's."""
    from benchmarks.crossform import piezo
    from sizing.diagnose.effects.amplifier_slew_limit import BANDWIDTH
    assert BANDWIDTH.params[1].lo == pytest.approx(2 * np.pi * 20.0)
    rig, runs = piezo.campaign({"viscous": 180.0}, seed=37, wide_in=3.5)
    folder = write_campaign(tmp_path / "c", rig, runs)
    d = api.diagnose(folder, ["stairs_b"])
    assert d.verdict["effect"] == "viscous_damping", d.verdict["reason"]
    assert d.verdict["status"] in ("explained", "partial")


@pytest.mark.slow
def test_a_mount_behind_friction_is_paired_in_the_form_that_rings(tmp_path):
    """LuGre friction (40 N) with a 27 Hz sensor mount on an 8.5 mm stroke:
    friction alone removes about 95 % of the gap, and the mount leaves a
    line in what remains. The top families' pair held the mount family in
    its sinusoid form, which does not ring after a step and removed almost
    nothing; the forward step now also screens the mount form given the
    friction, and that pair is named."""
    folder = _campaign(tmp_path, {"friction": dict(fc=40.0, fs=58.0, vs=0.0032, sigma0=3.2e6, sigma1=2.1e3,
                                                   sigma2=220.0),
                                  "mount": dict(f_Hz=27.0, zeta=0.028, gain=0.21)}, seed=41, stroke=0.0085,
                       misstate=0.02)
    d = api.diagnose(folder, ["stairs_b"])
    assert set(d.verdict["effect"].split("+")) == {"coulomb_friction", "sensor_vibration"}, d.verdict["reason"]
    assert d.verdict["form"].split("+")[d.verdict["effect"].split("+").index("sensor_vibration")] == "mount"
    params = d.fits[0].params
    assert params["sensor_vibration.frequency_Hz"] == pytest.approx(27.0, rel=0.05)


@pytest.mark.slow
def test_a_small_backlash_in_a_stiff_loop_is_named_when_it_leaves_only_the_noise(tmp_path):
    """A 0.14 mm backlash with 6.5 MN/m contact on a 17.8 mm stroke: a gap
    of about 3 x the 0.08 % noise floor, inside 1.5 x the model-form floor
    (0.2 %, an allowance for what a nominal of another form leaves). The
    backlash leaves the holdout at the noise floor and is separated from
    every other explanation, so nothing of that allowance is needed on
    this campaign and it is named (in each of the four held-out sets that
    held one it was refused as "within the model-form floor")."""
    folder = _campaign(tmp_path, {"backlash": dict(gap_m=1.4e-4, k_N_m=6.5e6, zeta=0.19, m_kg=0.75,
                                                   c_ground=230.0)}, seed=47, stroke=0.0178)
    d = api.diagnose(folder, ["stairs_b"])
    assert d.verdict["effect"] == "backlash" and d.verdict["status"] == "explained", d.verdict["reason"]
    assert d.verdict["judged_on_noise_floor"]
    assert d.baseline_holdout < 1.5 * np.hypot(d.noise_floor_holdout, 0.002)    # inside the band


@pytest.mark.slow
def test_a_current_limit_behind_a_delay_is_found_by_a_screen_fine_enough_for_its_valley(tmp_path):
    """A 4.5 A drive current limit and a 6.5 ms Pade delay on an 11.2 mm
    stroke (the seventh held-out set's dc-h7-ilimit+pade, its seed). With
    the delay unmodelled, the single current limit's training cost has a
    narrow valley (0.035 at 3 A, 0.0195 at 4 A, 0.024 at 5 A, stated c1, c2)
    that ten Latin-hypercube points over 0.05-20 A (a factor 1.8 apart)
    missed; the screen kept an inactive limit with c2 re-calibrated to its
    bound, every fit followed, and nothing was named with a gap 23 x the
    noise. At least ``min_screen`` points per effect find the valley and the
    pair is named."""
    case = cases.find("dc-h7-ilimit+pade")
    rig, runs, holdout = cases.generate(case)
    folder = write_campaign(tmp_path / "c", rig, runs)
    d = api.diagnose(folder, [holdout])
    named = set((d.verdict["effect"] or "").split("+"))
    assert named == {"current_saturation", "sensor_delay"}, d.verdict["reason"]
    params = d.fits[0].params
    assert params["current_saturation.current_limit_A"] == pytest.approx(4.5, rel=0.1)
    assert params["sensor_delay.delay_s"] == pytest.approx(0.0065, rel=0.15)


@pytest.mark.slow
def test_a_ringing_mount_at_the_noise_is_named_from_its_spectral_line(tmp_path):
    """A 38 Hz sensor mount with 1.8 % damping and gain 0.17 (the fifth
    held-out set's dc-h5-mount-high, its seed): it rings for a few cycles
    after each step, so its broadband gap is within 1.5 x the noise floor
    and the campaign was judged "no significant gap". Its holdout gap has
    a line at 38 Hz far above the local level (LINE_FACTOR), which the
    fitted mount removes: named from the line, at the true frequency."""
    case = cases.find("dc-h5-mount-high")
    rig, runs, holdout = cases.generate(case)
    d = api.diagnose(write_campaign(tmp_path / "c", rig, runs), [holdout])
    assert d.baseline_holdout <= 1.5 * d.noise_floor_holdout              # at the noise, broadband
    assert d.verdict["effect"] == "sensor_vibration" and d.verdict["status"] == "explained", d.verdict["reason"]
    assert d.verdict["line"]["judged_on"] and d.verdict["line"]["removed"] >= 0.75
    assert d.verdict["line"]["frequencies_Hz"][0] == pytest.approx(38.0, rel=0.02)
    mount = next(f for f in d.fits if f.name == "sensor_vibration")
    assert mount.params["frequency_Hz"] == pytest.approx(38.0, rel=0.02)


@pytest.mark.slow
def test_a_mount_behind_a_backlash_is_paired_from_the_line_the_backlash_leaves(tmp_path):
    """A 0.17 mm backlash and a 36 Hz sensor mount with 2 % damping (the
    ninth set's dc-h9-backlash+mount, its seed). Backlash alone removes all of the
    broadband gap above the floor and leaves 1.5 x the noise, so no pair
    was tried and backlash alone was named; but it leaves the mount's
    line, of which it removes 14 %. Pairs are tried when the best single
    leaves a line, and backlash + mount removes most of it."""
    case = cases.find("dc-h9-backlash+mount")
    rig, runs, holdout = cases.generate(case)
    d = api.diagnose(write_campaign(tmp_path / "c", rig, runs), [holdout])
    assert set((d.verdict["effect"] or "").split("+")) == {"backlash", "sensor_vibration"}, d.verdict["reason"]
    assert d.verdict["status"] == "explained"
    assert d.fits[0].params["sensor_vibration.frequency_Hz"] == pytest.approx(case.effects["mount"]["f_Hz"], rel=0.05)
