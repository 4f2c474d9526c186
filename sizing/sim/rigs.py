"""Simulation models of test rigs (rig.toml) for fitting and diagnosis."""
from __future__ import annotations

from ..io.rig import DCRig, PiezoRig
from ..physics import hydraulics
from .dc_motor import DCMotorModel
from .piezohydraulic import PiezoHydraulicModel


def piezo_model(rig: PiezoRig, **changes) -> PiezoHydraulicModel:
    h = rig.hydraulics
    A_w, A_n = float(hydraulics.area(h.wide_diameter)), float(hydraulics.area(h.narrow_diameter))
    R = A_w / A_n
    bw = rig.stack.bouc_wen
    model = PiezoHydraulicModel(
        k_stacks=rig.stack.count * rig.stack.stiffness, d33=rig.stack.d33,
        alpha=bw.alpha, beta=bw.beta, gamma=bw.gamma, delta=bw.delta, n_bw=bw.n,
        wide_area=A_w, narrow_area=A_n, oil_volume=A_w * h.wide_gap + A_n * h.narrow_length,
        bulk_modulus=h.bulk_modulus, narrow_mass=h.narrow_piston_mass, density=h.fluid_density,
        k_contract=h.loss_coefficient,
        k_expand=h.expansion_loss_coefficient if h.expansion_loss_coefficient is not None
        else float(hydraulics.expansion_loss_coefficient(R)),
        wide_friction=rig.seals.wide_friction, narrow_friction=rig.seals.narrow_friction,
        wide_breakaway=rig.seals.breakaway_ratio, narrow_breakaway=rig.seals.breakaway_ratio,
        load_force=rig.load.force, load_stiffness=rig.load.stiffness, no_return=float(rig.no_return))
    return model.replace(**changes) if changes else model


def dc_model(rig: DCRig, **changes) -> DCMotorModel:
    m, c = rig.motor, rig.controller
    model = DCMotorModel(
        c1=m.c1, c2=m.c2, lead=m.screw_lead, rate=c.rate, kp=c.kp, ki=c.ki, kd=c.kd,
        derivative_on_measurement=float(c.derivative_on == "measurement"),
        current_limit=c.current_limit, load_force=rig.load.force, load_stiffness=rig.load.stiffness,
        efficiency=m.screw_efficiency, torque_constant=m.torque_constant)
    return model.replace(**changes) if changes else model
