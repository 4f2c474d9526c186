"""No return mechanism: the stacks push the wide piston but cannot pull it
back (seed sec. 4: the first prototype had to be reset by hand), so on a
falling voltage the output stays put unless the load pushes it back.

Model: one-sided stack contact. No parameter; it has one size.
"""
from __future__ import annotations

import numpy as np

from .base import Effect


class NoReturn(Effect):
    def applicable(self, rig, model):
        return float(np.max(model.no_return)) < 0.5

    def model_changes(self, model, values):
        n = max([len(np.atleast_1d(v)) for v in values.values()] or [1])
        return {"no_return": np.ones(n)}


NO_RETURN = NoReturn(
    name="no_return", technology="piezohydraulic", params=(), sizes=({}, {}),
    source="seed sec. 4 (first prototype without return mechanism); docs/models.md")

# the forms this module adds to the library (effects.library), the family's default first
FORMS = (NO_RETURN,)
