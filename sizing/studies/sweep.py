"""``sizing sweep``: a full ``sizing solve`` at every point of a grid over
requirement fields (docs/formats.md, sweep.json).

``--vary FIELD=FROM..TO:N``: FIELD is a key of [requirements] (``stroke``)
or ``table.key`` of another table (``options.wide_gap``); FROM and TO are
written as in the file (``35mm``, ``80degC``, bare numbers SI) and are
validated by the requirements parser itself, by putting them in the file's
place. Each grid point is the file with those fields replaced (by their SI
value: bare numbers mean SI) and solved by ``engine.solve.solve``, one task
per point on the executor.
"""
from __future__ import annotations

import copy
import hashlib
import itertools
import json
import re
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from ..errors import InputError
from ..io.requirements import parse_requirements
from .executor import Executor

if TYPE_CHECKING:
    from ..engine.candidate import Candidate

VARY = re.compile(r"^\s*(?P<field>[A-Za-z_][\w.]*)\s*=\s*(?P<lo>.+?)\s*\.\.\s*(?P<hi>.+?)\s*:\s*(?P<n>\d+)\s*$")
MAX_POINTS = 400


@dataclass(frozen=True)
class Vary:
    table: str
    key: str
    values: tuple[float, ...]        # SI (degC for temperatures)

    @property
    def name(self) -> str:
        return self.key if self.table == "requirements" else f"{self.table}.{self.key}"


def parse_vary(text: str, data: dict, path) -> Vary:
    """One ``--vary`` option against the file's data; InputError naming --vary."""
    m = VARY.match(text)
    if not m:
        raise InputError(None, "--vary", f"expected FIELD=FROM..TO:N (e.g. stroke=35mm..50mm:4), got {text!r}")
    field, n = m["field"], int(m["n"])
    table, _, key = field.rpartition(".")
    table = table or "requirements"
    if not 1 <= n <= MAX_POINTS:
        raise InputError(None, f"--vary {field}", f"expected 1 to {MAX_POINTS} points, got {n}")
    ends = [_value_of(data, path, table, key, raw, field) for raw in (m["lo"], m["hi"])]
    values = np.linspace(ends[0], ends[1], n) if n > 1 else np.array(ends[:1])
    return Vary(table, key, tuple(float(v) for v in values))


def _value_of(data: dict, path, table: str, key: str, raw: str, field: str) -> float:
    if not isinstance(data.get(table, {}), dict) or (table in data and key not in data[table]
                                                      and table in ("requirements", "load")):
        raise InputError(None, f"--vary {field}", f"no field {key!r} in [{table}] of {path}")
    edited = copy.deepcopy(data)
    edited.setdefault(table, {})[key] = raw
    try:
        req = parse_requirements(edited, path)
    except InputError as exc:
        raise InputError(None, f"--vary {field}", f"{raw!r}: {exc.message}") from None
    value = getattr(getattr(req, table, None), key, None)
    if not isinstance(value, (int, float)) or isinstance(value, bool):
        raise InputError(None, f"--vary {field}", "expected a field holding one quantity")
    return float(value)


def grid_points(data: dict, varies: list[Vary]) -> list[tuple[dict, dict]]:
    """(file data, varied values) per grid point; the last --vary runs fastest."""
    points = []
    for values in itertools.product(*(v.values for v in varies)):
        edited = copy.deepcopy(data)
        for v, x in zip(varies, values):
            edited.setdefault(v.table, {})[v.key] = x
        points.append((edited, {v.name: x for v, x in zip(varies, values)}))
    if len(points) > MAX_POINTS:
        raise InputError(None, "--vary", f"expected at most {MAX_POINTS} grid points, got {len(points)}")
    return points


@dataclass
class PointTask:
    data: dict
    path: str
    catalog: object
    varied: dict


def run_point(task: PointTask) -> dict:
    """One grid point: a full solve, reduced to what the sweep reports."""
    from ..engine.solve import solve            # imported here: the engine's imports take seconds
    req = parse_requirements(task.data, task.path)
    sha = hashlib.sha256(json.dumps(task.data, sort_keys=True, default=str).encode()).hexdigest()
    results = solve(req, sha, task.catalog, fast=True).results     # a point needs feasibility, not flips
    return point_summary(results, task.varied)


def point_summary(results: dict, varied: dict) -> dict:
    """What the sweep keeps of one point's solve (its results, the
    candidates ``Candidate``s)."""
    cands = results["candidates"]
    from ..technologies.registry import technologies
    techs = sorted({c.technology for c in cands} | {t.name for t in technologies() if t.in_every_sweep_point})
    feasible = {t: sum(1 for c in cands if c.technology == t and c.feasible) for t in techs}
    best_by = {t: _brief(next((c for c in cands if c.technology == t and c.feasible), None)) for t in techs}
    best = _brief(cands[0] if cands and cands[0].feasible else None)
    front = [{"id": c.id, "name": c.name or c.id, "technology": c.technology, **_two(c.metrics)}
             for c in cands if c.pareto]
    return {"varied": varied, "requirements": results["requirements"], "feasible": feasible, "best": best,
            "best_by_technology": best_by, "front": front,
            "requirements_sha256": results["requirements_sha256"], "runtime_s": results.get("runtime_s")}


def _two(metrics: dict) -> dict:
    return {k: metrics[k] for k in ("mass_kg", "cost_usd") if k in metrics}


def _brief(c: Candidate | None) -> dict | None:
    if c is None:
        return None
    return {"id": c.id, "name": c.name or c.id, "technology": c.technology,
            "metrics": dict(c.metrics), "driver": c.driver, "rank": c.rank}


def limits(grid: list[dict], varies: list[Vary]) -> dict:
    """Where each technology stops being feasible: for each varied field, at
    each setting of the other fields, the last value (in the sweep's order)
    with a feasible design and the first value after it without one."""
    techs = sorted({t for g in grid for t in g["feasible"]})
    out = {}
    for t in techs:
        out[t] = {}
        for v in varies:
            others = [w.name for w in varies if w is not v]
            rows = []
            for key in sorted({tuple(g["varied"][o] for o in others) for g in grid}):
                line = [g for g in grid if tuple(g["varied"][o] for o in others) == key]
                ok = [g["feasible"][t] > 0 for g in line]
                last = max((i for i, f in enumerate(ok) if f), default=None)
                first_bad = next((i for i, f in enumerate(ok) if not f and (last is None or i > last)), None)
                rows.append({"others": dict(zip(others, key)),
                             "last_feasible": None if last is None else line[last]["varied"][v.name],
                             "first_infeasible": None if first_bad is None else line[first_bad]["varied"][v.name],
                             "feasible_everywhere": all(ok)})
            out[t][v.name] = rows
    return out


def sweep(data: dict, path, catalog, vary: list[str], executor: Executor, progress=None) -> dict:
    """sweep.json for the requirements ``data`` (read from ``path``)."""
    if not vary:
        raise InputError(None, "--vary", "expected at least one --vary FIELD=FROM..TO:N")
    parse_requirements(data, path)                       # the file itself is valid
    varies = [parse_vary(v, data, path) for v in vary]
    names = [v.name for v in varies]
    if len(set(names)) != len(names):
        raise InputError(None, "--vary", f"expected each field once, got {', '.join(names)}")
    points = grid_points(data, varies)
    tasks = [PointTask(d, str(path), catalog, varied) for d, varied in points]
    grid = executor.map(run_point, tasks, progress=progress)
    return {"vary": [{"field": v.name, "values": list(v.values)} for v in varies], "grid": grid,
            "limits": limits(grid, varies), "where": executor.where,
            "catalog_sha256": catalog.sha256, "requirements_file": str(Path(path))}
