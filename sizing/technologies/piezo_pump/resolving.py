"""How the flips re-solve the piezo pump (``registry.Resolving``): its
verdict and best design from the rows its stage would simulate that pass
every check the simulation does not replace (``designs.complying_designs``:
the others cannot comply), and its static screen alone where no row passes
it (``designs.could_comply``)."""
from __future__ import annotations

from ..registry import Resolving


def complying(req, catalog, loads) -> list[dict]:
    """The records of the designs that can comply, simulated."""
    from .designs import complying_designs
    from .record import pump_candidate
    return [pump_candidate(req, d) for d in complying_designs(req, catalog, loads)]


def screen(req, catalog, loads) -> bool:
    """Whether some row passes the static screen."""
    from .designs import could_comply
    return could_comply(req, catalog, loads)


RESOLVING = Resolving(complying=complying, screen=screen)
