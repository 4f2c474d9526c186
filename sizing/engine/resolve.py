"""Re-solve one technology with a requirement or a catalog value changed:
what the flips (``flip.py``) bisect over.

Each re-solve runs the technology's own stages of ``solve`` (enumeration,
sizing, static screen, simulation, margins) on the changed inputs and
judges the candidates with the same ``rank.standings``. Two things keep it
cheap without changing its answer:

* Feasibility is monotone in each requirement: a part combination with no
  feasible design at a requirement has none at a stricter one (sizing is
  re-run, so this is the sizing's optimality, not a margin read off a
  design). A search that tightens therefore re-solves only the designs
  feasible today, one combination at a time, most slack first, and stops
  at the first that still complies; a design found feasible (infeasible) at
  one value is so at every looser (stricter) one without a re-solve.
* A changed catalog value only moves the designs that hold that part: the
  others keep their solved verdicts (``fixed``) and only the holders are
  re-solved.

A re-solve is asked one question at a time (does this design still comply
at this value?) and answers for its whole part combination; a
piezohydraulic one sizes only the structure materials and compensators of
the designs asked about (each is a part combination of its own, sized by
its own geometric program), and reads back, by their whole input, the
programs, simulations and enumerations run before at the same value
(``stage_cache.py``). A flip found this way is confirmed by re-solving the
technology whole, except where today's solve judged every combination in
full (``unsettled``): then only the combinations it left open and those
feasible today can comply at a stricter value. The piezo pump is
re-solved whole, but simulates only the rows its stage would simulate that
pass every check the simulation does not replace
(``pump.complying_designs``): the others cannot comply.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, fields, replace

from .rank import OBJECTIVE_KEYS, standings

DC_PARTS = {"motor": "motors", "screw": "screws", "gear": "gears", "drive": "drives", "actuator": "dc_actuators"}


@dataclass(frozen=True)
class Verdict:
    """One technology after a (re-)solve: feasible, the id and first
    objective of its best feasible design, and its feasible candidates
    (the ``Alive`` of a search that tightens from here)."""

    feasible: bool
    best: str | None = None
    objective: float = math.inf
    alive: tuple = ()


def verdict_of(req, candidates: list[dict]) -> Verdict:
    """The technology's verdict over ``candidates`` (results.json records),
    with the ranking ``solve`` uses."""
    if not candidates:
        return Verdict(False)
    keys = [OBJECTIVE_KEYS[k] for k in req.objectives.minimize]
    ranked = standings([c["margins"] for c in candidates], [c.get("metrics") or {} for c in candidates], keys)
    feasible = [(s.rank, c) for c, s in zip(candidates, ranked) if s.feasible]
    if not feasible:
        return Verdict(False)
    best = min(feasible, key=lambda rc: rc[0])[1]
    value = (best.get("metrics") or {}).get(keys[0]) if keys else None
    return Verdict(True, best["id"], value if value is not None else math.inf,
                   tuple(c for _, c in feasible))


def piezo_key(c: dict) -> str:
    """The part combination (``search.Combo.key``) of a piezohydraulic candidate."""
    k = c["components"]
    return f"ph-{k['stack']}-n{k['n_stacks']}-{k['fluid']}-{k['seal']}-{k['amplifier']}"


def variant_key(c: dict) -> tuple:
    """A piezohydraulic candidate's part combination with its structure
    material and compensator: what one geometric program sizes (its passive
    variant is built from the as-built one)."""
    k = c["components"]
    return piezo_key(c), k.get("material"), k.get("compensator")


def unit_key(tech: str, c: dict) -> str:
    """What one re-solve of candidate ``c`` covers: its piezohydraulic part
    combination (every material and compensator), else the design itself."""
    return piezo_key(c) if tech == "piezohydraulic" else c["id"]


# margins a simulation replaces or adds (``candidate.sim_margins``): a design
# left unsimulated that misses only these might comply once simulated
SIMULATED = ("stroke", "speed", "overshoot", "stiffness")


def unsettled(tech: str, candidates: list[dict]) -> list[dict] | None:
    """The piezohydraulic designs a solve left open: sized, passing every
    check a simulation does not replace, but not simulated (the solve
    simulates at most ``options.max_simulated``). Every other design was
    judged in full (simulated, or missing a check no simulation changes).
    None for a technology whose solve does not record every design it
    leaves unsimulated (the DC search counts those it drops)."""
    if tech != "piezohydraulic":
        return None
    return [c for c in candidates if c.get("stage") == "sized"
            and all(v >= 0 or k in SIMULATED for k, v in c["margins"].items())]


def whole(stages, tech: str, req, catalog, loads) -> list[dict]:
    """Every candidate of ``tech`` re-solved for ``req`` and ``catalog``
    (``stages``: the technologies' stages of ``solve``, ``solve.technology_stages``)."""
    return getattr(stages, tech)(req, catalog, loads, None, "summary")[0].candidates


def units(stages, tech: str, req, catalog, loads, cs: list[dict]) -> list[dict]:
    """The candidates of the part combinations of candidates ``cs``
    re-solved for ``req`` and ``catalog``: piezohydraulic combinations
    re-sized (the structure materials and compensators of ``cs``), DC designs from
    parts (those of ``cs``, each simulated) or catalog DC actuators
    re-simulated."""
    if tech == "piezohydraulic":
        keys = {piezo_key(c) for c in cs}
        wanted = {variant_key(c) for c in cs}
        parts = {tuple(c["components"][k] for k in ("stack", "fluid", "seal", "amplifier")) for c in cs}
        return stages.piezohydraulic(
            req, catalog, loads, None, "summary", only=lambda combo: combo.key in keys,
            variants=lambda combo, v: (combo.key, v.material.id, v.compensator and v.compensator.id) in wanted,
            parts=parts,
        )[0].candidates
    if tech == "dc_motor":
        rows = {tuple((c.get("components") or {}).get(k) for k in ("motor", "screw", "gear", "drive")) for c in cs}
        return stages.dc_motor(req, dc_parts_of(catalog, tuple(cs)), loads, None, "summary", rows=rows)[0].candidates
    raise ValueError(f"no re-solve by design for {tech!r}")


def mass_floor(tech: str, req, catalog) -> float | None:
    """A lower bound on the mass (kg) of every design ``tech`` can give for
    ``req``, from its enumeration alone (no sizing); None where none is
    known. Piezohydraulic: each combination the enumeration keeps (not
    pruned) holds its n stacks and at least one amplifier unit, and a sized
    design's mass adds hydraulics, structure and compensator to them
    (``verify``'s mass; the same sum the pruned candidates' records state);
    inf when every combination is pruned."""
    if tech != "piezohydraulic":
        return None
    from ..technologies.piezohydraulic.search import enumerate_combos
    return min((c.n * c.stack.mass + c.amplifier.mass for c in enumerate_combos(req, catalog) if not c.pruned),
               default=math.inf)


def pump_lightest(stages, req, catalog, loads) -> tuple[str, float] | None:
    """The pump's best complying design (id, first objective), None when
    none complies: of the rows the solve's pump stage would simulate, those
    that pass every check the simulation does not replace, simulated
    (``complying_designs``: the same verdict and best design; the
    static screen alone when no row passes those checks)."""
    from ..technologies.piezo_pump.designs import complying_designs
    from ..technologies.piezo_pump.record import pump_candidate
    v = verdict_of(req, [pump_candidate(req, d) for d in complying_designs(req, catalog, loads)])
    return (v.best, v.objective) if v.feasible else None


def pump_could_comply(req, catalog, loads) -> bool:
    """The pump's static screen alone (``pump.could_comply``)."""
    from ..technologies.piezo_pump.designs import could_comply
    return could_comply(req, catalog, loads)


def dc_parts_of(catalog, alive: tuple):
    """The catalog with only the DC parts (and catalog actuators) that
    ``alive`` DC designs use; the other technologies' parts are kept."""
    used = {attr: set() for attr in DC_PARTS.values()}
    for c in alive:
        for kind, ident in (c.get("components") or {}).items():
            if kind in DC_PARTS and ident is not None:
                used[DC_PARTS[kind]].add(ident)
    return replace(catalog, **{attr: {k: v for k, v in getattr(catalog, attr).items() if k in ids}
                               for attr, ids in used.items()})


def group_of(catalog, ident: str) -> str:
    """The Catalog attribute (``stacks``, ``motors`` ...) that holds ``ident``."""
    for f in fields(catalog):
        group = getattr(catalog, f.name)
        if isinstance(group, dict) and f.name not in ("files", "origin") and ident in group:
            return f.name
    raise KeyError(ident)


def with_value(catalog, ident: str, field: str, value: float):
    """The catalog with ``ident``'s ``field`` set to ``value`` (SI)."""
    attr = group_of(catalog, ident)
    group = getattr(catalog, attr)
    return replace(catalog, **{attr: {**group, ident: group[ident].model_copy(update={field: value})}})


def holds(c: dict, ident: str) -> bool:
    """Whether candidate ``c`` is built with catalog entry ``ident``."""
    return ident in (v for v in (c.get("components") or {}).values() if isinstance(v, str))
