"""Enumerate piezohydraulic combinations and prune the hopeless ones.

Every (stack, fluid, seal, amplifier, stack count) is one combination. Most
are ruled out before any sizing, each with the requirement that rules it
out, and all of them stay in the results:

- temperature: a stack, fluid or seal rated below the required maximum
  temperature; amplifier_temperature: the amplifier rated below the
  temperature where it sits (the requirement when it sits at the actuator,
  the electronics bay's temperature otherwise);
- work: n k_s (d33 V)^2 >= F S (docs/models.md, "Piezohydraulic sizing") fails at the
  voltage the amplifier can reach;
- amplifier_voltage: the same bound would hold at the stack's rated voltage
  but the amplifier cannot reach it.

The survivors are sized by the geometric program of ``convex.py``.
"""
from __future__ import annotations

import itertools
from dataclasses import dataclass, field

from ...io.catalog import Amplifier, Catalog, Fluid, Seal, Stack
from ...io.requirements import RequirementsFile
from ...physics import stack as stack_phys



def temperature_margin(rated_degC: float, required_degC: float) -> float:
    """(rated - required) / required (docs/formats.md: "rated limit minus
    requirement, over the requirement in K"): the difference is a number of
    kelvin, divided by the required temperature's degC value, as the
    contract's example reads (a 150 degC stack at a 100 degC requirement:
    0.5). A requirement near 0 degC divides by 1 K instead of by ~0."""
    return (rated_degC - required_degC) / max(abs(required_degC), 1.0)


@dataclass
class Combo:
    stack: Stack
    n: int
    fluid: Fluid
    seal: Seal
    amplifier: Amplifier
    voltage_fraction_max: float           # min(1, V_amp / V_stack)
    stack_stroke: float                   # m, one stack at its rated voltage, derated to temperature
    margins: dict = field(default_factory=dict)
    temperatures: dict = field(default_factory=dict)   # component -> (rated, required) degC
    pruned: bool = False

    @property
    def key(self) -> str:
        return f"ph-{self.stack.id}-n{self.n}-{self.fluid.id}-{self.seal.id}-{self.amplifier.id}"

    @property
    def voltage(self) -> float:
        return self.stack.max_voltage * self.voltage_fraction_max


def component_temperatures(req: RequirementsFile, stack: Stack, fluid: Fluid, seal: Seal,
                           amplifier: Amplifier) -> dict[str, tuple[float, float]]:
    """Each component's rating and the temperature it must work at (degC)."""
    T = req.requirements.max_temperature
    o = req.options
    amp_T = T if o.amplifier_location == "actuator" else o.electronics_bay_temperature
    return {f"stack {stack.id}": (stack.max_temperature, T),
            f"fluid {fluid.id}": (fluid.max_temperature, T),
            f"seal {seal.id}": (seal.max_temperature, T),
            f"amplifier {amplifier.id}": (amplifier.max_temperature, amp_T)}


def enumerate_combos(req: RequirementsFile, catalog: Catalog) -> list[Combo]:
    """Every combination of the catalog's parts and stack counts 1..max_stacks,
    with the margins known before sizing and ``pruned`` set when one of them
    rules the combination out."""
    combos = []
    parts = itertools.product(catalog.stacks.values(), catalog.fluids.values(),
                              catalog.seals.values(), catalog.amplifiers.values())
    for stack, fluid, seal, amp in parts:
        combos.extend(combos_of(req, stack, fluid, seal, amp, range(1, req.options.max_stacks + 1)))
    return combos


def combos_of(req: RequirementsFile, stack: Stack, fluid: Fluid, seal: Seal, amp: Amplifier,
              counts) -> list[Combo]:
    """The combinations of these parts with each stack count of ``counts``
    (``enumerate_combos``; ``sizing evaluate --requirements`` asks for one)."""
    r = req.requirements
    work_needed = r.blocked_force * r.stroke
    temps = component_temperatures(req, stack, fluid, seal, amp)
    t_margin = min(temperature_margin(rated, need) for k, (rated, need) in temps.items()
                   if not k.startswith("amplifier"))
    a_margin = temperature_margin(*temps[f"amplifier {amp.id}"])
    x0 = float(stack_phys.derated_stroke(stack.stroke, stack.stroke_temperature_coefficient, r.max_temperature))
    v_max = min(1.0, amp.max_voltage / stack.max_voltage)
    combos = []
    for n in counts:
        work_amp = float(stack_phys.work_capacity(n, stack.stiffness, x0 * v_max))
        work_full = float(stack_phys.work_capacity(n, stack.stiffness, x0))
        margins = {"temperature": t_margin, "amplifier_temperature": a_margin,
                   "work": work_amp / work_needed - 1}
        if v_max < 1 and work_full >= work_needed > work_amp:
            # voltage at which the work bound is just met, against what the amplifier gives
            v_needed = (work_needed / (n * stack.stiffness)) ** 0.5 / x0
            margins["amplifier_voltage"] = v_max / v_needed - 1
            margins["work"] = work_full / work_needed - 1
        c = Combo(stack, n, fluid, seal, amp, v_max, x0, margins=margins, temperatures=temps)
        c.pruned = min(margins.values()) < 0
        combos.append(c)
    return combos
