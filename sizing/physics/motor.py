"""Brushless DC motor limits: the bus-voltage (back-EMF) speed ceiling and
the winding temperature over a duty cycle.

Voltage ceiling (any motor text, e.g. Hughes,
"Electric Motors and Drives", ch. 3): at the bus voltage U a motor carrying
current i cannot turn faster than

    omega_max = (U - R i) / k_e                                   [rad/s]

with k_e bus-referred (no-load speed = U / k_e). A current-driven plant
(seed eq. 13) has no such limit; the drive's current loop hides the back-EMF
until the voltage runs out, and then the motor is voltage-driven.

Winding temperature (steady state, one thermal resistance R_th winding to
ambient, copper resistance R(T) = R_25 (1 + alpha (T - 25 degC))):

    dT = R_th R(T_a + dT) i_rms^2
    => dT = R_th R_25 (1 + alpha (T_a - 25)) i_rms^2 / (1 - alpha R_th R_25 i_rms^2)

The denominator vanishing is thermal runaway (dT -> inf). All functions are
vectorised over candidates (numpy broadcasting), SI units, temperatures degC.
"""
from __future__ import annotations

import numpy as np

REFERENCE_TEMPERATURE = 25.0    # degC: catalog resistances are given at 25 degC


def resistance_at(r25, alpha, temperature):
    """Winding resistance at ``temperature`` (ohm)."""
    return np.asarray(r25) * (1.0 + np.asarray(alpha) * (np.asarray(temperature) - REFERENCE_TEMPERATURE))


def torque_constant_at(kt25, beta, temperature):
    """k_t at the magnet temperature (magnets weaken as they warm; beta < 0)."""
    return np.asarray(kt25) * (1.0 + np.asarray(beta) * (np.asarray(temperature) - REFERENCE_TEMPERATURE))


def speed_ceiling(bus_voltage, back_emf_constant, resistance, current):
    """Motor speed the bus voltage allows while carrying ``current`` (rad/s),
    omega = (U - R i) / k_e, floored at 0 (the motor stalls)."""
    w = (np.asarray(bus_voltage) - np.asarray(resistance) * np.abs(current)) / np.asarray(back_emf_constant)
    return np.maximum(w, 0.0)


def winding_rise(thermal_resistance, r25, alpha, ambient, i_rms):
    """Steady winding temperature rise above ``ambient`` (K) at RMS current
    ``i_rms``, with the resistance evaluated at the winding temperature.
    Returns inf where the copper loss outruns the cooling (thermal runaway)."""
    rth, r25, alpha = np.asarray(thermal_resistance), np.asarray(r25), np.asarray(alpha)
    i2 = np.asarray(i_rms) ** 2
    num = rth * r25 * (1.0 + alpha * (np.asarray(ambient) - REFERENCE_TEMPERATURE)) * i2
    den = 1.0 - alpha * rth * r25 * i2
    return np.where(den > 0, num / np.where(den > 0, den, 1.0), np.inf)


def rms_current_allowed(thermal_resistance, r25, alpha, ambient, max_winding):
    """The RMS current that brings the winding exactly to ``max_winding``
    (inverse of ``winding_rise``; 0 where the ambient is already above it)."""
    dT = np.maximum(np.asarray(max_winding) - np.asarray(ambient), 0.0)
    r_hot = resistance_at(r25, alpha, max_winding)
    return np.sqrt(dT / (np.asarray(thermal_resistance) * r_hot))


# --- ratings at temperature ------------------------------------------------
# Continuous torque at a hotter ambient (Exlar, "Elevated ambient temperature
# de-rating of brushless motors", catalog-sources.md 2b): the copper loss the
# housing can shed falls with the margin between winding limit and ambient,
#     T_cont(T_a) = T_cont(25 degC) sqrt((T_w,max - T_a) / (T_w,max - 25))
# (84.5 % at 55 degC for a 130 degC stator; 53 % at 100 degC).
def continuous_torque_at(t_cont25, max_winding, ambient):
    """Rated continuous torque (N m) at ``ambient`` (degC); 0 at or above the winding limit."""
    span = np.asarray(max_winding, float) - REFERENCE_TEMPERATURE
    left = np.maximum(np.asarray(max_winding, float) - np.asarray(ambient, float), 0.0)
    return np.asarray(t_cont25) * np.sqrt(left / np.where(span > 0, span, np.inf))


def derated_winding(thermal_resistance, r25, alpha, kt25, beta, ambient, torque_rms, iterations=12):
    """Steady winding temperature (degC), k_t (N m/A) and RMS current (A) of a
    motor delivering ``torque_rms`` with its magnets at the winding
    temperature: k_t(T_w) = k_t25 (1 + beta (T_w - 25)) needs more current,
    which heats the winding, which weakens the magnets (fixed point, a
    contraction while the winding stays below runaway). Magnets taken at the
    winding temperature: the rotor of a small motor runs close to it, and
    nothing in the datasheets says how far below (conservative).
    Returns inf where the winding runs away."""
    kt25, beta = np.asarray(kt25, float), np.asarray(beta, float)
    Tw = np.broadcast_to(np.asarray(ambient, float), np.broadcast(kt25, torque_rms, ambient).shape).copy()
    for _ in range(iterations):
        kt = torque_constant_at(kt25, beta, np.minimum(Tw, 1e3))
        kt = np.maximum(kt, 1e-3 * kt25)
        i = np.asarray(torque_rms) / kt
        Tw = np.asarray(ambient) + winding_rise(thermal_resistance, r25, alpha, ambient, i)
    kt = np.maximum(torque_constant_at(kt25, beta, np.minimum(Tw, 1e3)), 1e-3 * kt25)
    return Tw, kt, np.asarray(torque_rms) / kt


def holding_temperature(start, steady, time, time_constant):
    """Winding temperature (degC) after holding for ``time`` s, first order
    from ``start`` towards the holding steady state ``steady``."""
    start, steady = np.asarray(start, float), np.asarray(steady, float)
    decay = np.exp(-np.asarray(time) / np.asarray(time_constant))
    finite = np.isfinite(start) & np.isfinite(steady)
    mixed = np.where(finite, steady + (np.where(finite, start, 0.0) - np.where(finite, steady, 0.0)) * decay, np.inf)
    return np.where(np.isnan(start) | np.isnan(steady), np.nan, mixed)
