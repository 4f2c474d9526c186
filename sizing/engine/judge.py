"""``sizing evaluate DESIGN.toml --requirements REQUIREMENTS.toml``: one
design file judged with the very checks of ``sizing solve``.

The design is rebuilt as the solve holds its own designs and re-verified
by the solve's code, so a design taken from results.json reproduces its
candidate's metrics and margins, and a design of the user's own is judged
as a solved one would be: each technology judges its own design files in
its folder (``Technology.judge``).
"""
from __future__ import annotations

from ..errors import InputError
from ..io.catalog import Catalog
from ..technologies.registry import technologies
from .loads import load_cases
from .rank import verdict


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
            for i, cand in zip(mine, tech.judge(req, catalog, [designs[i] for i in mine], [files[i] for i in mine],
                                                loads)):
                out[i] = cand
    return [_verdict(cand) for cand in out]


def _verdict(cand: dict) -> dict:
    feasible, driver = verdict(cand["margins"])
    return {"margins": dict(cand["margins"]), "feasible": feasible, "driver": driver,
            "metrics": dict(cand.get("metrics") or {}),
            "static_margins": dict(cand.get("static_margins") or cand["margins"])}
