"""The seed solve's best piezohydraulic design is a local optimum: every
continuous design variable perturbed by +-10 % (ratio, bore, voltage,
plate thickness, frame section, oil gap; the drive re-sized for each, as
the builder does) and the structure material swapped finds no design that
the solve's own checks (static figures, simulation under every load case,
margins: ``solve.verify_sized``) judge feasible and more than 2 % lighter.

A neighbour must also keep the design margin the program sizes stroke and
blocked force with (5 %): one that spends it (a 10 % thinner frame costs
some 4 % of the blocked force and is still feasible) is the margin at
work, not a better optimum."""
from __future__ import annotations

import dataclasses

import pytest

from sizing.engine.loads import load_cases
from sizing.technologies.piezohydraulic.records import Variant
from sizing.engine.solve import solve
from sizing.technologies.piezohydraulic.stage import verify_sized
from sizing.io.catalog import load_catalog
from sizing.io.requirements import load_requirements

from ..conftest import STUDIES

VARIABLES = ("ratio", "wide_area", "voltage_fraction", "cap_thickness", "frame_area", "wide_gap")
STEP = 0.10
LIGHTER = 0.02


def _neighbours(design, catalog) -> list[tuple]:
    combo, variant, res = design.sized
    out = []
    for name in VARIABLES:
        for sign in (-1, 1):
            value = getattr(res, name) * (1 + sign * STEP)
            if name == "voltage_fraction":
                value = min(value, combo.voltage_fraction_max)
            out.append((combo, variant, dataclasses.replace(res, **{name: value})))
    for material in catalog.materials.values():
        if material.id != variant.material.id:
            out.append((combo, Variant(material, variant.compensator), res))
    return out


def _best(results, technology="piezohydraulic"):
    """The technology's best: its rank-1 feasible design, else its closest."""
    t = results["summary"]["comparison"]["technologies"][technology]
    best_id = t.get("best") or t.get("closest")
    if best_id is None:
        best_id = min((c for c in results["candidates"] if c.technology == technology), key=lambda c: c.rank).id
    return next(c for c in results["candidates"] if c.id == best_id)


@pytest.mark.slow
@pytest.mark.parametrize("drift", [None, 1.0])
def test_no_lighter_feasible_design_next_to_the_best(drift, tmp_path):
    """``drift`` None: the seed's requirements as written (no piezohydraulic
    design is feasible: its best is the closest, and no neighbour may turn
    feasible and lighter); 1.0: the drift allowance opened to the whole
    stroke, where the best is feasible."""
    req, sha = load_requirements(STUDIES / "seed-requirements.toml")
    if drift is not None:
        req = req.model_copy(update={"options": req.options.model_copy(update={"max_drift_fraction": drift})})
    catalog = load_catalog()
    out = solve(req, sha, catalog, fast=True)       # the best designs; their flips are not needed
    best = _best(out.results)
    design = out.stages.held("piezohydraulic", best.id)
    loads = [c["load_N"] for c in load_cases(req.load)]
    neighbours = _neighbours(design, catalog)
    judged = verify_sized(req, catalog, neighbours, loads)
    mass = best.metrics["mass_kg"]
    m = req.options.design_margin * (1 - 1e-6)
    sized = lambda c: all(c["static_margins"][k] >= m for k in ("stroke", "blocked_force"))  # noqa: E731
    better = [(c["id"], c["metrics"]["mass_kg"]) for group in judged for c in group
              if c["feasible"] and sized(c) and c["metrics"].get("mass_kg", float("inf")) < (1 - LIGHTER) * mass]
    assert len(judged) == len(VARIABLES) * 2 + len(catalog.materials) - 1
    assert better == [], f"{best.id} ({mass:.1f} kg) has lighter feasible neighbours: {better}"
    if drift is not None:
        assert best.feasible
