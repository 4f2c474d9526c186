"""Pin-and-lug end fittings (a clevis and the eye it holds).

A pin in double shear through a fork carries the force on two sections
(any machine-design text, e.g. Shigley, Mechanical Engineering Design):
tau = 2 F / (pi d^2), so

    d = sqrt(2 F / (pi tau_allow))

with tau_allow = S_y / sqrt(3) (distortion energy, Shigley eq. 5-21). The
eye (one lug of thickness t) bears on the pin over d t:

    t = F / (d S_y)

(bearing stress taken at the yield strength, conservative against the 1.5
S_y of aircraft practice); its net section across the hole, (w - d) t,
carries F at w = 2 d at the same stress. The fork's two lugs carry half
the force each, together the eye's thickness.

The pin also bends: with the eye's load spread over its thickness t and
each fork lug's over t / 2, without a gap, the moment at the pin's middle
is M = (F / 2) (t / 4 + t / 4) = F t / 4 (the lug-and-pin analysis of Bruhn,
Analysis and Design of Flight Vehicle Structures, ch. D1, without a gap or
"peaking"), sigma = 32 M / (pi d^3). With t = F / (d S_y) this is
sigma = 8 F^2 / (pi d^4 S_y), at most S_y when

    d >= (8 / pi)^(1/4) sqrt(F / S_y)

which needs a thicker pin than shear (sqrt(2 sqrt 3 / pi) sqrt(F / S_y)).

Vectorised over candidates; SI.
"""
from __future__ import annotations

import numpy as np

EYE_WIDTH_OVER_PIN = 2.0     # lug width w over the pin diameter: net section (w - d) t = d t


def pin_diameter(force, yield_strength):
    """Pin diameter (m) in double shear at the distortion-energy shear yield."""
    tau = np.asarray(yield_strength, float) / np.sqrt(3.0)
    return np.sqrt(2 * np.abs(np.asarray(force, float)) / (np.pi * tau))


def pin_bending_diameter(force, yield_strength):
    """Pin diameter (m) whose bending stress in a clevis sized by
    ``eye_thickness`` is the yield strength: (8 / pi)^(1/4) sqrt(F / S_y)."""
    return (8 / np.pi) ** 0.25 * np.sqrt(np.abs(np.asarray(force, float)) / np.asarray(yield_strength, float))


def pin_bending_stress(force, diameter, thickness):
    """Bending stress (Pa) of the pin: M = F t / 4, sigma = 32 M / (pi d^3)."""
    return 32 * np.abs(np.asarray(force, float)) * np.asarray(thickness) / 4 / (np.pi * np.asarray(diameter) ** 3)


def pin_shear_stress(force, diameter):
    """Shear stress (Pa) of a pin in double shear: 2 F / (pi d^2)."""
    return 2 * np.abs(np.asarray(force, float)) / (np.pi * np.asarray(diameter) ** 2)


def eye_thickness(force, pin, yield_strength):
    """Eye thickness (m) at which the bearing stress F / (d t) is the yield strength."""
    return np.abs(np.asarray(force, float)) / (np.asarray(pin) * np.asarray(yield_strength))


def fitting_volume(pin, thickness):
    """Volume (m^3) of one end fitting: an eye and a fork (together twice
    the eye's thickness) of width w = EYE_WIDTH_OVER_PIN d and as long as
    wide, less the holes, plus the pin through both."""
    d, t = np.asarray(pin), np.asarray(thickness)
    w = EYE_WIDTH_OVER_PIN * d
    lugs = 2 * t * (w * w - np.pi / 4 * d**2)
    return lugs + np.pi / 4 * d**2 * 2 * t
