"""The DC motor stages of ``sizing solve``: the catalog's DC actuators,
simulated under the same load cases (``catalog_actuators``), and DC
actuators sized from parts, motor x screw x gear x drive (``from_parts``)."""
from __future__ import annotations

from collections import Counter

from ...engine.records import Outcome

from .records import DCDesign, DCPartsOutcome
from .catalog_actuators import actuator_designs
from .from_parts import dc_parts_designs
from .record import actuator_candidate, parts_candidate


def solve(req, catalog, loads, progress, detail, rows=None) -> tuple[Outcome, tuple]:
    """The catalog's DC actuators and those sized from parts; also their
    records (the report's traces re-simulate them). ``rows``: the only
    designs from parts to size (``dc_parts_designs``), for a re-solve."""
    if not req.options.dc_motors:
        return Outcome("dc_motor", [], counts=_dc_counts(DCPartsOutcome())), ()
    actuators = actuator_designs(req, catalog, loads)
    parts = dc_parts_designs(req, catalog, loads, progress, rows=rows)
    dropped = detail != "full"          # a design ruled out before simulation is counted, not recorded
    kept = [d for d in parts.designs if not (dropped and d.stage == "pruned")]
    ruled = Counter(parts.ruled_out) + Counter(_dc_pruned_reason(d) for d in parts.designs
                                               if dropped and d.stage == "pruned")
    candidates = ([actuator_candidate(req, catalog, d) for d in actuators]
                  + [parts_candidate(req, catalog, d) for d in kept])
    return Outcome("dc_motor", candidates, ruled, (), _dc_counts(parts)), actuators + parts.designs


def _dc_pruned_reason(d: DCDesign) -> str:
    """The check a DC design ruled out before simulation misses most (a NaN
    margin rules it out but names no check)."""
    missed = [k for k, v in d.margins.items() if v < 0]
    return min(missed, key=lambda k: d.margins[k]) if missed else "pruned"


def _dc_counts(parts: DCPartsOutcome) -> dict:
    """DC combinations from parts: all of them, those ruled out (by reason,
    before or after the static screen) and those simulated."""
    stages = [d.stage for d in parts.designs]
    return {"combinations": int(parts.combinations), "pruned": sum(parts.ruled_out.values()) + stages.count("pruned"),
            "simulated": stages.count("simulated")}


def dc_actuator_steps(req, catalog) -> float:
    """Simulation steps of the catalog's DC actuators over every load case."""
    from ...engine.loads import load_cases
    from ...limits import dc_steps
    from .actuator import output_rate
    from .catalog_actuators import dc_duration
    if not req.options.dc_motors:
        return 0.0
    T, n = dc_duration(req), len(load_cases(req.load))
    return float(sum(dc_steps(T, act.pid.rate, n, output_rate(T)) for act in catalog.dc_actuators.values()))
