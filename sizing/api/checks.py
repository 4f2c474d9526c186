"""Checks of a command's inputs before any work: simulation steps within the
limit (``sizing.limits``), an envelope some stack fits in, and the JSON files
an earlier command wrote. Each refusal is an InputError (exit 2, one line)."""
from __future__ import annotations

from pathlib import Path

from ..errors import InputError
from ..io.catalog import Catalog
from ..technologies.registry import checks_module as _checks


def check_evaluate_steps(design, cat: Catalog, file: str) -> None:
    """Refuse a design whose simulation would need more steps than the
    limit (its technology's ``checks.check_design_steps``)."""
    check = getattr(_checks(design.technology), "check_design_steps", None)
    if check is not None:
        check(design, cat, file)


def check_solve_steps(req, cat: Catalog, file: str) -> None:
    """Refuse requirements whose verification would need more steps than
    the limit (each technology's ``checks.check_requirements_steps``); the
    technologies without such a check simulate within what is left (a slow,
    long stroke simulates fewer designs, or none, instead of stopping the
    solve); then the envelope."""
    from ..technologies.registry import names
    for technology in names():
        check = getattr(_checks(technology), "check_requirements_steps", None)
        if check is not None:
            check(req, cat, file)
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
