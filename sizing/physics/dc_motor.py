"""Brushless DC motor lead-screw actuator (seed section 3, eqs. 11-14).

    J w' + lambda w = k_t i                                       (11)
    v' = c1 v + (l / 2 pi) c2 (i - i_load)                        (13, + load)

c1 = -lambda/J (1/s), c2 = k_t/J (rad/(s^2 A)). The seed has no load term;
docs/models.md adds i_load = F l / (2 pi eta k_t), the current that balances a
force F on the output through a screw of lead l and efficiency eta.
Eq. 14 is the exact zero-order-hold discretisation of eq. 13.
"""
from __future__ import annotations

import numpy as np


def zoh_coefficients(c1, c2, lead, dt):
    """(a, b, a_y, b_y) such that over one hold interval dt with constant
    current u: v+ = a v + b u (eq. 14) and y+ = y + a_y v + b_y u."""
    c1 = np.asarray(c1, float)
    g = np.asarray(lead) / (2 * np.pi) * np.asarray(c2)
    a = np.exp(c1 * dt)
    phi = np.where(c1 != 0.0, (a - 1.0) / np.where(c1 != 0.0, c1, 1.0), dt)   # int_0^dt e^{c1 s} ds
    b = phi * g
    a_y = phi
    psi = np.where(c1 != 0.0, (phi - dt) / np.where(c1 != 0.0, c1, 1.0), dt**2 / 2)  # int_0^dt phi(s) ds
    b_y = psi * g
    return a, b, a_y, b_y


def load_current(force, lead, efficiency, torque_constant):
    """Motor current that holds an output force F (A)."""
    return np.asarray(force) * np.asarray(lead) / (2 * np.pi * np.asarray(efficiency) * np.asarray(torque_constant))


def max_force(current_limit, lead, efficiency, torque_constant):
    """Output force at the current limit (N)."""
    return 2 * np.pi * np.asarray(efficiency) * np.asarray(torque_constant) * np.asarray(current_limit) / np.asarray(lead)


def steady_speed(current, c1, c2, lead):
    """Speed at which eq. 13 settles for a constant net current (m/s)."""
    return -np.asarray(lead) / (2 * np.pi) * np.asarray(c2) * np.asarray(current) / np.asarray(c1)
