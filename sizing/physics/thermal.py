"""The thermal budget of a sealed piezohydraulic actuator (docs/models.md,
"Thermal budget").

Heated from the fill temperature by dT, each part moves the output
(positive: the output extends). Geometry, from the stack base: base plate,
stacks (length L_s), wide piston (thickness t_p), oil gap g, end cap; the
frame (tie rods, length L_f = L_s + t_p + g) ties the base plate to the
end cap. Terms:

- oil:        + V alpha_oil dT / A_n             (the enclosed oil grows)
- casing:     - 2 alpha_c V dT / A_n            (the bores widen; their
              axial growth is the frame's term, so only the radial 2 alpha)
- stacks:     + R alpha_s L_s dT                 (stacks push the wide piston)
- pistons:    + R alpha_p t_p dT + alpha_p L_n dT (wide piston thickness,
              narrow piston / push rod length)
- frame:      - R alpha_f L_f dT                 (the end cap moves away)
- compensator: minus whatever hydraulic volume an active compensator
              takes up (all of the oil, casing, stack, frame and wide piston
              terms when it has the capacity), else 0.

``net_m`` is the plain sum of the terms. The old one-term model
(V alpha_T dT / A_n) is ``oil_m``.
"""
from __future__ import annotations

import numpy as np

TERMS = ("oil_m", "casing_m", "stacks_m", "pistons_m", "frame_m", "compensator_m")


def oil_volume(wide_area, narrow_area, wide_gap, stroke):
    """Enclosed oil volume (m^3): wide chamber plus the narrow bore."""
    return np.asarray(wide_area) * np.asarray(wide_gap) + np.asarray(narrow_area) * np.asarray(stroke)


def output_drift(oil_volume_m3, thermal_expansion, delta_T, narrow_area):
    """Output displacement from heating the enclosed oil by delta_T (m)."""
    return np.asarray(oil_volume_m3) * np.asarray(thermal_expansion) * np.asarray(delta_T) / np.asarray(narrow_area)


def budget(delta_T, ratio, narrow_area, oil_volume_m3, oil_expansion, casing_expansion,
           stack_expansion, stack_length, frame_expansion, frame_length,
           piston_expansion, wide_piston_thickness, narrow_piston_length,
           compensated=False, compensator_capacity=np.inf):
    """Every term of the thermal budget (m) and ``net_m`` their sum, arrays
    over candidates. ``compensated``: an active compensator takes up the
    hydraulic volume change, up to ``compensator_capacity`` (m^3)."""
    dT, R, A_n = np.asarray(delta_T, float), np.asarray(ratio, float), np.asarray(narrow_area, float)
    V = np.asarray(oil_volume_m3, float)
    out = {
        "oil_m": V * np.asarray(oil_expansion) * dT / A_n,
        "casing_m": -2.0 * np.asarray(casing_expansion) * V * dT / A_n,
        "stacks_m": R * np.asarray(stack_expansion) * np.asarray(stack_length) * dT,
        "pistons_m": (R * np.asarray(piston_expansion) * np.asarray(wide_piston_thickness)
                      + np.asarray(piston_expansion) * np.asarray(narrow_piston_length)) * dT,
        "frame_m": -R * np.asarray(frame_expansion) * np.asarray(frame_length) * dT,
    }
    hydraulic = (out["oil_m"] + out["casing_m"] + out["stacks_m"] + out["frame_m"]
                 + R * np.asarray(piston_expansion) * np.asarray(wide_piston_thickness) * dT)
    volume = np.abs(hydraulic) * A_n
    taken = np.minimum(volume, np.asarray(compensator_capacity, float))
    share = np.divide(taken, volume, out=np.ones_like(volume), where=volume > 0)
    out["compensator_m"] = np.where(np.asarray(compensated, bool), -hydraulic * share, 0.0)
    out["net_m"] = sum(out[k] for k in TERMS)
    out["compensator_volume_m3"] = np.where(np.asarray(compensated, bool), volume, 0.0)
    return out


def passive_frame_length(delta_T, ratio, narrow_area, oil_volume_m3, oil_expansion, casing_expansion,
                         stack_expansion, stack_length, frame_expansion,
                         piston_expansion, wide_piston_thickness, narrow_piston_length):
    """Frame length (m) at which the budget's net is zero (passive
    compensation by frame material and length): every other term divided
    by R alpha_f dT. A result shorter than the parts it must span means the
    material cannot compensate."""
    other = budget(delta_T, ratio, narrow_area, oil_volume_m3, oil_expansion, casing_expansion,
                   stack_expansion, stack_length, frame_expansion, 0.0,
                   piston_expansion, wide_piston_thickness, narrow_piston_length)["net_m"]
    return other / (np.asarray(ratio) * np.asarray(frame_expansion) * np.asarray(delta_T))


def compensator_time_constant(wide_area, path_stiffness, leak_conductance):
    """tau = C_h / G of a compensator behind a restrictor, s: the chamber's
    hydraulic capacitance with the output held, C_h = A_w^2 / k (k the force
    path's stiffness at the wide piston, oil column included: the volume the
    chamber takes per pascal), over the restrictor's conductance G."""
    G = np.asarray(leak_conductance, float)
    C_h = np.asarray(wide_area, float) ** 2 / np.asarray(path_stiffness, float)
    return np.divide(C_h, G, out=np.full(np.broadcast(C_h, G).shape, np.inf), where=G > 0)


def compensated_share(time_constant, warm_up_time, hold_time):
    """Share of the thermal volume a first-order compensator (time constant
    tau) has taken up at the end of a hold t_h that follows a warm-up t_w
    during which the volume grew linearly: a ramp into a first-order lag
    leaves (tau / t_w) (1 - exp(-t_w / tau)) of it at the end of the ramp,
    which then decays as exp(-t_h / tau). 1 for an instant compensator
    (tau = 0), 0 for one that never acts (tau = inf)."""
    tau = np.asarray(time_constant, float)
    t_w, t_h = float(warm_up_time), float(hold_time)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        x = t_w / tau
        left = np.where(tau > 0, -np.expm1(-x) / x, 0.0) * np.exp(-t_h / tau)
    left = np.where(np.isinf(tau), 1.0, np.where(tau > 0, left, 0.0))
    return 1.0 - left
