"""A piezo pump design file judged with the very checks of ``sizing solve``
(``Technology.judge``): ``evaluate.evaluate_pump`` on the file's parts and
settings with the requirements' stroke, speed, blocked force, duty and
load in place of the file's own (``evaluate.design_from_candidate``)."""
from __future__ import annotations


def judge(req, catalog, designs: list, files: list[str], loads) -> list[dict]:
    from .evaluate import design_from_candidate, evaluate_pump
    out = []
    for design, file in zip(designs, files):
        judged = design_from_candidate(req, {"design": design.model_dump(exclude={
            "stroke", "speed", "blocked_force", "strokes_per_second", "load"})})
        figures = evaluate_pump(judged, catalog, file)
        out.append({"margins": figures["margins"], "metrics": figures["metrics"]})
    return out
