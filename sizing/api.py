"""The library's front door: one function per command, returning plain
result objects (dicts of SI floats). ``cli.py`` is a thin layer over this."""
from __future__ import annotations

from pathlib import Path

from .io.catalog import Catalog, load_catalog
from .io.design import PiezoDesignFile, load_design


def catalog(folder: str | Path | None = None) -> Catalog:
    return load_catalog(folder)


def evaluate(design_path: str | Path, catalog_dir: str | Path | None = None) -> dict:
    """Static and simulated figures of one design file (CONTRACTS.md)."""
    from .engine.evaluate import evaluate_dc, evaluate_piezo

    design = load_design(design_path)
    cat = load_catalog(catalog_dir)
    if isinstance(design, PiezoDesignFile):
        return evaluate_piezo(design, cat, str(design_path))
    return evaluate_dc(design, cat, str(design_path))
