"""How many amplifier units a piezo drive needs, and the heat they shed.

A stack group is a capacitor C (large-signal). Ramping it from 0 to V in a
time t_r draws i_r = C V / t_r (PI piezo tutorial 4.29: I = C dU/dt). An
amplifier's peak current is rated for a short pulse only (PI's E-617 manual:
the peak is available for about 5 ms, then the output falls to the average
current), so a ramp longer than the rated pulse must be carried by the
continuous rating. Over a duty of f full strokes a second (out and back),
the current flows during two ramps per cycle:

    mean  I_mean = 2 C V f            (charge out and back)
    rms   I_rms  = i_r sqrt(2 t_r f)  (two rectangular pulses of i_r and t_r)

and the thermal (continuous) rating must cover I_rms >= I_mean. Units in
parallel add their currents; the count needed is the larger of the two
requirements, rounded up.

Heat: charging a capacitor through a linear stage from a supply at V loses
C V^2 / 2 in the stage, and discharging it dumps the stored C V^2 / 2: C V^2
a cycle. A switching amplifier with energy recovery returns a fraction r of
it: P = (1 - r) C V^2 f.
"""
from __future__ import annotations

import numpy as np


def ramp_current(capacitance, voltage, ramp_time):
    """i_r = C V / t_r, A (C large-signal, F)."""
    return np.asarray(capacitance) * np.asarray(voltage) / np.asarray(ramp_time)


def mean_current(capacitance, voltage, strokes_per_second):
    """I_mean = 2 C V f, A."""
    return 2.0 * np.asarray(capacitance) * np.asarray(voltage) * np.asarray(strokes_per_second)


def rms_current(capacitance, voltage, ramp_time, strokes_per_second):
    """I_rms = i_r sqrt(2 t_r f), A; the duty factor is capped at 1 (ramps
    back to back)."""
    duty = np.minimum(2.0 * np.asarray(ramp_time) * np.asarray(strokes_per_second), 1.0)
    return ramp_current(capacitance, voltage, ramp_time) * np.sqrt(duty)


def usable_ramp_current(peak_current, continuous_current, peak_duration, ramp_time):
    """What one unit can hold for the whole ramp: its peak when the ramp is
    no longer than the rated pulse, else its continuous rating, A."""
    return np.where(np.asarray(ramp_time) <= np.asarray(peak_duration), peak_current, continuous_current)


def units_needed(capacitance, voltage, ramp_time, strokes_per_second, peak_current, continuous_current,
                 peak_duration):
    """Units in parallel that carry the ramp and the duty's rms (count, >= 1)."""
    i_r = ramp_current(capacitance, voltage, ramp_time)
    usable = usable_ramp_current(peak_current, continuous_current, peak_duration, ramp_time)
    i_rms = rms_current(capacitance, voltage, ramp_time, strokes_per_second)
    need = np.maximum(i_r / np.asarray(usable), i_rms / np.asarray(continuous_current))
    return np.maximum(np.ceil(need - 1e-9), 1.0)


def dissipated_power(capacitance, voltage, strokes_per_second, energy_recovery=0.0):
    """Heat shed by the drive, W: (1 - r) C V^2 f."""
    return ((1.0 - np.asarray(energy_recovery)) * np.asarray(capacitance) * np.asarray(voltage) ** 2
            * np.asarray(strokes_per_second))


def drive_for_speed(capacitance, voltage, longest_ramp, strokes_per_second, peak_current, continuous_current,
                    peak_duration, max_units=np.inf):
    """The drive sized against the speed and the duty: the fewest units
    that ramp the stack group to ``voltage`` within ``longest_ramp`` (the
    ramp that reaches the stroke at the required speed) and carry the
    duty's rms, capped at ``max_units``; and the shortest ramp those units
    drive. Within each regime (a ramp within the rated pulse, on the peak;
    a longer one, on the continuous rating) both the ramp current and the
    rms fall as the ramp lengthens, so the fewest units are found at the
    longest ramp of either regime: min(longest, pulse) on the peak, the
    longest on the continuous rating. Returns arrays: ``needed`` (units the
    speed and duty need), ``units`` (min(needed, max_units)) and ``ramp`` (s;
    longer than ``longest_ramp`` when the cap holds the count back)."""
    C, V = np.asarray(capacitance, float), np.asarray(voltage, float)
    f, pulse = np.asarray(strokes_per_second, float), np.asarray(peak_duration, float)
    longest = np.asarray(longest_ramp, float)
    on_peak = units_needed(C, V, np.minimum(longest, pulse), f, peak_current, continuous_current, pulse)
    on_continuous = units_needed(C, V, longest, f, peak_current, continuous_current, pulse)
    needed = np.minimum(on_peak, on_continuous)
    units = np.minimum(needed, max_units)
    charge = C * V
    t_rms = 2.0 * f * (charge / (units * np.asarray(continuous_current, float))) ** 2   # i_rms <= units x I_c
    ramp_peak = np.maximum(charge / (units * np.asarray(peak_current, float)), t_rms)
    ramp_cont = np.maximum(charge / (units * np.asarray(continuous_current, float)), t_rms)
    ramp = np.where(ramp_peak <= pulse, ramp_peak, ramp_cont)
    return {"needed": needed, "units": units, "ramp": ramp}
