"""``sizing evaluate DESIGN.toml --requirements REQUIREMENTS.toml``: one
design file judged with the very checks of ``sizing solve``.

The design is rebuilt as the solve holds its own designs and re-verified
by the solve's code, so a design taken from results.json reproduces its
candidate's metrics and margins, and a design of the user's own is judged
as a solved one would be:

- piezohydraulic: the parts as one search combination
  (``search.combos_of``), the geometry, structure and drive of the file as
  a ``convex.SizingResult`` (amplifier units and ramp fixed by the file),
  then ``piezohydraulic.stage.verify_sized``: static figures, margins, the simulation under
  every load case of the requirements, verdict. A passive spacer is derived
  again from the thermal budget, as the solve derives it;
- DC from parts: ``dc_sizing.verify_parts`` with the file's controller and
  drive limits (``controller``), else ``dc_parts_designs`` on a catalog of
  these parts alone (the solve's controller rule);
- catalog DC actuator: the solve's margins of that actuator;
- piezo pump: ``pump_evaluate.evaluate_pump`` on the file's parts and
  settings with the requirements' stroke, speed, blocked force, duty and
  load.
"""
from __future__ import annotations

import numpy as np

from ..errors import InputError
from ..io.catalog import Catalog
from ..io.design import DCDesignFile, PiezoDesignFile
from ..technologies.piezohydraulic.convex import SizingResult
from .evaluate import geometry, lookup, structure_of
from .loads import load_cases
from .rank import verdict
from .records import Variant
from ..technologies.piezohydraulic.search import combos_of


def judge(req, catalog: Catalog, design, file: str) -> dict:
    """{"margins", "feasible", "driver", "metrics", "static_margins"} of
    ``design`` against ``req`` (results.json's meaning of each)."""
    return judge_all(req, catalog, [design], [file])[0]


def judge_all(req, catalog: Catalog, designs: list, files: list[str]) -> list[dict]:
    """``judge`` of several design files, in order; the piezohydraulic ones
    are verified together (one batched simulation per chunk, as the solve)."""
    loads = [c["load_N"] for c in load_cases(req.load)]
    out: list = [None] * len(designs)
    piezo = [i for i, d in enumerate(designs) if isinstance(d, PiezoDesignFile)]
    if piezo:
        for i, cand in zip(piezo, _piezo(req, catalog, [designs[i] for i in piezo], [files[i] for i in piezo], loads)):
            out[i] = cand
    for i, d in enumerate(designs):
        if out[i] is None:
            out[i] = JUDGES[_kind(d)](req, catalog, d, files[i], loads)
    return [_verdict(cand) for cand in out]


def _kind(design) -> str:
    if design.technology == "dc_motor":
        return "dc_actuator" if design.actuator is not None else "dc_parts"
    return design.technology


def _verdict(cand: dict) -> dict:
    feasible, driver = verdict(cand["margins"])
    return {"margins": dict(cand["margins"]), "feasible": feasible, "driver": driver,
            "metrics": dict(cand.get("metrics") or {}),
            "static_margins": dict(cand.get("static_margins") or cand["margins"])}


def _piezo(req, catalog: Catalog, designs: list[PiezoDesignFile], files: list[str], loads) -> list[dict]:
    from ..technologies.piezohydraulic.stage import verify_sized
    triples = [_triple(req, catalog, d, f) for d, f in zip(designs, files)]
    out = []
    for design, cands in zip(designs, verify_sized(req, catalog, triples, loads)):
        passive = [c for c in cands if c["id"].endswith("-pc")]
        out.append(passive[0] if design.spacer_length > 0 and passive else cands[0])
    return out


def _triple(req, catalog: Catalog, design: PiezoDesignFile, file: str) -> tuple:
    """The design file as the solve holds a sized design: (Combo, Variant, SizingResult)."""
    for name in ("fluid", "seal", "amplifier"):
        if getattr(design, name) is None:
            raise InputError(file, name, "expected a catalog id: judging a design against requirements "
                                         "needs every part")
    stack = lookup(catalog, catalog.stacks, design.stack, file, "stack")
    fluid = lookup(catalog, catalog.fluids, design.fluid, file, "fluid")
    seal = lookup(catalog, catalog.seals, design.seal, file, "seal")
    amp = lookup(catalog, catalog.amplifiers, design.amplifier, file, "amplifier")
    voltage = design.voltage or stack.max_voltage
    ratio, wide_area = geometry(design, stack, voltage, seal, [])
    material, compensator, t_cap, frame_area = structure_of(design, catalog, file, stack, seal, voltage, wide_area)
    combo = combos_of(req, stack, fluid, seal, amp, [design.n_stacks])[0]
    res = SizingResult(success=True, ratio=ratio, wide_area=wide_area, voltage_fraction=voltage / stack.max_voltage,
                       cap_thickness=float(t_cap), frame_area=float(frame_area), wide_gap=design.wide_gap,
                       status="given by the design file", amplifier_units=design.amplifier_units,
                       ramp_time=design.ramp_time)
    return combo, Variant(material, compensator, False), res


def _dc_actuator(req, catalog: Catalog, design: DCDesignFile, file: str, loads) -> dict:
    from ..technologies.dc_motor.catalog_actuators import actuator_design
    act = lookup(catalog, catalog.dc_actuators, design.actuator, file, "actuator")
    d = actuator_design(req, act, loads)
    return {"margins": dict(d.margins), "metrics": dict(d.metrics)}


def _dc_parts(req, catalog: Catalog, design: DCDesignFile, file: str, loads) -> dict:
    from ..technologies.dc_motor.parts import metrics, static_screen
    from ..technologies.dc_motor.from_parts import dc_parts_designs, verify_parts
    from .records import DCParts
    from .sized import SETTINGS, parts_catalog, parts_design
    parts = DCParts(*(lookup(catalog, getattr(catalog, k + "s"), getattr(design, k), file, k).id
                      if getattr(design, k) is not None else None for k in ("motor", "screw", "gear", "drive")))
    if design.controller is None:
        found = dc_parts_designs(req, parts_catalog(catalog, parts), loads, duration=design.duration,
                                 exhaustive=True).designs
        d = next(x for x in found if x.parts.gear == parts.gear)
        return {"margins": dict(d.margins), "metrics": dict(d.metrics)}
    missing = [k for k in SETTINGS if k not in design.controller]
    if missing:
        raise InputError(file, "controller", f"expected {', '.join(SETTINGS)}; missing {', '.join(missing)}")
    one = parts_design(catalog, parts, {k: float(design.controller[k]) for k in SETTINGS}, design.duration)
    settings = {k: np.full(1, v) for k, v in one.settings.items()}
    checked = verify_parts(req, one.parts, loads, settings, duration=design.duration)[0]
    static = static_screen(one.parts, req, loads, settings=settings)[1]
    met = metrics(one.parts, req, static)
    return {"margins": checked["margins"], "metrics": {k: float(v[0]) for k, v in met.items()}}


def _piezo_pump(req, catalog, design, file, loads) -> dict:
    """A pump design file judged against ``req``: its parts and settings
    with the requirements' stroke, speed, blocked force, duty and load in
    place of the file's own (``pump_evaluate.design_from_candidate``)."""
    from ..technologies.piezo_pump.evaluate import design_from_candidate, evaluate_pump
    judged = design_from_candidate(req, {"design": design.model_dump(exclude={"stroke", "speed", "blocked_force",
                                                                              "strokes_per_second", "load"})})
    figures = evaluate_pump(judged, catalog, file)
    return {"margins": figures["margins"], "metrics": figures["metrics"]}


JUDGES = {"dc_actuator": _dc_actuator, "dc_parts": _dc_parts, "piezo_pump": _piezo_pump}
