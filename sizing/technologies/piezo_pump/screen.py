"""The piezo pump's design space, screened by the cycle-averaged model.

Every stack x count x amplifier x valve x accumulator (each rated for the
required temperature, with the fluid and the seal rated for it) is tried at
every pump piston diameter and pumping frequency of the grids below; the
cylinder bore is sized in closed form so that the stall pressure, less both
valves' cracking pressures and the seal friction, gives the blocked force
with the design margin. Each row's static figures (physics/pump.py, eqs.
P1-P4), margins and metrics are arrays over the rows (docs/models.md,
"Piezo pump").
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...physics import amplifier as amp_phys, fluid as fluid_props, geometry, pump, stack as stack_phys
from ...physics.bouc_wen import free_displacement
from ..piezohydraulic.convex import DEFAULT_MAX_MASS
from ...engine.loads import surface_mass
from ..piezohydraulic.parts import reference_bouc_wen, stack_bouc_wen
from ..piezohydraulic.search import temperature_margin

PUMP_DIAMETERS = (0.008, 0.012, 0.016, 0.020, 0.025, 0.032, 0.040, 0.050, 0.063, 0.080)   # m
FREQUENCIES = (50.0, 100.0, 150.0, 200.0, 300.0, 400.0, 600.0, 800.0, 1000.0)  # Hz
MAX_STACKS = 4                 # stacks side by side on one pump piston
# assumed (docs/models.md, "Piezo pump"): free air in the oil at atmospheric
# pressure after filling and bleeding; the Lynch group blamed "possible air
# entrapment" for their external-valve pump's low output
AIR_FRACTION = 0.005
CHAMBER_CLEARANCE = 0.3e-3     # m, assumed: oil gap of the chamber beyond the stack's stroke
PORT_DEPTH = 5e-3              # m, assumed: each valve port's dead volume is its area x this
DEAD_LENGTH = 0.02             # m, assumed: line and manifold oil of the cylinder's high side, over its bore area
ALUMINIUM_MODULUS = 69e9       # Pa, the body's 6061-T6 (geometry.py's construction)
# assumed: the stacks sit in the circulating low-pressure oil; forced
# convection to a liquid, the low end of Incropera's Table 1.1 range
# (100-20000 W/(m^2 K))
PUMP_FILM_COEFFICIENT = 200.0
# the line from the pump to the cylinder (physics/pump.py, P6): assumed 0.2 m,
# the pump beside the cylinder in the control-surface bay; its bore keeps the
# mean oil velocity at the required speed below LINE_VELOCITY (hydraulic
# pressure-line practice, 2-6 m/s; assumed: 5 m/s), at least LINE_MIN_DIAMETER
# (a 1/4 in tube's 4 mm bore, assumed)
LINE_LENGTH = 0.2
LINE_VELOCITY = 5.0
LINE_MIN_DIAMETER = 0.004
DIRECTION_VALVE_MASS = 0.35    # kg, assumed: a pair of solenoid poppets switching the cylinder's sides
DIRECTION_VALVE_COST = 600.0   # USD, assumed
from ...settings import RESONANCE_FRACTION, VALVE_DROP_FRACTION  # noqa: E402  the screen's thresholds (sizing/settings.py)
# assumed: a reed's damping in oil (viscous and squeeze film against its
# seat), a fraction of critical; no maker states one for these reeds
REED_DAMPING_RATIO = 0.15
BW_CYCLES, BW_POINTS = 4, 200  # Bouc-Wen at the pumping frequency: cycles run, points a cycle


@dataclass
class Group:
    """One combination of parts; the grids run inside it."""
    stack: object
    n: int
    amplifier: object
    valve: object
    accumulator: object
    fluid: object
    seal: object


def groups(req, catalog) -> tuple[list[Group], dict]:
    """The part combinations rated for the required temperature, and the
    counts of those ruled out by a rating (reason -> n)."""
    T = req.requirements.max_temperature
    ruled: dict[str, int] = {}

    def rated(parts, key):
        ok = [p for p in parts if p.max_temperature >= T and getattr(p, "min_temperature", -math.inf) <= T]
        if len(ok) < len(parts):
            ruled["temperature"] = ruled.get("temperature", 0) + len(parts) - len(ok)
        return sorted(ok, key=key)

    fluids = rated(list(catalog.fluids.values()), lambda f: -f.bulk_modulus)[:1]
    seals = rated(list(catalog.seals.values()), lambda s: s.friction_per_length)[:1]
    stacks = rated(list(catalog.stacks.values()), lambda s: s.id)
    valves = rated(list(catalog.valves.values()), lambda v: v.id)
    accs = rated(list(catalog.accumulators.values()), lambda a: a.id)
    out = []
    for s in stacks:
        amps = [a for a in catalog.amplifiers.values() if a.max_voltage >= 0.9 * s.max_voltage]
        for a in sorted(amps, key=lambda a: a.continuous_current)[-1:]:
            for n in range(1, MAX_STACKS + 1):
                out += [Group(s, n, a, v, acc, f, sl) for v in valves for acc in accs for f in fluids for sl in seals]
    return out, ruled


def bouc_wen_stroke(stack, reference, voltage: float, frequency: float, temperature: float) -> float:
    """Peak-to-peak free stroke of one stack (m) under a sine 0..V at f, the
    last of BW_CYCLES cycles of the Bouc-Wen model (seed eqs. 1-2), derated
    to the temperature."""
    bw, _ = stack_bouc_wen(stack, reference)
    t = np.linspace(0.0, BW_CYCLES / frequency, BW_CYCLES * BW_POINTS + 1)
    v = 0.5 * voltage * (1.0 - np.cos(2.0 * np.pi * frequency * t))
    x = free_displacement(t, v, bw)[-BW_POINTS - 1:]
    return float(stack_phys.derated_stroke(x.max() - x.min(), stack.stroke_temperature_coefficient, temperature))


def rows(req, catalog, gs: list[Group], frequencies=FREQUENCIES, diameters=PUMP_DIAMETERS, rated=True,
         voltage=None) -> dict[str, np.ndarray]:
    """The grid of every group as flat arrays (n_rows,), SI, with the index
    of each row's group in ``group``: at most each valve's rated frequency
    (``rated``), the stacks at their and the amplifier's voltage unless
    ``voltage`` is given."""
    T = req.requirements.max_temperature
    ref = reference_bouc_wen(catalog.stacks)
    strokes: dict[tuple, float] = {}
    cols: dict[str, list] = {k: [] for k in ("group", "pump_diameter", "frequency", "stroke")}
    volts = [voltage or min(g.stack.max_voltage, g.amplifier.max_voltage) for g in gs]
    for i, g in enumerate(gs):
        V = volts[i]
        for f in frequencies:
            if rated and f > g.valve.max_frequency:
                continue
            key = (id(g.stack), V, f)          # a perturbed stack (sizing robust) is its own object
            if key not in strokes:
                strokes[key] = bouc_wen_stroke(g.stack, ref, V, f, T)
            for d in diameters:
                cols["group"].append(i)
                cols["pump_diameter"].append(d)
                cols["frequency"].append(f)
                cols["stroke"].append(strokes[key])
    R = {k: np.asarray(v, dtype=int if k == "group" else float) for k, v in cols.items()}
    gi = R["group"]

    def part(fn):
        return np.array([fn(g) for g in gs], dtype=float)[gi]

    R.update({
        "n_stacks": part(lambda g: g.n), "stack_stiffness": part(lambda g: g.stack.stiffness),
        "voltage": np.asarray(volts, float)[gi],
        "capacitance": part(lambda g: g.stack.capacitance), "loss_factor": part(lambda g: g.stack.loss_factor or stack_phys.DEFAULT_LOSS_FACTOR),
        "stack_mass": part(lambda g: g.stack.mass), "stack_cost": part(lambda g: g.stack.cost_usd),
        "stack_length": part(lambda g: g.stack.length), "stack_diameter": part(lambda g: g.stack.diameter),
        "square": part(lambda g: g.stack.section == "square"),
        "bulk_modulus": part(lambda g: fluid_props.bulk_modulus_at(g.fluid.bulk_modulus, g.fluid.bulk_modulus_temperature_coefficient, T)),
        "density": part(lambda g: fluid_props.density_at(g.fluid.density, g.fluid.thermal_expansion, T)),
        "air_dissolution_pressure": part(lambda g: g.fluid.air_dissolution_pressure or math.inf),
        "kinematic_viscosity": part(lambda g: fluid_props.kinematic_viscosity(g.fluid.viscosity_40C, g.fluid.viscosity_100C, T)),
        "bias_pressure": part(lambda g: g.accumulator.bias_pressure),
        "f0": part(lambda g: g.seal.friction_per_length), "cp": part(lambda g: g.seal.friction_pressure_coefficient),
    })
    for name in ("cracking_pressure", "port_area", "reed_stiffness", "max_lift", "discharge_coefficient", "reed_mass",
                 "seat_width", "seat_gap"):
        R[name] = part(lambda g, name=name: getattr(g.valve, name))
    R["reed_wetted_mass"] = R["reed_mass"] + np.array(
        [pump.reed_added_mass(g.valve.reed_shape, fluid_props.density_at(g.fluid.density, g.fluid.thermal_expansion, T),
                              g.valve.reed_width, g.valve.reed_length, g.valve.modal_factor) for g in gs])[gi]
    return R


def valve_of(R) -> dict:
    return {k: R[k] for k in ("cracking_pressure", "port_area", "reed_stiffness", "max_lift", "discharge_coefficient")}


def figures(req, R: dict, loads: list[float]) -> dict[str, np.ndarray]:
    """Static figures of every row (cycle-averaged model), SI."""
    r, o = req.requirements, req.options
    A_p = math.pi * R["pump_diameter"] ** 2 / 4.0
    K = R["n_stacks"] * R["stack_stiffness"]
    K_path = K * o.structure_stiffness_ratio / (1.0 + o.structure_stiffness_ratio)   # frame in series
    gap = R["stroke"] + CHAMBER_CLEARANCE
    V_c = A_p * gap + 2.0 * R["port_area"] * PORT_DEPTH
    swept = pump.swept_volume(A_p, R["stroke"])
    stall = np.zeros_like(swept)
    for _ in range(3):                       # the chamber's modulus at its mean pressure
        wall = pump.wall_compliance(R["pump_diameter"], geometry.wall_thickness(A_p, R["bias_pressure"] + stall), ALUMINIUM_MODULUS)
        beta = pump.effective_bulk_modulus(R["bulk_modulus"], AIR_FRACTION, R["bias_pressure"] + pump.P_ATM + stall / 2, wall,
                                           dissolution_pressure=R["air_dissolution_pressure"])
        stall = pump.stall_pressure(swept, pump.chamber_compliance(V_c, beta, A_p, K_path))
    net = stall - 2.0 * R["cracking_pressure"]
    D_c = R.get("cylinder_diameter")                     # a stated bore (sizing evaluate), else sized
    if D_c is None:
        D_c = _bore(net, R["f0"] + R["cp"] * (R["bias_pressure"] + stall), r.blocked_force * (1.0 + o.design_margin))
    A_c = math.pi * D_c**2 / 4.0
    friction = lambda p: math.pi * D_c * (R["f0"] + R["cp"] * p)        # noqa: E731  (seal at gauge pressure p)
    blocked = A_c * net - friction(R["bias_pressure"] + stall)
    line = line_of(R, A_c, r.speed, R.get("line_length", LINE_LENGTH), R.get("line_diameter"))
    speeds = []
    for F in loads:
        v = np.zeros_like(A_c)
        for _ in range(2):                   # the line's viscous drop at the speed it carries
            p_load = (F + friction(R["bias_pressure"] + F / A_c) + line["line_damping_N_s_m"] * v) / A_c
            avg = pump.cycle_averaged(swept, V_c, R["bulk_modulus"], AIR_FRACTION, wall, A_p, K_path, R["frequency"],
                                      R["bias_pressure"], p_load, R["cracking_pressure"], R["air_dissolution_pressure"])
            v = avg["flow_m3_s"] / A_c
        speeds.append(v)
    speeds = np.array(speeds).reshape(len(loads), -1)
    worst = int(np.argmax(loads)) if loads else 0
    mean_speed = speeds[worst] if loads else swept * R["frequency"] / A_c
    C_L = R["n_stacks"] * R["capacitance"] * stack_phys.LARGE_SIGNAL_CAPACITANCE_FACTOR
    peak, rms = pump.sine_current(C_L, R["voltage"], R["frequency"])
    run = min(1.0, 2.0 * req.duty.strokes_per_second * r.stroke / r.speed)   # pumping out and back at speed
    heat = stack_phys.heat_per_stack(R["loss_factor"], R["capacitance"], R["voltage"], R["frequency"]) * run
    area = stack_phys.side_area(R["stack_length"], R["stack_diameter"], R["square"] > 0)
    p_h = R["bias_pressure"] + max(loads or [0.0]) / A_c
    m_out = surface_mass(req.load) + geometry.narrow_piston_mass(A_c, r.stroke)
    beta_h = pump.effective_bulk_modulus(R["bulk_modulus"], AIR_FRACTION, p_h + pump.P_ATM,
                                         dissolution_pressure=R["air_dissolution_pressure"])
    V_h = A_c * (DEAD_LENGTH + r.stroke) + line["line_volume_m3"]
    f_n = np.sqrt(beta_h * A_c**2 / (V_h * (m_out + line["line_mass_kg"]))) / (2 * math.pi)
    return {
        "pump_area_m2": A_p, "cylinder_diameter_m": D_c, "cylinder_area_m2": A_c, "chamber_volume_m3": V_c,
        "chamber_gap_m": gap, "wall_compliance_1_Pa": wall, "chamber_bulk_modulus_Pa": beta,
        "chamber_stiffness_N_m": pump.chamber_stiffness(beta, A_p, V_c), "stack_stiffness_N_m": K_path,
        "swept_volume_m3": swept, "stall_pressure_Pa": stall, "blocked_force_N": blocked,
        "peak_pressure_Pa": R["bias_pressure"] + stall, "speeds": speeds, "mean_speed_m_s": mean_speed,
        "no_load_speed_m_s": swept * R["frequency"] / A_c,
        "output_power_W": (max(loads) if loads else 0.0) * mean_speed,
        "peak_current_A": peak, "rms_current_A": rms,
        "amplifier_power_VA": pump.apparent_power(C_L, R["voltage"], R["frequency"]),
        "reactive_power_var": pump.reactive_power(C_L, R["voltage"], R["frequency"]),
        "stack_heat_W": heat, "run_fraction": np.full_like(peak, run),
        "stack_temperature_rise_K": stack_phys.temperature_rise(heat, area, PUMP_FILM_COEFFICIENT),
        "output_natural_frequency_Hz": f_n, "output_mass_kg": m_out,
        # at rest the check valves lock the cylinder's loaded side: its oil column holds the output
        "output_stiffness_N_m": beta_h * A_c / (DEAD_LENGTH + r.stroke),
        "oil_volume_m3": V_c + A_c * (2.0 * r.stroke + 2.0 * DEAD_LENGTH) + line["line_volume_m3"],
        **line,
        "capacitance_large_F": C_L,
        "valve_wetted_resonance_Hz": pump.valve_resonance(R["reed_stiffness"], R["reed_wetted_mass"]),
        "valve_peak_drop_Pa": pump.valve_drop(pump.peak_flow(swept, R["frequency"]), R["density"], **valve_of(R),
                                              viscosity=R["kinematic_viscosity"] * R["density"],
                                              seat_width=R["seat_width"]),
    }


def line_of(R, cylinder_area, speed, length=LINE_LENGTH, diameter=None) -> dict[str, np.ndarray]:
    """The line from the pump to the cylinder (P6): its bore (given, or by
    the velocity rule), the mass and damping it reflects on the piston, its
    oil volume."""
    d = np.maximum(LINE_MIN_DIAMETER, np.sqrt(4.0 * cylinder_area * speed / (math.pi * LINE_VELOCITY)))
    d = d if diameter is None else np.full_like(d, diameter)
    L = np.full_like(d, length)
    mu = R["kinematic_viscosity"] * R["density"]
    return {"line_length_m": L, "line_diameter_m": d,
            "line_mass_kg": pump.reflected_mass(R["density"], L, d, cylinder_area),
            "line_damping_N_s_m": pump.reflected_damping(mu, L, d, cylinder_area),
            "line_volume_m3": pump.line_area(d) * L}


def _bore(net, g, force):
    """Cylinder bore D (m) with A(D) net - pi D g = force, rounded up to 1 mm
    (nan where the net pressure is not positive)."""
    net = np.where(net > 0, net, np.nan)
    D = (math.pi * g + np.sqrt((math.pi * g) ** 2 + math.pi * net * force)) / (math.pi * net / 2.0)
    return np.ceil(D * 1e3 - 1e-9) / 1e3


def drive(req, gs, R, st) -> dict[str, np.ndarray]:
    """The amplifier units each row needs (the sine's peak on max_current,
    its rms on continuous_current), those counted (at most the option's),
    and the heat they shed over the run fraction (physics/amplifier.py)."""
    gi = R["group"]
    pick = lambda fn: np.array([fn(g) for g in gs], dtype=float)[gi]   # noqa: E731
    needed = np.maximum(np.ceil(np.maximum(st["peak_current_A"] / pick(lambda g: g.amplifier.max_current),
                                           st["rms_current_A"] / pick(lambda g: g.amplifier.continuous_current)) - 1e-9), 1)
    heat = amp_phys.dissipated_power(st["capacitance_large_F"], R["voltage"], R["frequency"],
                                     pick(lambda g: g.amplifier.energy_recovery)) * st["run_fraction"]
    return {"amplifier_units_needed": needed, "amplifier_units": np.minimum(needed, req.options.max_amplifier_units),
            "amplifier_heat_W": heat}


def margins(req, gs, R, st, loads) -> dict[str, np.ndarray]:
    """Every static check of every row, floor/ceiling margins (>= 0 met)."""
    r, o = req.requirements, req.options
    T = r.max_temperature
    gi = R["group"]
    pick = lambda fn: np.array([fn(g) for g in gs], dtype=float)[gi]   # noqa: E731
    amp_T = T if o.amplifier_location == "actuator" else o.electronics_bay_temperature
    temps = pick(lambda g: min(temperature_margin(p.max_temperature, T)
                               for p in (g.stack, g.fluid, g.seal, g.valve, g.accumulator)))
    needed = st["amplifier_units_needed"]
    thermal_volume = st["oil_volume_m3"] * pick(lambda g: g.fluid.thermal_expansion) * (T - o.drift_reference_temperature)
    speed = np.min(st["speeds"], axis=0) if loads else st["mean_speed_m_s"]
    k_out, F_max = st["output_stiffness_N_m"], max(loads) if loads else 0.0
    travel = r.stroke * (1.0 + o.design_margin) - (F_max if r.stroke_from == "neutral" else 0.0) / k_out
    holds = {"stiffness": k_out / r.min_stiffness - 1.0} if r.min_stiffness is not None else {}
    return {
        **holds,
        "stroke": travel / r.stroke - 1.0,       # the cylinder's travel (from neutral: less the rest offset)
        "blocked_force": st["blocked_force_N"] / r.blocked_force - 1.0,
        "speed": speed / r.speed - 1.0,
        "temperature": temps,
        "amplifier_temperature": pick(lambda g: temperature_margin(g.amplifier.max_temperature, amp_T)),
        "pressure": pick(lambda g: g.seal.pressure_rating) / st["peak_pressure_Pa"] - 1.0,
        "amplifier_units": o.max_amplifier_units / needed - 1.0,
        "stack_temperature": (pick(lambda g: g.stack.max_temperature) - T - st["stack_temperature_rise_K"]) / max(abs(T), 1.0),
        "valve_resonance": pick(lambda g: g.valve.max_frequency) / R["frequency"] - 1.0,
        # the outlet returns its drop within the cycle; the inlet refills the chamber without cavitating
        "valve_flow": np.minimum(VALVE_DROP_FRACTION * st["stall_pressure_Pa"],
                                 R["bias_pressure"] + pump.P_ATM) / st["valve_peak_drop_Pa"] - 1.0,
        "output_resonance": RESONANCE_FRACTION * st["output_natural_frequency_Hz"] / R["frequency"] - 1.0,
        "natural_frequency": st["output_natural_frequency_Hz"] / req.natural_frequency - 1.0,
        "accumulator_capacity": pick(lambda g: g.accumulator.capacity) / np.maximum(thermal_volume, 1e-12) - 1.0,
    }


def metrics(req, gs, R, st) -> dict[str, np.ndarray]:
    """Mass (kg), cost (USD), volume (m^3) and the amplifier's apparent power (VA as W)."""
    r, o = req.requirements, req.options
    gi = R["group"]
    pick = lambda fn: np.array([fn(g) for g in gs], dtype=float)[gi]   # noqa: E731
    A_p, A_c, p = st["pump_area_m2"], st["cylinder_area_m2"], st["peak_pressure_Pa"]
    rho = R["density"]
    in_stage = A_p * st["chamber_gap_m"] + A_c * r.stroke         # the oil hydraulic_mass counts
    hyd = geometry.hydraulic_mass(A_p, A_c, p, st["chamber_gap_m"], r.stroke, rho) + rho * (st["oil_volume_m3"] - in_stage)
    # the stacks' frame: tie rods structure_stiffness_ratio x the stacks' stiffness over their length,
    # and a base plate under the group carrying their blocked force
    L = R["stack_length"]
    frame = geometry.ALUMINIUM_DENSITY * o.structure_stiffness_ratio * R["n_stacks"] * R["stack_stiffness"] * L**2 / ALUMINIUM_MODULUS
    pack = math.pi / 4 * (R["stack_diameter"] * np.sqrt(R["n_stacks"]) * 1.2) ** 2
    plate = geometry.ALUMINIUM_DENSITY * pack * geometry.plate_thickness(pack, st["stall_pressure_Pa"] * A_p / pack)
    metal = hyd - rho * st["oil_volume_m3"] + frame + plate
    units = st["amplifier_units"]
    mass = (R["n_stacks"] * R["stack_mass"] + hyd + frame + plate + units * pick(lambda g: g.amplifier.mass)
            + 2 * pick(lambda g: g.valve.mass) + pick(lambda g: g.accumulator.mass) + DIRECTION_VALVE_MASS)
    cost = (R["n_stacks"] * R["stack_cost"] + units * pick(lambda g: g.amplifier.cost_usd)
            + 2 * pick(lambda g: g.valve.cost_usd) + pick(lambda g: g.accumulator.cost_usd) + DIRECTION_VALVE_COST
            + 2 * pick(lambda g: g.seal.cost_usd) + pick(lambda g: g.fluid.cost_usd) * st["oil_volume_m3"] * 1000
            + geometry.MACHINING_USD_PER_KG * metal + geometry.FIXED_HYDRAULIC_USD)
    stack_volume = math.pi / 4 * R["stack_diameter"] ** 2 * L
    volume = 1.5 * R["n_stacks"] * stack_volume + geometry.hydraulic_volume(A_p, A_c, p, st["chamber_gap_m"], r.stroke)
    return {"mass_kg": mass, "cost_usd": cost, "volume_m3": volume, "power_W": st["amplifier_power_VA"]}


def envelope(req, R, st, met) -> np.ndarray:
    """Why each row lies outside the requirements' envelope (or the 10 t
    plausibility ceiling), "" when inside: such a design is ruled out with
    reason ``envelope``, never ranked. Pump and cylinder in line: length
    stack + 30 mm of plates and chamber + the stroke and the rod's land;
    diameter the larger of the stack group (packed, with the body wall) and
    the cylinder with its wall."""
    r, env = req.requirements, req.envelope
    length = R["stack_length"] + 0.03 + r.stroke * (1 + req.options.design_margin) + geometry.ROD_EXTRA_LENGTH
    p = st["peak_pressure_Pa"]
    body = 1.2 * R["stack_diameter"] * np.sqrt(R["n_stacks"]) + 2 * geometry.MIN_WALL
    cylinder = st["cylinder_diameter_m"] + 2 * geometry.wall_thickness(st["cylinder_area_m2"], p)
    diameter = np.maximum(body, cylinder)
    out = np.full(len(length), "", dtype=object)
    checks = (("mass", met["mass_kg"], env.max_mass or DEFAULT_MAX_MASS, "kg"), ("diameter", diameter, env.diameter, "m"),
              ("length", length, env.max_length, "m"))
    for name, value, limit, unit in checks:
        if limit is None:
            continue
        over = (value > limit * (1 + 1e-9)) & (out == "")
        out[over] = [f"{name} {v:.4g} {unit} over the envelope's {limit:.4g} {unit}" for v in value[over]]
    return out
