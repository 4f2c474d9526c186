"""A solved DC design from parts as ``sizing robust`` perturbs it: its
parts and its settings (``DCPartsDesign``, re-verified by
``from_parts.verify_parts``), from the solve's record or read back from
its results.json record."""
from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

from .records import DCDesign, DCParts
from ...errors import InputError
from ...io.catalog import Catalog

if TYPE_CHECKING:                   # the types alone: not imported when the module loads
    from ...engine.candidate import Candidate
    from .parts import PartArrays


@dataclass(frozen=True)
class DCPartsDesign:
    """A solved DC design from parts, rebuilt for ``sizing robust``: its
    parts as one row of ``parts.PartArrays`` and what was set on the
    nominal parts and stays when the parts vary (the controller's gains and
    the drive's current and voltage limits, ``from_parts.verify_parts``)."""
    parts: PartArrays       # one row
    settings: dict          # kp, ki, kd, current_limit_A, voltage_limit_V
    duration: float         # simulated time of each step (s), as solved

    @property
    def has_gear(self) -> bool:
        return self.parts.gear[0] is not None

    @property
    def tolerated_parts(self) -> tuple[str, ...]:
        """The parts robust's tolerances move (``studies.tolerances.applicable``)."""
        from ...io.requirements import DC_PARTS
        return tuple(p for p in DC_PARTS if p != "gear" or self.has_gear)


def dc_parts_design(catalog: Catalog, d: DCDesign) -> DCPartsDesign:
    """The solve's record of a DC design from parts, as robust perturbs it."""
    return parts_design(catalog, d.parts, {k: float(d.controller[k]) for k in SETTINGS}, d.duration)


def read_back_parts(catalog: Catalog, cand: Candidate) -> DCPartsDesign:
    """The DC design of a results.json candidate sized from parts."""
    comp, ctl = cand.components or {}, cand.own.get("controller") or {}
    gear = comp.get("gear")
    ok = (cand.technology == "dc_motor" and cand.variant == "parts"
          and comp.get("motor") in catalog.motors and comp.get("screw") in catalog.screws
          and comp.get("drive") in catalog.drives and (gear is None or gear in catalog.gears)
          and all(k in ctl for k in SETTINGS))
    if not ok:
        raise InputError(None, cand.id, "expected a DC design sized from parts of this catalog")
    return parts_design(catalog, DCParts(comp["motor"], comp["screw"], gear, comp["drive"]),
                      {k: float(ctl[k]) for k in SETTINGS},
                      float((cand.design or {}).get("duration", 0.0)) or None)


def parts_design(catalog: Catalog, parts: DCParts, settings: dict, duration: float | None) -> DCPartsDesign:
    """``parts`` as one row of ``parts.PartArrays`` (enumerated from a
    catalog of these parts alone, so the row's values are the solve's)."""
    from .parts import enumerate_parts
    p = enumerate_parts(parts_catalog(catalog, parts))
    row = [i for i in range(len(p)) if p.gear[i] == parts.gear]
    return DCPartsDesign(p.take(row), settings, duration)


def parts_catalog(catalog: Catalog, parts: DCParts) -> Catalog:
    """The catalog with these DC parts as its only motor, screw, gear and drive."""
    return replace(catalog, motors={parts.motor: catalog.motors[parts.motor]},
                   screws={parts.screw: catalog.screws[parts.screw]},
                   gears={} if parts.gear is None else {parts.gear: catalog.gears[parts.gear]},
                   drives={parts.drive: catalog.drives[parts.drive]})


SETTINGS = ("kp", "ki", "kd", "current_limit_A", "voltage_limit_V")
