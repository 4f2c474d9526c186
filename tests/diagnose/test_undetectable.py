"""A gap beyond the noise but within the model-form floor is
"undetectable" (judge.within_form_floor), distinct from "no_significant_gap"
(at the noise) and from "unexplained" (a gap no effect of the library
explains): a DC campaign from the project's own simulator with an effect
outside the library at a known size against a known noise."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from sizing.diagnose import synth
from sizing.diagnose.diagnosis import diagnose_runs
from sizing.diagnose.settings import DEFAULT
from sizing.io.rig import load_rig
from .excitations import trapezoids

ROOT = Path(__file__).resolve().parents[2]
SIGMA = 1e-3        # position noise, of the span


def _scale_error(share: float, stroke: float):
    """A sensor whose reading bows along the stroke (a quadratic scale
    error, zero at both ends), of peak ``share`` x 4 / 3 of the stroke: smooth
    and without a spectral line, outside the library."""
    return lambda t, y, rng: y + 4.0 / 3.0 * 4.0 * share * stroke * (y / stroke) * (1.0 - y / stroke)


@pytest.mark.slow
@pytest.mark.parametrize("times_noise, status", [
    (0.0, "no_significant_gap"),     # no effect: the holdout gap is the noise
    (2.5, "undetectable"),           # above 1.5 x the noise, within 1.5 x sqrt(noise^2 + prior^2) = 0.0034
    (8.0, "unexplained"),            # far beyond the floors, and no effect of the library explains it
])
def test_a_gap_within_the_model_form_floor_is_undetectable(times_noise, status):
    rig = load_rig(ROOT / "studies/campaigns/dc-motor/rig.toml")
    stroke = 0.01
    inputs = trapezoids(stroke)
    hidden = _scale_error(times_noise * SIGMA, stroke) if times_noise else None
    runs = synth.synthesize("dc_motor", rig, inputs, hidden=hidden, noise=synth.Noise(position=SIGMA, seed=5))
    d = diagnose_runs("dc_motor", rig, runs, ["down"])
    v = d.verdict
    assert v["effect"] is None and v["status"] == status, v["reason"]
    stated = v["form_floor_position"]
    assert stated["prior"] == DEFAULT.form_floor_prior and stated["campaign"] is not None
    if status == "undetectable":
        assert "cannot be told" in v["reason"] and "training runs beyond their noise" in v["reason"]


def test_check_says_which_effects_the_campaign_can_tell():
    """``--check``'s table ends with each injected effect's sizes named
    right and the verdicts of the others: an effect named at neither size,
    its gap within the floors, reads "undetectable"."""
    from sizing.diagnose.check import NONE, Case, CheckResult

    cases = [Case("coulomb_friction", 0, NONE, 0.0, 1.0, "undetectable"),
             Case("coulomb_friction", 1, "coulomb_friction", 0.9, 1.0, "explained"),
             Case("backlash", 0, NONE, 0.0, 1.0, "undetectable"),
             Case("backlash", 1, NONE, 0.0, 1.0, "undetectable"),
             Case(NONE, 0, NONE, 0.0, 1.0, "no_significant_gap")]
    result = CheckResult("dc_motor", ["coulomb_friction", "backlash", NONE], cases)
    assert result.can_tell() == {"coulomb_friction": (1, 2, ("undetectable",)),
                                 "backlash": (0, 2, ("undetectable", "undetectable"))}
    lines = result.table().splitlines()
    assert "| coulomb_friction | 1/2 | undetectable |" in lines and "| backlash | 0/2 | undetectable, undetectable |" in lines
    assert result.to_json()["can_tell"]["backlash"] == {"sizes_told": 0, "sizes_tried": 2,
                                                       "others": ["undetectable", "undetectable"]}
