"""Piezohydraulic candidates: from catalog parts to arrays for the physics.

``part_row`` turns one choice of parts into a dict of SI floats; ``Candidates``
holds many of them as arrays (n_cand,), which is what the static figures,
the metrics and the batch simulator consume.
"""
from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np

from ..io.catalog import Amplifier, Fluid, Seal, Stack
from ..physics import fluid as fluid_props
from ..physics import geometry, hydraulics, stack as stack_phys
from ..physics.bouc_wen import BoucWen, transfer

# Values used when a design names no fluid or seal (seed section 2.3.2-2.3.3).
SEED_FRICTION_N = (10.0, 0.2)            # wide, narrow: seed's assumption
DEFAULT_PRESSURE_RATING_PA = 21e6        # PHYSICS-NOTES: seal and casing rating
FALLBACK_FLUID = {                       # ISO VG 15 mineral oil, typical values
    "density": 870.0, "bulk_modulus": 1.5e9, "thermal_expansion": 7e-4,
    "viscosity": 15e-6, "cost_usd": 0.0,
}
AIR_FRACTION = 0.0                       # entrained air by volume (0: well bled)


@dataclass
class Candidates:
    """Many piezohydraulic candidates; every field an array (n_cand,), SI."""

    n_stacks: np.ndarray
    stiffness: np.ndarray           # N/m per stack
    stack_stroke: np.ndarray        # m, nominal at max_voltage, derated to temperature
    max_voltage: np.ndarray         # V, stack rating
    voltage: np.ndarray             # V, drive
    capacitance: np.ndarray         # F per stack, small-signal
    stack_mass: np.ndarray
    stack_cost: np.ndarray
    stack_volume: np.ndarray        # m^3 per stack
    bouc_wen: np.ndarray            # (n_cand, 6) d33, alpha, beta, gamma, delta, n
    ratio: np.ndarray
    wide_area: np.ndarray           # m^2
    wide_gap: np.ndarray            # m, oil gap in the wide chamber
    pressure_rating: np.ndarray     # Pa
    wide_mass: np.ndarray
    narrow_mass: np.ndarray
    density: np.ndarray
    bulk_modulus: np.ndarray        # Pa, at temperature, with entrained air
    thermal_expansion: np.ndarray   # 1/K
    wide_friction: np.ndarray       # N running
    narrow_friction: np.ndarray
    breakaway: np.ndarray
    k_contract: np.ndarray
    k_expand: np.ndarray
    amp_max_current: np.ndarray     # A (inf: no amplifier chosen)
    amp_slew: np.ndarray            # V/s (0: unlimited)
    amp_mass: np.ndarray
    amp_cost: np.ndarray
    seal_cost: np.ndarray
    fluid_cost: np.ndarray
    no_return: np.ndarray

    @classmethod
    def from_rows(cls, rows: list[dict]) -> "Candidates":
        data = {}
        for f in fields(cls):
            values = [row[f.name] for row in rows]
            data[f.name] = np.array(values, dtype=float)
        return cls(**data)

    def __len__(self) -> int:
        return len(self.n_stacks)

    def take(self, index) -> "Candidates":
        return Candidates(**{f.name: getattr(self, f.name)[index] for f in fields(self)})

    # Derived geometry -----------------------------------------------------
    @property
    def narrow_area(self):
        return self.wide_area / self.ratio

    @property
    def stack_free_stroke(self):
        return stack_phys.free_stroke(self.stack_stroke, self.max_voltage, self.voltage)

    @property
    def free_stroke(self):
        return self.ratio * self.stack_free_stroke

    @property
    def oil_volume(self):
        return self.wide_area * self.wide_gap + self.narrow_area * self.free_stroke


def reference_bouc_wen(stacks: dict[str, Stack]) -> Stack | None:
    """The stack whose measured Bouc-Wen parameters others borrow (seed 2.3.2)."""
    measured = [s for s in stacks.values() if s.bouc_wen is not None]
    return measured[0] if measured else None


def stack_bouc_wen(stack: Stack, reference: Stack | None) -> tuple[BoucWen, str]:
    """Bouc-Wen parameters of ``stack``: its own, or transferred in
    normalised form from the reference stack (PHYSICS-NOTES item 4)."""
    if stack.bouc_wen is not None:
        b = stack.bouc_wen
        return BoucWen(b.d33, b.alpha, b.beta, b.gamma, b.delta, b.n), "measured (catalog)"
    if reference is None or reference.bouc_wen is None:
        d = stack.stroke / stack.max_voltage
        return BoucWen(d, 0.0, 0.0, 0.0, 0.0, 1.0), "assumed: no hysteresis data, linear stack"
    b = reference.bouc_wen
    params = transfer(BoucWen(b.d33, b.alpha, b.beta, b.gamma, b.delta, b.n),
                      reference.stroke, reference.max_voltage, stack.stroke, stack.max_voltage)
    return params, f"assumed: transferred in normalised form from {reference.id}"


def part_row(stack: Stack, n_stacks: int, ratio: float, wide_area: float, voltage: float,
             bouc_wen: BoucWen, temperature: float, wide_gap: float,
             fluid: Fluid | None = None, seal: Seal | None = None,
             amplifier: Amplifier | None = None, pressure_rating: float | None = None,
             overrides: dict | None = None) -> dict:
    """One candidate as a dict of SI floats (keys are Candidates fields)."""
    o = overrides or {}
    narrow_area = wide_area / ratio
    stroke = stack_phys.derated_stroke(stack.stroke, stack.stroke_temperature_coefficient, temperature)
    free_stroke = ratio * stroke * voltage / stack.max_voltage
    rating = pressure_rating or (seal.pressure_rating if seal else DEFAULT_PRESSURE_RATING_PA)
    row = {
        "n_stacks": n_stacks, "stiffness": stack.stiffness, "stack_stroke": float(stroke),
        "max_voltage": stack.max_voltage, "voltage": voltage, "capacitance": stack.capacitance,
        "stack_mass": stack.mass, "stack_cost": stack.cost_usd,
        "stack_volume": stack.length * stack.diameter**2 * (1.0 if stack.section == "square" else np.pi / 4),
        "bouc_wen": bouc_wen.as_array(), "ratio": ratio, "wide_area": wide_area, "wide_gap": wide_gap,
        "pressure_rating": rating,
        "wide_mass": o.get("wide_piston_mass") or geometry.wide_piston_mass(wide_area, rating),
        "narrow_mass": o.get("narrow_piston_mass") or geometry.narrow_piston_mass(narrow_area, free_stroke),
        "no_return": float(o.get("no_return", False)),
    }
    row.update(_fluid_row(fluid, temperature, o))
    row.update(_seal_row(seal, wide_area, narrow_area, o))
    k_loss = o.get("loss_coefficient")
    row["k_contract"] = k_loss if k_loss is not None else float(hydraulics.contraction_loss_coefficient(ratio))
    row["k_expand"] = float(hydraulics.expansion_loss_coefficient(ratio))
    row.update(_amplifier_row(amplifier))
    return row


def _fluid_row(fluid: Fluid | None, temperature: float, o: dict) -> dict:
    if fluid is None:
        f = dict(FALLBACK_FLUID)
        bulk = f["bulk_modulus"]
    else:
        f = {"density": float(fluid_props.density_at(fluid.density, fluid.thermal_expansion, temperature)),
             "thermal_expansion": fluid.thermal_expansion, "cost_usd": fluid.cost_usd}
        bulk = float(fluid_props.bulk_modulus_at(fluid.bulk_modulus, fluid.bulk_modulus_temperature_coefficient, temperature))
    if AIR_FRACTION > 0:
        bulk = float(fluid_props.effective_bulk_modulus(bulk, AIR_FRACTION, 101325.0))
    return {"density": f["density"], "bulk_modulus": o.get("bulk_modulus") or bulk,
            "thermal_expansion": f["thermal_expansion"], "fluid_cost": f["cost_usd"]}


def _seal_row(seal: Seal | None, wide_area: float, narrow_area: float, o: dict) -> dict:
    if seal is None:
        wide, narrow, breakaway, cost = *SEED_FRICTION_N, 1.0, 0.0
    else:
        from ..physics.seals import running_friction
        d_w, d_n = 2 * geometry.radius(wide_area), 2 * geometry.radius(narrow_area)
        wide = float(running_friction(seal.friction_per_length, d_w))
        narrow = float(running_friction(seal.friction_per_length, d_n))
        breakaway, cost = seal.breakaway_ratio, 2 * seal.cost_usd
    return {"wide_friction": _pick(o.get("wide_friction"), wide),
            "narrow_friction": _pick(o.get("narrow_friction"), narrow),
            "breakaway": _pick(o.get("breakaway_ratio"), breakaway), "seal_cost": cost}


def _pick(override, default):
    return default if override is None else override


def _amplifier_row(amplifier: Amplifier | None) -> dict:
    if amplifier is None:
        return {"amp_max_current": np.inf, "amp_slew": 0.0, "amp_mass": 0.0, "amp_cost": 0.0}
    return {"amp_max_current": amplifier.max_current, "amp_slew": amplifier.slew_rate or 0.0,
            "amp_mass": amplifier.mass, "amp_cost": amplifier.cost_usd}
