"""The frequency-rectified piezo pump as the solve and the stages after it
see it (``registry.Technology``)."""
from __future__ import annotations

from ..registry import Group, Technology
from . import stage, words

TECHNOLOGY = Technology(
    name="piezo_pump", label="piezo pump", order=2,
    part_kinds=("stack", "amplifier", "fluid", "seal", "valve", "accumulator"),
    solve=stage.solve,
    groups=(Group("pump", "piezo pump: stacks pumping through reed check valves into a cylinder"),),
    short_name=words.short_name, describe=words.describe,
    rests_on=("sizing.physics.pump", "sizing.physics.stack", "sizing.sim.pump"),
)
