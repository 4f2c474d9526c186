"""``sizing evaluate``: static and simulated figures of one design file."""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from ..io.catalog import load_catalog
from ..io.design import load_design
from .checks import check_evaluate_steps, check_solve_steps
from .output import Payload

PART_KEYS = ("stack", "fluid", "seal", "amplifier", "actuator", "motor", "screw", "gear", "drive", "valve", "accumulator")


@dataclass(frozen=True)
class EvaluateResult(Payload):
    """The figures of one design (docs/formats.md): technology, design,
    static, simulated, margins, warnings and the ``assumed`` catalog values
    they rest on. Reads as the ``figures`` mapping; writes no file."""

    figures: dict

    def _payload(self) -> dict:
        return self.figures

    @property
    def warnings(self) -> list[str]:
        return list(self.figures["warnings"])

    def summary(self) -> str:
        """The terminal summary (report/text.py)."""
        from ..report.text import evaluation_summary
        return evaluation_summary(self.figures)


def evaluate(design_path: str | Path, catalog_dir: str | Path | None = None,
             requirements: str | Path | None = None) -> EvaluateResult:
    """Static and simulated figures of one design file (docs/formats.md).
    ``requirements``: a requirements.toml to judge the design against with
    the checks of ``sizing solve``; the figures then add ``margins``,
    ``feasible``, ``driver`` and ``judged`` (the solve's metrics and
    static margins of the design, engine/judge.py)."""
    from ..io.provenance import assumed_values

    design = load_design(design_path)
    cat = load_catalog(catalog_dir)
    check_evaluate_steps(design, cat, str(design_path))
    req = None
    if requirements is not None:
        from ..io.requirements import load_requirements
        req = load_requirements(requirements)[0]
        check_solve_steps(req, cat, str(requirements))
    from ..technologies.registry import get     # cvxpy and numba load once the inputs read well
    figures = get(design.technology).evaluate(design, cat, str(design_path))
    parts = {k: v for k, v in figures["design"].items() if k in PART_KEYS}
    figures["assumed"] = assumed_values(cat, parts)     # the catalog values this result rests on that are assumed
    if req is not None:
        figures.update(judged(req, cat, design, str(design_path), str(requirements)))
    return EvaluateResult(figures)


def judge_designs(design_paths: list, requirements: str | Path, catalog_dir: str | Path | None = None) -> list[dict]:
    """What ``evaluate --requirements`` adds, for several design files at
    once (their simulations batched as the solve's):
    per file ``margins``, ``feasible``, ``driver`` and ``judged``."""
    from ..engine.judge import judge_all
    from ..io.requirements import load_requirements
    cat = load_catalog(catalog_dir)
    req = load_requirements(requirements)[0]
    check_solve_steps(req, cat, str(requirements))
    designs = [load_design(p) for p in design_paths]
    files = [str(p) for p in design_paths]
    return [_judged(v, str(requirements)) for v in judge_all(req, cat, designs, files)]


def judged(req, cat, design, design_file: str, requirements_file: str) -> dict:
    """What ``evaluate --requirements`` adds: the verdict of the solve's checks."""
    from ..engine.judge import judge
    return _judged(judge(req, cat, design, design_file), requirements_file)


def _judged(verdict: dict, requirements_file: str) -> dict:
    from ..engine.solve_summary import _clean
    return _clean({"margins": verdict["margins"], "feasible": verdict["feasible"], "driver": verdict["driver"],
            "judged": {"requirements": requirements_file, "metrics": verdict["metrics"],
                       "static_margins": verdict["static_margins"]}})
