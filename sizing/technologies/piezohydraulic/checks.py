"""Checks of a piezohydraulic design file before any work (``api.checks``
imports this module by its folder's name, without the registry: an input
error answers before the engine loads)."""
from __future__ import annotations


def check_design_steps(design, catalog, file: str) -> None:
    """Refuse a design whose simulation would need more steps than the
    limit: (ramp + settling) x 20 kHz x load cases."""
    from ...io.design import n_loads
    from ...limits import check_steps, piezo_steps
    from .verify import SETTLE_TIME_S
    ramp = design.ramp_time if design.ramp_time is not None else design.rise_time
    check_steps(piezo_steps(ramp + SETTLE_TIME_S, n_loads(design.load)), file, "rise_time",
                "simulation steps (rise time x 20 kHz x load cases)")
