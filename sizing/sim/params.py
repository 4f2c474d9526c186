"""Parameter sets of the batch simulators: a dataclass whose fields are
floats or arrays (n_cand,), flattened into the float matrix a compiled
kernel reads column by column."""
from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np


class ParameterSet:
    """Mixin for a dataclass; subclasses set PARAMS, the kernel's column order."""

    PARAMS: tuple[str, ...] = ()

    def matrix(self) -> np.ndarray:
        """(n_cand, len(PARAMS)) float matrix, scalars broadcast."""
        values = [np.asarray(getattr(self, name), dtype=float) for name in self.PARAMS]
        n = max(v.size for v in values)
        return np.column_stack([np.broadcast_to(v, (n,)) for v in values]).astype(float)

    @property
    def n_candidates(self) -> int:
        return self.matrix().shape[0]

    def replace(self, **changes):
        data = {f.name: getattr(self, f.name) for f in fields(self)}
        data.update(changes)
        return type(self)(**data)


@dataclass
class StackParameters(ParameterSet):
    """The fields a stack-driven simulator's parameters begin with: the
    stacks' stiffness (N/m), d33 (m/V) and Bouc-Wen hysteresis (seed eq.
    2: alpha in m/V, delta in m/V, beta, gamma and n_bw dimensionless)."""

    k_stacks: object
    d33: object
    alpha: object
    beta: object
    gamma: object
    delta: object
    n_bw: object
