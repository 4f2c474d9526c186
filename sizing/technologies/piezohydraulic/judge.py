"""A piezohydraulic design file judged with the very checks of ``sizing
solve`` (``Technology.judge``): the parts as one search combination
(``search.combos_of``), the geometry, structure and drive of the file as a
``convex.SizingResult`` (amplifier units and ramp fixed by the file), then
``stage.verify_sized``: static figures, margins, the simulation under every
load case of the requirements, verdict. A passive spacer is derived again
from the thermal budget, as the solve derives it."""
from __future__ import annotations

from ...engine.evaluate import lookup
from ...engine.judge import Judged
from .records import Variant
from ...errors import InputError
from ...io.catalog import Catalog
from .convex import SizingResult
from .design_file import PiezoDesignFile
from .evaluate_file import geometry, structure_of
from .search import combos_of


def judge(req, catalog: Catalog, designs: list[PiezoDesignFile], files: list[str], loads) -> list[Judged]:
    """``designs`` verified together (one batched simulation per chunk, as
    the solve), each as its candidate's margins and metrics."""
    from .stage import verify_sized
    triples = [_triple(req, catalog, d, f) for d, f in zip(designs, files)]
    out = []
    for design, cands in zip(designs, verify_sized(req, catalog, triples, loads)):
        passive = [c for c in cands if c["id"].endswith("-pc")]
        c = passive[0] if design.spacer_length > 0 and passive else cands[0]
        out.append(Judged(c["margins"], c["metrics"], c.get("static_margins")))
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
