"""The thresholds of the sizing, the screens and the answer, declared in one
place (the diagnosis declares its own in ``diagnose/settings.py``).

Each value here decides an outcome: whether a design passes a screen or a
check, how much margin it is sized with, or how the answer reads. The
modules that apply them import them from here; docs/settings.md gives the
rationale of each value and where it is applied (tests/project/test_settings.py
keeps the two in step). The requirements file overrides the first group
(``[options]``, ``[objectives]``); the others are the tool's own.
"""
from __future__ import annotations

# --- defaults of the requirements file (docs/formats.md) -----------------------
DESIGN_MARGIN = 0.05            # [options] design_margin: static sizing margin on stroke and blocked force
MAX_OVERSHOOT = 0.10            # [options] max_overshoot: simulated overshoot allowed, fraction of the stroke
MAX_DRIFT_FRACTION = 0.10       # [options] max_drift_fraction: thermal drift allowed, fraction of the stroke
STRUCTURE_STIFFNESS_RATIO = 3.0  # [options] structure_stiffness_ratio: each structural member over the stacks' stiffness
MIN_COMPLIANCE = 0.9            # [objectives] min_compliance: probability of compliance the recommendation must reach

# --- sizing --------------------------------------------------------------------
TRAVEL_FACTOR = 1.10            # a DC screw's designed travel over the required stroke (end stops, rigging)

# --- screens (the pump technology's) ------------------------------------------------------
RESONANCE_FRACTION = 0.4        # the pumping frequency stays below this x the output's natural frequency
VALVE_DROP_FRACTION = 0.2       # the valves' drop at peak delivery flow stays below this x the stall pressure

# --- the answer ----------------------------------------------------------------
KNIFE_EDGE = 0.01               # a margin met by less than this (and >= 0) is a knife edge
FLIP_TOLERANCE = 0.01           # a flip is found to this fraction of the value (of degC for a temperature)
REPORTED_SAMPLES = 200          # Monte Carlo samples, at least, behind a probability the answer states
MAX_EXAMINED = 10               # designs the compliance policy examines before it says none complies
