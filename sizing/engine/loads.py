"""The load cases and the driven surface's mass, from the requirements'
load table: what every stage of a solve and ``sizing evaluate`` read, kept
apart from both so that the records (``records.PiezoBrief``) can read them
without importing the engines."""
from __future__ import annotations

from ..io.design import LoadTable
from ..physics import load as load_phys


def load_cases(load: LoadTable) -> list[dict]:
    """Forces of the load cases: explicit forces, or tip forces of the
    hinged surface at each dynamic pressure (seed Figure 7)."""
    if load.force is not None:
        return [{"load_N": f} for f in load.force]
    return [{"dynamic_pressure_Pa": p, "load_N": float(load_phys.tip_force(p, load.span, load.chord))}
            for p in load.dynamic_pressure]


def surface_mass(load: LoadTable) -> float:
    """Tip-equivalent mass of the driven surface, kg (I / c^2); 0 when the
    load is given as forces (no surface)."""
    if load.force is not None:
        return 0.0
    return float(load_phys.tip_equivalent_mass(load.span, load.chord, load.thickness, load.density))
