"""A piezo pump design file judged with the very checks of ``sizing solve``
(``Technology.judge``): ``evaluate.evaluate_pump`` on the file's parts and
settings with the requirements' stroke, speed, blocked force, duty and
load in place of the file's own (``evaluate.design_file_of``)."""
from __future__ import annotations


def judge(req, catalog, designs: list, files: list[str], loads) -> list:
    """``Judged`` of each design file, in order."""
    from ...engine.judge import Judged
    from .evaluate import design_file_of, evaluate_pump
    out = []
    for design, file in zip(designs, files):
        judged = design_file_of(req, design.model_dump(exclude={
            "stroke", "speed", "blocked_force", "strokes_per_second", "load"}))
        figures = evaluate_pump(judged, catalog, file)
        out.append(Judged(figures["margins"], figures["metrics"]))
    return out
