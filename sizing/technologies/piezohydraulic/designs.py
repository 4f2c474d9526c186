"""Piezohydraulic designs of ``sizing solve``: the variants of every
combination (structure material, thermal compensation), their sizing by the
geometric program, the closed-form material screen, the passive spacer, the
static figures and margins, the nominal figures of pruned combinations and
the hysteresis time scale."""
from __future__ import annotations

import math
from dataclasses import replace
from functools import lru_cache

import numpy as np

from ...io.catalog import Catalog
from ...physics import bouc_wen, fluid as fluid_props
from ...physics import amplifier, geometry, stack as stack_phys, structure, thermal
from ...physics.bouc_wen import BoucWen
from . import force_path
from ...engine import stage_cache
from .batch_sizer import BatchSizer
from .convex import SizingInput, SizingResult
from .parts import Candidates, part_row, reference_bouc_wen, stack_bouc_wen, structure_row
from ...engine.rank import ceiling_margin, floor_margin
from ...engine.records import frozen
from .records import PiezoBrief, PiezoDesign, Variant
from .search import Combo, temperature_margin
from .convex import DEFAULT_MAX_MASS, NO_LIMIT
from .verify import (GAP_CLEARANCE_M, GAP_TOLERANCE_M, STACK_SPACING_M, metrics, ramp_time,
                     seal_friction_at, static_figures)

MAX_SPACER_M = 0.5          # longest passive-compensation spacer considered


def _progress(callback, stage, done, total):
    if callback is not None:
        callback(stage, done, total)


def effective_gap(b: PiezoBrief, stack_free_stroke: float) -> float:
    """The smallest wide gap: the stack stroke plus a clearance and a
    manufacturing tolerance (a gap below the stroke bottoms the wide piston
    out), or the requirements' floor when that is larger."""
    return max(b.wide_gap_floor, stack_free_stroke + GAP_CLEARANCE_M + GAP_TOLERANCE_M)


def sizing_input(b: PiezoBrief, c: Combo, material=None, compensator=None, spacer=None,
                 spacer_length=0.0) -> SizingInput:
    """The program's input for one combination and variant; a passive
    spacer of ``spacer_length`` lengthens the stack column (and the frame)
    and adds its compliance, mass and cost."""
    T = b.temperature
    f, s, st = c.fluid, c.seal, c.stack
    material = material if material is not None else force_path.default_material({})
    stack_volume = st.length * st.diameter**2 * (1.0 if st.section == "square" else math.pi / 4)
    footprint = c.n * math.pi * st.diameter**2 / 4
    sp_mass = spacer.density * footprint * spacer_length if spacer is not None else 0.0
    sp_cost = sp_mass * (spacer.cost_usd + geometry.MACHINING_USD_PER_KG) if spacer is not None else 0.0
    accumulator = (1.0 / compensator.volume_stiffness
                   if compensator is not None and compensator.kind == "accumulator" else 0.0)
    return SizingInput(
        n_stiffness=c.n * st.stiffness, stack_stroke=c.stack_stroke, rated_voltage=st.max_voltage,
        max_fraction=c.voltage_fraction_max, force=b.blocked_force, stroke=b.stroke,
        bulk_modulus=float(fluid_props.bulk_modulus_at(f.bulk_modulus, f.bulk_modulus_temperature_coefficient, T)),
        wide_gap=b.wide_gap_floor, gap_allowance=GAP_CLEARANCE_M + GAP_TOLERANCE_M,
        max_length=b.max_length or NO_LIMIT, max_diameter=b.max_diameter or NO_LIMIT,
        max_mass=b.max_mass or DEFAULT_MAX_MASS, pressure_rating=s.pressure_rating,
        natural_frequency=b.natural_frequency, stroke_time=b.stroke_time,
        n_capacitance=c.n * st.capacitance, max_current=b.max_amplifier_units * _unit_current(b, c.amplifier),
        margin=b.design_margin,
        fixed_mass=c.n * st.mass + (compensator.mass if compensator else 0.0) + sp_mass,
        amp_unit_mass=c.amplifier.mass, amp_unit_cost=c.amplifier.cost_usd,
        amp_unit_current=_unit_current(b, c.amplifier), amp_unit_continuous=c.amplifier.continuous_current,
        strokes_per_second=b.strokes_per_second, min_stiffness=b.min_stiffness,
        stroke_load=b.max_load if b.stroke_from == "neutral" else 0.0, edge_restraint=b.edge_restraint,
        fixed_cost=(c.n * st.cost_usd + 2 * s.cost_usd + geometry.FIXED_HYDRAULIC_USD
                    + (compensator.cost_usd if compensator else 0.0) + sp_cost),
        fixed_volume=1.5 * c.n * stack_volume,
        oil_density=float(fluid_props.density_at(f.density, f.thermal_expansion, T)),
        oil_cost=f.cost_usd * 1000.0,
        youngs_modulus=material.youngs_modulus, poisson=material.poisson, material_density=material.density,
        material_unit_cost=material.cost_usd + geometry.MACHINING_USD_PER_KG,
        allowable_stress=material.yield_strength / force_path.STRESS_SAFETY, stack_length=st.length + spacer_length,
        column_compliance=(spacer_length / (spacer.youngs_modulus * footprint) if spacer is not None else 0.0),
        stiffness_ratio=b.stiffness_ratio,
        packing_area=math.pi / 4 * float(structure.packing_diameter(c.n, st.diameter, STACK_SPACING_M)) ** 2,
        accumulator_compliance=accumulator, seal_f0=s.friction_per_length, seal_cp=s.friction_pressure_coefficient,
        surface_mass=b.surface_mass)


def _unit_current(b: PiezoBrief, amp) -> float:
    """What one amplifier unit holds over a ramp at the required speed (at
    least the stroke time, the free stroke exceeding the stroke), A: its
    peak within the rated pulse, else its continuous rating."""
    return float(amplifier.usable_ramp_current(amp.max_current, amp.continuous_current, amp.peak_duration,
                                               b.stroke_time))


def variants(b: PiezoBrief, catalog: Catalog) -> list[Variant]:
    """Every structure material rated to the requirement, each as built and
    with each catalog compensator rated to it (when compensation is on)."""
    T = b.temperature
    mats = [m for m in catalog.materials.values() if m.max_temperature >= T] or [force_path.default_material({})]
    comps = [c for c in catalog.compensators.values() if c.max_temperature >= T] if b.thermal_compensation else []
    return [Variant(m, comp) for m in mats for comp in [None, *comps]]


def size(b: PiezoBrief, catalog, combos, progress=None, keep=None):
    """One geometric program per combination and variant: each structure
    material, as built and with each catalog compensator, gets its own
    bore, plates, frame, gap, ratio, voltage and drive (an open
    accumulator adds its compliance to the force path; every compensator
    its mass and cost to the objective). ``keep(combo, variant)``: the
    variants to size (all by default)."""
    rows = variant_inputs(b, catalog, combos, keep)
    _progress(progress, "sizing", 0, len(combos))
    results = _solved(tuple(b.objectives), [s for _, _, s in rows])
    _progress(progress, "sizing", len(combos), len(combos))
    return [(c, v, res) for (c, v, _), res in zip(rows, results)]


def variant_inputs(b: PiezoBrief, catalog, combos, keep=None) -> list[tuple[Combo, Variant, SizingInput]]:
    """Each combination with each variant ``keep(combo, variant)`` keeps (all
    by default), and the program's input for it, in the order ``size`` sizes them."""
    vs = variants(b, catalog)
    return [(c, v, sizing_input(b, c, v.material, v.compensator)) for c in combos for v in vs
            if keep is None or keep(c, v)]


def designs(b: PiezoBrief, catalog, sized) -> list[PiezoDesign]:
    """Build the sized designs with the same code as ``sizing evaluate``;
    then, for as-built designs that drift, the passive variant. ``sized``:
    (Combo, Variant, SizingResult) triples; each design's ``origin`` is its
    triple's index (a passive design's, its parent's)."""
    reference = reference_bouc_wen(catalog.stacks)
    spacer = force_path.spacer_material(catalog.materials)
    transferred: dict[int, tuple] = {}      # one transfer per stack object (frozen), not per design

    def bouc_wen_of(stack):
        if id(stack) not in transferred:
            transferred[id(stack)] = stack_bouc_wen(stack, reference)
        return transferred[id(stack)]
    pending = [PiezoDesign(origin=i, id=combo.key + var.suffix(), combo=combo, variant=var, gp=res,
                           bouc_wen=(bouc_wen_of(combo.stack)
                                     if math.isfinite(res.ratio) and math.isfinite(res.wide_area) else None))
               for i, (combo, var, res) in enumerate(sized)]
    buildable = [d for d in pending if d.bouc_wen is not None]
    built = dict(zip((d.origin for d in buildable), _build(b, buildable, spacer)))
    as_built = [built.get(d.origin, d) for d in pending]
    passive = []
    for d in as_built:
        if not d.built or d.variant.compensator is not None:
            continue
        length = _spacer_length(b, d, spacer)
        if length > 0:
            var = Variant(d.variant.material, None, True)
            passive.append(replace(d, variant=var, spacer=length, id=d.combo.key + var.suffix()))
    return as_built + _build(b, passive, spacer)


def _solved(objectives: tuple, inputs: list[SizingInput]) -> list[SizingResult]:
    """Every input sized (``batch_sizer.BatchSizer``, all at once); inside
    ``stage_cache.reuse()`` (the re-solves behind the flips) an input
    solved before is read back and only the rest are solved. Outside it
    nothing is kept, so no key is built (a key copies every input field)."""
    if not stage_cache.active():
        return _sizer(objectives).solve(inputs)
    keys = [stage_cache.gp_key(objectives, s) for s in inputs]
    out = [stage_cache.lookup(k) for k in keys]
    todo = [i for i, res in enumerate(out) if res is None]
    for i, res in zip(todo, _sizer(objectives).solve([inputs[i] for i in todo])):
        out[i] = res
        stage_cache.remember(keys[i], res)
    return out


@lru_cache(maxsize=8)
def _sizer(objectives: tuple) -> BatchSizer:
    """One set of programs per objective set, laid out once per process."""
    return BatchSizer(objectives)


def resize_passive(b: PiezoBrief, catalog, built: list[PiezoDesign]) -> list[PiezoDesign]:
    """The passive designs of ``built`` (``designs``) sized on their own:
    the program re-sized with the spacer their as-built parent needs in
    the stack column (longer frame, the spacer's compliance, mass and
    cost), then built again the way ``designs`` derives a passive design
    (its spacer from the re-sized geometry's own budget), so re-verifying
    its sizing reproduces it. Other designs are returned as they are."""
    spacer = force_path.spacer_material(catalog.materials)
    idx = [i for i, d in enumerate(built) if d.variant.passive and d.built]
    again = _solved(tuple(b.objectives), [sizing_input(b, built[i].combo, built[i].variant.material, None, spacer,
                                                       built[i].spacer) for i in idx])
    triples = []
    for i, res in zip(idx, again):
        d = built[i]
        triples.append((d.combo, d.variant.as_built(), res if math.isfinite(res.wide_area) else d.gp))
    again = {d.origin: d for d in designs(b, catalog, triples) if d.variant.passive}
    out = list(built)
    for j, i in enumerate(idx):
        if j in again:
            out[i] = replace(again[j], origin=built[i].origin)
    return out


def _spacer_length(b: PiezoBrief, d: PiezoDesign, spacer) -> float:
    """Low-expansion spacer in the stack column (the frame longer by as
    much) that brings the as-built thermal budget to zero: net / (R
    (alpha_frame - alpha_spacer) dT). 0 when the design does not drift
    beyond the allowance, drifts the other way, or the frame material
    expands no more than the spacer."""
    st = d.static
    net = st["thermal_net_m"]
    allowed, dT = b.allowed_drift, b.delta_T
    d_alpha = d.variant.material.thermal_expansion - spacer.thermal_expansion
    if abs(net) <= allowed or net <= 0 or d_alpha <= 0 or dT <= 0:
        return 0.0
    length = net / (st["ratio"] * d_alpha * dT)
    return length if length < MAX_SPACER_M else 0.0


def _build(b: PiezoBrief, pending: list[PiezoDesign], spacer) -> list[PiezoDesign]:
    """The designs with their candidate row, static figures, metrics, force
    path and static margins, in the order given (new records)."""
    if not pending:
        return []
    T = b.temperature
    rows = []
    for d in pending:
        combo, res, var = d.combo, d.gp, d.variant
        v = min(res.voltage_fraction, combo.voltage_fraction_max)
        struct = structure_row(var.material, res.cap_thickness, res.frame_area, spacer, d.spacer,
                               var.compensator, b.surface_mass, b.delta_T, b.edge_restraint)
        rows.append(part_row(combo.stack, combo.n, res.ratio, res.wide_area, v * combo.stack.max_voltage,
                             d.bouc_wen[0], T,
                             max(res.wide_gap, effective_gap(b, combo.stack_stroke * v) * (1 + 1e-9)),
                             combo.fluid, combo.seal, combo.amplifier, structure=struct))
    c = Candidates.from_rows(rows)
    drive = sized_drive(b, c)
    c.amp_units = np.asarray(drive["units"], float).copy()
    rise = np.array(drive["ramp"], float, copy=True) * np.ones(len(pending))
    for i, d in enumerate(pending):             # units and ramp a design file gives
        if d.gp.amplifier_units is not None:
            c.amp_units[i] = d.gp.amplifier_units
        if d.gp.ramp_time is not None:
            rise[i] = d.gp.ramp_time
    ramp = ramp_time(c, rise)
    static = static_figures(c, ramp, b.strokes_per_second)
    met = metrics(c, ramp)
    members = force_path.members(c)
    p_load = b.max_load / c.narrow_area
    seal_f = seal_friction_at(c, p_load)
    # each design's figures read from lists, built once: thousands of designs
    static, met, members = force_path.columns(static), force_path.columns(met), force_path.listed(members)
    out, singles = [], c.rows()
    for i, d in enumerate(pending):
        comp = d.variant.compensator
        friction = {"wide": float(seal_f["wide"][i]), "narrow": float(seal_f["narrow"][i]),
                    "at_pressure_Pa": float(p_load[i])}
        figures = {k: v[i] for k, v in static.items()}
        figures.update(_derived_figures(b, d, figures, float(ramp[i]), friction))
        figures.update(amplifier_units_needed=float(drive["needed"][i]), amplifier_units_max=b.max_amplifier_units,
                       amplifier_units_at_cap=float(drive["needed"][i] >= b.max_amplifier_units))
        mets = {k: v[i] for k, v in met.items()}
        out.append(replace(
            d, cand=singles[i], ramp=float(ramp[i]), amplifier_units=float(c.amp_units[i]), static=frozen(figures), metrics=frozen(mets),
            force_path=tuple(force_path.as_list(members, i, d.variant.material.id, comp.id if comp else None,
                                                spacer.id if d.spacer > 0 else None)),
            seal_friction=frozen(friction), static_margins=frozen(_static_margins(b, d, figures)),
            ruled_out=ruled_out(b, figures, mets)))
    return out


def sized_drive(b: PiezoBrief, c: Candidates) -> dict:
    """Amplifier units and voltage ramp of built candidates, sized against
    the speed and the duty (``amplifier.drive_for_speed``): the longest ramp
    that still reaches the free stroke at the required speed sets the
    fewest units; the ramp is then the shortest those units drive. The
    count is capped at the options' ``max_amplifier_units`` (a design held
    at the cap ramps slower and misses the speed, and its
    ``amplifier_units`` margin says how many it needs)."""
    capacitance = c.n_stacks * c.capacitance * stack_phys.LARGE_SIGNAL_CAPACITANCE_FACTOR
    return amplifier.drive_for_speed(capacitance, c.voltage, c.free_stroke / b.speed, b.strokes_per_second,
                                     c.amp_max_current, c.amp_continuous, c.amp_peak_duration,
                                     b.max_amplifier_units)


def ruled_out(b: PiezoBrief, st: dict, met: dict) -> dict | None:
    """Why a built design is not a design at all, or None: a plate beyond its
    model's validity (``structure_out_of_range``) or a body outside the
    requirements' envelope (``envelope``). Such designs are never ranked."""
    ratio = st["plate_thickness_to_radius"]
    if not structure.plate_in_range(ratio, 1.0):
        return {"reason": "structure_out_of_range",
                "detail": f"end cap and base plate t/a = {ratio:.2f}, beyond the plate model's "
                          f"{structure.MINDLIN_MAX_THICKNESS_RATIO:g}"}
    checks = (("length", st["length_m"], b.max_length, "m"), ("diameter", st["outer_diameter_m"], b.max_diameter, "m"),
              ("mass", met["mass_kg"], b.max_mass or DEFAULT_MAX_MASS, "kg"))
    for name, value, limit, unit in checks:
        if limit is not None and value > limit * (1 + 1e-9):
            return {"reason": "envelope", "detail": f"{name} {value:.4g} {unit} over the envelope's {limit:.4g} {unit}"}
    return None


def _derived_figures(b: PiezoBrief, d: PiezoDesign, st: dict, ramp: float, friction: dict) -> dict:
    """The static figures the margins read beyond ``verify.static_figures``:
    the drift as judged, the current the stroke needs, the planned speed and,
    for a leaking compensator, its creep over the hold."""
    combo = d.combo
    stack = combo.stack
    c_large = combo.n * stack.capacitance * stack_phys.LARGE_SIGNAL_CAPACITANCE_FACTOR
    volts_to_stroke = b.stroke * stack.max_voltage / (st["ratio"] * combo.stack_stroke)
    out = {"thermal_drift_m": st["thermal_net_m"],
           "thermal_drift_oil_only_m": st["thermal_drift_per_K_m"] * b.delta_T,
           "thermal_drift_free_output_m": st["thermal_net_m"] - st["thermal_compensator_m"],
           "required_current_A": c_large * volts_to_stroke / b.stroke_time,
           "speed_m_s": st["free_stroke_m"] / ramp,         # the planned drive ramp, at the amplifier's limit
           "rise_time_s": ramp}
    comp = d.variant.compensator
    if comp is not None and comp.leak_conductance > 0:
        # behind its restrictor the compensator takes up the thermal volume with the
        # time constant C_h / G, and only while a held output lets pressure build: it
        # is credited with what it takes within the warm-up and the hold
        tau = float(thermal.compensator_time_constant(math.pi / 4 * st["wide_diameter_m"] ** 2, st["force_path_stiffness_N_m"],
                                                      comp.leak_conductance))
        share = float(thermal.compensated_share(tau, b.warm_up_time, b.hold_time))
        out.update(compensator_time_constant_s=tau, compensator_share=share,
                   thermal_drift_m=st["thermal_net_m"] - st["thermal_compensator_m"] * (1.0 - share))
        # output creep under the steady (largest) load over the held deflection
        out["compensator_creep_m"] = compensator_creep(comp.leak_conductance, friction["at_pressure_Pa"],
                                                       b.hold_time, st["narrow_diameter_m"])
        out["compensator_hold_s"] = b.hold_time
    return out


def _static_margins(b: PiezoBrief, d: PiezoDesign, st: dict) -> dict:
    """Every static check of one design, from its own figures (nothing is
    copied between variants)."""
    combo = d.combo
    stack, var, T = combo.stack, d.variant, b.temperature
    units, amp = st["amplifier_units"], combo.amplifier
    usable = units * float(amplifier.usable_ramp_current(amp.max_current, amp.continuous_current, amp.peak_duration,
                                                         b.stroke_time))
    temps = [combo.margins["temperature"], temperature_margin(var.material.max_temperature, T)]
    margins = {
        "stroke": floor_margin(st["free_stroke_m"], b.stroke),
        # the whole force path in series, less the seal friction at the blocked pressure
        "blocked_force": floor_margin(st["blocked_force_net_N"], b.blocked_force),
        "speed": floor_margin(st["speed_m_s"], b.speed),
        "temperature": min(temps),
        "amplifier_temperature": combo.margins["amplifier_temperature"],
        "pressure": floor_margin(combo.seal.pressure_rating, st["blocked_pressure_Pa"]),
        "drive_current": floor_margin(usable, st["required_current_A"]),
        "amplifier_continuous_current": floor_margin(units * amp.continuous_current,
                                                     max(st["rms_current_A"], st["continuous_current_A"])),
        "amplifier_units": floor_margin(b.max_amplifier_units, st["amplifier_units_needed"]),
        "stack_temperature": temperature_margin(stack.max_temperature, T + st["stack_temperature_rise_K"]),
        "natural_frequency": floor_margin(st["natural_frequency_Hz"], b.natural_frequency),
        "thermal_drift": ceiling_margin(abs(st["thermal_drift_m"]), b.allowed_drift),
        "wide_gap": floor_margin(st["wide_gap_m"], st["gap_needed_m"]),
        "packing": floor_margin(st["stacks_that_fit"], combo.n),
    }
    if b.min_stiffness > 0:
        margins["stiffness"] = floor_margin(st["output_stiffness_N_m"], b.min_stiffness)
    if b.stroke_from == "neutral":       # the load's push-back at zero drive is travel lost
        margins["stroke"] = floor_margin(st["free_stroke_m"] - b.max_load / st["output_stiffness_N_m"], b.stroke)
    comp = var.compensator
    if comp is not None:
        margins["temperature"] = min(margins["temperature"], temperature_margin(comp.max_temperature, T))
        margins["compensator_capacity"] = floor_margin(comp.capacity, st["thermal_compensator_volume_m3"])
        if "compensator_creep_m" in st:
            margins["compensator_hold"] = ceiling_margin(st["compensator_creep_m"], b.allowed_drift)
    return margins


def compensator_creep(leak_conductance, pressure, hold_time, narrow_diameter):
    """Output creep of a leaking compensator, m: the oil that leaks out at the
    load pressure over the hold, over the narrow bore (Q = G p)."""
    return leak_conductance * pressure * hold_time / (math.pi / 4 * narrow_diameter**2)


def nominal_figures(b: PiezoBrief, catalog, combos: list[Combo]) -> list[dict]:
    """Per combination ruled out before sizing, in order, the figures of a
    nominal design, so its record still carries a force path, a thermal
    budget, seal friction and static figures (``record.pruned_candidate``):
    R that just gives the stroke at the voltage the amplifier allows, the
    bore at the seal's pressure rating (or the stack packing), the default
    structure material sized by the closed-form rule, no compensator.
    Each: {"static", "ratio", "material", "force_path", "thermal_budget",
    "seal_friction_N"}."""
    if not combos:
        return []
    T = b.temperature
    material = force_path.default_material(catalog.materials)
    spacer = force_path.spacer_material(catalog.materials)
    surface, dT = b.surface_mass, b.delta_T
    rows, ratios, index, where = [], [], {}, []
    for c in combos:
        # the figures below do not depend on the amplifier beyond its voltage: build each once
        key = (c.stack.id, c.n, c.fluid.id, c.seal.id, c.voltage_fraction_max)
        if key in index:
            where.append(index[key])
            continue
        index[key] = len(rows)
        where.append(len(rows))
        x = c.stack_stroke * c.voltage_fraction_max
        R = max(b.stroke * (1 + b.design_margin) / x, 1.5)
        nk = c.n * c.stack.stiffness
        pack = math.pi / 4 * float(structure.packing_diameter(c.n, c.stack.diameter, STACK_SPACING_M)) ** 2
        A = max(nk * x / c.seal.pressure_rating, pack)
        gap = effective_gap(b, x)
        t, area = force_path.design_structure(nk, nk * x, A, c.stack.length, gap, c.seal.pressure_rating,
                                              material, b.stiffness_ratio)
        struct = structure_row(material, t, area, spacer, 0.0, None, surface, dT, b.edge_restraint)
        rows.append(part_row(c.stack, c.n, R, A, c.voltage, BoucWen(x / c.voltage, 0, 0, 0, 0, 1), T, gap,
                             c.fluid, c.seal, c.amplifier, structure=struct))
        ratios.append(R)
    cand = Candidates.from_rows(rows)
    static = static_figures(cand, b.stroke_time / 2, b.strokes_per_second)
    members = force_path.members(cand)
    p_load = b.max_load / cand.narrow_area
    seal_f = seal_friction_at(cand, p_load)
    keys = ("free_stroke_m", "blocked_force_N", "blocked_force_ideal_N", "blocked_force_net_N",
            "natural_frequency_Hz", "wide_diameter_m", "narrow_diameter_m", "ratio", "thermal_net_m",
            "wide_gap_m", "stacks_that_fit", "continuous_current_A")
    per_row = [{"static": {k: float(static[k][i]) for k in keys}, "ratio": ratios[i], "material": material.id,
                "force_path": force_path.as_list(members, i, material.id, None),
                "thermal_budget": {k: float(static["thermal_" + k][i]) for k in (*thermal.TERMS, "net_m")},
                "seal_friction_N": {"wide": float(seal_f["wide"][i]), "narrow": float(seal_f["narrow"][i]),
                                    "at_pressure_Pa": float(p_load[i])}} for i in range(len(rows))]
    return [per_row[i] for i in where]


@lru_cache(maxsize=4096)
def _ramp_stroke(stack_id, params, voltage, ramp):
    return bouc_wen.ramp_stroke(BoucWen(*params), voltage, ramp, points=1000)


def hysteresis(stack, bw, voltage, ramp) -> dict:
    """The stroke the (transferred) Bouc-Wen model gives at this design's own
    ramp against the datasheet stroke at that voltage (docs/models.md, piezo stack)."""
    params = tuple(float(v) for v in bw.as_array())
    got = _ramp_stroke(stack.id, params, round(voltage, 3), round(ramp, 4))
    nominal = stack.stroke * voltage / stack.max_voltage
    return {"ramp_time_s": ramp, "model_stroke_m": got, "datasheet_stroke_m": nominal, "ratio": got / nominal}


def hysteresis_time_scales(catalog: Catalog) -> dict:
    """Per stack: the ramp time at which its Bouc-Wen model (own or
    transferred) gives the datasheet stroke, and the stroke at 0.01, 1 and 10 s."""
    reference = reference_bouc_wen(catalog.stacks)
    out = {}
    for st in catalog.stacks.values():
        bw, source = stack_bouc_wen(st, reference)
        out[st.id] = {"matching_ramp_time_s": bouc_wen.matching_ramp_time(bw, st.max_voltage, st.stroke),
                      "datasheet_stroke_m": st.stroke, "source": source,
                      "stroke_at_m": {str(T): bouc_wen.ramp_stroke(bw, st.max_voltage, T) for T in (0.01, 1.0, 10.0)}}
    return out
