"""The verdict as a typed record decided by declared rules (judge.RULES),
and the effect modules' one declared export (FORMS)."""
from __future__ import annotations

import json
import pickle

import numpy as np
import pytest

from sizing.diagnose import effects, judge
from sizing.diagnose.effects import library
from sizing.diagnose.fitting import EffectFit
from sizing.diagnose.settings import DEFAULT
from sizing.diagnose.verdict import Verdict


def _fit(name, holdout, blocks):
    effect = effects.get("piezohydraulic", name)
    f = EffectFit((effect,), np.zeros(len(effect.params)), holdout, message="ok")
    f.nrmse_holdout, f.residual_blocks = holdout, np.asarray(blocks, float)
    return f


def test_verdict_to_dict_gives_the_documented_fields():
    v = Verdict("explained", "seal_stick_slip", "karnopp", 0.86, {"p_vs_baseline": 0.0, "p_vs_runner_up": 0.01},
                ("seal_stick_slip removes 90 %",), rule="explains", details={"explained_gap_energy": 0.9})
    d = v.to_dict()
    assert d == {"status": "explained", "effect": "seal_stick_slip", "form": "karnopp", "shrink_holdout": 0.86,
                 "reason": "seal_stick_slip removes 90 %", "separation": {"p_vs_baseline": 0.0, "p_vs_runner_up": 0.01},
                 "explained_gap_energy": 0.9}
    assert v["status"] == "explained" and v.get("form") == "karnopp" and v.get("line") is None
    assert v == d and json.loads(json.dumps(d)) == d
    assert pickle.loads(pickle.dumps(v)) == v and pickle.loads(pickle.dumps(v)).rule == "explains"
    # a null verdict has no form
    assert "form" not in Verdict("unexplained", reasons=("a", "b")).to_dict()
    assert Verdict("unexplained", reasons=("a", "b")).reason == "a; b"


def test_verdict_refuses_an_unknown_status_or_a_named_status_without_an_effect():
    with pytest.raises(ValueError):
        Verdict("maybe")
    with pytest.raises(ValueError):
        Verdict("partial")
    with pytest.raises(Exception):
        Verdict("unexplained").status = "explained"          # frozen


def test_rules_are_declared_in_order_and_each_decides_one_verdict():
    assert [r.__name__ for r in judge.RULES] == [
        "no_significant_gap", "nothing_fitted", "within_form_floor", "no_gap_on_training", "explains",
        "tied_with_runner_up",
        "explains_part", "explains_too_little"]
    blocks = np.full(40, 10.0)
    # a gap within 1.5 x the noise: no gap
    v = judge.verdict(0.0012, 0.001, [_fit("viscous_damping", 0.0011, np.full(40, 9.0))], blocks)
    assert (v.status, v.rule, v.effect) == ("no_significant_gap", "no_significant_gap", None)
    # nothing fitted
    assert judge.verdict(0.02, 0.001, [], blocks).rule == "nothing_fitted"
    # an effect that takes the gap to the noise, alone
    v = judge.verdict(0.02, 0.001, [_fit("viscous_damping", 0.0015, np.full(40, 0.05))], blocks)
    assert (v.status, v.rule, v.effect, v.form) == ("explained", "explains", "viscous_damping", "default")
    assert v.shrink == pytest.approx(1 - 0.0015 / 0.02)
    assert v.separation["p_vs_baseline"] < DEFAULT.alpha
    # one that removes little: nothing named
    v = judge.verdict(0.02, 0.001, [_fit("viscous_damping", 0.0195, np.full(40, 9.8))], blocks)
    assert (v.status, v.rule, v.effect) == ("unexplained", "explains_too_little", None)


def test_every_threshold_of_the_rules_comes_from_the_settings():
    """The same evidence, a stricter ``explained``: explained becomes partial."""
    blocks = np.full(40, 10.0)
    fits = [_fit("viscous_damping", 0.005, np.full(40, 1.0))]
    assert judge.verdict(0.02, 0.001, fits, blocks).status == "explained"
    stricter = DEFAULT.varied("explained", 1.3)
    v = judge.verdict(0.02, 0.001, fits, blocks, settings=stricter)
    assert (v.status, v.rule) == ("partial", "explains_part")
    assert "< 98 %" in v.reason


@pytest.mark.parametrize("kind", ["piezohydraulic", "dc_motor"])
def test_the_library_is_every_effect_modules_forms(kind):
    forms = [f for module in effects.FAMILIES[kind] for f in module.FORMS if f.technology == kind]
    assert list(library(kind)) == forms
    for module in effects.FAMILIES[kind]:
        assert all(f.name == module.__name__.rsplit(".", 1)[-1] for f in module.FORMS)
        first = next(f for f in module.FORMS if f.technology == kind)
        assert next(f for f in library(kind) if f.name == first.name) is first     # the default form first


def test_a_verdict_naming_nothing_is_revisited_by_the_first_measure_that_names():
    """judge.revisit: a named verdict and one without a gap are kept and no
    measure runs; an `unexplained` one takes the first measure that names
    an effect, with the point-by-point reason and details beside its own."""
    calls = []

    def measure(found):
        def run():
            calls.append(found)
            return found
        return run

    seal = Verdict("partial", "seal_stick_slip", "karnopp", 0.7, reasons=("slips",), details={"events": 1})
    named = Verdict("explained", "leakage", "laminar", 0.9, reasons=("leak",))
    no_gap = Verdict("no_significant_gap", reasons=("within the noise",))
    for kept in (named, no_gap):
        assert judge.revisit(kept, (measure((seal, "z")),)) == (kept, None) and not calls
    unexplained = Verdict("unexplained", reasons=("nothing removes it",), details={"floors": 2})
    out, payload = judge.revisit(unexplained, (measure(None), measure((seal, "z")), measure((named, "w"))))
    assert payload == "z" and calls == [None, (seal, "z")]
    assert out.effect == "seal_stick_slip" and out.status == "partial"
    assert out.reasons == ("slips", "on the point-by-point measure: nothing removes it")
    assert out.details == {"floors": 2, "events": 1}
    assert judge.revisit(unexplained, (measure(None),)) == (unexplained, None)
