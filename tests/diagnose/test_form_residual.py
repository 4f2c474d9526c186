"""A nominal of another form leaves a structured residual that flexible
families of the library take up: the verdict names none of them for it
(judge.no_gap_on_training: a candidate fitted to training runs that show
no gap; judge.lines_carry: a line the excitation leaves in that residual
does not decide), and still names an effect that the data pin on it.
The figures are those of the project's second generator's two-stack rig
(a nominal stated 2.5 % off, another simulator's form) with no effect
and with entrained air: 3-7 x the noise on the held-out run."""
from __future__ import annotations

import numpy as np
import pytest

from sizing.diagnose import effects, judge
from sizing.diagnose.fitting import EffectFit

NOISE = 0.0009        # noise floor of the held-out run, share of the span


def _fit(name, holdout, form=None):
    """A fitted candidate leaving ``holdout`` (NRMSE) evenly on 40 holdout
    blocks (their energies sum to the holdout's mean square)."""
    family = [e for e in effects.library("piezohydraulic") if e.name == name]
    effect = next((e for e in family if form is None or e.form == form), family[0])
    f = EffectFit((effect,), np.zeros(len(effect.params)), holdout, message="ok")
    f.nrmse_holdout, f.residual_blocks = holdout, np.full(40, holdout ** 2 / 40)
    return f


def test_a_line_that_a_broadband_candidate_removes_with_the_form_residual_does_not_decide():
    """Within 1.5 x the floor with model form (0.0032 against 0.0022), a
    6 Hz line holding 3 % of the residual's power that the softer oil
    removes (87 %) with two thirds of the broadband gap: the line carries
    4 % of what it removes, and the gap is judged on the model-form floor
    (nothing named). A mount's line, 40 % of a residual at the noise,
    removed with it, decides."""
    base = 0.0032
    line = {"frequencies_Hz": [6.0], "ratio": 31.0, "share": 0.031, "removed": 0.87}
    fits = [_fit("fluid_compressibility", 0.00183, form="air"), _fit("leakage", 0.00296)]
    v = judge.verdict(base, NOISE, fits, np.full(40, base ** 2 / 40), line=line)
    assert v.effect is None and not v["line"]["judged_on"]
    mount = [_fit("sensor_vibration", 0.0010, form="mount"), _fit("leakage", 0.00125)]
    line = {"frequencies_Hz": [40.0], "ratio": 50.0, "share": 0.4, "removed": 1.0}
    v = judge.verdict(0.00125, NOISE, mount, np.full(40, 0.00125 ** 2 / 40), line=line)
    assert (v.effect, v["line"]["judged_on"]) == ("sensor_vibration", True)


@pytest.mark.parametrize("base, after, share, removed, carried", [
    (0.0032, 0.00183, 0.031, 0.87, False),   # a softer oil on a null's 6 Hz staircase line: 4 %
    (0.00216, 0.00129, 0.108, 0.555, True),  # viscous damping on a damped 89 Hz ring: 9 %
    (0.00125, 0.0010, 0.4, 1.0, True),       # a mount's line: all of what it removes
])
def test_lines_carry_compares_the_lines_energy_with_what_the_candidate_removes(base, after, share, removed, carried):
    """The lines' energy removed, share x removed of the residual's power,
    against 1 - (after / base)^2 removed in all: 0.027 / 0.67, 0.060 /
    0.64 and 0.4 / 0.36, against ``line_share`` (a twentieth)."""
    ev = judge.Evidence(base, NOISE, 0.0022, judge.DEFAULT, best=_fit("fluid_compressibility", after))
    assert judge.lines_carry(ev, {"share": share, "removed": removed}) is carried


@pytest.mark.parametrize("train_baseline, train_best, status", [
    (0.00176, 0.00147, "undetectable"),    # no effect: the training runs within their band, the oil leaves 1.6 x noise
    (0.00572, 0.00147, "explained"),       # 0.4 % of entrained air: a gap on the training runs too
    (0.00176, 0.00100, "explained"),       # within the band, but the candidate takes the training runs to the noise
])
def test_an_effect_fitted_to_training_runs_without_a_gap_is_not_named(train_baseline, train_best, status):
    """A fresh campaign of the second generator's two-stack rig with no
    effect: the held-out run's gap is 0.00358 (3.9 x the noise 0.00092),
    a softer oil leaves 0.00145 there, separated from every other family;
    but the nominal leaves 0.00176 on the training runs, within 1.5 x
    their floor with the model-form prior (0.0022), and the oil leaves
    0.00147 there, 1.6 x their noise: it was fitted to form error, nothing
    named. With entrained air the training runs show a gap and the oil is
    named; so it is where the candidate takes the training runs to their
    noise (within ``noise_match``), which then show no model-form error
    to allow for (a DC current limit the training runs barely reach)."""
    base = 0.00358
    fits = [_fit("fluid_compressibility", 0.00145, form="air"), _fit("sensor_vibration", 0.00353)]
    fits[0].nrmse_train = train_best
    v = judge.verdict(base, 0.00092, fits, np.full(40, base ** 2 / 40),
                      training={"baseline": train_baseline, "noise": 0.00092})
    assert v.status == status
    assert (v.effect is None) is (status == "undetectable")
    if v.effect is None:
        assert v.rule == "no_gap_on_training" and "the training runs show no gap" in v.reason
    assert judge.verdict(base, 0.00092, fits, np.full(40, base ** 2 / 40)).status == "explained"   # without


@pytest.mark.parametrize("holdout, named", [
    (0.0896, True),     # 26 x the training runs' 0.0034: more than a form error's spread
    (0.0136, False),    # 4 x and a little: the rule still asks the training runs
])
def test_a_held_out_gap_many_times_the_training_runs_is_not_taken_for_form_error(holdout, named):
    """The shipped piezo campaign's check with a weak fluid compressibility
    injected into every run: the training runs show 0.0034 (their noise
    0.0028, within 1.5 x their floor with the model-form prior) and the
    held-out staircase 0.0896. A nominal's form error does not grow 26 x
    from one run to another (3.9 / 1.8 and 4.9 / 3.0 on the two-stack
    nulls): beyond ``form_spread`` x the training runs' error the held-out
    gap is judged on its own and the effect named."""
    fits = [_fit("fluid_compressibility", 0.0029), _fit("sensor_vibration", 0.8 * holdout)]
    fits[0].nrmse_train = 0.0031
    v = judge.verdict(holdout, 0.0028, fits, np.full(40, holdout ** 2 / 40),
                      training={"baseline": 0.0034, "noise": 0.0028})
    assert (v.effect == "fluid_compressibility") is named
    assert (v.rule == "no_gap_on_training") is (not named)


@pytest.mark.slow
@pytest.mark.parametrize("effects, seed, named", [
    ({}, 101, None),                                                   # 0.0036 held out, 3.9 x the noise
    ({"air": {"eps0": 0.002, "kappa": 1.2}}, 102, "fluid_compressibility"),   # 0.0059, 6.5 x
])
def test_a_two_stack_null_is_not_named_and_entrained_air_is(tmp_path, effects, seed, named):
    """The second generator's two-stack rig with 3 in pistons (a nominal
    stated 2.5 % off): with no effect a softer oil was named `explained`
    (the training runs show 0.0018, within their floor's band); with 0.2 %
    of entrained air it is named."""
    from benchmarks.crossform import piezo
    from benchmarks.crossform.common import write_campaign
    from sizing import api

    rig, runs = piezo.campaign(effects, seed, n_stacks=2, wide_in=3.0, v_max=125.0, misstate=0.025)
    d = api.diagnose(write_campaign(tmp_path / "c", rig, runs), ["stairs_b"])
    assert d.verdict["effect"] == named
    if named is None:
        assert (d.verdict.status, d.verdict.rule) == ("undetectable", "no_gap_on_training")
