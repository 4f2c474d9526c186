"""Designs, technologies and grid points in the words people read: short
names, never ids; requirement fields by the names the user wrote, with
their units (``sizing.display``)."""
from __future__ import annotations

from ..display import requirement
from ..technologies.registry import label


def tech_label(tech: str) -> str:
    return label(tech)


def design_name(d: dict | None) -> str:
    """A design's short name (its id only when it has none)."""
    if not d:
        return "none"
    return d.get("name") or d["id"]


def varied_text(varied: dict) -> str:
    """A sweep point's varied fields: "stroke 40 mm, max_temperature 100 degC"."""
    return ", ".join(f"{field} {requirement(field, value)}" for field, value in varied.items())


def sweep_point_line(point: dict) -> str:
    """One line per sweep point for the terminal: the varied values, the
    feasible count per technology and the best design by short name."""
    counts = ", ".join(f"{tech_label(t)} {n}" for t, n in sorted(point["feasible"].items()))
    best = point.get("best")
    return f"{varied_text(point['varied'])}: feasible {counts}; best {design_name(best) if best else 'none feasible'}"
