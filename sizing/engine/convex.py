"""Convex sizing of one piezohydraulic combination: a geometric program.

For a fixed choice of parts (stack, n stacks, fluid, seal, amplifier) the
continuous variables are the amplification ratio R, the wide piston area
A_w and the drive voltage as a fraction v of the stack's rating. With the
stack stroke x = x0 v, the oil volume A_w (g + x) (wide gap g plus the
narrow bore over the stroke) and the fluid spring beta A_w / (g + x) in
series with the stacks (PHYSICS-NOTES), every static requirement is a
posynomial <= 1 (m: the design margin):

    stroke             S (1+m) / (R x)                                   <= 1
    blocked force      F (1+m) R (1/(n k_s) + (g + x)/(beta A_w)) / x    <= 1
    pressure           n k_s x / (A_w p_rating)                          <= 1
    drive current      n C_L V0 S (1+m) / (R x0 t_S I_amp)                <= 1
    natural frequency  w^2 (m_w + R^2 m_n) (1/(n k_s) + (g + x)/(beta A_w)) <= 1
    voltage            v / v_max                                         <= 1

(t_S = stroke / speed, i.e. the charge n C_L V_S that reaches the stroke
must flow within t_S; C_L the large-signal capacitance; w = 2 pi f_min.)
The pressure bound uses the stack force, which the compliant blocked
pressure never exceeds, so it is conservative. The objective is the product
of the requested objectives (mass, cost, volume, power), each a posynomial
from ``physics.geometry``: the product is scale free, so no weights.

The problem is built once per objective set with cvxpy Parameters (DPP),
so each combination only re-solves. When it is infeasible, a phase-1
problem with one slack s_i >= 1 per requirement (minimise prod s_i) names
the binding requirement: the one whose slack stays largest.
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

import cvxpy as cp

from ..physics import geometry
from ..physics.stack import LARGE_SIGNAL_CAPACITANCE_FACTOR

CONSTRAINTS = ("stroke", "blocked_force", "pressure", "drive_current", "natural_frequency")
MIN_RATIO = 1.5
FEASIBLE_SLACK = 1.0 + 1e-6
SOLVER = "CLARABEL"


@dataclass
class SizingInput:
    """One combination's data, SI floats. Costs in USD, masses in kg."""

    n_stiffness: float          # n k_s, N/m
    stack_stroke: float         # x0, m, one stack at its rated voltage, derated
    rated_voltage: float        # V0, V
    max_fraction: float         # v_max = min(1, V_amp / V0)
    force: float                # required blocked force, N
    stroke: float               # required stroke, m
    bulk_modulus: float         # Pa, at temperature
    wide_gap: float             # m
    pressure_rating: float      # Pa
    natural_frequency: float    # Hz, lowest accepted
    stroke_time: float          # s, stroke / speed
    n_capacitance: float        # n C (small-signal), F
    max_current: float          # A, amplifier
    margin: float               # design margin on stroke and force
    fixed_mass: float           # kg: stacks with frame, amplifier
    fixed_cost: float           # USD: stacks, amplifier, seals, assembly
    fixed_volume: float         # m^3: stacks envelope
    oil_density: float          # kg/m^3
    oil_cost: float             # USD/m^3


@dataclass
class SizingResult:
    success: bool
    ratio: float
    wide_area: float
    voltage_fraction: float
    slack: dict = field(default_factory=dict)     # requirement -> phase-1 slack (1: met)
    binding: list = field(default_factory=list)   # requirements that cannot be met, worst first
    status: str = ""

    @property
    def driver(self) -> str | None:
        return self.binding[0] if self.binding else None


class GPSizer:
    """The parametrised geometric program for a set of objectives."""

    def __init__(self, objectives=("mass", "cost")):
        self.objectives = tuple(objectives)
        self.R = cp.Variable(pos=True, name="R")
        self.A = cp.Variable(pos=True, name="A_w")
        self.v = cp.Variable(pos=True, name="v")
        names = ["nk", "x0", "V0", "vmax", "F", "S", "beta", "g", "p", "w2", "cur", "m0", "c0", "vol0",
                 "rho", "coil", "pw"]
        self.par = {k: cp.Parameter(pos=True, name=k) for k in names}
        terms = self._constraint_terms()
        bounds = [self.v <= self.par["vmax"], MIN_RATIO / self.R <= 1]
        self.problem = cp.Problem(cp.Minimize(self._objective()), [t <= 1 for t in terms.values()] + bounds)
        self.slack = {k: cp.Variable(pos=True, name=f"s_{k}") for k in CONSTRAINTS}
        phase1 = [terms[k] <= self.slack[k] for k in CONSTRAINTS] + [1 / s <= 1 for s in self.slack.values()]
        obj1 = 1
        for s in self.slack.values():
            obj1 = obj1 * s
        self.phase1 = cp.Problem(cp.Minimize(obj1), phase1 + bounds)
        assert self.problem.is_dgp(dpp=True) and self.phase1.is_dgp(dpp=True)

    # expressions ------------------------------------------------------
    def _geometry(self):
        P, R, A, v = self.par, self.R, self.A, self.v
        x = P["x0"] * v
        narrow = A / R
        stroke = R * x
        return x, narrow, stroke

    def _constraint_terms(self) -> dict:
        P, R, A = self.par, self.R, self.A
        x, narrow, stroke = self._geometry()
        compliance = 1 / P["nk"] + (P["g"] + x) / (P["beta"] * A)     # 1 / k_wide
        reflected = (geometry.wide_piston_mass(A, P["p"])
                     + R**2 * geometry.ALUMINIUM_DENSITY * narrow * (stroke + geometry.ROD_EXTRA_LENGTH))
        return {
            "stroke": P["S"] / (R * x),
            "blocked_force": P["F"] * R * compliance / x,
            "pressure": P["nk"] * x / (A * P["p"]),
            "drive_current": P["cur"] / R,
            "natural_frequency": P["w2"] * reflected * compliance,
        }

    def _objective(self):
        P, R, A, v = self.par, self.R, self.A, self.v
        x, narrow, stroke = self._geometry()
        p, g = P["p"], P["g"]
        metal = (geometry.wide_piston_mass(A, p) + geometry.narrow_piston_mass(narrow, stroke)
                 + geometry.casing_mass(A, narrow, p, g, stroke))
        oil = A * g + narrow * stroke
        exprs = {
            "mass": P["m0"] + metal + P["rho"] * oil,
            "cost": P["c0"] + geometry.MACHINING_USD_PER_KG * metal + P["coil"] * oil,
            "volume": P["vol0"] + geometry.hydraulic_volume(A, narrow, p, g, stroke),
            "power": P["pw"] * v / R,
        }
        obj = 1
        for name in self.objectives:
            obj = obj * exprs[name]
        return obj

    # solving -----------------------------------------------------------
    def set(self, s: SizingInput) -> None:
        c_large = s.n_capacitance * LARGE_SIGNAL_CAPACITANCE_FACTOR
        values = {
            "nk": s.n_stiffness, "x0": s.stack_stroke, "V0": s.rated_voltage, "vmax": s.max_fraction,
            "F": s.force * (1 + s.margin), "S": s.stroke * (1 + s.margin), "beta": s.bulk_modulus,
            "g": s.wide_gap, "p": s.pressure_rating, "w2": (2 * math.pi * s.natural_frequency) ** 2,
            "cur": c_large * s.rated_voltage * s.stroke * (1 + s.margin) / (s.stack_stroke * s.stroke_time * s.max_current),
            "m0": max(s.fixed_mass, 1e-9), "c0": max(s.fixed_cost, 1e-9), "vol0": max(s.fixed_volume, 1e-12),
            "rho": s.oil_density, "coil": max(s.oil_cost, 1e-12),
            # power = V * i at the drive ramp that reaches the stroke in half of t_S
            "pw": 2 * c_large * s.rated_voltage**2 * s.stroke / (s.stack_stroke * s.stroke_time),
        }
        for k, val in values.items():
            self.par[k].value = float(val)

    def solve(self, s: SizingInput) -> SizingResult:
        """Size one combination: the optimum, or the phase-1 point with the
        requirements that bind when no design meets them all."""
        self.set(s)
        status = self._run(self.problem)
        if status in ("optimal", "optimal_inaccurate"):
            return SizingResult(True, float(self.R.value), float(self.A.value), float(self.v.value), status=status)
        status1 = self._run(self.phase1)
        if status1 not in ("optimal", "optimal_inaccurate"):
            return SizingResult(False, math.nan, math.nan, math.nan, status=f"phase 1 {status1}",
                                binding=["solver"])
        slack = {k: float(self.slack[k].value) for k in CONSTRAINTS}
        binding = sorted((k for k in CONSTRAINTS if slack[k] > FEASIBLE_SLACK), key=lambda k: -slack[k])
        if not binding:       # phase 1 met everything: the first solve was a numerical failure
            binding = [max(slack, key=slack.get)]
        return SizingResult(False, float(self.R.value), float(self.A.value), float(self.v.value),
                            slack=slack, binding=binding, status=status)

    @staticmethod
    def _run(problem: cp.Problem) -> str:
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                problem.solve(gp=True, solver=SOLVER)
        except cp.error.SolverError:
            return "solver_error"
        return problem.status
