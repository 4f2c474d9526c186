"""Brushless DC motor limits: the bus-voltage (back-EMF) speed ceiling and
the winding temperature over a duty cycle.

Voltage ceiling (PHYSICS-NOTES, second round; any motor text, e.g. Hughes,
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
