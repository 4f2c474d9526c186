"""The technology comparison (engine/comparison.py): an infeasible technology
is compared through its lightest design that misses only one check."""
import pytest

from sizing.engine.comparison import technology_comparison
from sizing.io.requirements import load_requirements

from ..conftest import STUDIES


def _cand(id_, tech, feasible, margins, mass, rank, stage="simulated"):
    driver = min(margins, key=margins.get)
    return {"id": id_, "technology": tech, "feasible": feasible, "margins": margins, "driver": driver,
            "metrics": {"mass_kg": mass, "cost_usd": 10 * mass}, "rank": rank, "stage": stage}


def test_infeasible_side_is_counted_by_its_lightest_one_miss_design():
    req, _ = load_requirements(STUDIES / "seed-requirements.toml")
    cands = [
        _cand("dc", "dc_motor", True, {"speed": 0.1}, 2.0, 1),
        # smallest miss, but heavy: the "closest" by margin
        _cand("ph-heavy", "piezohydraulic", False, {"amp": -0.1, "force": 0.2}, 900.0, 2),
        # misses two checks: never the stand-in
        _cand("ph-two", "piezohydraulic", False, {"amp": -0.5, "force": -0.1}, 50.0, 3),
        _cand("ph-light", "piezohydraulic", False, {"amp": -0.8, "force": 0.05}, 150.0, 4),
    ]
    out = technology_comparison(req, cands)
    ph = out["technologies"]["piezohydraulic"]
    assert ph["best"] == "ph-heavy" and ph["one_miss"]["id"] == "ph-light"
    # by hand: 150 kg / 2 kg = 75, 1500 USD / 20 USD = 75
    assert "mass x75" in out["text"] and "cost x75" in out["text"]


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
    a = dict(base, id="dc-a", components={"motor": "allied-mf0127008-48v", "screw": "hiwin-r12-05k4",
                                          "gear": "belt-2", "drive": "servo-48v-10a"})
    b = dict(base, id="dc-b", components=dict(a["components"], drive="servo-96v-12a"))
    c = dict(base, id="dc-c", components=dict(a["components"], screw="thk-bif1605-5"))
    assert names.unique([a]) == ["DC MF0127008 R12-05K4 belt-2"]
    got = names.unique([a, b, c])
    assert len(set(got)) == 3 and all(len(n) <= 32 for n in got)
    assert got[0].endswith("48v") and got[1].endswith("96v")
    # the same design gets the same name in a list ordered otherwise
    assert names.unique([b, a, c]) == [got[1], got[0], got[2]]
    assert "name" not in a                  # the candidates are read, not written
