"""Piezohydraulic candidates: from catalog parts to arrays for the physics.

``part_row`` turns one choice of parts into a dict of SI floats; ``Candidates``
holds many of them as arrays (n_cand,), which is what the static figures,
the metrics and the batch simulator consume.
"""
from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np

from ...io.catalog import Amplifier, Fluid, Seal, Stack
from ...physics import fluid as fluid_props
from ...physics import geometry, hydraulics, seals, stack as stack_phys
from ...physics.bouc_wen import BoucWen, transfer

# Values used when a design names no fluid or seal (seed section 2.3.2-2.3.3).
SEED_FRICTION_N = (10.0, 0.2)            # wide, narrow: seed's assumption
DEFAULT_PRESSURE_RATING_PA = 21e6        # docs/models.md (force path): seal and casing rating
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
    # seals at pressure, force path, thermal budget, geometry
    wide_friction_cp: np.ndarray    # N/Pa: running friction added per Pa of chamber pressure
    narrow_friction_cp: np.ndarray
    mat_E: np.ndarray               # structure material (caps, base plate, frame, casing)
    mat_nu: np.ndarray
    mat_density: np.ndarray
    mat_cte: np.ndarray             # 1/K, linear
    mat_yield: np.ndarray
    mat_cost: np.ndarray            # USD/kg
    cap_thickness: np.ndarray       # m, end cap and base plate
    frame_area: np.ndarray          # m^2, tie rods in total
    spacer_length: np.ndarray       # m, low-expansion spacer in the stack column (0: none)
    spacer_E: np.ndarray
    spacer_density: np.ndarray
    spacer_cte: np.ndarray
    spacer_cost: np.ndarray
    stack_length: np.ndarray        # m
    stack_diameter: np.ndarray      # m
    stack_cte: np.ndarray           # 1/K along the stroke
    comp_kind: np.ndarray           # 0 none, 1 accumulator (open), 2 orifice reservoir
    comp_volume_stiffness: np.ndarray   # Pa/m^3
    comp_leak: np.ndarray           # m^3/(s Pa)
    comp_capacity: np.ndarray       # m^3
    comp_mass: np.ndarray
    comp_cost: np.ndarray
    surface_mass: np.ndarray        # kg, tip-equivalent mass of the driven surface (I / c^2)
    delta_T: np.ndarray             # K, fill temperature to the required temperature
    amp_continuous: np.ndarray      # A, amplifier continuous current per unit (inf: none)
    amp_peak_duration: np.ndarray   # s, how long one unit may draw amp_max_current
    amp_recovery: np.ndarray        # fraction of C V^2 a cycle the drive returns
    amp_units: np.ndarray           # units in parallel (amp_* ratings, mass and cost are per unit)
    loss_factor: np.ndarray         # small-signal tan(delta) of the stack
    stack_square: np.ndarray        # 1: square section, 0: circular
    edge_restraint: np.ndarray      # end cap and base plate edge, k_theta a / D: 0 simply supported, inf clamped

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

    def rows(self) -> list["Candidates"]:
        """Each candidate on its own, as ``take([i])`` gives it but as one-row
        views of these arrays (no copy: a solve splits thousands)."""
        columns = [(f.name, getattr(self, f.name)) for f in fields(self)]
        return [Candidates(**{name: col[i:i + 1] for name, col in columns}) for i in range(len(self))]

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

    @property
    def reflected_mass(self):
        """Mass at the wide piston (kg): the wide piston plus R^2 x (narrow
        piston, the oil in the narrow bore, the surface's tip-equivalent
        mass) (docs/models.md, "Force path")."""
        narrow_oil = self.density * self.narrow_area * (self.free_stroke + geometry.ROD_EXTRA_LENGTH)
        return self.wide_mass + self.ratio**2 * (self.narrow_mass + narrow_oil + self.surface_mass)


def reference_bouc_wen(stacks: dict[str, Stack]) -> Stack | None:
    """The stack whose measured Bouc-Wen parameters others borrow (seed 2.3.2)."""
    measured = [s for s in stacks.values() if s.bouc_wen is not None]
    return measured[0] if measured else None


def stack_bouc_wen(stack: Stack, reference: Stack | None) -> tuple[BoucWen, str]:
    """Bouc-Wen parameters of ``stack``: its own, or transferred in
    normalised form from the reference stack (docs/models.md, corrections to the seed, item 4)."""
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
             overrides: dict | None = None, structure: dict | None = None) -> dict:
    """One candidate as a dict of SI floats (keys are Candidates fields).
    ``structure``: the force-path choices (``structure_row``); default: the
    catalog's first material sized by the closed-form rule, no compensator."""
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
    row.update({"stack_length": stack.length, "stack_diameter": stack.diameter,
                "stack_cte": stack.thermal_expansion if stack.thermal_expansion is not None else STACK_CTE_DEFAULT,
                "loss_factor": stack.loss_factor if stack.loss_factor is not None else stack_phys.DEFAULT_LOSS_FACTOR,
                "stack_square": float(stack.section == "square")})
    row["edge_restraint"] = 0.0             # simply supported unless the structure says otherwise
    row.update(structure if structure is not None else {})
    return row


# assumed: the reviewer's "stacks about 0 to +3 ppm/K" (an independent
# review of the sizing) for stacks whose catalog entry gives no expansion coefficient.
STACK_CTE_DEFAULT = 2e-6


def structure_row(material, cap_thickness, frame_area, spacer=None, spacer_length=0.0,
                  compensator=None, surface_mass=0.0, delta_T=0.0, edge_restraint=0.0) -> dict:
    """The force-path and thermal fields of a candidate row (SI floats)."""
    sp = spacer if spacer is not None else material
    row = {"edge_restraint": float(edge_restraint),"mat_E": material.youngs_modulus, "mat_nu": material.poisson, "mat_density": material.density,
           "mat_cte": material.thermal_expansion, "mat_yield": material.yield_strength,
           "mat_cost": material.cost_usd, "cap_thickness": float(cap_thickness), "frame_area": float(frame_area),
           "spacer_length": float(spacer_length), "spacer_E": sp.youngs_modulus, "spacer_density": sp.density,
           "spacer_cte": sp.thermal_expansion, "spacer_cost": sp.cost_usd,
           "surface_mass": float(surface_mass), "delta_T": float(delta_T)}
    if compensator is None:
        row.update({"comp_kind": 0.0, "comp_volume_stiffness": np.inf, "comp_leak": 0.0, "comp_capacity": 0.0,
                    "comp_mass": 0.0, "comp_cost": 0.0})
    else:
        row.update({"comp_kind": 1.0 if compensator.kind == "accumulator" else 2.0,
                    "comp_volume_stiffness": compensator.volume_stiffness, "comp_leak": compensator.leak_conductance,
                    "comp_capacity": compensator.capacity, "comp_mass": compensator.mass,
                    "comp_cost": compensator.cost_usd})
    return row


def _fluid_row(fluid: Fluid | None, temperature: float, o: dict) -> dict:
    if fluid is None:
        f = dict(FALLBACK_FLUID)
        bulk = f["bulk_modulus"]
    else:
        f = {"density": float(fluid_props.density_at(fluid.density, fluid.thermal_expansion, temperature)),
             "thermal_expansion": fluid.thermal_expansion, "cost_usd": fluid.cost_usd}
        bulk = float(fluid_props.bulk_modulus_at(fluid.bulk_modulus, fluid.bulk_modulus_temperature_coefficient, temperature))
    air = o.get("air_fraction") or AIR_FRACTION
    if air > 0:
        bulk = float(fluid_props.effective_bulk_modulus(bulk, air, o.get("air_pressure") or 101325.0))
    return {"density": f["density"], "bulk_modulus": o.get("bulk_modulus") or bulk,
            "thermal_expansion": f["thermal_expansion"], "fluid_cost": f["cost_usd"]}


def _seal_row(seal: Seal | None, wide_area: float, narrow_area: float, o: dict) -> dict:
    """Running friction at zero pressure and its growth per Pa of chamber
    pressure (pi d c_p, physics/seals.py). An explicit friction override
    replaces both for that seal (the seed's fixed 10 N / 0.2 N)."""
    if seal is None:
        wide, narrow, breakaway, cost = *SEED_FRICTION_N, 1.0, 0.0
        cp_w = cp_n = 0.0
    else:
        d_w, d_n = 2 * geometry.radius(wide_area), 2 * geometry.radius(narrow_area)
        wide = float(seals.running_friction(seal.friction_per_length, d_w))
        narrow = float(seals.running_friction(seal.friction_per_length, d_n))
        cp_w = float(np.pi * d_w * seal.friction_pressure_coefficient)
        cp_n = float(np.pi * d_n * seal.friction_pressure_coefficient)
        breakaway, cost = seal.breakaway_ratio, 2 * seal.cost_usd
    return {"wide_friction": _pick(o.get("wide_friction"), wide),
            "narrow_friction": _pick(o.get("narrow_friction"), narrow),
            "wide_friction_cp": 0.0 if o.get("wide_friction") is not None else cp_w,
            "narrow_friction_cp": 0.0 if o.get("narrow_friction") is not None else cp_n,
            "breakaway": _pick(o.get("breakaway_ratio"), breakaway), "seal_cost": cost}


def _pick(override, default):
    return default if override is None else override


def _amplifier_row(amplifier: Amplifier | None) -> dict:
    if amplifier is None:
        return {"amp_max_current": np.inf, "amp_slew": 0.0, "amp_mass": 0.0, "amp_cost": 0.0,
                "amp_continuous": np.inf, "amp_peak_duration": np.inf, "amp_recovery": 0.0, "amp_units": 1.0}
    return {"amp_max_current": amplifier.max_current, "amp_slew": amplifier.slew_rate or 0.0,
            "amp_mass": amplifier.mass, "amp_cost": amplifier.cost_usd,
            "amp_continuous": amplifier.continuous_current, "amp_peak_duration": amplifier.peak_duration,
            "amp_recovery": amplifier.energy_recovery, "amp_units": 1.0}
