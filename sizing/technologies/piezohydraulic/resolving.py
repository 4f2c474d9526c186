"""How the flips re-solve the piezohydraulic actuator (``registry.Resolving``):
by part combination, sizing only the structure materials and compensators
of the designs asked about (each is a part combination of its own, sized
by its own geometric program); the designs its solve left unsimulated are
listed, and a mass floor bounds every design from the enumeration alone."""
from __future__ import annotations

from typing import TYPE_CHECKING

import math

from ..registry import Resolving

if TYPE_CHECKING:
    from ...engine.candidate import Candidate

# margins a simulation replaces or adds (``record.sim_margins``): a design
# left unsimulated that misses only these might comply once simulated
SIMULATED = ("stroke", "speed", "overshoot", "stiffness")


def combination_key(c: Candidate) -> str:
    """The part combination (``search.Combo.key``) of a candidate."""
    k = c.components
    return f"ph-{k['stack']}-n{k['n_stacks']}-{k['fluid']}-{k['seal']}-{k['amplifier']}"


def variant_key(c: Candidate) -> tuple:
    """A candidate's part combination with its structure material and
    compensator: what one geometric program sizes (its passive variant is
    built from the as-built one)."""
    k = c.components
    return combination_key(c), k.get("material"), k.get("compensator")


def units(solve, req, catalog, loads, cs: list[Candidate]) -> list[dict]:
    """The candidates of the part combinations of ``cs`` re-sized for
    ``req`` and ``catalog`` (the structure materials and compensators of ``cs``)."""
    keys = {combination_key(c) for c in cs}
    wanted = {variant_key(c) for c in cs}
    parts = {tuple(c.components[k] for k in ("stack", "fluid", "seal", "amplifier")) for c in cs}
    return solve(
        req, catalog, loads, None, "summary", only=lambda combo: combo.key in keys,
        variants=lambda combo, v: (combo.key, v.material.id, v.compensator and v.compensator.id) in wanted,
        parts=parts,
    )[0].candidates


def unsettled(candidates: list[Candidate]) -> list[Candidate]:
    """The designs a solve left open: sized, passing every check a
    simulation does not replace, but not simulated (the solve simulates at
    most ``options.max_simulated``). Every other design was judged in full
    (simulated, or missing a check no simulation changes)."""
    return [c for c in candidates if c.stage == "sized"
            and all(v >= 0 or k in SIMULATED for k, v in c.margins.items())]


def mass_floor(req, catalog) -> float:
    """Each combination the enumeration keeps (not pruned) holds its n
    stacks and at least one amplifier unit, and a sized design's mass adds
    hydraulics, structure and compensator to them (``verify``'s mass; the
    same sum the pruned candidates' records state); inf when every
    combination is pruned."""
    from .search import enumerate_combos
    return min((c.n * c.stack.mass + c.amplifier.mass for c in enumerate_combos(req, catalog) if not c.pruned),
               default=math.inf)


RESOLVING = Resolving(units=units, unit_key=combination_key, unsettled=unsettled, mass_floor=mass_floor)
