"""The catalog-scale DC search loses no feasible design: on a subset of the
shipped catalog (makers' motors with every gearhead that mounts on them,
sourced and generic screws, every drive) the pruned search finds exactly the
combinations the static screen of the whole enumeration finds feasible, and
accounts for every other combination in its counts by reason."""
from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from sizing.technologies.dc_motor.record import parts_candidate
from sizing.technologies.dc_motor import parts as dc_parts
from sizing.technologies.dc_motor import search as dc_search
from sizing.technologies.dc_motor import from_parts as dc_sizing
from sizing.engine.evaluate import load_cases
from sizing.io.catalog import load_catalog
from sizing.io.requirements import load_requirements

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def seed():
    req, _ = load_requirements(ROOT / "studies" / "seed-requirements.toml")
    return req, load_catalog(), [c["load_N"] for c in load_cases(req.load)]


def _subset(cat):
    # heavy and light maxon motors (flat and inner rotor), Allied frameless, two generic ones
    motors = ["maxon-500267", "maxon-597974", "maxon-634043", "maxon-579165", "maxon-496661",
              "allied-mf0127008-48v", "allied-mf0095020-48v", "gen-bldc42-28v-h", "gen-bldc60-96v-h"]
    screws = ["thk-bnk1202-3", "hiwin-r12-05k4-fscdin", "thk-bif1605-5", "hiwin-r16-10k3-fscdin",
              "ball-12x2", "ball-16x5"]
    return replace(cat, motors={k: cat.motors[k] for k in motors}, screws={k: cat.screws[k] for k in screws})


def _feasible_ids(p, margins) -> set:
    M = np.nan_to_num(np.vstack(list(margins.values())), nan=-np.inf)
    ok = M.min(axis=0) >= 0
    return {dc_sizing.row_parts(p, i).id for i in np.flatnonzero(ok)}


def _variant(req, which):
    """The seed's requirements, or a milder set (1 kN, 70 degC, 150 mm/s, drive at the actuator)."""
    if which == "seed":
        return req
    r = req.requirements.model_copy(update={"blocked_force": 1000.0, "max_temperature": 70.0, "speed": 0.15})
    o = req.options.model_copy(update={"amplifier_location": "actuator"})
    return req.model_copy(update={"requirements": r, "options": o})


@pytest.mark.parametrize("which", ["seed", "mild"])
def test_pruned_search_matches_brute_force(seed, which):
    req, cat, loads = seed
    req = _variant(req, which)
    sub = _subset(cat)
    brute = dc_parts.enumerate_parts(sub)
    _, _, margins = dc_parts.static_screen(brute, req, loads)
    expected = _feasible_ids(brute, margins)
    found = dc_search.search(sub, req, loads)
    _, _, m2 = dc_parts.static_screen(found.parts, req, loads)
    got = _feasible_ids(found.parts, m2)
    assert len(expected) > 20                       # the subset has feasible designs to lose
    assert got == expected
    assert found.n_feasible == len(expected)
    # every combination is either kept or counted, and the bounds did the work
    assert found.combinations == len(brute)
    assert sum(found.ruled_out.values()) + len(found.parts) == len(brute)
    assert found.screened < len(brute) / 5


def test_counts_name_the_margins_and_bounds(seed):
    req, cat, loads = seed
    found = dc_search.search(_subset(cat), req, loads)
    assert {"speed", "blocked_force"} <= set(found.ruled_out)
    assert all(type(k) is str and type(v) is int and v > 0 for k, v in found.ruled_out.items())


def test_solve_records_only_simulated_designs(seed):
    """results.json does not grow with the combinations ruled out: only the
    simulated designs get a record; the rest are counts."""
    req, cat, loads = seed
    out = dc_sizing.dc_parts_designs(req, _subset(cat), loads)
    assert all(d.stage == "simulated" for d in out.designs)
    assert len(out.designs) <= dc_sizing.MAX_SIMULATED
    assert sum(out.ruled_out.values()) + len(out.designs) == out.combinations
    for c in (parts_candidate(req, cat, d) for d in out.designs):
        assert isinstance(c["rests_on_assumed"], list)
        assert all(set(x) == {"part", "field", "decides"} for x in c["rests_on_assumed"])


def test_two_objective_levels_agree_with_the_general_sort():
    from sizing.engine.rank import nondominated_levels
    rng = np.random.default_rng(3)
    for _ in range(100):
        F = rng.integers(0, 5, size=(int(rng.integers(1, 40)), 2)).astype(float)   # ties on purpose
        assert (dc_sizing.pareto_levels(F) == nondominated_levels(F)).all()
