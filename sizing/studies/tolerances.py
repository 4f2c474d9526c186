"""Perturb a design's catalog parts by the [tolerances] of requirements.toml.

A tolerance ``"kind.field" = s`` is a relative 1-sigma normal spread: each
sample multiplies the field by ``1 + s z`` with z ~ N(0, 1), floored at
``FACTOR_FLOOR`` so a positive quantity stays positive (at s = 10 % that
floor is 9.5 sigma away). The perturbed parts then go through the solve's
own checks (``Technology.verify_perturbed``); nothing here computes physics
beyond picking the inputs.

Two rules tie fields together:
- ``stack.stroke`` and ``stack.stroke_per_volt`` both scale the stack's
  displacement per volt: stroke, stroke_per_volt and the measured Bouc-Wen
  loop (carried by ``physics.bouc_wen.transfer``) move together, so the
  simulated stroke follows the catalog stroke.
- ``operating.temperature`` (a pseudo-field): the temperature the design
  works at, uniform over the top fraction s of the required range; the
  parts' properties follow it through the solve's own temperature laws
  (ratings are still judged at the required maximum).
- ``stack.bouc_wen.PARAM``: a relative spread of one of the stack's Bouc-Wen
  parameters as the solve uses them (measured, or transferred from the
  reference stack), e.g. a fit's standard error over its value.
- ``fluid.air_fraction`` (a pseudo-field) is entrained free air, an absolute
  volume fraction a = s |z| (half-normal: air is never negative), lowering
  the oil's bulk modulus by Wood's rule at ``AIR_PRESSURE_PA``
  (``physics.fluid.effective_bulk_modulus``).
- DC designs from parts (``perturbed_parts``): ``motor.torque_constant``
  also scales ``back_emf_constant`` (one magnet flux: k_t = k_e in SI), and
  an efficiency (screw, gear) is capped at 1.

A tolerance applies to the designs whose parts have that field
(``applicable``): stack, fluid, seal and amplifier fields to designs of
stacks and oil, motor, screw, gear and drive fields to DC designs from parts (gear
fields only where the design has a gear), ``operating.temperature`` to all.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..io.catalog import BoucWenTable
from ..physics import fluid as fluid_props
from ..physics.bouc_wen import BoucWen, transfer

FACTOR_FLOOR = 0.05
# assumed: oil pre-charged to ~1 MPa absolute (bootstrap reservoir); free air
# at atmospheric pressure would be ten times softer (docs/models.md, hydraulic stage).
AIR_PRESSURE_PA = 1.0e6
DISPLACEMENT_FIELDS = ("stroke", "stroke_per_volt")
OPERATING_TEMPERATURE = "operating.temperature"
BOUC_WEN_PREFIX = "stack.bouc_wen."
# samples whose operating temperatures fall on the same step are verified
# together (one simulation call per step): 2 K moves the derated stack
# stroke and the bulk modulus by ~0.1 %
TEMPERATURE_STEP_K = 2.0


@dataclass(frozen=True)
class Tolerance:
    key: str          # "stack.stiffness"
    spread: float     # relative 1-sigma (absolute for fluid.air_fraction)

    @property
    def part(self) -> str:
        return self.key.partition(".")[0]

    @property
    def field(self) -> str:
        return self.key.partition(".")[2]


def tolerances_of(spreads: dict[str, float]) -> list[Tolerance]:
    """Sorted, so the order of the sample columns does not depend on the file."""
    return [Tolerance(k, float(v)) for k, v in sorted(spreads.items())]


def applicable(tols: list[Tolerance], design) -> list[Tolerance]:
    """The tolerances that move ``design``'s parts (``engine.sized.study_designs``:
    a (combo, variant, sizing) triple, or a design that names the parts its
    tolerances move, ``tolerated_parts``, and whether the operating
    temperature is sampled for it, ``sampled_temperature``), in the given order."""
    from ..io.requirements import PIEZO_PARTS
    parts = getattr(design, "tolerated_parts", PIEZO_PARTS)
    sampled = getattr(design, "sampled_temperature", True)
    return [t for t in tols if (sampled and t.key == OPERATING_TEMPERATURE) or t.part in parts]


def factors(tols: list[Tolerance], z: np.ndarray) -> np.ndarray:
    """Multiplying factor per sample and tolerance; for fluid.air_fraction
    the air fraction, for operating.temperature the fraction of the range
    below the maximum (uniform: the normal z mapped through its CDF).
    z (n, p) standard normal."""
    from scipy.special import ndtr
    s = np.array([t.spread for t in tols])
    air = np.array([t.key == "fluid.air_fraction" for t in tols])
    temp = np.array([t.key == OPERATING_TEMPERATURE for t in tols])
    relative = np.maximum(1.0 + s * z, FACTOR_FLOOR)
    return np.where(air, s * np.abs(z), np.where(temp, s * ndtr(z), relative))


def operating_temperatures(tols: list[Tolerance], f: np.ndarray, low: float, high: float):
    """Per sample, the operating temperature (degC) rounded to TEMPERATURE_STEP_K,
    or None when the temperature does not vary."""
    cols = [j for j, t in enumerate(tols) if t.key == OPERATING_TEMPERATURE]
    if not cols:
        return None
    t = high - f[:, cols[0]] * max(high - low, 0.0)
    return np.round(t / TEMPERATURE_STEP_K) * TEMPERATURE_STEP_K


def perturbed_combo(combo, tols: list[Tolerance], row: np.ndarray, bouc_wen: BoucWen | None = None):
    """The combo with its parts' fields scaled by one sample's factors.
    ``bouc_wen``: the stack's parameters as the solve uses them (measured or
    transferred, ``parts.stack_bouc_wen`` of the stacks' technology), needed when a
    ``stack.bouc_wen.*`` tolerance scales them."""
    updates = {"stack": {}, "fluid": {}, "seal": {}, "amplifier": {}}
    displacement, air, loop = 1.0, 0.0, {}
    for t, f in zip(tols, row):
        if t.key == OPERATING_TEMPERATURE:
            continue                       # not a part: the requirements' temperature (robust.run_batch)
        if t.key.startswith(BOUC_WEN_PREFIX):
            loop[t.key.removeprefix(BOUC_WEN_PREFIX)] = float(f)
        elif t.key == "fluid.air_fraction":
            air = float(f)
        elif t.part == "stack" and t.field in DISPLACEMENT_FIELDS:
            displacement *= float(f)
        else:
            part = getattr(combo, t.part)
            updates[t.part][t.field] = getattr(part, t.field) * float(f)
    stack = combo.stack
    if loop:
        if bouc_wen is None:
            raise ValueError("a stack.bouc_wen tolerance needs the stack's Bouc-Wen parameters")
        b = replace(bouc_wen, **{k: getattr(bouc_wen, k) * f for k, f in loop.items()})
        stack = stack.model_copy(update={"bouc_wen": _table(b)})
    if displacement != 1.0:
        updates["stack"].update(_scaled_displacement(stack, displacement))
    if loop:
        updates["stack"].setdefault("bouc_wen", stack.bouc_wen)
    if air > 0.0:
        k = updates["fluid"].get("bulk_modulus", combo.fluid.bulk_modulus)
        updates["fluid"]["bulk_modulus"] = float(fluid_props.effective_bulk_modulus(k, air, AIR_PRESSURE_PA))
    parts = {name: getattr(combo, name).model_copy(update=u) for name, u in updates.items() if u}
    return replace(combo, **parts)


def _scaled_displacement(stack, factor: float) -> dict:
    out = {"stroke": stack.stroke * factor, "stroke_per_volt": stack.stroke_per_volt * factor}
    if stack.bouc_wen is not None:
        b = stack.bouc_wen
        moved = transfer(BoucWen(b.d33, b.alpha, b.beta, b.gamma, b.delta, b.n),
                         stack.stroke, stack.max_voltage, stack.stroke * factor, stack.max_voltage)
        out["bouc_wen"] = _table(moved)
    return out


def _table(b: BoucWen) -> BoucWenTable:
    return BoucWenTable.model_construct(d33=b.d33, alpha=b.alpha, beta=b.beta, gamma=b.gamma, delta=b.delta, n=b.n)


def perturbed_parts(parts, tols: list[Tolerance], f: np.ndarray):
    """``parts`` (a ``PartArrays`` of the DC parts, one row)
    repeated once per sample, each field named by a tolerance scaled by that
    sample's factor (f (n, p), ``factors``). The catalog parts are untouched."""
    n = f.shape[0]
    out = parts.take(np.zeros(n, dtype=int))
    values = dict(out.values)
    for j, t in enumerate(tols):
        if t.key == OPERATING_TEMPERATURE:
            continue                       # not a part: the operating temperature (robust.run_batch)
        names = [f"{t.part}_{t.field}"] + (["motor_back_emf_constant"] if t.key == "motor.torque_constant" else [])
        for name in names:
            scaled = values[name] * f[:, j]
            values[name] = np.minimum(scaled, 1.0) if t.field == "efficiency" else scaled
    out.values = values
    return out
