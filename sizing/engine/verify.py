"""Static figures, metrics and simulated load cases of piezohydraulic
candidates (arrays over candidates)."""
from __future__ import annotations

import numpy as np

from ..physics import geometry, hydraulics, stack as stack_phys, thermal
from ..sim.metrics import step_metrics
from ..sim.piezohydraulic import PiezoHydraulicModel, simulate
from .piezo import Candidates

OUTPUT_RATE_HZ = 2000.0
SETTLE_TIME_S = 0.25


def ramp_time(c: Candidates, rise_time) -> np.ndarray:
    """Time to ramp the drive from 0 to its voltage: the requested rise time,
    or longer when the amplifier cannot supply i = n C_large dV/dt or slew."""
    charge = c.n_stacks * c.capacitance * stack_phys.LARGE_SIGNAL_CAPACITANCE_FACTOR * c.voltage
    t_current = charge / c.amp_max_current
    t_slew = np.where(c.amp_slew > 0, c.voltage / np.where(c.amp_slew > 0, c.amp_slew, 1.0), 0.0)
    return np.maximum.reduce([np.broadcast_to(rise_time, c.voltage.shape), t_current, t_slew])


def static_figures(c: Candidates, rise_time) -> dict[str, np.ndarray]:
    out = hydraulics.static_figures(
        c.n_stacks, c.stiffness, c.stack_free_stroke, c.ratio,
        wide_area=c.wide_area, oil_volume=c.oil_volume, bulk_modulus=c.bulk_modulus,
        wide_mass=c.wide_mass, narrow_mass=c.narrow_mass)
    out["ratio"] = c.ratio
    out["wide_diameter_m"] = 2 * geometry.radius(c.wide_area)
    out["narrow_diameter_m"] = 2 * geometry.radius(c.narrow_area)
    out["drive_current_A"] = stack_phys.drive_current(c.n_stacks, c.capacitance, c.voltage / np.asarray(rise_time))
    out["oil_volume_m3"] = c.oil_volume
    out["thermal_drift_per_K_m"] = thermal.output_drift(c.oil_volume, c.thermal_expansion, 1.0, c.narrow_area)
    return out


def metrics(c: Candidates, rise_time) -> dict[str, np.ndarray]:
    """Mass (kg), cost (USD), volume (m^3) and peak electrical power (W)."""
    hyd_mass = geometry.hydraulic_mass(c.wide_area, c.narrow_area, c.pressure_rating, c.wide_gap,
                                       c.free_stroke, c.density)
    stacks_mass = c.n_stacks * c.stack_mass * (1 + geometry.FRAME_FRACTION)
    mass = stacks_mass + hyd_mass + c.amp_mass
    metal = hyd_mass - c.density * c.oil_volume
    cost = (c.n_stacks * c.stack_cost + c.amp_cost + c.seal_cost + c.fluid_cost * c.oil_volume * 1000
            + geometry.MACHINING_USD_PER_KG * metal + geometry.FIXED_HYDRAULIC_USD)
    volume = 1.5 * c.n_stacks * c.stack_volume + geometry.hydraulic_volume(
        c.wide_area, c.narrow_area, c.pressure_rating, c.wide_gap, c.free_stroke)
    current = stack_phys.drive_current(c.n_stacks, c.capacitance, c.voltage / np.asarray(rise_time))
    return {"mass_kg": mass, "cost_usd": cost, "volume_m3": volume, "power_W": c.voltage * current}


def dynamic_model(c: Candidates, load_force, load_stiffness=0.0, **effects) -> PiezoHydraulicModel:
    bw = c.bouc_wen
    return PiezoHydraulicModel(
        k_stacks=c.n_stacks * c.stiffness, d33=bw[:, 0], alpha=bw[:, 1], beta=bw[:, 2],
        gamma=bw[:, 3], delta=bw[:, 4], n_bw=bw[:, 5],
        wide_area=c.wide_area, narrow_area=c.narrow_area, oil_volume=c.oil_volume,
        bulk_modulus=c.bulk_modulus, narrow_mass=c.narrow_mass, density=c.density,
        k_contract=c.k_contract, k_expand=c.k_expand,
        wide_friction=c.wide_friction, narrow_friction=c.narrow_friction,
        wide_breakaway=c.breakaway, narrow_breakaway=c.breakaway,
        load_force=load_force, load_stiffness=load_stiffness, no_return=c.no_return, **effects)


def ramp_drive(c: Candidates, ramp: np.ndarray, t_end: float):
    """Output times and per-candidate voltage: ramp from 0 to V, then hold."""
    t = np.arange(0.0, t_end + 0.5 / OUTPUT_RATE_HZ, 1.0 / OUTPUT_RATE_HZ)
    frac = np.clip(t[None, :] / ramp[:, None], 0.0, 1.0)
    return t, frac * c.voltage[:, None]


def simulate_cases(c: Candidates, load_forces, rise_time, target_stroke=None, keep_traces=False):
    """Simulate every candidate under each load force (N). Returns one dict per
    load case with arrays (n_cand,): stroke_m, time_to_stroke_s, speed_m_s,
    overshoot, peak_m, and when asked the traces (t, position)."""
    ramp = ramp_time(c, rise_time)
    t_end = float(np.max(ramp)) + SETTLE_TIME_S
    t, volts = ramp_drive(c, ramp, t_end)
    cases = []
    for force in load_forces:
        result = simulate(dynamic_model(c, force), t, volts)
        y = result["position_m"]
        target = 0.9 * y[:, -1] if target_stroke is None else np.broadcast_to(target_stroke, (len(c),))
        case = step_metrics(t, y, target)
        case["load_N"] = np.full(len(c), float(force))
        case["ramp_time_s"] = ramp
        if keep_traces:
            case["t"] = t
            case["position_m"] = y
            case["voltage_V"] = result["voltage_V"]
        cases.append(case)
    return cases
