"""The technology comparison (engine/comparison.py): an infeasible technology
is compared through its lightest design that misses only one check."""
from types import SimpleNamespace

from sizing.engine.comparison import technology_comparison


def _cand(id_, tech, feasible, margins, mass, rank, stage="simulated"):
    driver = min(margins, key=margins.get)
    return {"id": id_, "technology": tech, "feasible": feasible, "margins": margins, "driver": driver,
            "metrics": {"mass_kg": mass, "cost_usd": 10 * mass}, "rank": rank, "stage": stage}


def test_infeasible_side_is_counted_by_its_lightest_one_miss_design():
    req = SimpleNamespace(objectives=SimpleNamespace(minimize=["mass", "cost"]))
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
