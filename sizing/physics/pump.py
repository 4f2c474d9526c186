"""The frequency-rectified piezohydraulic pump: chamber, reed check valves,
and the cycle-averaged flow (docs/models.md, "Piezo pump").

Stacks drive a pump piston (area A_p) into a chamber of volume V_c with an
inlet and an outlet reed check valve; the inlet draws from a bias-pressure
accumulator at p_b, the outlet feeds the output cylinder (area A_c) whose
other side returns to the accumulator.

Chamber (Sirohi and Chopra, J. Intell. Mater. Syst. Struct. 14(3), 2003,
"quasi-static model"): the stacks (stiffness K, free stroke x_f) and the
oil (effective bulk modulus beta_e) are springs in series, so the chamber
takes a volume C dp for a pressure rise dp, with the compliance

    C = V_c / beta_e + A_p^2 / K                                     (P1)

beta_e: Wood's rule for oil with free air (fraction a0 at atmospheric
pressure, compressed polytropically) plus the radial growth of a thin
chamber wall, dV / (V dp) = D / (E t):

    1 / beta_e = (1 - a) / beta + a / (kappa p) + D / (E t)          (P2)

Reed check valve (a cantilever reed over a circular port of area A_v, preload
set by the cracking pressure p_cr, stiffness k_v, reed mass m_v): the reed
lifts x = (dp - p_cr) A_v / k_v up to its stop, the flow area is the curtain
pi d_v x capped at the port, Q = C_d A sqrt(2 dp / rho) (orifice), and the
reed follows the pressure only well below its resonance
f_v = sqrt(k_v / m_v) / (2 pi).                                      (P3)

Cycle-averaged flow: a cycle starts with the chamber at the inlet pressure
p_b - p_in; it delivers once it reaches the cylinder pressure plus the outlet
valve's drop. With the total drop dp across the pump, one cycle delivers

    V_del = A_p x_f - C dp,   Q = f V_del,   v = Q / A_c             (P4)

and the stall (blocked) pressure is A_p x_f / C. dp includes both valves'
cracking pressures and their orifice drops at the delivery-phase flow.
"""
from __future__ import annotations

import numpy as np

P_ATM = 101325.0          # Pa
BISECTION_STEPS = 40


def free_air(air_fraction, pressure, dissolution_pressure=np.inf):
    """Eq. P8, the air the oil holds free at absolute pressure p, as a
    fraction at atmospheric pressure: a0 up to atmospheric, falling linearly
    to 0 at ``dissolution_pressure`` where all of it has dissolved, and
    released again as the pressure falls (the equilibrium air-dissolution
    model of Simscape's isothermal liquid, MathWorks, "Isothermal Liquid
    Modeling Options"; inf: no dissolution)."""
    a0 = np.asarray(air_fraction, float)
    p = np.asarray(pressure, float)
    pd = np.asarray(dissolution_pressure, float)
    share = np.where(np.isfinite(pd), np.clip((pd - p) / np.where(np.isfinite(pd), pd - P_ATM, 1.0), 0.0, 1.0), 1.0)
    return a0 * share


def wall_compliance(bore, wall_thickness, youngs_modulus):
    """Volumetric compliance of a thin cylindrical wall, dV / (V dp) = D / (E t), 1/Pa."""
    return np.asarray(bore) / (np.asarray(youngs_modulus) * np.asarray(wall_thickness))


def effective_bulk_modulus(bulk_modulus, air_fraction, pressure, wall=0.0, polytropic=1.4,
                           dissolution_pressure=np.inf):
    """Eq. P2: oil with entrained air at absolute pressure p (Pa) in a
    compliant chamber (``wall``: D / (E t), 1/Pa), Pa. With dissolution
    (P8) the air that goes into solution as the pressure rises is volume
    lost too: the mixture's compliance -dV / (V dp) adds
    a0 / (p_d - p_atm) (p_atm / p)^(1 / kappa) below p_d."""
    a0 = np.asarray(air_fraction, float)
    p = np.maximum(np.asarray(pressure, float), 1e3)
    pd = np.asarray(dissolution_pressure, float)
    r = (P_ATM / p) ** (1.0 / polytropic)
    v_air = free_air(a0, p, pd) * r
    dissolving = np.where(np.isfinite(pd) & (p > P_ATM) & (p < pd), a0 / np.where(np.isfinite(pd), pd - P_ATM, 1.0), 0.0)
    compliance = ((1.0 - a0) / np.asarray(bulk_modulus) + dissolving * r + v_air / (polytropic * p)) / (1.0 - a0 + v_air)
    return 1.0 / (compliance + np.asarray(wall))


def chamber_stiffness(bulk_modulus, pump_area, chamber_volume):
    """Oil in the pumping chamber as a spring on the pump piston, beta A^2 / V, N/m."""
    return np.asarray(bulk_modulus) * np.asarray(pump_area) ** 2 / np.asarray(chamber_volume)


def chamber_compliance(chamber_volume, bulk_modulus, pump_area, stack_stiffness):
    """Eq. P1: volume the chamber takes up per pascal, stacks and oil in series, m^3/Pa."""
    return np.asarray(chamber_volume) / np.asarray(bulk_modulus) + np.asarray(pump_area) ** 2 / np.asarray(stack_stiffness)


def valve_resonance(reed_stiffness, reed_mass):
    """f_v = sqrt(k_v / m_v) / (2 pi), Hz."""
    return np.sqrt(np.asarray(reed_stiffness) / np.asarray(reed_mass)) / (2.0 * np.pi)


def valve_lift(dp, cracking_pressure, port_area, reed_stiffness, max_lift):
    """Reed lift at a pressure difference dp (Pa), m: shut below cracking."""
    x = (np.asarray(dp) - np.asarray(cracking_pressure)) * np.asarray(port_area) / np.asarray(reed_stiffness)
    return np.clip(x, 0.0, np.asarray(max_lift))


def curtain_area(port_area, lift):
    """Open area of a reed valve lifted by ``lift``, m^2: its curtain pi d x,
    at most the port."""
    d = np.sqrt(4.0 * np.asarray(port_area) / np.pi)
    return np.minimum(np.pi * d * lift, np.asarray(port_area))


def valve_flow(dp, density, cracking_pressure, port_area, reed_stiffness, max_lift, discharge_coefficient,
               viscosity=0.0, seat_width=0.0, seat_gap=0.0):
    """Forward flow through a reed check valve at dp (Pa), m^3/s; 0 when dp <= p_cr.
    With ``viscosity`` (Pa s) and ``seat_width`` (m), eq. P9: the curtain's
    laminar resistance 12 mu w / (pi d x^3) (plane Poiseuille flow across
    the seat's land w in a gap x) in series with the orifice,
    dp = R Q + Q^2 / (C_d A sqrt(2 / rho))^2. ``seat_gap`` (m): the gap a
    seated reed leaves (P7), so a shut valve leaks through it."""
    dp = np.maximum(np.asarray(dp, float), 0.0)
    x = np.maximum(valve_lift(dp, cracking_pressure, port_area, reed_stiffness, max_lift), np.asarray(seat_gap))
    d = np.sqrt(4.0 * np.asarray(port_area) / np.pi)
    k = np.asarray(discharge_coefficient) * curtain_area(port_area, x) * np.sqrt(2.0 / np.asarray(density))
    with np.errstate(divide="ignore", invalid="ignore"):
        rl = 12.0 * np.asarray(viscosity) * np.asarray(seat_width) / (np.pi * d * x**3)
        q = 2.0 * dp / (rl + np.sqrt(rl**2 + 4.0 * dp / k**2))
    return np.where(x > 0, np.nan_to_num(q), 0.0)


def valve_drop(flow, density, cracking_pressure, port_area, reed_stiffness, max_lift, discharge_coefficient,
               viscosity=0.0, seat_width=0.0):
    """The pressure difference (Pa) at which a reed valve passes ``flow``
    (m^3/s): the inverse of ``valve_flow`` (monotone), by bisection."""
    flow = np.asarray(flow, float)
    lo = np.broadcast_to(np.asarray(cracking_pressure, float), flow.shape).copy()
    # at full lift over the cracking pressure and the full-lift drops, the
    # valve passes at least the flow: an upper bound
    d = np.sqrt(4.0 * np.asarray(port_area) / np.pi)
    full = np.minimum(np.pi * d * np.asarray(max_lift), np.asarray(port_area))
    laminar = 12.0 * np.asarray(viscosity) * np.asarray(seat_width) / (np.pi * d * np.asarray(max_lift) ** 3)
    hi = (lo + np.asarray(reed_stiffness) * np.asarray(max_lift) / np.asarray(port_area) + laminar * flow
          + 0.5 * np.asarray(density) * (flow / (np.asarray(discharge_coefficient) * full)) ** 2)
    args = (density, cracking_pressure, port_area, reed_stiffness, max_lift, discharge_coefficient, viscosity,
            seat_width)
    for _ in range(BISECTION_STEPS):
        mid = 0.5 * (lo + hi)
        over = valve_flow(mid, *args) >= flow
        hi, lo = np.where(over, mid, hi), np.where(over, lo, mid)
    return hi


def swept_volume(pump_area, stack_free_stroke):
    """Volume one pumping cycle sweeps, A_p x_f, m^3."""
    return np.asarray(pump_area) * np.asarray(stack_free_stroke)


def stall_pressure(swept, compliance):
    """Pressure difference at which the pump delivers nothing, A_p x_f / C, Pa."""
    return np.asarray(swept) / np.asarray(compliance)


def delivered_volume(swept, compliance, dp):
    """Eq. P4: volume delivered per cycle against a total drop dp, m^3 (>= 0)."""
    return np.maximum(np.asarray(swept) - np.asarray(compliance) * np.asarray(dp), 0.0)


def sine_current(capacitance, voltage, frequency):
    """Peak and rms current of a stack group driven 0..V by a sine at f:
    i = C dv/dt, peak pi f C V, rms pi f C V / sqrt 2, A."""
    peak = np.pi * np.asarray(frequency) * np.asarray(capacitance) * np.asarray(voltage)
    return peak, peak / np.sqrt(2.0)


def reactive_power(capacitance, voltage, frequency):
    """Reactive power of a capacitor driven 0..V by a sine at f, var:
    omega C V_a^2 / 2 with amplitude V_a = V / 2, = (pi / 4) C V^2 f."""
    return np.pi / 4.0 * np.asarray(capacitance) * np.asarray(voltage) ** 2 * np.asarray(frequency)


def apparent_power(capacitance, voltage, frequency):
    """What the amplifier must supply, V x I_rms, VA (its output swings to V)."""
    return np.asarray(voltage) * sine_current(capacitance, voltage, frequency)[1]


def cycle_averaged(swept, chamber_volume, bulk_modulus, air_fraction, wall, pump_area, stack_stiffness,
                   frequency, bias_pressure, load_pressure, cracking_pressure, dissolution_pressure=np.inf):
    """Eq. P4, vectorised over candidates: the quasi-static model of Sirohi
    and Chopra (2003), who found the viscous losses through the valves and
    tubing negligible beside the chamber's compliance and the load's inertia.
    A cycle loses C dp with dp the cylinder's pressure over the bias
    (``load_pressure``: load and seal friction over the bore) plus both
    valves' cracking pressures; the orifice drop of the delivery flow is
    returned by the chamber as the stack slows at the top of its sine, so
    it enters only as a check (``peak_flow``, ``valve_drop``). The chamber's
    modulus is taken at its mean pressure, p_b + dp / 2.
    Returns {"flow_m3_s", "delivered_m3", "drop_Pa", "compliance_m3_Pa"}.
    """
    dp = np.asarray(load_pressure, float) + 2.0 * np.asarray(cracking_pressure)
    beta = effective_bulk_modulus(bulk_modulus, air_fraction, np.asarray(bias_pressure) + P_ATM + dp / 2.0, wall,
                                  dissolution_pressure=dissolution_pressure)
    C = chamber_compliance(chamber_volume, beta, pump_area, stack_stiffness)
    V = delivered_volume(swept, C, dp)
    return {"flow_m3_s": V * np.asarray(frequency), "delivered_m3": V, "drop_Pa": dp, "compliance_m3_Pa": C}


def peak_flow(swept, frequency):
    """Peak of A_p dx_f/dt under a sine drive, pi f A_p x_f, m^3/s."""
    return np.pi * np.asarray(frequency) * np.asarray(swept)


# Lines and passages (P6). The oil in a line of length L and bore d moves
# with the flow; between the pump's oil volume and the cylinder it moves
# A_c / A_line times as fast as the piston, so the load feels it as a mass
# rho L A_c^2 / A_line (the line's inertance rho L / A_line times A_c^2),
# and the laminar (Hagen-Poiseuille) resistance 128 mu L / (pi d^4) as a
# viscous force A_c^2 R u.
def line_area(diameter):
    return np.pi * np.asarray(diameter) ** 2 / 4.0


def line_inertance(density, length, diameter):
    """Fluid inertance rho L / A of a line, Pa s^2 / m^3."""
    return np.asarray(density) * np.asarray(length) / line_area(diameter)


def line_resistance(viscosity, length, diameter):
    """Laminar (Hagen-Poiseuille) resistance 128 mu L / (pi d^4), Pa s / m^3;
    ``viscosity`` dynamic, Pa s."""
    return 128.0 * np.asarray(viscosity) * np.asarray(length) / (np.pi * np.asarray(diameter) ** 4)


def reflected_mass(density, length, diameter, cylinder_area):
    """The line's oil as a mass on the piston, rho L A_c^2 / A_line, kg."""
    return line_inertance(density, length, diameter) * np.asarray(cylinder_area) ** 2


def reflected_damping(viscosity, length, diameter, cylinder_area):
    """The line's laminar resistance as a viscous coefficient on the piston, A_c^2 R, N s/m."""
    return line_resistance(viscosity, length, diameter) * np.asarray(cylinder_area) ** 2


# Leakage (P7): laminar flow through the concentric annulus of a piston of
# diameter D with radial clearance c over a land of length L (plane
# Poiseuille flow, valid for c << D): Q = pi D c^3 dp / (12 mu L).
def annulus_leakage(diameter, clearance, land_length, viscosity):
    """Leak conductance of a concentric clearance, m^3 / (s Pa)."""
    return (np.pi * np.asarray(diameter) * np.asarray(clearance) ** 3
            / (12.0 * np.asarray(viscosity) * np.asarray(land_length)))


# Reed dynamics (P5). A reed moving in oil carries the oil it displaces:
# potential flow gives a plate of width b moving normal to itself, oil on
# both sides, an added mass (pi / 4) rho b^2 per unit length (a strip;
# Lamb, Hydrodynamics, sec. 71; Blevins, Formulas for Natural Frequency and
# Mode Shape, table 14-2), and a disc of radius a (8 / 3) rho a^3. A
# cantilever reed's first mode moves this oil with the same modal weight as
# its own mass (the modal factor of its effective mass, 0.24 for a uniform
# cantilever). The wetted resonance is sqrt(k / (m + m_a)) / (2 pi).
def added_mass_strip(density, width, length, modal_factor=1.0):
    """Added mass of a strip (cantilever reed) of width b and length L in fluid, kg."""
    return np.asarray(modal_factor) * np.pi / 4.0 * np.asarray(density) * np.asarray(width) ** 2 * np.asarray(length)


def added_mass_disc(density, radius, modal_factor=1.0):
    """Added mass of a disc of radius a moving normal to itself in fluid, (8 / 3) rho a^3, kg."""
    return np.asarray(modal_factor) * 8.0 / 3.0 * np.asarray(density) * np.asarray(radius) ** 3


def wetted_resonance(reed_stiffness, reed_mass, added_mass):
    """A reed's resonance in the fluid, sqrt(k / (m + m_a)) / (2 pi), Hz."""
    return valve_resonance(reed_stiffness, np.asarray(reed_mass) + np.asarray(added_mass))


def reed_added_mass(shape, density, width, length, modal_factor):
    """The added mass of a reed (kg, 0 without its geometry): a cantilever as
    a strip of its width over its length, a disc of diameter ``width``, each
    weighted by the mode's ``modal_factor``."""
    if width is None or (shape == "cantilever" and length is None):
        return 0.0
    if shape == "disc":
        return float(added_mass_disc(density, width / 2.0, modal_factor))
    return float(added_mass_strip(density, width, length, modal_factor))
