"""Static figures, metrics and simulated load cases of piezohydraulic
candidates (arrays over candidates)."""
from __future__ import annotations

import numpy as np

from ...physics import amplifier, geometry, hydraulics, stack as stack_phys, structure, thermal
from . import force_path
from ...sim.metrics import final_value, step_metrics
from ...sim.piezohydraulic import PiezoHydraulicModel, simulate
from .parts import Candidates

OUTPUT_RATE_HZ = 2000.0
SETTLE_TIME_S = 0.25


def ramp_time(c: Candidates, rise_time) -> np.ndarray:
    """Time to ramp the drive from 0 to its voltage: the requested rise time,
    or longer when the amplifier units cannot supply i = n C_large dV/dt
    (at their peak for a ramp within the rated pulse, else at their
    continuous rating) or slew."""
    charge = c.n_stacks * c.capacitance * stack_phys.LARGE_SIGNAL_CAPACITANCE_FACTOR * c.voltage
    t_peak = charge / (c.amp_units * c.amp_max_current)
    t_current = np.where(t_peak <= c.amp_peak_duration, t_peak, charge / (c.amp_units * c.amp_continuous))
    t_slew = np.where(c.amp_slew > 0, c.voltage / np.where(c.amp_slew > 0, c.amp_slew, 1.0), 0.0)
    return np.maximum.reduce([np.broadcast_to(rise_time, c.voltage.shape), t_current, t_slew])


GAP_CLEARANCE_M = 0.5e-3       # assumed: wide gap left over the stack stroke (machining, tilt, oil film)
GAP_TOLERANCE_M = 0.1e-3       # assumed: manufacturing tolerance on the gap (IT9 over a 100 mm bore is 87 um)
STACK_SPACING_M = force_path.STACK_SPACING_M
FILL_TEMPERATURE_DEGC = 20.0   # oil filled and sealed at this temperature (thermal budget reference)
PISTON_CTE = 23.6e-6           # 1/K, 6061-T6 casing and pistons (catalogs/materials.toml al-6061-t6)


def static_figures(c: Candidates, rise_time, strokes_per_second=1.0) -> dict[str, np.ndarray]:
    """Static figures with the whole force path in series (force_path.py),
    seals at pressure, the thermal budget, the geometry checks and the
    amplifier's continuous current over the duty cycle."""
    m = force_path.members(c)
    tot = force_path.totals(m)
    x = c.stack_free_stroke
    R = c.ratio
    k_stacks = c.n_stacks * c.stiffness
    k = tot["total"]
    out = {
        "free_stroke_m": R * x,
        # docs/formats.md, force_path: d33 V over the summed compliances, over R
        "blocked_force_N": x / tot["compliance_sum"] / R,
        "blocked_force_ideal_N": k_stacks * x / R,
        "stack_force_N": k_stacks * x,
        "work_J": k_stacks * x**2,
        "force_path_stiffness_N_m": k,
        "fluid_stiffness_N_m": m["oil_column"]["stiffness"],
        "compliance_force_fraction": k / k_stacks,
        "output_stiffness_N_m": k / R**2,
        "blocked_pressure_Pa": k * x / c.wide_area,
        "reflected_mass_kg": c.reflected_mass,
    }
    out["blocked_force_compliant_N"] = out["blocked_force_N"]
    out["blocked_force_oil_only_N"] = hydraulics.series(k_stacks, m["oil_column"]["stiffness"]) * x / R
    with np.errstate(divide="ignore"):
        out["natural_frequency_Hz"] = np.sqrt(k / c.reflected_mass) / (2 * np.pi)
    out.update(_seal_figures(c, out["blocked_pressure_Pa"]))
    out["blocked_force_net_N"] = out["blocked_force_N"] - out["seal_output_force_blocked_N"]
    out["ratio"] = c.ratio
    out["wide_diameter_m"] = 2 * geometry.radius(c.wide_area)
    out["narrow_diameter_m"] = 2 * geometry.radius(c.narrow_area)
    out["drive_current_A"] = stack_phys.drive_current(c.n_stacks, c.capacitance, c.voltage / np.asarray(rise_time))
    # amplifier continuous current: charge n C_L V out and back per cycle
    out["continuous_current_A"] = 2 * c.n_stacks * c.capacitance * stack_phys.LARGE_SIGNAL_CAPACITANCE_FACTOR \
        * c.voltage * strokes_per_second
    out.update(drive_figures(c, rise_time, strokes_per_second))
    out["oil_volume_m3"] = c.oil_volume
    out["thermal_drift_per_K_m"] = thermal.output_drift(c.oil_volume, c.thermal_expansion, 1.0, c.narrow_area)
    out.update({"thermal_" + k_: v for k_, v in thermal_budget(c, m).items()})
    out["wide_gap_m"] = c.wide_gap
    out["gap_needed_m"] = x + GAP_CLEARANCE_M + GAP_TOLERANCE_M
    out["stacks_that_fit"] = structure.stacks_that_fit(out["wide_diameter_m"], c.stack_diameter, STACK_SPACING_M)
    structural = sum(np.asarray(m[k_]["mass"]) for k_ in ("base_plate", "end_cap", "frame", "spacer"))
    out["structure_mass_kg"] = structural
    out["length_m"] = 2 * c.cap_thickness + m["frame"]["length"] + c.free_stroke + geometry.ROD_EXTRA_LENGTH
    out["casing_diameter_m"] = (out["wide_diameter_m"] * (1 + c.pressure_rating / geometry.DESIGN_STRESS)
                                + 2 * geometry.MIN_WALL)
    out["outer_diameter_m"] = outer_diameter(out["casing_diameter_m"], c.frame_area)
    out["plate_thickness_to_radius"] = structure.thickness_ratio(c.cap_thickness, geometry.radius(c.wide_area))
    return out


def outer_diameter(casing_diameter, frame_area):
    """Outer diameter with the tie-rod frame as a ring of its whole section
    around the casing: sqrt(D_casing^2 + 4 A_f / pi), m."""
    return np.sqrt(np.asarray(casing_diameter) ** 2 + 4.0 / np.pi * np.asarray(frame_area))


def drive_figures(c: Candidates, rise_time, strokes_per_second) -> dict[str, np.ndarray]:
    """The drive at the duty (physics/amplifier.py) and the stacks' own heat
    (physics/stack.py): currents, units needed, heat and temperature rise."""
    C = c.n_stacks * c.capacitance * stack_phys.LARGE_SIGNAL_CAPACITANCE_FACTOR
    ramp = np.broadcast_to(np.asarray(rise_time, dtype=float), c.voltage.shape)
    heat = stack_phys.heat_per_stack(c.loss_factor, c.capacitance, c.voltage, strokes_per_second)
    area = stack_phys.side_area(c.stack_length, c.stack_diameter, c.stack_square > 0)
    return {
        "ramp_current_A": amplifier.ramp_current(C, c.voltage, ramp),
        "rms_current_A": amplifier.rms_current(C, c.voltage, ramp, strokes_per_second),
        "amplifier_units_needed": amplifier.units_needed(C, c.voltage, ramp, strokes_per_second, c.amp_max_current,
                                                         c.amp_continuous, c.amp_peak_duration),
        "amplifier_units": c.amp_units,
        "amplifier_heat_W": amplifier.dissipated_power(C, c.voltage, strokes_per_second, c.amp_recovery),
        "stack_heat_W": heat,
        "stack_temperature_rise_K": stack_phys.temperature_rise(heat, area),
    }


def _seal_figures(c: Candidates, pressure) -> dict[str, np.ndarray]:
    """Running seal friction at the blocked pressure, and what it takes off
    the output force (narrow seal plus wide seal over R)."""
    wide = c.wide_friction + c.wide_friction_cp * pressure
    narrow = c.narrow_friction + c.narrow_friction_cp * pressure
    return {"seal_wide_blocked_N": wide, "seal_narrow_blocked_N": narrow,
            "seal_output_force_blocked_N": narrow + wide / c.ratio}


def seal_friction_at(c: Candidates, pressure) -> dict[str, np.ndarray]:
    """Running friction of both seals at a chamber pressure (Pa), N."""
    return {"wide": c.wide_friction + c.wide_friction_cp * pressure,
            "narrow": c.narrow_friction + c.narrow_friction_cp * pressure}


def thermal_budget(c: Candidates, m: dict | None = None) -> dict[str, np.ndarray]:
    """physics/thermal.budget for the candidates, from the fill temperature
    to the required one (``c.delta_T``)."""
    m = m if m is not None else force_path.members(c)
    t_p = geometry.plate_thickness(c.wide_area, c.pressure_rating)
    L_n = c.free_stroke + geometry.ROD_EXTRA_LENGTH
    stack_column = c.stack_cte * c.stack_length + c.spacer_cte * c.spacer_length
    return thermal.budget(c.delta_T, c.ratio, c.narrow_area, c.oil_volume, c.thermal_expansion, PISTON_CTE,
                          stack_column, 1.0, c.mat_cte, m["frame"]["length"], PISTON_CTE, t_p, L_n,
                          compensated=c.comp_kind > 0, compensator_capacity=c.comp_capacity)


def metrics(c: Candidates, rise_time) -> dict[str, np.ndarray]:
    """Mass (kg), cost (USD), volume (m^3) and peak electrical power (W)."""
    m = force_path.members(c)
    hyd_mass = geometry.hydraulic_mass(c.wide_area, c.narrow_area, c.pressure_rating, c.wide_gap,
                                       c.free_stroke, c.density)
    structural = ("base_plate", "end_cap", "frame", "spacer")
    s_mass = sum(np.asarray(m[k]["mass"]) for k in structural)
    s_cost = sum(np.asarray(m[k]["cost"]) for k in structural)
    mass = c.n_stacks * c.stack_mass + hyd_mass + c.amp_units * c.amp_mass + s_mass + c.comp_mass
    metal = hyd_mass - c.density * c.oil_volume
    cost = (c.n_stacks * c.stack_cost + c.amp_units * c.amp_cost + c.seal_cost + c.fluid_cost * c.oil_volume * 1000
            + geometry.MACHINING_USD_PER_KG * metal + geometry.FIXED_HYDRAULIC_USD + s_cost + c.comp_cost)
    volume = 1.5 * c.n_stacks * c.stack_volume + geometry.hydraulic_volume(
        c.wide_area, c.narrow_area, c.pressure_rating, c.wide_gap, c.free_stroke)
    current = stack_phys.drive_current(c.n_stacks, c.capacitance, c.voltage / np.asarray(rise_time))
    return {"mass_kg": mass, "cost_usd": cost, "volume_m3": volume, "power_W": c.voltage * current}


def dynamic_model(c: Candidates, load_force, load_stiffness=0.0, **effects) -> PiezoHydraulicModel:
    """The simulator's parameters: the mechanical side of the force path as
    the stack stiffness, the hydraulic side folded into the oil's bulk
    modulus, seals at pressure, the compensator's leak and the reflected
    surface and narrow-bore oil."""
    bw = c.bouc_wen
    m = force_path.members(c)
    k_mech = structure.series(*(m[k]["stiffness"] for k in force_path.MECHANICAL))
    narrow_oil = c.density * c.narrow_area * (c.free_stroke + geometry.ROD_EXTRA_LENGTH)
    leak = np.where(c.comp_kind == 2, c.comp_leak, 0.0)
    effects.setdefault("leak_conductance", leak)
    return PiezoHydraulicModel(
        k_stacks=k_mech, d33=bw[:, 0], alpha=bw[:, 1], beta=bw[:, 2],
        gamma=bw[:, 3], delta=bw[:, 4], n_bw=bw[:, 5],
        wide_area=c.wide_area, narrow_area=c.narrow_area, oil_volume=c.oil_volume,
        bulk_modulus=force_path.simulator_bulk_modulus(c, m),
        narrow_mass=c.narrow_mass + narrow_oil + c.surface_mass, density=c.density,
        k_contract=c.k_contract, k_expand=c.k_expand,
        wide_friction=c.wide_friction, narrow_friction=c.narrow_friction,
        wide_friction_pressure=c.wide_friction_cp, narrow_friction_pressure=c.narrow_friction_cp,
        wide_breakaway=c.breakaway, narrow_breakaway=c.breakaway,
        load_force=load_force, load_stiffness=load_stiffness, no_return=c.no_return, **effects)


def ramp_drive(c: Candidates, ramp: np.ndarray, t_end: float):
    """Output times and per-candidate voltage: ramp from 0 to V, then hold."""
    t = np.arange(0.0, t_end + 0.5 / OUTPUT_RATE_HZ, 1.0 / OUTPUT_RATE_HZ)
    frac = np.clip(t[None, :] / ramp[:, None], 0.0, 1.0)
    return t, frac * c.voltage[:, None]


def simulate_cases(c: Candidates, load_forces, rise_time, target_stroke=None, keep_traces=False,
                   load_stiffness=0.0):
    """Simulate every candidate under each load force (N), plus an optional
    load spring (N/m). Returns one dict per load case with arrays (n_cand,):
    stroke_m, time_to_stroke_s, speed_m_s, overshoot, peak_m, and when asked
    the traces (t, position)."""
    ramp = ramp_time(c, rise_time)
    t_end = float(np.max(ramp)) + SETTLE_TIME_S
    t, volts = ramp_drive(c, ramp, t_end)
    cases = []
    for force in load_forces:
        result = simulate(dynamic_model(c, force, load_stiffness), t, volts)
        y = result["position_m"]
        horizon = ramp + SETTLE_TIME_S      # each candidate's own run, whatever its batch
        target = (0.9 * final_value(t, y, horizon) if target_stroke is None
                  else np.broadcast_to(target_stroke, (len(c),)))
        case = step_metrics(t, y, target, horizon=horizon)
        case["load_N"] = np.full(len(c), float(force))
        case["ramp_time_s"] = ramp
        if keep_traces:
            case["t"] = t
            case["position_m"] = y
            case["voltage_V"] = result["voltage_V"]
        cases.append(case)
    return cases
