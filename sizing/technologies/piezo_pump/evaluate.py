"""``sizing evaluate`` on a piezo pump design (technology "piezo_pump"):
the screen's static figures and margins of that one design, and its
cycle-resolved simulation under every load case (docs/models.md, "Piezo
pump"). The pumping frequency may be set anywhere below the valve's wetted
resonance: above the valve's rating it is a warning, not a refusal, so a
design can be swept through the frequency at which its flow peaks."""
from __future__ import annotations

import numpy as np

from ...errors import InputError
from ...io.requirements import RequirementsFile
from ...physics import pump as pump_phys
from ...limits import check_steps
from ...sim.pump import simulate, stable_step
from . import screen
from ...engine.loads import load_cases
from ..piezohydraulic.parts import reference_bouc_wen
from .designs import _sim_cases, simulation_model


def _part(catalog, kind: str, entry_id: str, file: str):
    group = getattr(catalog, kind + "s")
    if entry_id not in group:
        raise InputError(file, kind, f"unknown catalog id {entry_id!r} (known: {', '.join(sorted(group)) or 'none'})")
    return group[entry_id]


def pump_requirements(design) -> RequirementsFile:
    """The requirements a pump design file states for its margins, with its load."""
    return RequirementsFile.model_validate({
        "requirements": {"stroke": design.stroke, "blocked_force": design.blocked_force, "speed": design.speed,
                         "max_temperature": design.temperature},
        "load": design.load.model_dump(exclude_none=True), "duty": {"strokes_per_second": design.strokes_per_second}})


def design_file_of(req, design: Mapping):
    """The pump design file a pump candidate's ``design`` (results.json)
    stands for, judged against ``req``'s stroke, speed, blocked force, duty
    and load."""
    from .design_file import PumpDesignFile
    r = req.requirements
    return PumpDesignFile.model_validate({
        **design, "stroke": r.stroke, "speed": r.speed, "blocked_force": r.blocked_force,
        "strokes_per_second": req.duty.strokes_per_second, "load": req.load.model_dump(exclude_none=True)})


def verify_samples(design, catalog, groups: list, loads: list[float]) -> list[dict]:
    """The design's checks on each of ``groups`` (its parts, perturbed per
    sample by ``sizing robust``), vectorised: per sample its ``margins`` (the
    speed the simulated one) and ``feasible``."""
    req = pump_requirements(design)
    R = screen.rows(req, catalog, groups, (design.pump_frequency,), (design.pump_diameter,), rated=False,
                    voltage=design.voltage)
    n = len(groups)
    R["cylinder_diameter"] = np.full(n, design.cylinder_diameter)
    if design.bias_pressure is not None:
        R["bias_pressure"] = np.full(n, design.bias_pressure)
    st = screen.figures(req, R, loads)
    st.update(screen.drive(req, groups, R, st))
    M = screen.margins(req, groups, R, st, loads)
    model = simulation_model(req, reference_bouc_wen(catalog.stacks), groups, R, st, np.arange(n))
    if loads:
        M["speed"] = np.min([simulate(model.replace(load_force=F))["mean_speed_m_s"] for F in loads], axis=0) \
            / design.speed - 1.0
    out = []
    for i in range(n):
        margins = {k: float(v[i]) for k, v in M.items()}
        out.append({"margins": margins, "feasible": all(v >= 0 for v in margins.values())})
    return out


def evaluate_pump(design, catalog, file: str) -> dict:
    """Static figures, margins, metrics and simulated load cases of one pump design."""
    kinds = ("stack", "valve", "accumulator", "fluid", "seal", "amplifier")
    parts = {k: _part(catalog, k, getattr(design, k), file) for k in kinds}
    stack, valve, fluid = parts["stack"], parts["valve"], parts["fluid"]
    if design.voltage is not None and design.voltage > stack.max_voltage * (1 + 1e-9):
        raise InputError(file, "voltage", f"expected at most the stack's rated {stack.max_voltage:g} V, "
                                          f"got {design.voltage:g} V")
    group = screen.Group(stack, design.n_stacks, parts["amplifier"], valve, parts["accumulator"], fluid, parts["seal"])
    cases = load_cases(design.load)
    loads = [c["load_N"] for c in cases]
    req = pump_requirements(design)
    f = design.pump_frequency
    R = screen.rows(req, catalog, [group], (f,), (design.pump_diameter,), rated=False, voltage=design.voltage)
    wetted = float(pump_phys.valve_resonance(R["reed_stiffness"][0], R["reed_wetted_mass"][0]))
    if f >= wetted:
        raise InputError(file, "pump_frequency", f"expected below the valve {valve.id}'s wetted resonance "
                                                 f"{wetted:.4g} Hz in {fluid.id}, got {f:.4g} Hz")
    warnings = []
    if f > valve.max_frequency:
        warnings.append(f"pump_frequency {f:g} Hz is above valve {valve.id}'s rating {valve.max_frequency:g} Hz "
                        f"(a third of its wetted resonance {wetted:.4g} Hz): the reeds lag the chamber")
    R["cylinder_diameter"] = np.array([design.cylinder_diameter])
    if design.bias_pressure is not None:
        R["bias_pressure"] = np.array([design.bias_pressure])
    if design.line_length is not None:
        R["line_length"] = design.line_length
    if design.line_diameter is not None:
        R["line_diameter"] = design.line_diameter
    st = screen.figures(req, R, loads)
    st.update(screen.drive(req, [group], R, st))
    margins = {k: float(v[0]) for k, v in screen.margins(req, [group], R, st, loads).items()}
    metrics = {k: float(v[0]) for k, v in screen.metrics(req, [group], R, st).items()}
    model = simulation_model(req, reference_bouc_wen(catalog.stacks), [group], R, st, np.array([0]))
    check_steps(float(model.t_end / stable_step(model.matrix())[0]) * max(len(loads), 1), file, "pump_frequency",
                "simulation steps (twice the stroke time at the pump's step, x load cases)")
    sims = [simulate(model.replace(load_force=F)) for F in loads]
    simulated = [dict(case, **c) for case, c in zip(cases, _sim_cases(sims, 0, loads, st["speeds"], 0))]
    if simulated:
        margins["speed"] = min(c["mean_speed_m_s"] for c in simulated) / design.speed - 1.0
    static = {k: float(v[0]) for k, v in st.items() if k != "speeds"}
    return {
        "technology": "piezo_pump",
        "design": {"stack": stack.id, "n_stacks": design.n_stacks, "voltage_V": float(R["voltage"][0]),
                   "pump_frequency_Hz": f, "pump_diameter_m": design.pump_diameter,
                   "cylinder_diameter_m": design.cylinder_diameter, "bias_pressure_Pa": float(R["bias_pressure"][0]),
                   "valve": valve.id, "accumulator": design.accumulator, "fluid": fluid.id, "seal": design.seal,
                   "amplifier": design.amplifier, "temperature_degC": design.temperature},
        "static": static,
        "valve": {"rated_frequency_Hz": valve.max_frequency, "wetted_resonance_Hz": wetted,
                  "resonance_in_air_Hz": float(pump_phys.valve_resonance(valve.reed_stiffness, valve.reed_mass))},
        "simulated": {"cases": simulated, "worst": max(simulated, key=lambda c: c["load_N"]) if simulated else {}},
        "margins": margins,
        "feasible": all(v >= 0 for v in margins.values()),
        "metrics": metrics,
        "warnings": warnings,
    }
