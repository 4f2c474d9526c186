"""A piezo pump design's results.json record (CONTRACTS.md, "The piezo
pump"): the one place that turns a ``records.PumpDesign`` into its
candidate dict."""
from __future__ import annotations

from ...physics import pump as pump_phys
from ...engine import holding
from .records import PumpDesign


def pump_candidate(req, d: PumpDesign) -> dict:
    g, T = d.group, req.requirements.max_temperature
    parts = {"stack": g.stack.id, "n_stacks": g.n, "fluid": g.fluid.id, "seal": g.seal.id,
             "amplifier": g.amplifier.id, "valve": g.valve.id, "accumulator": g.accumulator.id}
    return {
        "id": d.id, "technology": "piezo_pump", "variant": "pump",
        "stage": "simulated" if d.simulation is not None else "sized",
        "components": parts,
        "stack_params": {"stiffness_N_m": g.stack.stiffness, "d33_m_V": g.stack.stroke_per_volt,
                         "max_voltage_V": g.stack.max_voltage},
        "design": {"technology": "piezo_pump", "stack": g.stack.id, "n_stacks": g.n, "voltage": d.voltage,
                   "pump_frequency": d.frequency, "pump_diameter": d.pump_diameter,
                   "cylinder_diameter": d.cylinder_diameter, "bias_pressure": d.bias_pressure,
                   "valve": g.valve.id, "accumulator": g.accumulator.id, "fluid": g.fluid.id, "seal": g.seal.id,
                   "amplifier": g.amplifier.id, "temperature": T},
        "static": dict(d.static), "static_margins": dict(d.static_margins), "simulated": _simulated(d),
        "margins": dict(d.margins), "metrics": dict(d.metrics),
        "temperatures": {f"{kind} {p.id}": {"rated_degC": p.max_temperature, "required_degC": T}
                         for kind, p in (("stack", g.stack), ("fluid", g.fluid), ("seal", g.seal), ("valve", g.valve),
                                         ("accumulator", g.accumulator))},
        "valve_resonance_Hz": float(pump_phys.valve_resonance(g.valve.reed_stiffness, g.valve.reed_mass)),
        "reason": "",
    }


def _simulated(d: PumpDesign) -> dict:
    """The contract's ``simulated`` figures: the largest load's, the least speed."""
    sim = d.simulation
    if sim is None:
        return {}
    if not sim.success:
        return {"failed": True, "message": sim.message}
    cases = holding.held_cases(sim.cases, d.static["output_stiffness_N_m"])
    worst = max(cases, key=lambda c: c["load_N"])
    return {"stroke_m": worst["stroke_m"], "time_to_stroke_s": worst["time_to_stroke_s"],
            "speed_m_s": min(c["speed_m_s"] for c in cases), "mean_speed_m_s": worst["mean_speed_m_s"],
            "overshoot": 0.0, "load_N": worst["load_N"], "cases": cases}
