"""The technology comparison (engine/comparison.py): an infeasible technology
is compared through its lightest design that misses only one check."""
import pytest

from sizing.engine.candidate import Candidate
from sizing.engine.comparison import technology_comparison as _comparison
from sizing.io.requirements import load_requirements

from ..conftest import STUDIES


def technology_comparison(req, cands, *args, **kwargs):
    """The comparison of the candidates these records stand for."""
    return _comparison(req, [Candidate.from_dict(c) for c in cands], *args, **kwargs)


def _cand(id_, tech, feasible, margins, mass, rank, stage="simulated"):
    driver = min(margins, key=margins.get)
    return {"id": id_, "technology": tech, "feasible": feasible, "margins": margins, "driver": driver,
            "metrics": {"mass_kg": mass, "cost_usd": 10 * mass}, "rank": rank, "stage": stage}


def test_infeasible_side_is_counted_by_its_lightest_one_miss_design_with_what_it_needs():
    """Like with like: an infeasible technology is compared through its
    design that misses only the amplifier count, with the units it needs;
    a design that misses a requirement (it delivers less) is named, never
    compared."""
    from sizing.io.catalog import load_catalog
    req, _ = load_requirements(STUDIES / "seed-requirements.toml")
    cat = load_catalog()
    amp = cat.amplifiers["pi-e-481"]                     # 10 kg, 15000 USD a unit

    def needs(c, units):
        return dict(c, static={"amplifier_units_needed": units}, components={"amplifier": "pi-e-481"})

    cands = [
        _cand("dc", "dc_motor", True, {"speed": 0.1}, 2.0, 1),
        # smallest miss, but heavy: the "closest" by margin
        _cand("ph-heavy", "piezohydraulic", False, {"amplifier_units": -0.1, "force": 0.2}, 900.0, 2),
        # misses two checks: never the stand-in
        _cand("ph-two", "piezohydraulic", False, {"amplifier_units": -0.5, "force": -0.1}, 50.0, 3),
        # 150 kg as sized with 16 units; needs 30: 150 + 14 x 10 = 290 kg
        needs(_cand("ph-light", "piezohydraulic", False, {"amplifier_units": -0.47, "force": 0.05}, 150.0, 4), 30),
        # 200 kg, needs 18: 220 kg, lighter with what it needs than ph-light
        needs(_cand("ph-mid", "piezohydraulic", False, {"amplifier_units": -0.11, "force": 0.05}, 200.0, 5), 18),
        # the lightest, but short of speed: not a rival
        _cand("ph-slow", "piezohydraulic", False, {"speed": -0.3, "force": 0.05}, 4.0, 6),
    ]
    out = technology_comparison(req, cands, cat)
    ph = out["technologies"]["piezohydraulic"]
    assert ph["best"] == "ph-heavy" and ph["one_miss"]["id"] == "ph-mid"
    assert ph["one_miss"]["needs"]["amplifier_units"] == 18 and ph["one_miss"]["comparable"]
    assert ph["one_miss"]["metrics"]["mass_kg"] == pytest.approx(200.0 + 2 * amp.mass)
    # by hand: 220 kg / 2 kg = 110; (2000 + 2 x 15000) USD / 20 USD = 1600
    assert "mass x110" in out["text"] and "cost x1.6e+03" in out["text"]
    assert "needs 18 amplifier units (16 allowed)" in out["text"]
    # without a design that more units would rescue: named, not compared
    slow = technology_comparison(req, [c for c in cands if c["id"] not in ("ph-light", "ph-mid")], cat)
    assert slow["technologies"]["piezohydraulic"]["one_miss"]["id"] == "ph-slow"
    assert not slow["technologies"]["piezohydraulic"]["one_miss"]["comparable"]
    assert "no design to compare like with like" in slow["text"] and "mass x" not in slow["text"]
    assert "lighter than" not in slow["recommendation"]


def test_the_flip_shown_is_the_smallest_re_solved_one():
    """``flip`` is the entry of ``flips`` that needs the smallest change
    (speed +25 % beats stroke +50 %); nothing flips in range: null, said so;
    flips not computed (``solve --fast``): null, said so."""
    req, _ = load_requirements(STUDIES / "seed-requirements.toml")
    cands = [_cand("dc-a", "dc_motor", True, {"speed": 0.1, "stroke": 0.5}, 2.0, 1)]
    entry = {"method": "re-solve", "tolerance": 0.01, "changes": "feasibility"}
    flips = {"dc_motor": [dict(entry, what="requirement stroke", field="stroke", to=0.06, within=[0.04, 0.16], **{"from": 0.04}),
                          dict(entry, what="requirement speed", field="speed", to=0.125, within=[0.1, 0.4], **{"from": 0.1}),
                          dict(entry, what="requirement blocked_force", field="blocked_force", to=None,
                               within=[2500.0, 10000.0], **{"from": 2500.0})]}
    dc = technology_comparison(req, cands, flips=flips)["technologies"]["dc_motor"]
    assert dc["flip"]["field"] == "speed" and dc["flip"]["relative_change"] == pytest.approx(0.25)
    assert dc["flip"]["text"].startswith("speed 100 mm/s -> 125 mm/s (+25%)")
    from sizing.engine.flip import flip_text
    assert flip_text(flips["dc_motor"][2]) == "blocked_force: nothing flips between 2500 N and 10,000 N"
    none = technology_comparison(req, cands, flips={"dc_motor": flips["dc_motor"][2:]})
    assert none["technologies"]["dc_motor"]["flip"] is None and "within the ranges searched" in none["text"]
    fast = technology_comparison(req, cands)
    assert fast["technologies"]["dc_motor"]["flips"] is None and "not computed (solve --fast)" in fast["text"]


def test_the_recommendation_names_the_lighter_feasible_technology():
    """Both feasible, DC at 2 kg and piezo at 150 kg: choose DC, 75 x lighter;
    none feasible: no recommendation, only what blocks each."""
    req, _ = load_requirements(STUDIES / "seed-requirements.toml")
    cands = [_cand("dc", "dc_motor", True, {"speed": 0.1}, 2.0, 1),
             _cand("ph", "piezohydraulic", True, {"stroke": 0.2}, 150.0, 2)]
    text = technology_comparison(req, cands)["recommendation"]
    assert text.startswith("Choose the DC motor actuator") and "75 x lighter" in text
    none = [dict(c, feasible=False, margins={"speed": -0.1}, driver="speed") for c in cands]
    assert technology_comparison(req, none)["recommendation"].startswith("No technology meets")


def test_names_are_unique_short_and_stable():
    """Designs whose short names coincide add the part they differ in (then
    a hash of their id): unique, at most 32 characters, and the same for a
    design whatever the others are."""
    from sizing.engine import names
    base = {"technology": "dc_motor", "variant": "parts"}
    a = Candidate.from_dict(dict(base, id="dc-a", components={"motor": "allied-mf0127008-48v",
                                                              "screw": "hiwin-r12-05k4", "gear": "belt-2",
                                                              "drive": "servo-48v-10a"}))
    b = a.with_fields(id="dc-b", components=dict(a.components, drive="servo-96v-12a"))
    c = a.with_fields(id="dc-c", components=dict(a.components, screw="thk-bif1605-5"))
    assert names.unique([a]) == ["DC MF0127008 R12-05K4 belt-2"]
    got = names.unique([a, b, c])
    assert len(set(got)) == 3 and all(len(n) <= 32 for n in got)
    assert got[0].endswith("48v") and got[1].endswith("96v")
    # the same design gets the same name in a list ordered otherwise
    assert names.unique([b, a, c]) == [got[1], got[0], got[2]]
    assert "name" not in a.order            # the candidates are read, not written
