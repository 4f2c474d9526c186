"""Static figures of a piezoelectric stack and of n stacks in parallel.

Seed eq. 3: x = x_free - F / k_s. Nominal free stroke scales linearly with
voltage at the datasheet's stroke per volt (the seed's Tables 2-3 "d33");
the Bouc-Wen model (bouc_wen.py) adds the loop around that line.
"""
from __future__ import annotations

import numpy as np

# Large-signal capacitance runs well above the small-signal datasheet value
# (docs/models.md, "Piezohydraulic sizing"); PI quotes up to +70% for full-range drive
# of PZT stacks. Assumed factor, applied to every stack.
LARGE_SIGNAL_CAPACITANCE_FACTOR = 1.7

REFERENCE_TEMPERATURE_DEGC = 25.0


def free_stroke(stroke, max_voltage, voltage):
    """Free stroke of one stack at ``voltage``: stroke * V / V_max, m."""
    return np.asarray(stroke) * np.asarray(voltage) / np.asarray(max_voltage)


def derated_stroke(stroke, temperature_coefficient, temperature_degC):
    """Stroke at temperature: fractional change per K above 25 degC."""
    dT = np.asarray(temperature_degC) - REFERENCE_TEMPERATURE_DEGC
    return np.asarray(stroke) * np.maximum(1.0 + np.asarray(temperature_coefficient) * dT, 0.0)


def work_capacity(n_stacks, stiffness, stack_free_stroke):
    """Upper bound of the work n stacks can do on a matched load, J:
    n k_s x_free^2 (= blocked force x free stroke of the stack group).
    A design can meet force F and stroke S only if this >= F S
    (docs/models.md, "Piezohydraulic sizing")."""
    return np.asarray(n_stacks) * np.asarray(stiffness) * np.asarray(stack_free_stroke) ** 2


def min_stacks_for_work(force, stroke, stiffness, stack_free_stroke):
    """Smallest stack count that the work bound allows."""
    per_stack = np.asarray(stiffness) * np.asarray(stack_free_stroke) ** 2
    return np.ceil(np.asarray(force) * np.asarray(stroke) / per_stack - 1e-12).astype(int)


def drive_current(n_stacks, capacitance, voltage_rate, large_signal_factor=LARGE_SIGNAL_CAPACITANCE_FACTOR):
    """Peak charging current i = n C_large dV/dt, A."""
    return np.asarray(n_stacks) * np.asarray(capacitance) * large_signal_factor * np.asarray(voltage_rate)


def loaded_displacement(x_free, force, stiffness):
    """Seed eq. 3: displacement of one stack under a compressive force."""
    return np.asarray(x_free) - np.asarray(force) / np.asarray(stiffness)


# Self-heating (dielectric loss). Noliac, "Heat dissipation" (dynamic
# actuators tutorial, noliac.com): in sinusoidal operation the average loss
# is P = (pi / 4) tan(delta) C U_pp^2 f, with C and tan(delta) the small-signal
# datasheet values; "at 3 kV/mm the product C tan(delta) is typically 7 to 10
# times higher". A full stroke out and back is one cycle of U_pp = V.
LARGE_SIGNAL_LOSS_MULTIPLIER = 7.0      # the low end of Noliac's 7-10 (PICA runs at 2 kV/mm, below 3)
DEFAULT_LOSS_FACTOR = 0.02              # assumed: small-signal tan(delta) of soft PZT (PIC151-type)
# assumed: natural convection from the stack's side to still gas, the middle
# of the 2-25 W/(m^2 K) range of textbook tables (Incropera, Table 1.1)
FILM_COEFFICIENT = 10.0


def heat_per_stack(loss_factor, capacitance, voltage, strokes_per_second,
                   multiplier=LARGE_SIGNAL_LOSS_MULTIPLIER):
    """Dielectric loss of one stack at the duty, W: (pi/4) m tan(d) C V^2 f."""
    return (np.pi / 4.0 * multiplier * np.asarray(loss_factor) * np.asarray(capacitance)
            * np.asarray(voltage) ** 2 * np.asarray(strokes_per_second))


def side_area(length, diameter, square=False):
    """Lateral surface of one stack, m^2 (pi d L, or 4 d L for a square one)."""
    perimeter = np.where(square, 4.0, np.pi) * np.asarray(diameter)
    return perimeter * np.asarray(length)


def temperature_rise(heat, area, film_coefficient=FILM_COEFFICIENT):
    """Steady rise of the stack above its surroundings, K: P / (h A)."""
    return np.asarray(heat) / (film_coefficient * np.asarray(area))
