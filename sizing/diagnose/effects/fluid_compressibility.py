"""Fluid compressibility: entrained air lowers the effective bulk modulus of
the oil tenfold or more (docs/models.md, "Hydraulic stage"), so the oil
column becomes a soft spring in series with the stacks: the output loses
stroke under load and rings after fast inputs.

Model: the oil spring p = beta_e (A_w x - A_n y) / V0 with a lower beta_e.
Sizes: 10x and 40x below the nominal bulk modulus (a few percent of
undissolved air by volume).

Form "air" (entrained air, pressure-dependent bulk modulus): free air
bubbles compress polytropically, so the oil is soft near atmospheric
pressure and stiffens as the pressure rises: 1 / beta(p) = (1 - eps0) /
beta_oil + eps(p) / (kappa p_abs), eps(p) = eps0 (p_atm / p_abs)^(1/kappa)
(Merritt 1967, sec. 2.3; Gholizadeh, Burton and Schoenau, Int. J. Fluid
Power 15 (2014) 1; sizing.sim.piezohydraulic.air_strain). beta_oil is the
nominal bulk modulus. Sizes: 1 % and 4 % of air by volume at atmospheric
pressure, adiabatic (kappa 1.4) and isothermal (kappa 1.0) bubbles.
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from .base import Effect, Param


class SofterOil(Effect):
    """The bulk modulus form, bounded above by the rig's nominal bulk
    modulus: entrained air only softens the oil. Above the nominal the
    "effect" would stiffen it, which is a restated nominal (or another
    simulator's hydraulic form), not compressibility: fitted as a partner,
    a stiffer oil took up the single's form error (+24-33 % of the bulk
    modulus on four campaigns of an independent simulator with no air)."""

    def for_rig(self, rig, model):
        nominal = float(np.min(getattr(model, "bulk_modulus")))
        (p,) = self.params
        if not p.lo < nominal < p.hi:
            return self
        return replace(self, params=(replace(p, hi=nominal),))


class EntrainedAir(Effect):
    def model_changes(self, model, values):
        return {"air_fraction": values["air_fraction"], "air_polytropic": values["polytropic_index"]}


BULK_MODULUS = SofterOil(
    form="bulk_modulus",
    name="fluid_compressibility", technology="piezohydraulic",
    params=(Param("bulk_modulus_Pa", 5e6, 2e9, log=True, doc="effective bulk modulus of the oil"),),
    fields={"bulk_modulus_Pa": "bulk_modulus"}, nominal_factors=(1 / 10, 1 / 40),
    source="docs/models.md (fluid compliance, entrained air); Merritt, Hydraulic Control Systems (1967) ch. 2")


AIR = EntrainedAir(
    name="fluid_compressibility", technology="piezohydraulic", form="air",
    params=(Param("air_fraction", 1e-4, 0.2, log=True, doc="entrained air, volume fraction at atmospheric pressure"),
            Param("polytropic_index", 1.0, 1.4, doc="polytropic index of the air (1 isothermal, 1.4 adiabatic)")),
    sizes=({"air_fraction": 0.01, "polytropic_index": 1.4}, {"air_fraction": 0.04, "polytropic_index": 1.0}),
    source="Merritt, Hydraulic Control Systems (1967) sec. 2.3; Gholizadeh et al., Int. J. Fluid Power 15 (2014) 1")

# the forms this module adds to the library (effects.library), the family's default first
FORMS = (BULK_MODULUS, AIR)
