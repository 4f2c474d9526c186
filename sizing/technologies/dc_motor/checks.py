"""Checks of DC design files and requirements before any work
(``api.checks`` imports this module by its folder's name, without the
registry: an input error answers before the engine loads)."""
from __future__ import annotations


def check_design_steps(design, catalog, file: str) -> None:
    """Refuse a catalog actuator whose simulation would need more steps than
    the limit: duration x rate x load cases."""
    if design.actuator not in catalog.dc_actuators:
        return
    from ...io.design import n_loads
    from ...limits import check_steps, dc_steps
    from .actuator import output_rate
    rate, out = catalog.dc_actuators[design.actuator].pid.rate, output_rate(design.duration)
    check_steps(dc_steps(design.duration, rate, n_loads(design.load), out), file, "duration",
                f"simulation steps (duration x {max(rate, out):g} Hz x load cases)")


def required_steps(req, catalog) -> float:
    """The steps of simulating the catalog's actuators (``stage.dc_actuator_steps``)."""
    from .stage import dc_actuator_steps
    return dc_actuator_steps(req, catalog)


def check_requirements_steps(req, catalog, file: str) -> None:
    """Refuse requirements whose verification of the catalog's actuators
    would need more steps than the limit: actuators x load cases x
    simulated time."""
    from ...limits import check_steps
    check_steps(required_steps(req, catalog), file, "[requirements].stroke",
                "simulation steps (DC actuators x load cases x stroke / speed)")
