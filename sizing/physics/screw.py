"""Screw (ball, roller, lead) and gear: force, buckling and life.

Force from torque (any machine-design text, e.g. Shigley ch. 8): a screw of
lead l and forward efficiency eta turning at torque T pushes

    F = 2 pi eta T / l,          T = F l / (2 pi eta)

and through a gear of ratio N and efficiency eta_g the motor torque is
T_m = F l / (2 pi eta eta_g N). The output speed is v = omega_m l / (2 pi N).

Euler buckling of the screw shaft in compression (Shigley sec. 4-13; Roark
table 15.1): P_cr = pi^2 E I / (K L)^2 with I = pi d_r^4 / 64 of the root
diameter d_r and the effective length factor K of the end fixity. The
actuator's stated fixity is FIXED-PINNED: the screw is held by the angular
contact bearings of the motor end (fixed), and the rod end carries the
surface horn on a pin (pinned), K = 0.7 (theoretical 0.699).

Life (ISO 3408-5 for ball screws, ISO 281 form): the basic rating life at a
constant equivalent load F_m is L10 = (C / F_m)^3 10^6 revolutions.
"""
from __future__ import annotations

import numpy as np

END_FIXITY = {"fixed-free": 2.0, "pinned-pinned": 1.0, "fixed-pinned": 0.7, "fixed-fixed": 0.5}
ACTUATOR_END_FIXITY = "fixed-pinned"


def force_from_torque(torque, lead, efficiency, ratio=1.0, gear_efficiency=1.0):
    """Output force (N) from motor torque (N m) through gear and screw."""
    return 2 * np.pi * np.asarray(efficiency) * np.asarray(gear_efficiency) * np.asarray(ratio) * np.asarray(torque) / np.asarray(lead)


def torque_for_force(force, lead, efficiency, ratio=1.0, gear_efficiency=1.0):
    """Motor torque (N m) that holds or drives an output force (N)."""
    return np.asarray(force) * np.asarray(lead) / (2 * np.pi * np.asarray(efficiency) * np.asarray(gear_efficiency) * np.asarray(ratio))


def output_speed(motor_speed, lead, ratio=1.0):
    """Output speed (m/s) from motor speed (rad/s)."""
    return np.asarray(motor_speed) * np.asarray(lead) / (2 * np.pi * np.asarray(ratio))


def buckling_load(elastic_modulus, root_diameter, length, fixity: str = ACTUATOR_END_FIXITY):
    """Euler critical load (N) of a solid circular shaft of ``root_diameter``
    and unsupported ``length`` with the named end fixity (END_FIXITY)."""
    K = END_FIXITY[fixity]
    inertia = np.pi * np.asarray(root_diameter) ** 4 / 64.0
    return np.pi**2 * np.asarray(elastic_modulus) * inertia / (K * np.asarray(length)) ** 2


def l10_revolutions(dynamic_load_rating, equivalent_load):
    """Basic rating life (revolutions) at a constant equivalent load."""
    F = np.maximum(np.asarray(equivalent_load, dtype=float), 1e-9)
    return (np.asarray(dynamic_load_rating) / F) ** 3 * 1e6


def cubic_mean_load(loads, fractions):
    """Equivalent load (N) of a load spectrum: (sum q_i F_i^3)^(1/3) with
    q_i the fraction of revolutions at load F_i (ISO 3408-5)."""
    loads, q = np.asarray(loads, float), np.asarray(fractions, float)
    return (np.sum(q * np.abs(loads) ** 3, axis=-1) / np.sum(q, axis=-1)) ** (1.0 / 3.0)


# --- makers' ratings -------------------------------------------------------
# Static safety factor (THK General Catalog, ball screw "static safety
# factor"; ISO 3408-5): f_s = C0a / F_a,max against the basic static load
# rating. THK asks f_s >= 1.0-3.5 for machinery without vibration or impact
# and 2.0-5.0 with them; an air-vehicle surface vibrates: 2.0 is the floor.
STATIC_SAFETY_WITH_VIBRATION = 2.0


def static_safety(static_load_rating, peak_force):
    """C0 / F_peak (-); inf where the static rating is unknown."""
    return np.asarray(static_load_rating, float) / np.maximum(np.asarray(peak_force, float), 1e-9)


def l10_hours(dynamic_load_rating, equivalent_load, rev_per_second, load_factor=1.0):
    """Basic rating life (h), THK's L = (C_a / (f_w F_a))^3 10^6 rev at
    ``rev_per_second`` (f_w 1.0-1.2 for smooth motion without impact)."""
    return l10_revolutions(dynamic_load_rating, np.asarray(equivalent_load) * load_factor) / np.asarray(rev_per_second) / 3600.0


def dn_speed_limit(dn, diameter):
    """Permissible speed (rad/s) from a maker's DN value: n = DN / D with
    DN in mm rpm (THK: 70 000 precision / 50 000 rolled over the
    ball-centre diameter; HIWIN: 70 000 rolled / 90 000 ground over d)."""
    return np.asarray(dn, float) / (np.asarray(diameter, float) * 1e3) * 2 * np.pi / 60.0


def holding_torque(force, lead, back_efficiency, ratio=1.0, gear_back_efficiency=1.0):
    """Motor torque (N m) that holds ``force`` on a back-drivable screw: the
    load drives the screw backwards and friction helps the motor,
    T = F l eta' eta_g' / (2 pi N) with the reverse efficiencies eta'
    (HIWIN 0.75-0.85 for ball screws). A brake holds the same at no power."""
    return (np.asarray(force) * np.asarray(lead) * np.asarray(back_efficiency) * np.asarray(gear_back_efficiency)
            / (2 * np.pi * np.asarray(ratio)))


# assumed: a preloaded 12-16 mm ball nut, 150 N/um; catalogue nut rigidities
# of the size are of this order (HIWIN and THK list some 100-300 N/um for
# preloaded 12-16 mm nuts); no datasheet of the catalog's screws was read
NUT_STIFFNESS_N_M = 1.5e8
# assumed: the fixed end's angular-contact support bearing pair, 100 N/um
# (the order of a 10-12 mm bore pair with light preload); not read from a datasheet
BEARING_STIFFNESS_N_M = 1.0e8


def axial_stiffness(elastic_modulus, root_diameter, length, nut=NUT_STIFFNESS_N_M, bearing=BEARING_STIFFNESS_N_M):
    """Output stiffness of a screw drive held at its motor angle, N/m: the
    shaft over its length (E pi d_r^2 / (4 L), the root diameter), the nut
    and the support bearing in series. A servo holding the motor angle does
    not see this compliance: the output gives F / k under a load."""
    shaft = np.asarray(elastic_modulus) * np.pi * np.asarray(root_diameter) ** 2 / (4.0 * np.asarray(length))
    return held_stiffness(shaft, nut, bearing)


def held_stiffness(shaft=np.inf, nut=NUT_STIFFNESS_N_M, bearing=BEARING_STIFFNESS_N_M):
    """Shaft, nut and bearing stiffness in series, N/m (a shaft of unknown
    size: inf, the nut and bearing alone)."""
    return 1.0 / (1.0 / np.asarray(shaft, float) + 1.0 / np.asarray(nut) + 1.0 / np.asarray(bearing))


def back_drives(back_efficiency) -> np.ndarray:
    """True where a load turns the screw backwards (reverse efficiency > 0):
    it holds only while the motor (or a brake) holds it."""
    return np.asarray(back_efficiency) > 0.0
