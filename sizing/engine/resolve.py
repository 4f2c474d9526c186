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
at this value?) and answers for its whole part combination, as the
technology re-solves by combination (``registry.Resolving``, in its
folder), and reads back, by their whole input, the programs, simulations
and enumerations run before at the same value (``stage_cache.py``). A flip
found this way is confirmed by re-solving the technology whole, except
where today's solve judged every combination in full (``unsettled``):
then only the combinations it left open and those feasible today can
comply at a stricter value. A technology whose verdict is read off its
complying designs alone (``Resolving.complying``) is re-solved whole, but
simulates only the designs that pass every check the simulation does not
replace: the others cannot comply.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, fields, replace

from ..technologies.registry import resolving, technologies
from .candidate import Candidate
from .rank import OBJECTIVE_KEYS, standings


@dataclass(frozen=True)
class Verdict:
    """One technology after a (re-)solve: feasible, the id and first
    objective of its best feasible design, and its feasible candidates
    (``alive``: where a search that tightens from here starts)."""

    feasible: bool
    best: str | None = None
    objective: float = math.inf
    alive: tuple = ()


def verdict_of(req, candidates: list[Candidate]) -> Verdict:
    """The technology's verdict over ``candidates``, with the ranking
    ``solve`` uses."""
    if not candidates:
        return Verdict(False)
    keys = [OBJECTIVE_KEYS[k] for k in req.objectives.minimize]
    ranked = standings([c.margins for c in candidates], [c.metrics or {} for c in candidates], keys)
    feasible = [(s.rank, c) for c, s in zip(candidates, ranked) if s.feasible]
    if not feasible:
        return Verdict(False)
    best = min(feasible, key=lambda rc: rc[0])[1]
    value = (best.metrics or {}).get(keys[0]) if keys else None
    return Verdict(True, best.id, value if value is not None else math.inf,
                   tuple(c for _, c in feasible))


def unit_key(tech: str, c: Candidate) -> str:
    """What one re-solve of candidate ``c`` covers (``Resolving.unit_key``:
    its part combination, or the design itself)."""
    return resolving(tech).unit_key(c)


def unsettled(tech: str, candidates: list[Candidate]) -> list[Candidate] | None:
    """The designs a solve left open: sized, passing every check a
    simulation does not replace, but not simulated. None for a technology
    whose solve does not record every design it leaves unsimulated (the DC
    search counts those it drops)."""
    return resolving(tech).unsettled(candidates)


def whole(stages, tech: str, req, catalog, loads) -> list[Candidate]:
    """Every candidate of ``tech`` re-solved for ``req`` and ``catalog``
    (``stages``: the technologies' stages of ``solve``, ``solve.technology_stages``)."""
    return _candidates(getattr(stages, tech)(req, catalog, loads, None, "summary")[0].candidates)


def _candidates(records: list[dict]) -> list[Candidate]:
    """The candidates of a technology's results.json records, as ``solve``
    makes them before ranking."""
    return [Candidate.from_dict(r) for r in records]


def units(stages, tech: str, req, catalog, loads, cs: list[Candidate]) -> list[Candidate]:
    """The candidates of the part combinations of candidates ``cs``
    re-solved for ``req`` and ``catalog`` (``Resolving.units``)."""
    by_units = resolving(tech).units
    if by_units is None:
        raise ValueError(f"no re-solve by design for {tech!r}")
    return _candidates(by_units(getattr(stages, tech), req, catalog, loads, cs))


def mass_floor(tech: str, req, catalog) -> float | None:
    """A lower bound on the mass (kg) of every design ``tech`` can give for
    ``req``, from its enumeration alone (no sizing); None where none is
    known (``Resolving.mass_floor``)."""
    return resolving(tech).mass_floor(req, catalog)


def by_complying(tech: str) -> bool:
    """Whether the flips read ``tech``'s verdict off its complying designs
    alone (``lightest``) rather than re-solving designs one by one."""
    return resolving(tech).complying is not None


def lightest(tech: str, req, catalog, loads) -> tuple[str, float] | None:
    """``tech``'s best complying design (id, first objective), None when
    none complies: of the designs its stage would simulate, those that pass
    every check the simulation does not replace, simulated
    (``Resolving.complying``: the same verdict and best design)."""
    v = verdict_of(req, _candidates(resolving(tech).complying(req, catalog, loads)))
    return (v.best, v.objective) if v.feasible else None


def pump_lightest(stages, req, catalog, loads) -> tuple[str, float] | None:
    """``lightest`` of the technology whose verdict the flips read off its
    complying designs (the pump); None when there is none."""
    tech = next((t.name for t in technologies() if t.resolving.complying is not None), None)
    return None if tech is None else lightest(tech, req, catalog, loads)


def screens(tech: str) -> bool:
    """Whether ``tech`` has a static screen the flips can bisect alone."""
    return resolving(tech).screen is not None


def could_comply(tech: str, req, catalog, loads) -> bool:
    """``tech``'s static screen alone (``Resolving.screen``)."""
    return resolving(tech).screen(req, catalog, loads)


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


def holds(c: Candidate, ident: str) -> bool:
    """Whether candidate ``c`` is built with catalog entry ``ident``."""
    return ident in (v for v in (c.components or {}).values() if isinstance(v, str))
