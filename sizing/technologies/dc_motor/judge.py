"""A DC motor design file judged with the very checks of ``sizing solve``
(``Technology.judge``): a catalog actuator with the solve's margins of that
actuator; a design from parts with ``from_parts.verify_parts`` and the
file's controller and drive limits (``controller``), else
``dc_parts_designs`` on a catalog of these parts alone (the solve's
controller rule)."""
from __future__ import annotations

import numpy as np

from ...engine.evaluate import lookup
from ...engine.judge import Judged
from ...errors import InputError
from ...io.catalog import Catalog
from .design_file import DCDesignFile


def judge(req, catalog: Catalog, designs: list[DCDesignFile], files: list[str], loads) -> list[Judged]:
    return [(_actuator if d.actuator is not None else _parts)(req, catalog, d, f, loads)
            for d, f in zip(designs, files)]


def _actuator(req, catalog: Catalog, design: DCDesignFile, file: str, loads) -> Judged:
    from .catalog_actuators import actuator_design
    act = lookup(catalog, catalog.dc_actuators, design.actuator, file, "actuator")
    d = actuator_design(req, act, loads)
    return Judged(dict(d.margins), dict(d.metrics))


def _parts(req, catalog: Catalog, design: DCDesignFile, file: str, loads) -> Judged:
    from .records import DCParts
    from .from_parts import dc_parts_designs, verify_parts
    from .parts import metrics, static_screen
    from .read_back import SETTINGS, parts_catalog, parts_design
    parts = DCParts(*(lookup(catalog, getattr(catalog, k + "s"), getattr(design, k), file, k).id
                      if getattr(design, k) is not None else None for k in ("motor", "screw", "gear", "drive")))
    if design.controller is None:
        found = dc_parts_designs(req, parts_catalog(catalog, parts), loads, duration=design.duration,
                                 exhaustive=True).designs
        d = next(x for x in found if x.parts.gear == parts.gear)
        return Judged(dict(d.margins), dict(d.metrics))
    missing = [k for k in SETTINGS if k not in design.controller]
    if missing:
        raise InputError(file, "controller", f"expected {', '.join(SETTINGS)}; missing {', '.join(missing)}")
    one = parts_design(catalog, parts, {k: float(design.controller[k]) for k in SETTINGS}, design.duration)
    settings = {k: np.full(1, v) for k, v in one.settings.items()}
    checked = verify_parts(req, one.parts, loads, settings, duration=design.duration)[0]
    static = static_screen(one.parts, req, loads, settings=settings)[1]
    met = metrics(one.parts, req, static)
    return Judged(checked["margins"], {k: float(v[0]) for k, v in met.items()})
