"""The solve's stages pass frozen records: a sized design cannot be changed
after it is built, a passive variant keeps its parent's origin, and the
design robust takes from the records is the one read back from results.json."""
from __future__ import annotations

import dataclasses
import math
import tomllib

import pytest

from sizing.technologies.piezohydraulic import designs as piezo_designs
from sizing.technologies.piezohydraulic.record import design_candidate
from sizing.engine.records import Simulation
from sizing.technologies.piezohydraulic.records import PiezoBrief, PiezoDesign, VerifiedDesign
from sizing.technologies.piezohydraulic.search import enumerate_combos
from sizing.engine.sized import study_designs
from sizing.technologies.piezohydraulic.read_back import sized_designs
from sizing.engine.solve import solve
from sizing.io.requirements import parse_requirements

from ..conftest import ONE_DESIGN, STUDIES, subset_catalog

REQ = (STUDIES / "seed-requirements.toml").read_text() + "\n[duty]\nstrokes_per_second = 0.1\n"


@pytest.fixture(scope="module")
def built():
    req = parse_requirements(tomllib.loads(REQ), "req.toml")
    catalog = subset_catalog(**ONE_DESIGN, dc_actuators=0)
    combos = [c for c in enumerate_combos(req, catalog) if not c.pruned]
    brief = PiezoBrief.of(req)
    sized = piezo_designs.size(brief, catalog, combos)
    return req, catalog, sized, piezo_designs.designs(brief, catalog, sized)


def test_a_built_design_is_frozen(built):
    _, _, _, designs = built
    d = next(d for d in designs if d.built)
    with pytest.raises(dataclasses.FrozenInstanceError):
        d.ramp = 1.0
    with pytest.raises(TypeError):
        d.static["speed_m_s"] = 1.0              # figures are read-only views
    with pytest.raises(TypeError):
        d.static_margins["stroke"] = 1.0


def test_origins_point_back_to_the_sizing_and_passive_variants_share_them(built):
    _, _, sized, designs = built
    as_built = designs[:len(sized)]
    assert [d.origin for d in as_built] == list(range(len(sized)))
    for d, (combo, var, res) in zip(as_built, sized):
        assert d.combo is combo and d.variant == var and d.gp is res
    passive = [d for d in designs[len(sized):]]
    assert passive, "the seed's parts drift: at least one passive variant"
    for p in passive:
        parent = as_built[p.origin]
        assert p.variant.passive and not parent.variant.passive and p.id == parent.id + "-pc"
        assert p.spacer > 0 and parent.spacer == 0
        # the spacer cancels the as-built drift (the closed form of piezo_designs._spacer_length)
        assert abs(p.static["thermal_net_m"]) < 0.05 * abs(parent.static["thermal_net_m"])


def test_derived_figures_and_margins_agree(built):
    req, _, _, designs = built
    for d in (d for d in designs if d.built):
        st, m = d.static, d.static_margins
        assert st["speed_m_s"] == pytest.approx(st["free_stroke_m"] / d.ramp, rel=1e-12)
        assert m["speed"] == pytest.approx(st["speed_m_s"] / req.requirements.speed - 1, rel=1e-9)
        assert m["stroke"] == pytest.approx(st["free_stroke_m"] / req.requirements.stroke - 1, rel=1e-9)


def test_a_failed_simulation_is_a_record_with_its_message(built):
    req, _, _, designs = built
    d = next(d for d in designs if d.built)
    c = design_candidate(req, VerifiedDesign(d, Simulation.failed("step too large")))
    assert c["simulated"] == {"failed": True, "message": "step too large"}
    assert c["margins"]["simulation"] == -math.inf and c["stage"] == "simulated"


def test_robust_takes_the_records_and_they_match_the_results_json_reading(built):
    req, catalog, _, _ = built
    out = solve(req, "0" * 64, catalog, fast=True)      # the records, not the flips
    piezo = [c for c in out.results["candidates"] if c.technology == "piezohydraulic" and c.design is not None]
    assert piezo and set(c.id for c in piezo) <= set(out.stages.designs["piezohydraulic"])
    from_records = study_designs(req, catalog, piezo, out.stages)
    read_back = sized_designs(req, catalog, piezo)
    for c, (combo, var, res), (combo2, var2, res2) in zip(piezo, from_records, read_back):
        assert combo.key == combo2.key and var == var2, c.id
        for f in ("ratio", "wide_area", "voltage_fraction", "cap_thickness", "frame_area"):
            assert getattr(res, f) == pytest.approx(getattr(res2, f), rel=1e-9), (c.id, f)
    assert all(isinstance(d, PiezoDesign) for d in out.stages.designs["piezohydraulic"].values())
