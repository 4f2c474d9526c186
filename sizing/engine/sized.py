"""A solved design as ``sizing robust`` perturbs it, to re-run the solve's
checks on perturbed parts: a piezohydraulic design as the (Combo, Variant,
SizingResult) triple that ``piezohydraulic.stage.verify_sized`` re-verifies (the parts
from the catalog, the geometry (R, wide bore, drive voltage) as sized); a
DC design from parts as its parts and its settings (``DCPartsDesign``,
re-verified by ``dc_sizing.verify_parts``). Taken from the solve's records
(``records.Stages``) when robust ran the solve; ``read_back`` rebuilds
either from a results.json candidate."""
from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import InputError
from ..io.catalog import Catalog
from ..io.requirements import RequirementsFile
from ..technologies.piezohydraulic.convex import SizingResult
from .records import DCDesign, DCParts, Variant
from ..technologies.piezohydraulic.search import enumerate_combos


def sized_designs(req: RequirementsFile, catalog: Catalog, candidates: list[dict]) -> list[tuple]:
    """(Combo, Variant, SizingResult) of each piezohydraulic candidate, in
    order. A passively compensated candidate ("-pc") is rebuilt as its
    as-built variant: ``piezo_designs.designs`` derives the spacer again."""
    combos = {c.key: c for c in enumerate_combos(req, catalog)}
    out = []
    for cand in candidates:
        design = cand.get("design", {})
        comp_id = design.get("compensator")
        key = _combo_key(cand["id"], design.get("material", ""), comp_id)
        if cand.get("technology") != "piezohydraulic" or key not in combos or "design" not in cand \
                or design.get("material") not in catalog.materials \
                or (comp_id is not None and comp_id not in catalog.compensators):
            raise InputError(None, cand.get("id"), "expected a sized piezohydraulic design of this catalog")
        combo = combos[key]
        variant = Variant(catalog.materials[design["material"]],
                          None if comp_id is None else catalog.compensators[comp_id], False)
        gp = cand.get("gp", {})
        res = SizingResult(success=bool(gp.get("success", True)), ratio=float(cand["components"]["ratio"]),
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


@dataclass(frozen=True)
class DCPartsDesign:
    """A solved DC design from parts, rebuilt for ``sizing robust``: its
    parts as one row of ``dc_parts.PartArrays`` and what was set on the
    nominal parts and stays when the parts vary (the controller's gains and
    the drive's current and voltage limits, ``dc_sizing.verify_parts``)."""
    parts: object           # PartArrays, one row
    settings: dict          # kp, ki, kd, current_limit_A, voltage_limit_V
    duration: float         # simulated time of each step (s), as solved

    @property
    def has_gear(self) -> bool:
        return self.parts.gear[0] is not None


def dc_parts_design(catalog: Catalog, d: DCDesign) -> DCPartsDesign:
    """The solve's record of a DC design from parts, as robust perturbs it."""
    return parts_design(catalog, d.parts, {k: float(d.controller[k]) for k in SETTINGS}, d.duration)


def read_back_parts(catalog: Catalog, cand: dict) -> DCPartsDesign:
    """The DC design of a results.json candidate sized from parts."""
    comp, ctl = cand.get("components", {}), cand.get("controller", {})
    gear = comp.get("gear")
    ok = (cand.get("technology") == "dc_motor" and cand.get("variant") == "parts"
          and comp.get("motor") in catalog.motors and comp.get("screw") in catalog.screws
          and comp.get("drive") in catalog.drives and (gear is None or gear in catalog.gears)
          and all(k in ctl for k in SETTINGS))
    if not ok:
        raise InputError(None, cand.get("id"), "expected a DC design sized from parts of this catalog")
    return parts_design(catalog, DCParts(comp["motor"], comp["screw"], gear, comp["drive"]),
                      {k: float(ctl[k]) for k in SETTINGS},
                      float(cand.get("design", {}).get("duration", 0.0)) or None)


def parts_design(catalog: Catalog, parts: DCParts, settings: dict, duration: float | None) -> DCPartsDesign:
    """``parts`` as one row of ``dc_parts.PartArrays`` (enumerated from a
    catalog of these parts alone, so the row's values are the solve's)."""
    from ..technologies.dc_motor.parts import enumerate_parts
    p = enumerate_parts(parts_catalog(catalog, parts))
    row = [i for i in range(len(p)) if p.gear[i] == parts.gear]
    return DCPartsDesign(p.take(row), settings, duration)


def parts_catalog(catalog: Catalog, parts: DCParts) -> Catalog:
    """The catalog with these DC parts as its only motor, screw, gear and drive."""
    from dataclasses import replace
    return replace(catalog, motors={parts.motor: catalog.motors[parts.motor]},
                   screws={parts.screw: catalog.screws[parts.screw]},
                   gears={} if parts.gear is None else {parts.gear: catalog.gears[parts.gear]},
                   drives={parts.drive: catalog.drives[parts.drive]})


SETTINGS = ("kp", "ki", "kd", "current_limit_A", "voltage_limit_V")


def read_back(req: RequirementsFile, catalog: Catalog, cand: dict):
    """What robust perturbs, read back from a results.json candidate (a
    solve whose records are gone)."""
    return study_designs(req, catalog, [cand])[0]


def study_designs(req: RequirementsFile, catalog: Catalog, candidates: list[dict], stages=None) -> list:
    """What ``sizing robust`` perturbs, per candidate, as its technology
    builds it (``Technology.study_design``): taken as sized from the solve's
    own records (``stages``, ``records.Stages``) when they hold it, else
    read back from its results.json record."""
    from ..technologies.registry import get
    out = []
    for c in candidates:
        tech = get(c["technology"])
        if tech is None or tech.study_design is None:
            raise InputError(None, c.get("id"), "expected a design whose parts robust can perturb")
        out.append(tech.study_design(req, catalog, c, stages))
    return out
