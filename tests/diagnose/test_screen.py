"""The screen tries every head start (stated and re-calibrated nominal
values) and reports the one its best point was found with."""
import numpy as np

from sizing.diagnose import attribution
from sizing.diagnose.effects.base import Effect, Param


class _Bench:
    train = [0]
    rig = model = None


def test_screen_keeps_the_head_start_that_scores_best(monkeypatch):
    effect = Effect(name="toy", technology="dc_motor", params=(Param("a", 0.0, 1.0),))
    # cost: the head coordinate must be 0.7 and the effect's 0.25
    monkeypatch.setattr(attribution.fitting, "cost",
                        lambda bench, effects, Z, runs: (Z[:, 0] - 0.7) ** 2 + (Z[:, 1] - 0.25) ** 2)
    stated, recalibrated = np.array([0.2]), np.array([0.7])
    z, score, start = attribution.screen(_Bench(), effect, head=(effect,), z_heads=(stated, recalibrated))
    assert start is recalibrated
    assert abs(z[0] - 0.25) < 0.05 and score < 0.05
    z1, score1, start1 = attribution.screen(_Bench(), effect, head=(effect,), z_heads=(stated,))
    assert start1 is stated and score1 > 0.45          # the stated start alone cannot get below |0.7 - 0.2|
