"""Convex sizing of one piezohydraulic combination: a geometric program.

For a fixed choice of parts (stack, n stacks, fluid, seal, amplifier) the
continuous variables are the amplification ratio R, the wide piston area
A_w and the drive voltage as a fraction v of the stack's rating. With the
stack stroke x = x0 v, the oil volume A_w (g + x) (wide gap g plus the
narrow bore over the stroke) and the fluid spring beta A_w / (g + x) in
series with the stacks (docs/models.md), every static requirement is a
posynomial <= 1 (m: the design margin):

    stroke             (S + F_L R^2 C) (1+m) / (R x)                     <= 1
    blocked force      F (1+m) R (1/(n k_s) + (g + x)/(beta A_w)) / x    <= 1
    pressure           n k_s x / (A_w p_rating)                          <= 1
    drive              U / U_max                                         <= 1
    natural frequency  w^2 (m_w + R^2 m_n) (1/(n k_s) + (g + x)/(beta A_w)) <= 1
    voltage            v / v_max                                         <= 1
    stiffness          k_min R^2 C                                       <= 1

(C the force path's compliance at the wide piston, so R^2 C is the output's
at rest; F_L the largest load when the stroke is counted from neutral, else
0; k_min the requirements' ``min_stiffness``, else 0.)

(C_L the large-signal capacitance; w = 2 pi f_min.) The drive is sized with
the rest: the voltage ramp reaches the free stroke R x0 v at the required
speed u, t_r = R x0 v / u, and the amplifier units U (a continuous count,
rounded up when the design is built) carry its current at a unit's usable
ramp current I_u (the peak within the rated pulse, else the continuous
rating I_c), the duty's rms and its mean (physics/amplifier.py):

    ramp   n C_L V0 u / (R x0 I_u)                 <= U
    rms    n C_L V0 sqrt(2 f u / x0) v^0.5 R^-0.5 / I_c <= U
    mean   2 n C_L V0 f v / I_c                     <= U

U_max is the options' ``max_amplifier_units``; the units' mass and cost
are in the objective.
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

import numpy as np

from ...physics import geometry, structure
from ...physics.stack import LARGE_SIGNAL_CAPACITANCE_FACTOR
from ...settings import DEFAULT_MAX_MASS, MIN_AREA_RATIO

CONSTRAINTS = ("stroke", "blocked_force", "pressure", "drive_current", "natural_frequency", "stiffness",
               "structure_out_of_range", "envelope_length", "envelope_diameter", "envelope_mass")
# what a binding constraint rules a design out as (never ranked): the rest are missed requirements
RULED_OUT_BY = {"structure_out_of_range": "structure_out_of_range", "envelope_length": "envelope",
                "envelope_diameter": "envelope", "envelope_mass": "envelope"}
RELAXED_MISS = 1.25     # the closest bounded design of infeasible parts: 25 % more miss (log) than the infimum
NO_LIMIT = 1e6          # stands in for an envelope dimension that is not given (m)
FEASIBLE_SLACK = 1.0 + 1e-6
SOLVER = "CLARABEL"
ALUMINIUM_E = 68.9e9    # Pa, 6061-T6 wide piston (force_path.ALUMINIUM_E)


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
    wide_gap: float             # m, smallest wide-chamber gap allowed (the option; the gap is sized)
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
    # force path: structure material, stack column, seals at pressure, geometry
    youngs_modulus: float = 68.9e9      # Pa, caps, base plate and frame
    poisson: float = 0.33
    material_density: float = 2700.0    # kg/m^3
    material_unit_cost: float = 70.0    # USD/kg (stock + machining)
    allowable_stress: float = 138e6     # Pa, yield / 2
    stack_length: float = 0.1           # m
    stiffness_ratio: float = 3.0        # caps and frame at least this x n k_s
    packing_area: float = 1e-9          # m^2, smallest wide piston the stacks fit under
    accumulator_compliance: float = 0.0 # m^3/Pa, open accumulator (0: none)
    seal_f0: float = 0.0                # N/m, seal running friction per metre at zero pressure
    seal_cp: float = 0.0                # N/(m Pa)
    surface_mass: float = 0.0           # kg, tip-equivalent mass of the surface
    gap_allowance: float = 0.6e-3       # m, wide gap over the stack stroke: clearance + tolerance
    max_length: float = NO_LIMIT        # m, envelope
    max_diameter: float = NO_LIMIT      # m, envelope (outer diameter of the wide cylinder)
    max_mass: float = DEFAULT_MAX_MASS  # kg, envelope
    amp_unit_mass: float = 0.0          # kg, one amplifier unit (the drive's mass scales with the units)
    amp_unit_cost: float = 0.0          # USD, one unit
    amp_unit_current: float = math.inf  # A, what one unit holds over the ramp (inf: max_current is one unit)
    column_compliance: float = 0.0      # m/N, a passive spacer in the stack column (its length is in stack_length)
    amp_unit_continuous: float = math.inf   # A, one unit's continuous rating (inf: amp_unit_current)
    strokes_per_second: float = 0.0     # 1/s, the duty the rms and mean currents are taken over
    min_stiffness: float = 0.0          # N/m, output stiffness at rest asked (0: none)
    stroke_load: float = 0.0            # N, the load the stroke is counted from neutral under (0: from the loaded rest)
    edge_restraint: float = 0.0         # end cap and base plate edge, k_theta a / D (0 simply supported, inf clamped)


@dataclass
class SizingResult:
    success: bool
    ratio: float
    wide_area: float
    voltage_fraction: float
    cap_thickness: float = math.nan
    frame_area: float = math.nan
    wide_gap: float = math.nan
    amplifier_units_sized: float = math.nan   # the continuous count the program sized (built designs round it up)
    slack: dict = field(default_factory=dict)     # requirement -> phase-1 slack (1: met)
    binding: list = field(default_factory=list)   # requirements that cannot be met, worst first
    status: str = ""
    # the drive as a design file fixes it (``sizing evaluate``); None: planned
    # by ``designs._build`` from the requirements (units the ramp needs)
    amplifier_units: float | None = None
    ramp_time: float | None = None     # s

    @property
    def driver(self) -> str | None:
        return self.binding[0] if self.binding else None

    @property
    def ruled_out(self) -> str | None:
        """``structure_out_of_range`` or ``envelope`` when no design of these
        parts fits the members' validity or the envelope; else None."""
        return next((RULED_OUT_BY[k] for k in self.binding if k in RULED_OUT_BY), None)


VARIABLES = ("R", "A_w", "v", "t_cap", "A_frame", "gap", "amplifier_units",
             # epigraph variables: keep the posynomials short (one cone per term)
             "compliance", "force_with_seals", "reflected_mass")
# the point a solve returns: the variables a design is built from
POINT = VARIABLES[:7]
PARAMETERS = ("nk", "x0", "V0", "vmax", "F", "S", "beta", "p", "w2", "cur", "m0", "c0", "vol0",
              "rho", "coil", "pw", "E", "pc", "ps", "sig", "Ls", "knk", "rhom", "cm", "Apack", "cacc",
              "f0", "fc", "msurf", "sh", "gmin", "gfloor", "tv", "Lmax", "Dmax", "Mmax", "wall", "uam", "uac",
              "uramp", "urms", "umean", "kmin", "FL", "ccol")


class Program:
    """The sizing program's expressions over its symbols: ``variable(name)``
    and ``parameter(name)`` make them (cvxpy's for ``GPSizer``, plain
    posynomials for the batch solver of ``batch_gp.py``), so both solve the
    one program written here."""

    def __init__(self, objectives, variable, parameter):
        self.objectives = tuple(objectives)
        (self.R, self.A, self.v, self.t, self.Af, self.g, self.U,
         self.C, self.Fs, self.M) = (variable(n) for n in VARIABLES)
        self.par = {k: parameter(k) for k in PARAMETERS}

    def _bounds(self) -> list:
        """What every design keeps, besides the requirements' terms."""
        return ([self.v <= self.par["vmax"], MIN_AREA_RATIO / self.R <= 1] + self._structure_bounds() + self._gap_bounds()
                + self._drive_bounds()
                + [self._compliance() / self.C <= 1, (self.par["F"] + self._seal_force()) / self.Fs <= 1,
                   self._reflected() / self.M <= 1])

    # expressions ------------------------------------------------------
    def _geometry(self):
        P, R, A, v = self.par, self.R, self.A, self.v
        x = P["x0"] * v
        narrow = A / R
        stroke = R * x
        return x, narrow, stroke

    def _frame_length(self):
        P = self.par
        return P["Ls"] + geometry.plate_thickness(self.A, P["p"]) + self.g

    def _gap_bounds(self) -> list:
        """The wide gap covers the stack stroke plus clearance and tolerance,
        and is at least the requirements' floor."""
        P = self.par
        x, _, _ = self._geometry()
        return [(P["gmin"] + x) / self.g <= 1, P["gfloor"] / self.g <= 1]

    def _drive_bounds(self) -> list:
        """The units carry the ramp at the required speed, the duty's rms and its mean."""
        P, R, v, U = self.par, self.R, self.v, self.U
        return [P["uramp"] / (R * U) <= 1, P["urms"] * v**0.5 * R**-0.5 / U <= 1, P["umean"] * v / U <= 1]

    def _length(self):
        """Overall length: base plate, frame (stacks, wide piston, gap), end
        cap, narrow bore over the output stroke and the rod's seal land."""
        _, _, stroke = self._geometry()
        return 2 * self.t + self._frame_length() + stroke + geometry.ROD_EXTRA_LENGTH

    def _outer_diameter_squared(self):
        """Outer diameter squared: the wide cylinder (bore plus two thin
        walls) with the tie-rod frame's section as a ring around it,
        D^2 = D_casing^2 + 4 A_f / pi (``verify.outer_diameter``)."""
        P = self.par
        casing = P["wall"] * self.A ** 0.5 + 2 * geometry.MIN_WALL
        return casing**2 + 4 / math.pi * self.Af

    def _structure_bounds(self) -> list:
        """Caps and frame: within the allowable stress at the stack force and
        at least ``stiffness_ratio`` x n k_s stiff (force_path.size_structure)."""
        P, A, t, Af = self.par, self.A, self.t, self.Af
        return [P["ps"] * self.v / t**2 <= 1,                      # plate stress
                P["knk"] * P["pc"] * A / t**3 <= 1,                # plate stiffness floor
                P["nk"] * P["x0"] * self.v / (P["sig"] * Af) <= 1,  # tie rod stress
                P["knk"] * self._frame_length() / (P["E"] * Af) <= 1,   # frame stiffness floor
                P["Apack"] / A <= 1]                               # the stacks fit under the piston

    def _compliance(self):
        """1 / k of the whole force path at the wide piston (force_path.py):
        stacks, base plate and end cap (simply supported), frame, wide piston,
        oil column, open accumulator."""
        P, A, t = self.par, self.A, self.t
        x, _, _ = self._geometry()
        t_p = geometry.plate_thickness(A, P["p"])
        return (1 / P["nk"] + P["ccol"] + 2 * P["pc"] * A / t**3 + 2 * P["sh"] / t + self._frame_length() / (P["E"] * self.Af)
                + t_p / (ALUMINIUM_E * A) + (self.g + x) / (P["beta"] * A) + P["cacc"] / A**2)

    def _seal_force(self):
        """Seal friction at the output at the blocked-force pressure F/A_n:
        narrow seal + wide seal / R, each pi d (f0 + c_p p) (physics/seals.py)."""
        P, R, A = self.par, self.R, self.A
        k = 2 * math.sqrt(math.pi)
        return (k * P["f0"] * (A / R) ** 0.5 + k * P["fc"] * (A / R) ** -0.5
                + k * P["f0"] * A**0.5 / R + k * P["fc"] * A**-0.5)

    def _reflected(self):
        """Mass at the wide piston: wide piston + R^2 (narrow piston, narrow-bore oil, surface)."""
        P, R, A = self.par, self.R, self.A
        x, narrow, stroke = self._geometry()
        return (geometry.wide_piston_mass(A, P["p"])
                + R**2 * (geometry.ALUMINIUM_DENSITY + P["rho"]) * narrow * (stroke + geometry.ROD_EXTRA_LENGTH)
                + R**2 * P["msurf"])

    def _constraint_terms(self) -> dict:
        P, R, A = self.par, self.R, self.A
        x, narrow, stroke = self._geometry()
        compliance, reflected = self.C, self.M
        return {
            # from neutral the load's push-back F_L / k_out = F_L R^2 C is lost
            "stroke": (P["S"] + P["FL"] * R**2 * compliance) / (R * x),
            "blocked_force": self.Fs * R * compliance / x,
            "pressure": P["nk"] * x / (A * P["p"]),
            "drive_current": self.U / P["cur"],
            "natural_frequency": P["w2"] * reflected * compliance,
            "stiffness": P["kmin"] * R**2 * compliance,          # k_out = 1 / (R^2 C)
            "structure_out_of_range": P["tv"] * self.t * A ** -0.5,
            "envelope_length": self._length() / P["Lmax"],
            "envelope_diameter": self._outer_diameter_squared() / P["Dmax"] ** 2,
            "envelope_mass": self._mass() / P["Mmax"],
        }

    def _parts(self):
        """Metal of the hydraulic stage, its oil and the structure (posynomials)."""
        P, R, A = self.par, self.R, self.A
        x, narrow, stroke = self._geometry()
        p, g = P["p"], self.g
        metal = (geometry.wide_piston_mass(A, p) + geometry.narrow_piston_mass(narrow, stroke)
                 + geometry.casing_mass(A, narrow, p, g, stroke))
        oil = A * g + narrow * stroke
        structure = P["rhom"] * (2 * A * self.t + self.Af * self._frame_length())
        return metal, oil, structure

    def _mass(self):
        metal, oil, structure = self._parts()
        return self.par["m0"] + metal + self.par["rho"] * oil + structure + self.par["uam"] * self._units()

    def _units(self):
        """Amplifier units, a continuous count (``_drive_bounds``)."""
        return self.U

    def _objective_factors(self) -> list:
        """The requested objectives, each a posynomial; the objective is their product."""
        P, R, A, v = self.par, self.R, self.A, self.v
        x, narrow, stroke = self._geometry()
        p, g = P["p"], self.g
        metal, oil, structure = self._parts()
        exprs = {
            "mass": self._mass,
            "cost": lambda: (P["c0"] + geometry.MACHINING_USD_PER_KG * metal + P["coil"] * oil + P["cm"] * structure
                             + P["uac"] * self._units()),
            "volume": lambda: P["vol0"] + geometry.hydraulic_volume(A, narrow, p, g, stroke),
            "power": lambda: P["pw"] * v / R,
        }
        return [exprs[name]() for name in self.objectives]

    def _objective(self):
        obj = 1
        for factor in self._objective_factors():
            obj = obj * factor
        return obj

class GPSizer(Program):
    """The parametrised geometric program for a set of objectives, solved
    by Clarabel through cvxpy, one combination at a time."""

    def __init__(self, objectives=("mass", "cost")):
        import cvxpy as cp
        super().__init__(objectives, lambda n: cp.Variable(pos=True, name=n),
                         lambda n: cp.Parameter(pos=True, name=n))
        terms = self._constraint_terms()
        bounds = self._bounds()
        self.problem = cp.Problem(cp.Minimize(self._objective()), [t <= 1 for t in terms.values()] + bounds)
        self.slack = {k: cp.Variable(pos=True, name=f"s_{k}") for k in CONSTRAINTS}
        phase1 = [terms[k] <= self.slack[k] for k in CONSTRAINTS] + [1 / s <= 1 for s in self.slack.values()]
        obj1 = 1
        for s in self.slack.values():
            obj1 = obj1 * s
        self.phase1 = cp.Problem(cp.Minimize(obj1), phase1 + bounds)
        # the closest design: the least objective with each requirement missed
        # by no more than phase 1 had to (bounded geometry for infeasible parts)
        self.allowed = {k: cp.Parameter(pos=True, name=f"allow_{k}") for k in CONSTRAINTS}
        relaxed = [terms[k] / self.allowed[k] <= 1 for k in CONSTRAINTS]
        self.relaxed = cp.Problem(cp.Minimize(self._objective()), relaxed + bounds)
        assert self.problem.is_dgp(dpp=True) and self.phase1.is_dgp(dpp=True) and self.relaxed.is_dgp(dpp=True)
        point = [self.R, self.A, self.v, self.t, self.Af, self.g, self.U]
        self._runs = {id(p): _Resolver(p, point + extra) for p, extra in
                      ((self.problem, []), (self.phase1, list(self.slack.values())), (self.relaxed, []))}

    # solving -----------------------------------------------------------
    def set(self, s: SizingInput) -> None:
        for k, val in parameter_values(s).items():
            self.par[k].save_value(np.asarray(val))     # checked there; cvxpy's own check costs more than a solve

    def solve(self, s: SizingInput) -> SizingResult:
        """Size one combination: the optimum, or the phase-1 point with the
        requirements that bind when no design meets them all."""
        self.set(s)
        status = self._run(self.problem)
        if status in ("optimal", "optimal_inaccurate"):
            return SizingResult(True, *self._point(), status=status)
        status1 = self._run(self.phase1)
        if status1 not in ("optimal", "optimal_inaccurate"):
            return SizingResult(False, math.nan, math.nan, math.nan, status=f"phase 1 {status1}",
                                binding=["solver"])
        slack = {k: float(self.slack[k].value) for k in CONSTRAINTS}
        binding = binding_of(slack)
        point = self._point()
        for k, allowed in allowed_misses(slack, binding).items():
            _assign(self.allowed[k], allowed)
        if self._run(self.relaxed) in ("optimal", "optimal_inaccurate"):
            point = self._point()
        return SizingResult(False, *point, slack=slack, binding=binding, status=status)

    def _point(self) -> tuple:
        point = [float(v.value) for v in (self.R, self.A, self.v, self.t, self.Af, self.g, self.U)]
        point[2] = min(point[2], float(self.par["vmax"].value))   # v <= v_max, within the solver's tolerance
        return tuple(point)

    def _run(self, problem) -> str:
        return self._runs[id(problem)].run()


def binding_of(slack: dict) -> list:
    """The requirements phase 1 could not meet, worst first; when it met
    them all (the first solve was a numerical failure), the one nearest."""
    binding = sorted((k for k in CONSTRAINTS if slack[k] > FEASIBLE_SLACK), key=lambda k: -slack[k])
    return binding or [max(slack, key=slack.get)]


def allowed_misses(slack: dict, binding: list) -> dict:
    """What the closest design may miss each requirement by. Phase 1's
    least miss is often reached only as the geometry grows without bound
    (a stiffer path needs a larger bore, and so on): the closest design of
    bounded size misses each binding requirement by RELAXED_MISS times as
    much (in log terms) and is otherwise the optimum."""
    return {k: max(slack[k], 1.0) ** (RELAXED_MISS if k in binding else 1.0) * FEASIBLE_SLACK for k in CONSTRAINTS}


def parameter_values(s: SizingInput) -> dict:
    """The program's parameters for one combination, each checked positive and finite."""
    c_large = s.n_capacitance * LARGE_SIGNAL_CAPACITANCE_FACTOR
    unit = s.amp_unit_current if math.isfinite(s.amp_unit_current) else s.max_current
    continuous = s.amp_unit_continuous if math.isfinite(s.amp_unit_continuous) else unit
    speed = s.stroke / s.stroke_time
    charge = c_large * s.rated_voltage      # C at the full rated voltage
    f = s.strokes_per_second
    values = {
        "nk": s.n_stiffness, "x0": s.stack_stroke, "V0": s.rated_voltage, "vmax": s.max_fraction,
        "F": s.force * (1 + s.margin), "S": s.stroke * (1 + s.margin), "beta": s.bulk_modulus,
        "p": s.pressure_rating, "w2": (2 * math.pi * s.natural_frequency) ** 2,
        "cur": s.max_current / unit,        # the most units allowed
        "ccol": max(s.column_compliance, 1e-30),
        "kmin": max(s.min_stiffness, 1e-30), "FL": max(s.stroke_load * (1 + s.margin), 1e-30),
        "uramp": charge * speed / (s.stack_stroke * unit),
        "urms": max(charge * math.sqrt(2 * f * speed / s.stack_stroke) / continuous, 1e-12),
        "umean": max(2 * charge * f / continuous, 1e-12),
        "m0": max(s.fixed_mass, 1e-9), "c0": max(s.fixed_cost, 1e-9), "vol0": max(s.fixed_volume, 1e-12),
        "rho": s.oil_density, "coil": max(s.oil_cost, 1e-12),
        # power = V * i over the ramp that reaches the free stroke at the required speed
        "pw": c_large * s.rated_voltage**2 * speed / s.stack_stroke,
        "E": s.youngs_modulus,
        "pc": float(structure.plate_compliance_factor(s.poisson, "flange", s.edge_restraint)) * 12 * (1 - s.poisson**2) / (math.pi * s.youngs_modulus),
        "ps": 3 * (3 + s.poisson) * s.n_stiffness * s.stack_stroke / (8 * math.pi * s.allowable_stress),
        "sig": s.allowable_stress, "Ls": s.stack_length, "knk": s.stiffness_ratio * s.n_stiffness,
        "rhom": s.material_density, "cm": max(s.material_unit_cost, 1e-9), "Apack": s.packing_area,
        "cacc": max(s.accumulator_compliance, 1e-30), "f0": max(s.seal_f0, 1e-12),
        "fc": max(s.seal_cp * s.force * (1 + s.margin), 1e-12), "msurf": max(s.surface_mass, 1e-12),
        "sh": float(structure.plate_shear_compliance(1.0, s.youngs_modulus, s.poisson)),
        "gmin": max(s.gap_allowance, 1e-9), "gfloor": max(s.wide_gap, 1e-9),
        "tv": math.sqrt(math.pi) / structure.MINDLIN_MAX_THICKNESS_RATIO,
        "Lmax": s.max_length, "Dmax": s.max_diameter, "Mmax": s.max_mass,
        "wall": 2 / math.sqrt(math.pi) * (1 + s.pressure_rating / geometry.DESIGN_STRESS),
        "uam": max(s.amp_unit_mass, 1e-12), "uac": max(s.amp_unit_cost, 1e-12),
    }
    for k, val in values.items():
        val = float(val)
        if not 0 < val < math.inf:
            raise ValueError(f"sizing parameter {k} must be positive and finite, got {val!r}")
        values[k] = val
    return values


def _assign(par, value: float) -> None:
    """A positive parameter's value: saved as it is when positive and
    finite (cvxpy's own check then passes), else through cvxpy's check."""
    if 0 < value < math.inf:
        par.save_value(np.asarray(float(value)))
    else:
        par.value = value


class _Resolver:
    """Re-solves one compiled geometric program with new parameter values.

    The first solve goes through cvxpy, which compiles the program once
    (DPP) into a parametrised cone program. Later solves fill that program
    with the logarithms of the parameters and call the solver on it
    directly, then write the variables back: cvxpy's own re-solve validates
    and unpacks every leaf each time, which is four fifths of a solve here.
    The result is the same program solved by the same solver
    (tests/engine/test_solve.py compares both paths); when cvxpy's compiled
    form is not available the ordinary path is used."""

    def __init__(self, problem, variables: list):
        self.problem, self.variables = problem, variables
        self.compiled = None            # (solver, cone program, log parameters, variable columns)
        self.direct = True
        self.cone_data = None           # _ConeData: the cone program's data without scipy's slicing

    def run(self) -> str:
        if self.compiled is None or not self.direct:
            status = self._cvxpy()
            if self.compiled is None and self.direct and status in ("optimal", "optimal_inaccurate"):
                self._compile()
            return status
        return self._direct()

    def _cvxpy(self) -> str:
        import cvxpy as cp
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                self.problem.solve(gp=True, solver=SOLVER)
        except cp.error.SolverError:
            return "solver_error"
        return self.problem.status

    def _compile(self) -> None:
        from cvxpy.reductions.dgp2dcp.dgp2dcp import Dgp2Dcp
        try:
            cache = self.problem._cache
            chain, prog = cache.solving_chain, cache.param_prog
            dgp = next(r for r in chain.reductions if isinstance(r, Dgp2Dcp))
            logs = [(p, dgp.canon_methods._parameters[p]) for p in self.problem.parameters()]
            cols = [prog.var_id_to_col[dgp.canon_methods._variables[v].id] for v in self.variables]
            self.compiled = (chain.solver, prog, logs, cols)
        except (AttributeError, KeyError, StopIteration, TypeError):
            self.direct = False
            return
        self.cone_data = _ConeData.of(chain.solver, prog, logs)

    def _direct(self) -> str:
        solver, prog, logs, cols = self.compiled
        try:
            if self.cone_data is not None:
                raw = self.cone_data.solve()
            else:
                for p, log_p in logs:
                    log_p.save_value(np.log(p.value))
                raw = solver.solve_via_data(solver.apply(prog)[0], False, False, {})
        except Exception:                       # the solver's own failure: as cvxpy reports it
            return "solver_error"
        status = solver.STATUS_MAP.get(str(raw.status), "solver_error")
        if status in ("optimal", "optimal_inaccurate"):
            x = np.asarray(raw.x)
            for v, col in zip(self.variables, cols):
                v.save_value(np.exp(np.asarray(x[col])))
        return status


class _ConeData:
    """The cone program's data (A, b, c) for the solver, from the parameter
    vector, as cvxpy's ``ConicSolver.apply`` builds it, without its sparse
    slicing: one product with cvxpy's own reduced map, then the columns of
    A and b read off the fixed sparsity pattern. ``of`` checks that both
    give the same arrays, entry for entry, and returns None otherwise (the
    solver's own ``apply`` is used then); half the time of a re-solve went
    into scipy building and slicing those matrices.

    ``solve`` hands those arrays to Clarabel as cvxpy's ``solve_via_data``
    does (the same empty quadratic term, cones and default settings, so
    the same iterates), with the cones and settings built once: after the
    solver's own work, what is left of a re-solve is filling the parameter
    vector (the parameters' logarithms, in the reduced map's columns)."""

    def __init__(self, solver, prog, base: dict, logs: list):
        from cvxpy.cvxcore.python import canonInterface
        import scipy.sparse as sp
        from cvxpy import settings as cvx
        from cvxpy.reductions.solvers.conic_solvers.clarabel_conif import dims_to_solver_cones
        self.solver, self.prog, self.base = solver, prog, base
        indices, indptr, shape = prog.reduced_A.problem_data_index
        n = prog.x.size
        self.m, self.n, self.split = shape[0], n, int(indptr[n])
        self.a_indices, self.a_indptr = np.asarray(indices[:self.split]), np.asarray(indptr[:n + 1])
        self.b_rows = np.asarray(indices[self.split:])
        self.b_unique = np.unique(self.b_rows).size == self.b_rows.size
        self.A = None
        # the parameter vector as canonInterface.get_parameter_vector lays it out: scalars only
        self.params = [p for p, _ in logs]
        if any(prog.param_id_to_size[log_p.id] != 1 for _, log_p in logs):
            raise ValueError("only scalar parameters are laid out here")
        self.columns = np.array([prog.param_id_to_col[log_p.id] for _, log_p in logs], dtype=np.intp)
        self.template = canonInterface.get_parameter_vector(
            prog.total_param_size, prog.param_id_to_col, prog.param_id_to_size, lambda i: np.zeros(1))
        self.cones = dims_to_solver_cones(base[cvx.DIMS])
        self.P = sp.triu(sp.csc_array((n, n))).tocsc()
        self.settings = solver.parse_solver_opts(False, {})

    @classmethod
    def of(cls, solver, prog, logs) -> "_ConeData | None":
        from cvxpy import settings as cvx
        if solver.name() != "CLARABEL":     # ``solve`` speaks Clarabel's interface
            return None
        try:
            for p, log_p in logs:
                log_p.save_value(np.log(p.value))
            reference, _ = solver.apply(prog)
            mine = cls(solver, prog, {k: v for k, v in reference.items() if k not in (cvx.A, cvx.B, cvx.C)}, logs)
            data = mine.data()
            same = (data[cvx.A].shape == reference[cvx.A].shape and (data[cvx.A] != reference[cvx.A]).nnz == 0
                    and np.array_equal(data[cvx.B], reference[cvx.B]) and np.array_equal(data[cvx.C], reference[cvx.C]))
        except Exception:                  # a cvxpy without these internals: its own path
            return None
        return mine if same else None

    def vector(self) -> np.ndarray:
        """The reduced map's parameter vector: each parameter's logarithm in its column."""
        vec = self.template.copy()
        vec[self.columns] = np.log(np.array([p.value for p in self.params], dtype=float))
        return vec

    def data(self, copy: bool = True) -> dict:
        """The solver's data at the parameters' current values (``copy``
        False: A is the one matrix this object refills on every call)."""
        import scipy.sparse as sp
        from cvxpy import settings as cvx
        vec = self.vector()
        c = np.asarray(self.prog.q @ vec).ravel()
        flat = np.asarray(self.prog.reduced_A.reduced_mat @ vec).ravel()
        if self.A is None:
            self.A = sp.csc_array((-flat[:self.split], self.a_indices, self.a_indptr), shape=(self.m, self.n))
        A = self.A.copy() if copy else self.A
        A.data = -flat[:self.split]    # the pattern is fixed: scipy's checks once, not per solve
        b = np.zeros(self.m)
        if self.b_unique:
            b[self.b_rows] += flat[self.split:]     # what np.add.at gives when no row repeats
        else:
            np.add.at(b, self.b_rows, flat[self.split:])
        return {**self.base, cvx.A: A, cvx.B: b, cvx.C: c[:-1]}

    def solve(self):
        """Clarabel's solution of the program at the parameters' current values."""
        import clarabel
        from cvxpy import settings as cvx
        data = self.data(copy=False)
        return clarabel.DefaultSolver(self.P, data[cvx.C], data[cvx.A], data[cvx.B], self.cones,
                                      self.settings).solve()
