"""A piezohydraulic design's results.json record (docs/formats.md, results).

The one place that turns the solve's records (``records.VerifiedDesign``, a
``search.Combo`` ruled out before sizing) into the candidate dicts of
results.json; ``api`` writes them out and ``sized.study_designs`` reads them
back."""
from __future__ import annotations

import math

from ...physics import fluid as fluid_props
from ...physics import stack as stack_phys, structure, thermal
from ...engine import holding
from . import designs as piezo_designs
from ...engine.rank import ceiling_margin, floor_margin
from ...engine.records import Simulation
from .records import PiezoDesign, VerifiedDesign
from .search import Combo


def components(combo: Combo, ratio) -> dict:
    return {"stack": combo.stack.id, "n_stacks": combo.n, "ratio": ratio, "fluid": combo.fluid.id,
            "seal": combo.seal.id, "amplifier": combo.amplifier.id}


def stack_params(combo: Combo) -> dict:
    s = combo.stack
    return {"stiffness_N_m": s.stiffness, "d33_m_V": s.stroke_per_volt, "max_voltage_V": s.max_voltage}


def temperatures(combo: Combo) -> dict:
    return {k: {"rated_degC": a, "required_degC": b} for k, (a, b) in combo.temperatures.items()}


def sim_margins(req, sim: Simulation, stiffness: float = math.inf) -> tuple[dict, dict]:
    """Margins and the contract's ``simulated`` figures from the cases, each
    with its rest offset and travel from neutral at the output ``stiffness``
    (engine/holding.py)."""
    r = req.requirements
    if not sim.success:
        return {"simulation": -math.inf}, {"failed": True, "message": sim.message}
    cases = holding.held_cases(sim.cases, stiffness)
    worst = max(cases, key=lambda c: c["load_N"])
    figures = {"stroke_m": worst["stroke_m"], "time_to_stroke_s": worst["time_to_stroke_s"],
               "speed_m_s": min(c["speed_m_s"] for c in cases), "overshoot": worst["overshoot"],
               "load_N": worst["load_N"], "cases": cases}
    margins = {"stroke": floor_margin(min(c["stroke_m"] for c in cases), r.stroke),
               "speed": floor_margin(min(c["speed_m_s"] for c in cases), r.speed),
               "overshoot": ceiling_margin(max(c["overshoot"] for c in cases), req.options.max_overshoot)}
    margins.update(holding.margins(req, stiffness, cases))
    return margins, figures


def ruled_out_record(d: PiezoDesign) -> dict | None:
    """One line for a design that is not a design (a plate beyond its model,
    a body outside the envelope): never ranked, plotted or named a best."""
    why = dict(d.ruled_out) if d.ruled_out is not None else None
    res = d.gp
    if why is None and not res.success and res.ruled_out is not None:
        why = {"reason": res.ruled_out, "detail": "no design of these parts fits: " + ", ".join(res.binding)}
    if why is None:
        return None
    return {"id": d.id, "technology": "piezohydraulic", "variant": d.variant.name, **why}


def pruned_candidate(combo: Combo, nominal: dict | None = None) -> dict:
    """A combination ruled out before sizing (``--detail full``), with the
    figures of its nominal design when given (``piezo_designs.nominal_figures``),
    marked ``nominal_geometry``: not a sized design."""
    base = _pruned(combo)
    if nominal is None:
        return base
    return dict(base, static={**base["static"], **nominal["static"]},
                components=dict(base["components"], ratio=nominal["ratio"], material=nominal["material"]),
                nominal_geometry=True, force_path=nominal["force_path"], thermal_budget=nominal["thermal_budget"],
                seal_friction_N=nominal["seal_friction_N"], compensator=None)


def _pruned(combo: Combo) -> dict:
    s, a = combo.stack, combo.amplifier
    reasons = [k for k, v in combo.margins.items() if v < 0]
    return {
        "id": combo.key, "technology": "piezohydraulic", "variant": "uncompensated", "stage": "pruned",
        "components": components(combo, None), "stack_params": stack_params(combo),
        "static": {"work_J": float(stack_phys.work_capacity(combo.n, s.stiffness,
                                                            combo.stack_stroke * combo.voltage_fraction_max))},
        "simulated": {}, "margins": dict(combo.margins),
        "metrics": {"mass_kg": combo.n * s.mass + a.mass,
                    "cost_usd": combo.n * s.cost_usd + a.cost_usd},
        "metrics_lower_bound": True, "temperatures": temperatures(combo),
        "reason": "ruled out before sizing: " + ", ".join(reasons),
    }


def design_candidate(req, v: VerifiedDesign) -> dict:
    """The results.json record of one sized (and perhaps simulated) design."""
    d = v.design
    combo, res, var = d.combo, d.gp, d.variant
    comp = var.compensator
    base = {
        "id": d.id, "technology": "piezohydraulic", "variant": var.name,
        "components": dict(components(combo, res.ratio), material=var.material.id,
                           compensator=comp.id if comp else None),
        "stack_params": stack_params(combo), "temperatures": temperatures(combo),
    }
    if not d.built:
        return dict(base, stage="gp_failed", static={}, simulated={},
                    margins={**combo.margins, res.driver or "solver": -math.inf},
                    metrics={}, reason=f"the geometric program failed ({res.status})")
    margins = dict(d.static_margins)
    margins["work"] = combo.margins["work"]
    simulated = {}
    if v.simulation is not None:
        sim_m, simulated = sim_margins(req, v.simulation, d.static["output_stiffness_N_m"])
        margins.update(sim_m)
    stage = "simulated" if simulated else ("sized" if res.success else "gp_infeasible")
    st = dict(d.static)
    base.update({
        "stage": stage, "static": st, "simulated": simulated,
        "static_margins": dict(d.static_margins),
        "force_path": [dict(row) for row in d.force_path],
        "thermal_budget": {k: st["thermal_" + k] for k in (*thermal.TERMS, "net_m")},
        "seal_friction_N": dict(d.seal_friction),
        "compensator": _compensator_entry(d),
        "design": _design_variables(req, d),
        "fluid_at_temperature": _fluid_at_temperature(req, d),
        "bouc_wen_source": d.bouc_wen[1],
        "hysteresis": (piezo_designs.hysteresis(combo.stack, d.bouc_wen[0], float(d.cand.voltage[0]), d.ramp)
                       if v.simulation is not None else None),
        "gp": {"success": res.success, "status": res.status, "binding": res.binding, "slack": res.slack},
        "reason": "" if res.success else "no design of these parts meets: " + ", ".join(res.binding),
        "metrics": dict(d.metrics), "margins": margins,
    })
    if d.spacer > 0:
        base["passive_compensation"] = {"spacer_length_m": d.spacer,
                                        "spacer_material": next(r["material"] for r in d.force_path
                                                                if r["member"] == "spacer")}
    return base


def _design_variables(req, d: PiezoDesign) -> dict:
    """What to build: the ``design`` a ``sizing evaluate`` file takes."""
    combo, res, var, st = d.combo, d.gp, d.variant, d.static
    comp = var.compensator
    out = {"technology": "piezohydraulic", "stack": combo.stack.id, "n_stacks": combo.n,
           "voltage": d.cand.voltage[0], "wide_diameter": st["wide_diameter_m"],
           "narrow_diameter": st["narrow_diameter_m"], "fluid": combo.fluid.id, "seal": combo.seal.id,
           "amplifier": combo.amplifier.id, "wide_gap": st["wide_gap_m"], "rise_time": d.ramp,
           "temperature": req.requirements.max_temperature, "material": var.material.id,
           "end_cap_thickness": res.cap_thickness, "frame_area": res.frame_area,
           "compensator": comp.id if comp else None, "strokes_per_second": req.duty.strokes_per_second,
           "amplifier_units": _count(st["amplifier_units"]), "ramp_time": d.ramp}
    if d.spacer > 0:
        out["spacer_length"] = d.spacer
    restraint = float(d.cand.edge_restraint[0])
    if restraint != 0:
        out["plate_edge"] = structure.edge_name(restraint)
        if out["plate_edge"] == "flange":
            out["flange_restraint"] = restraint
    return out


def _count(units: float) -> int | float:
    """A whole number of amplifier units as an int (TOML and JSON read it back as one)."""
    return int(units) if float(units).is_integer() else float(units)


def _fluid_at_temperature(req, d: PiezoDesign) -> dict:
    f, T = d.combo.fluid, req.requirements.max_temperature
    return {"kinematic_viscosity_m2_s": float(fluid_props.kinematic_viscosity(f.viscosity_40C, f.viscosity_100C, T)),
            "bulk_modulus_Pa": float(d.cand.bulk_modulus[0]), "flash_point_degC": f.flash_point}


def _compensator_entry(d: PiezoDesign) -> dict | None:
    comp = d.variant.compensator
    if comp is None:
        return None
    k = next((r["stiffness_N_m"] for r in d.force_path if r["member"] == "compensator"), None)
    return {"id": comp.id, "kind": comp.kind, "stiffness_N_m": k, "leak_m3_s_Pa": comp.leak_conductance,
            "mass_kg": comp.mass, "cost_usd": comp.cost_usd, "capacity_m3": comp.capacity,
            "volume_taken_m3": d.static["thermal_compensator_volume_m3"]}
