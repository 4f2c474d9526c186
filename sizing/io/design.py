"""design.toml: one design for ``sizing evaluate`` (docs/formats.md)."""
from __future__ import annotations

from pathlib import Path
from typing import Optional, get_args

from pydantic import Field, field_validator

from . import toml_text
from .schema import Qty, Strict, parse_tagged


class LoadTable(Strict):
    """The hinged control surface of the seed's Figure 7, or plain forces."""

    span: Qty("length", positive=True) = 15 * 0.0254
    chord: Qty("length", positive=True) = 10 * 0.0254
    thickness: Qty("length", positive=True) = 0.0625 * 0.0254
    density: Qty("density", positive=True) = 2700.0   # surface material (its inertia, reflected by R^2); assumed aluminium
    dynamic_pressure: list[Qty("pressure", nonnegative=True)] = Field(default_factory=lambda: [10e3, 25e3])
    force: Optional[list[Qty("force")]] = None      # explicit forces instead of pressures
    stiffness: Qty("stiffness", nonnegative=True) = 0.0

    @field_validator("force")
    @classmethod
    def _some_force(cls, value):
        # an empty list would run no load case: evaluate rejects it as solve does
        if value is not None and not value:
            raise ValueError("expected at least one load case, got an empty list")
        return value


def n_loads(load: LoadTable) -> int:
    """How many load cases a design file's load gives."""
    return len(load.force) if load.force is not None else len(load.dynamic_pressure)


def design_files() -> dict[str, type]:
    """Each technology's design file model by its ``technology`` tag (its
    folder's ``design_file.DESIGN_FILE``), found without loading the engine."""
    from ..technologies.registry import folder_module, names
    kinds = [getattr(folder_module(name, "design_file"), "DESIGN_FILE", None) for name in names()]
    return {get_args(kind.model_fields["technology"].annotation)[0]: kind for kind in kinds if kind is not None}


def load_design(path: str | Path):
    """The design file of the technology its ``technology`` field names
    (each kind's tag is its own ``technology`` literal)."""
    return parse_tagged(path, "technology", design_files())


def design_toml(block: dict) -> str:
    """A results.json ``design`` block as a design.toml that ``sizing
    evaluate`` reads back: floats at full precision (a margin of 1e-7 must
    not flip on rounding), None left out, a dict value as a table."""
    top = [toml_text.line(k, v) for k, v in block.items() if v is not None and not isinstance(v, dict)]
    tables = [f"\n[{toml_text.key(k)}]\n" + "\n".join(toml_text.line(kk, vv) for kk, vv in v.items() if vv is not None)
              for k, v in block.items() if isinstance(v, dict)]
    return "\n".join(top) + "\n" + "".join(t + "\n" for t in tables)
