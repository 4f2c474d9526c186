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
ULTIMATE_FACTOR = 1.5           # a DC design's structure sized for this x its largest force, against yield
REQUIRED_LIFE_H = 200.0         # h: the L10 life a DC screw and its thrust bearings are sized for at the duty
BEARING_STATIC_SAFETY = 2.0     # a DC thrust bearing's static rating C0 over its peak load, at least
STRESS_SAFETY = 2.0             # a hydraulic actuator's structural member: allowable stress = its yield over this
DEFAULT_MAX_MASS = 1e4          # kg: the geometric programs' mass ceiling when the envelope states none
MIN_AREA_RATIO = 1.5            # a stack-and-oil design's area ratio R, at least (an amplifier, not a direct drive)

# --- checks --------------------------------------------------------------------
STEP_SETTLED = 0.98             # a DC step counts as reached at this fraction of its size
DIVERGED_FACTOR = 5.0           # a simulated pump speed above this x what the pump sweeps is a divergence

# --- simulation budgets ---------------------------------------------------------
DC_MAX_SIMULATED = 300          # DC designs from parts simulated per solve, before the rest is tried
DC_MIN_SIMULATED = 24           # DC designs simulated at least (the closest to feasible when fewer pass)
DC_REAL_SHARE = 1 / 3           # of the DC budget, first for designs whose parts all exist
PUMP_FEASIBLE_SIMULATED = 24    # pump designs that pass the screen simulated, best first
PUMP_CLOSEST_SIMULATED = 8      # pump designs that miss the screen simulated, closest first, at least
PUMP_SIMULATED = 32             # pump designs simulated in all

# --- screens (the pump technology's) ------------------------------------------------------
RESONANCE_FRACTION = 0.4        # the pumping frequency stays below this x the output's natural frequency
VALVE_DROP_FRACTION = 0.2       # the valves' drop at peak delivery flow stays below this x the stall pressure

# --- the answer ----------------------------------------------------------------
KNIFE_EDGE = 0.01               # a margin met by less than this (and >= 0) is a knife edge
FLIP_TOLERANCE = 0.01           # a flip is found to this fraction of the value (of degC for a temperature)
FLIP_RANGE = 4.0                # a flip is searched from the value / this to the value x this
FLIP_TEMPERATURE_SPAN = 150.0   # degC: a temperature's flip is searched this far either side
FLIP_COLD_LIMIT = -55.0         # degC: and never below this
FAR_MISS = -0.5                 # a simulated design missing a check by more than this is counted, not recorded
REPORTED_SAMPLES = 200          # Monte Carlo samples, at least, behind a probability the answer states
MAX_EXAMINED = 10               # designs the compliance policy examines before it says none complies
