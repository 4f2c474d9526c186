"""``sizing evaluate DESIGN.toml --requirements REQUIREMENTS.toml``: one
design file judged with the very checks of ``sizing solve``.

The design is rebuilt as the solve holds its own designs and re-verified
by the solve's code, so a design taken from results.json reproduces its
candidate's metrics and margins, and a design of the user's own is judged
as a solved one would be: each technology judges its own design files in
its folder (``Technology.judge``).
"""
from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from ..errors import InputError
from ..io.catalog import Catalog
from ..technologies.registry import technologies
from .loads import load_cases
from .rank import verdict


@dataclass(frozen=True)
class Judged:
    """What a technology's judge gives for one design file (``Technology.
    judge``): its margins and metrics as the solve's candidate holds them,
    and the margins of its static screen alone where the simulation
    replaced some (None: the same as ``margins``)."""

    margins: Mapping[str, float]
    metrics: Mapping[str, float]
    static_margins: Mapping[str, float] | None = None


def judge(req, catalog: Catalog, design, file: str) -> dict:
    """{"margins", "feasible", "driver", "metrics", "static_margins"} of
    ``design`` against ``req`` (results.json's meaning of each)."""
    return judge_all(req, catalog, [design], [file])[0]


def judge_all(req, catalog: Catalog, designs: list, files: list[str]) -> list[dict]:
    """``judge`` of several design files, in order; each technology judges
    its own together (in one batched simulation per chunk, where it
    simulates in batches as the solve does)."""
    loads = [c["load_N"] for c in load_cases(req.load)]
    out: list = [None] * len(designs)
    techs = {t.name: t for t in technologies()}
    for i, d in enumerate(designs):
        tech = techs.get(d.technology)
        if tech is None or tech.judge is None:
            raise InputError(files[i], "technology", f"no judge against requirements for {d.technology!r}")
    for name, tech in techs.items():
        mine = [i for i, d in enumerate(designs) if d.technology == name]
        if mine:
            for i, judged in zip(mine, tech.judge(req, catalog, [designs[i] for i in mine], [files[i] for i in mine],
                                                  loads)):
                out[i] = judged
    return [_verdict(cand) for cand in out]


def _verdict(judged: Judged) -> dict:
    feasible, driver = verdict(judged.margins)
    return {"margins": dict(judged.margins), "feasible": feasible, "driver": driver,
            "metrics": dict(judged.metrics or {}),
            "static_margins": dict(judged.static_margins or judged.margins)}
