"""What an unmodelled effect is: a model augmentation with a few physical
parameters, their bounds, and two realistic sizes.

An effect acts in one or both of two places:
- ``model_changes``: fields of the simulator's model (PiezoHydraulicModel or
  DCMotorModel) set from the effect's parameters, vectorised over candidate
  parameter sets: values {param: (n_cand,)} -> {field: (n_cand,)};
- ``measure``: the measurement path, a pure post-processing of one simulated
  position trace (sensor delay, backlash, sensor vibration).
Effects are plain data plus these two hooks (scikit-learn habit: bounds are
declared as data). An effect ``name`` is a family (the names of docs/formats.md);
the library may hold several ``form``s of one family, alternatives that the
attribution fits side by side and reports under the family name.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


@dataclass(frozen=True)
class Param:
    """One effect parameter, SI. ``log``: searched on a log scale."""

    name: str            # key in diagnosis.json, with its unit suffix
    lo: float
    hi: float
    log: bool = False
    doc: str = ""

    def to_unit(self, value):
        """Physical value -> [0, 1] search coordinate."""
        value = np.asarray(value, float)
        if self.log:
            return (np.log(value) - np.log(self.lo)) / (np.log(self.hi) - np.log(self.lo))
        return (value - self.lo) / (self.hi - self.lo)

    def from_unit(self, z):
        """[0, 1] search coordinate -> physical value."""
        z = np.clip(np.asarray(z, float), 0.0, 1.0)
        if self.log:
            return np.exp(np.log(self.lo) + z * (np.log(self.hi) - np.log(self.lo)))
        return self.lo + z * (self.hi - self.lo)


@dataclass(frozen=True)
class Effect:
    """A candidate unmodelled effect (see the module docstring)."""

    name: str                        # the family (effect name of docs/formats.md); several forms may share it
    technology: str                  # "piezohydraulic" or "dc_motor"
    params: tuple = ()
    sizes: tuple = ()                # two realistic sizes: ({param: value}, {param: value})
    source: str = ""                 # where the physics and the sizes come from
    post: bool = False               # True when only ``measure`` acts (no re-simulation)
    extra: dict = field(default_factory=dict)
    # The common case as data: each parameter sets one model field
    # ({param: field}), and the two sizes may be fractions of that field's
    # nominal value (``nominal_factors``) instead of fixed ``sizes``.
    fields: dict = field(default_factory=dict)
    nominal_factors: tuple = ()
    # Which form of the family this is (e.g. "karnopp" or "stribeck" for
    # friction): forms of one family are alternatives judged together, never
    # paired with each other and never each other's runner-up.
    form: str = "default"

    @property
    def names(self) -> list[str]:
        return [p.name for p in self.params]

    def values(self, Z: np.ndarray) -> dict[str, np.ndarray]:
        """Z (n_cand, n_par) in [0, 1] -> {param: (n_cand,)} physical."""
        Z = np.atleast_2d(np.asarray(Z, float))
        return {p.name: p.from_unit(Z[:, i]) for i, p in enumerate(self.params)}

    def unit(self, values: dict) -> np.ndarray:
        """{param: value} -> (n_par,) search coordinates."""
        return np.array([float(p.to_unit(values[p.name])) for p in self.params])

    def applicable(self, rig, model) -> bool:
        """False when the nominal model already contains the effect."""
        return True

    def for_rig(self, rig, model) -> "Effect":
        """This effect with its parameter bounds for this rig: itself, unless
        a bound depends on the rig's nominal (an effect that acts one way
        only, e.g. a softening, ends at the nominal value of its field)."""
        return self

    def sizes_for(self, rig, model) -> tuple:
        """Two realistic sizes for this rig: the declared ones, or the
        nominal value of the one field times each of ``nominal_factors``."""
        if not self.nominal_factors:
            return self.sizes
        (param, model_field), = self.fields.items()
        nominal = float(np.min(getattr(model, model_field)))
        return tuple({param: factor * nominal} for factor in self.nominal_factors)

    def time_constant(self, rig, model) -> float:
        """Longest time constant (s) of the effect at its realistic sizes:
        a run must last at least this long to show it (delays and time constants)."""
        taus = [v for size in self.sizes_for(rig, model) for k, v in size.items() if k == "delay_s" or k.endswith("time_s")]
        return float(max(taus, default=0.0))

    def observable(self, bench, head=(), z_head=np.zeros(0)) -> bool:
        """False when the campaign cannot show the effect (it is then not
        screened), e.g. a disturbance line absent from the residual."""
        return True

    def starts(self, bench, head=(), z_head=np.zeros(0)) -> list:
        """Screening start points (unit coordinates) taken from the data,
        besides the realistic sizes and the Latin hypercube."""
        return []

    def model_changes(self, model, values: dict) -> dict:
        return {model_field: values[param] for param, model_field in self.fields.items()}

    def measure(self, t: np.ndarray, y: np.ndarray, values: dict) -> np.ndarray:
        return y
