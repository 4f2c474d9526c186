"""``sizing evaluate``: static and simulated figures of one design file."""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from ..io.catalog import load_catalog
from ..io.design import PiezoDesignFile, load_design
from .checks import check_evaluate_steps
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


def evaluate(design_path: str | Path, catalog_dir: str | Path | None = None) -> EvaluateResult:
    """Static and simulated figures of one design file (docs/formats.md)."""
    from ..engine.evaluate import evaluate_dc, evaluate_piezo
    from ..engine.pump_evaluate import evaluate_pump
    from ..io.design import PumpDesignFile
    from ..io.provenance import assumed_values

    design = load_design(design_path)
    cat = load_catalog(catalog_dir)
    check_evaluate_steps(design, cat, str(design_path))
    run = (evaluate_pump if isinstance(design, PumpDesignFile)
           else evaluate_piezo if isinstance(design, PiezoDesignFile) else evaluate_dc)
    figures = run(design, cat, str(design_path))
    parts = {k: v for k, v in figures["design"].items() if k in PART_KEYS}
    figures["assumed"] = assumed_values(cat, parts)     # the catalog values this result rests on that are assumed
    return EvaluateResult(figures)
