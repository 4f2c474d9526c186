"""Each logged channel judged on its own floors (judge.channel_verdict,
floor.form_floor)."""
from __future__ import annotations

import numpy as np
import pytest

from sizing import api
from sizing.diagnose import judge
from sizing.diagnose.bench import timing_band
from sizing.diagnose.fitting import EffectFit
from sizing.diagnose.floor import form_floor
from benchmarks.crossform import dc
from benchmarks.crossform.common import write_campaign
from sizing.diagnose.settings import DEFAULT


class _Bench:
    """The few Bench methods form_floor uses, on given nominal channels."""

    def __init__(self, S, measured, channels=("position_m",)):
        self.S, self.M, self.channels, self.holdout = S, measured, channels, [0]

    def nominal_channels(self):
        return [self.S]

    def spans(self, i):
        return np.ptp(self.M, axis=1)

    def gap(self, i, S):
        G = self.M - S
        if len(self.channels) > 1:
            G[..., 1, :] = timing_band(self.M[1], S[..., 1, :])
        return G


def test_form_floor_of_a_ramp_is_half_a_sample_of_its_slope():
    """A nominal ramping at s per sample: half a sample later it is s/2
    lower everywhere but the first sample, so the floor is s/2 over the
    span, times sqrt((n-1)/n) (hand-computed)."""
    n, s = 1000, 2e-6
    y = s * np.arange(n, dtype=float)
    bench = _Bench(y[None], y[None])
    expected = 0.5 * s / np.ptp(y) * np.sqrt((n - 1) / n)
    assert form_floor(bench)[0] == pytest.approx(expected, rel=1e-9)


def test_form_floor_of_a_held_output_is_zero_and_a_current_jump_is_within_its_band():
    """A nominal at rest leaves no timing floor; a current that jumps once is
    within the current's one-sample band (bench.timing_band) half a sample
    later, so its floor is zero too."""
    n = 200
    pos = np.full(n, 1e-3)
    cur = np.where(np.arange(n) < 100, 0.0, 2.0)
    measured = np.vstack([pos + np.linspace(0, 1e-6, n), cur])
    bench = _Bench(np.vstack([pos, cur]), measured, ("position_m", "current_A"))
    assert form_floor(bench) == pytest.approx([0.0, 0.0], abs=1e-15)


def _fit(name, channels, blocks):
    f = EffectFit((type("E", (), {"name": name, "form": "default", "extra": {}, "params": ()})(),), np.zeros(0), 0.01)
    f.nrmse_holdout = float(np.mean(list(channels.values())))
    f.nrmse_channels = channels
    f.channel_blocks = blocks
    f.residual_blocks = blocks["current_A"]
    return f


def _channels(current_baseline):
    rng = np.random.default_rng(0)
    return {"position_m": {"baseline": 5e-5, "noise": 4e-5, "form": 0.002, "blocks": rng.uniform(0.9, 1.1, 40)},
            "current_A": {"baseline": current_baseline, "noise": 0.002, "form": 0.001,
                          "blocks": np.full(40, 100.0) + rng.uniform(0, 1, 40)}}


def test_channel_rule_names_an_effect_that_explains_the_current_alone():
    """Position within its floors (5e-5 against 4e-5 noise and a 0.002
    model-form floor), current 0.02 against a floor of hypot(0.002, 0.001):
    a candidate leaving 0.003 on the current removes
    1 - (0.003^2 - 0.002236^2) / (0.02^2 - 0.002236^2) = 99 % of its gap
    energy above the floor and is named from the current."""
    rng = np.random.default_rng(1)
    friction = _fit("coulomb_friction", {"position_m": 5e-5, "current_A": 0.003},
                    {"position_m": rng.uniform(0.9, 1.1, 40), "current_A": np.full(40, 2.0) + rng.uniform(0, 1, 40)})
    other = _fit("backlash", {"position_m": 4.8e-5, "current_A": 0.019},
                 {"position_m": rng.uniform(0.9, 1.1, 40), "current_A": np.full(40, 90.0) + rng.uniform(0, 1, 40)})
    out = judge.channel_verdict([other, friction], _channels(0.02))
    assert out["effect"] == "coulomb_friction" and out["judged_on_channel"] == "current_A"
    floor = np.hypot(0.002, 0.001)
    assert out["explained_gap_energy"] == pytest.approx(1 - (0.003 ** 2 - floor ** 2) / (0.02 ** 2 - floor ** 2))
    # the same current gap within ``gap_factor`` x that channel's floor: nothing named from it
    assert judge.channel_verdict([other, friction], _channels(0.003)) is None


def test_friction_seen_only_in_the_current_is_named_from_the_current(tmp_path):
    """LuGre friction (20 N, Stribeck rise to 26 N) on a 50 mm stroke of
    the independent generator, the position read with 0.03 % noise: the
    position's gap (about 2 x its noise) is within its model-form floor,
    the combined measure too, and the current's gap is 10 x its floor.
    Named from the current."""
    friction = dict(fc=20.0, fs=26.0, vs=0.004, sigma0=3e6, sigma1=2.5e3, sigma2=0.0)
    rig, runs = dc.campaign({"friction": friction}, 31, stroke=0.05, current_noise_A=0.005,
                            sensor={"white": 3e-4, "flicker": 0.0, "lsb": 1e-9})
    d = api.diagnose(write_campaign(tmp_path / "c", rig, runs), ["stairs_b"])
    floors = d.verdict["floors"]
    assert floors["position_m"]["baseline"] < DEFAULT.gap_factor * np.hypot(floors["position_m"]["noise"], 0.002)
    assert d.baseline_holdout < DEFAULT.gap_factor * np.hypot(d.noise_floor_holdout, 0.002)
    assert d.verdict["effect"] == "coulomb_friction" and d.verdict["status"] == "explained"
    assert d.verdict["judged_on_channel"] == "current_A"


def test_an_effect_that_removes_most_of_the_current_gap_but_leaves_some_is_named_partial_from_it():
    """A ball-screw servo's record: friction of the library's form removes
    80 % of the current's NRMSE, 1 - (0.01^2 - f^2) / (0.05^2 - f^2) = 96 %
    of its gap energy above the floor f = hypot(0.002, 0.001), but leaves
    0.01 > 2.5 f (the hardware's friction has another form). The position
    gap lies within its model-form floor, so the combined measure names
    nothing; the current names the friction "partial", says it decided,
    and the reason states the position's prior it overrode."""
    rng = np.random.default_rng(2)
    friction = _fit("coulomb_friction", {"position_m": 4.5e-5, "current_A": 0.01},
                    {"position_m": rng.uniform(0.9, 1.1, 40), "current_A": np.full(40, 20.0) + rng.uniform(0, 1, 40)})
    other = _fit("backlash", {"position_m": 4.8e-5, "current_A": 0.045},
                 {"position_m": rng.uniform(0.9, 1.1, 40), "current_A": np.full(40, 90.0) + rng.uniform(0, 1, 40)})
    channels = _channels(0.05)
    out = judge.verdict(5e-5, 4e-5, [friction, other], baseline_blocks=channels["position_m"]["blocks"],
                        channels=channels)
    assert out["status"] == "partial" and out["effect"] == "coulomb_friction"
    assert out["judged_on_channel"] == "current_A"
    floor = np.hypot(0.002, 0.001)
    assert out["explained_gap_energy"] == pytest.approx(1 - (0.01 ** 2 - floor ** 2) / (0.05 ** 2 - floor ** 2))
    assert "judged on current_A" in out["reason"] and "prior 0.002" in out["reason"]
    # the current's gap within 1.5 x its floor: nothing is named
    quiet = _channels(1.4 * floor)
    assert judge.verdict(5e-5, 4e-5, [friction, other], baseline_blocks=quiet["position_m"]["blocks"],
                         channels=quiet)["effect"] is None
