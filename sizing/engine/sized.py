"""Rebuild a solved piezohydraulic design (a results.json candidate) as the
(Combo, SizingResult) pair that ``solve.verify_sized`` re-verifies: the
parts from the catalog, the geometry (R, wide bore, drive voltage) as sized.
Used by ``sizing robust`` to re-run the solve's checks on perturbed parts."""
from __future__ import annotations

import math

from ..errors import InputError
from ..io.catalog import Catalog
from ..io.requirements import RequirementsFile
from .convex import SizingResult
from .search import enumerate_combos


def sized_designs(req: RequirementsFile, catalog: Catalog, candidates: list[dict]) -> list[tuple]:
    """(Combo, SizingResult) of each piezohydraulic candidate, in order."""
    combos = {c.key: c for c in enumerate_combos(req, catalog)}
    out = []
    for cand in candidates:
        key = cand["id"].removesuffix("-tc")
        if cand.get("technology") != "piezohydraulic" or key not in combos or "design" not in cand:
            raise InputError(None, cand.get("id"), "expected a sized piezohydraulic design of this catalog")
        combo, design = combos[key], cand["design"]
        gp = cand.get("gp", {})
        res = SizingResult(success=bool(gp.get("success", True)), ratio=float(cand["components"]["ratio"]),
                           wide_area=math.pi / 4 * float(design["wide_diameter"]) ** 2,
                           voltage_fraction=float(design["voltage"]) / combo.stack.max_voltage,
                           slack=dict(gp.get("slack", {})), binding=list(gp.get("binding", [])),
                           status=str(gp.get("status", "")))
        out.append((combo, res))
    return out
