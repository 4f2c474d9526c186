"""Fluid compressibility: entrained air lowers the effective bulk modulus of
the oil tenfold or more (PHYSICS-NOTES, "Fluid compliance"), so the oil
column becomes a soft spring in series with the stacks: the output loses
stroke under load and rings after fast inputs.

Model: the oil spring p = beta_e (A_w x - A_n y) / V0 with a lower beta_e.
Sizes: 10x and 40x below the nominal bulk modulus (a few percent of
undissolved air by volume).
"""
from __future__ import annotations

from .base import Effect, Param


EFFECT = Effect(
    name="fluid_compressibility", technology="piezohydraulic",
    params=(Param("bulk_modulus_Pa", 5e6, 2e9, log=True, doc="effective bulk modulus of the oil"),),
    fields={"bulk_modulus_Pa": "bulk_modulus"}, nominal_factors=(1 / 10, 1 / 40),
    source="PHYSICS-NOTES (fluid compliance, entrained air); Merritt, Hydraulic Control Systems (1967) ch. 2")
