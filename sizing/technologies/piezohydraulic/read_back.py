"""A solved piezohydraulic design as ``sizing robust`` perturbs it, read
back from its results.json record: the (Combo, Variant, SizingResult)
triple that ``stage.verify_sized`` re-verifies (the parts from the
catalog, the geometry (R, wide bore, drive voltage) as sized)."""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

from .records import Variant
from ...errors import InputError
from ...io.catalog import Catalog
from ...io.requirements import RequirementsFile
from .convex import SizingResult
from .search import enumerate_combos

if TYPE_CHECKING:
    from ...engine.candidate import Candidate


def sized_designs(req: RequirementsFile, catalog: Catalog, candidates: list[Candidate]) -> list[tuple]:
    """(Combo, Variant, SizingResult) of each piezohydraulic candidate, in
    order. A passively compensated candidate ("-pc") is rebuilt as its
    as-built variant: ``designs.designs`` derives the spacer again."""
    combos = {c.key: c for c in enumerate_combos(req, catalog)}
    out = []
    for cand in candidates:
        design = cand.design or {}
        comp_id = design.get("compensator")
        key = _combo_key(cand.id, design.get("material", ""), comp_id)
        if cand.technology != "piezohydraulic" or key not in combos or cand.design is None \
                or design.get("material") not in catalog.materials \
                or (comp_id is not None and comp_id not in catalog.compensators):
            raise InputError(None, cand.id, "expected a sized piezohydraulic design of this catalog")
        combo = combos[key]
        variant = Variant(catalog.materials[design["material"]],
                          None if comp_id is None else catalog.compensators[comp_id], False)
        gp = cand.own.get("gp", {})
        res = SizingResult(success=bool(gp.get("success", True)), ratio=float(cand.components["ratio"]),
                           wide_area=math.pi / 4 * float(design["wide_diameter"]) ** 2,
                           voltage_fraction=float(design["voltage"]) / combo.stack.max_voltage,
                           cap_thickness=float(design["end_cap_thickness"]),
                           frame_area=float(design["frame_area"]), wide_gap=float(design["wide_gap"]),
                           slack=dict(gp.get("slack", {})), binding=list(gp.get("binding", [])),
                           status=str(gp.get("status", "")))
        out.append((combo, variant, res))
    return out


def _combo_key(candidate_id: str, material: str, compensator: str | None) -> str:
    """The search combination's key: the id without its variant suffix
    (``Variant.suffix``: -MATERIAL, then -tc-COMPENSATOR or -pc)."""
    tail = f"-{material}" + (f"-tc-{compensator}" if compensator is not None else "")
    return candidate_id.removesuffix("-pc").removesuffix(tail)
