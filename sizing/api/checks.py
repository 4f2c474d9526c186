"""Checks of a command's inputs before any work: simulation steps within the
limit (``sizing.limits``), an envelope some stack fits in, and the JSON files
an earlier command wrote. Each refusal is an InputError (exit 2, one line)."""
from __future__ import annotations

from pathlib import Path

from ..errors import InputError
from ..io.catalog import Catalog
from ..io.design import PiezoDesignFile


def n_loads(load) -> int:
    return len(load.force) if load.force is not None else len(load.dynamic_pressure)


def check_evaluate_steps(design, cat: Catalog, file: str) -> None:
    """Refuse a design whose simulation would need more steps than the
    limit: duration x rate x load cases."""
    from ..technologies.dc_motor.actuator import output_rate
    from ..technologies.piezohydraulic.verify import SETTLE_TIME_S
    from ..limits import check_steps, dc_steps, piezo_steps
    if isinstance(design, PiezoDesignFile):
        ramp = design.ramp_time if design.ramp_time is not None else design.rise_time
        check_steps(piezo_steps(ramp + SETTLE_TIME_S, n_loads(design.load)), file, "rise_time",
                    "simulation steps (rise time x 20 kHz x load cases)")
    elif getattr(design, "actuator", None) in cat.dc_actuators:
        rate, out = cat.dc_actuators[design.actuator].pid.rate, output_rate(design.duration)
        check_steps(dc_steps(design.duration, rate, n_loads(design.load), out), file, "duration",
                    f"simulation steps (duration x {max(rate, out):g} Hz x load cases)")


def check_solve_steps(req, cat: Catalog, file: str) -> None:
    """Refuse requirements whose DC verification would need more steps than
    the limit: catalog actuators x load cases x simulated time. The
    piezohydraulic designs are simulated within what is left
    (``technologies.piezohydraulic.stage.piezo_simulation_budget``): a slow, long stroke
    simulates fewer of them, or none, instead of stopping the solve."""
    from ..technologies.dc_motor.stage import dc_actuator_steps
    from ..limits import check_steps
    check_steps(dc_actuator_steps(req, cat), file, "[requirements].stroke",
                "simulation steps (DC actuators x load cases x stroke / speed)")
    check_envelope(req, cat, file)


def check_envelope(req, cat: Catalog, file: str) -> None:
    """Refuse an envelope that no stack fits in: shorter than the shortest
    stack or narrower than the thinnest one."""
    env, stacks = req.envelope, list(cat.stacks.values())
    if not stacks:
        return
    for field, limit, need, what in (("max_length", env.max_length, min(s.length for s in stacks), "length"),
                                     ("max_diameter", env.diameter, min(s.diameter for s in stacks), "diameter")):
        if limit is not None and limit < need:
            raise InputError(file, f"[envelope].{field}",
                             f"expected room for at least one stack: the smallest stack {what} is "
                             f"{need * 1e3:g} mm, the envelope gives {limit * 1e3:g} mm")


def one_of(value, choices, option: str) -> None:
    """An option that takes one of a few words."""
    if value not in choices:
        words = " or ".join(f'"{c}"' for c in choices if c is not None)
        raise InputError(None, option, f"expected {words}, got {value!r}")


def read_json(path: Path, what: str, writer: str):
    """A JSON file a command wrote (exit 2, one line, when it is not JSON)."""
    import json

    from ..io.schema import read_input_bytes
    try:
        return json.loads(read_input_bytes(path, f"a {what}").decode("utf-8"))
    except (json.JSONDecodeError, UnicodeDecodeError, RecursionError) as exc:
        raise InputError(str(path), None, f"expected a {what} written by {writer} ({exc})") from None
