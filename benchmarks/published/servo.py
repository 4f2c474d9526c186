"""A unit mass with LuGre friction under a sampled PID: the servo example
of Canudas de Wit, Olsson, Astrom and Lischinsky, "A new model for control
of systems with friction", IEEE Trans. Autom. Control 40(3) (1995)
419-425, with the friction parameters of its Table I and the PID of its
limit-cycle example (the values as used in the reconstruction of the
paper's figures, github.com/auralius/LuGre, demo1.m):

    M x'' = u - F,  M = 1 kg
    F = sigma0 z + sigma1 z' + sigma2 v,   z' = v - sigma0 |v| z / g(v)
    g(v) = Fc + (Fs - Fc) exp(-(v / vs)^2)
    u = -Kv v - Kp e - Ki int e,  e = x - x_d

Table I: sigma0 = 1e5 N/m, sigma1 = sqrt(1e5) N s/m, sigma2 = 0.4 N s/m,
Fc = 1 N, Fs = 1.5 N, vs = 0.001 m/s; PID: Kp = 3, Ki = 4, Kv = 6.

The PID is sampled at 1 kHz and held (zero-order hold), its velocity the
difference of the sampled position, its integral the sum of the sampled
errors up to and including the current one. Integration: the bristle state z is
advanced exactly for the velocity held over each substep (z relaxes to
g(v) sgn(v) / sigma0 at rate sigma0 |v| / g(v): an exponential step that
stays stable however fast the mass slides), the mass by semi-implicit
Euler, SUBSTEPS per control period.

As a sizing rig it is a DC lead-screw servo whose current is the force:
(lead / 2 pi) c2 = 1 / M and kt = lead / (2 pi eta), so 1 A of command
accelerates the mass at 1 m/s^2 and 1 N of friction is 1 A.
"""
from __future__ import annotations

import numpy as np

TABLE_I = dict(sigma0=1e5, sigma1=float(np.sqrt(1e5)), sigma2=0.4, fc=1.0, fs=1.5, vs=0.001)
PID = dict(kp=3.0, ki=4.0, kv=6.0)
MASS = 1.0
RATE = 1000.0
SUBSTEPS = 20
LEAD = 2e-3
ETA = 0.9


def rig_toml() -> str:
    c2 = 2 * np.pi / LEAD / MASS
    kt = LEAD / (2 * np.pi * ETA)
    return f"""kind = "dc_motor"
notes = "unit mass under the PID of Canudas de Wit et al. 1995 (benchmarks/published)"

[motor]
c1 = -0.001
c2 = {c2:.9g}
screw_lead = "{LEAD * 1e3:g} mm"
torque_constant = "{kt:.9g} N*m/A"
screw_efficiency = {ETA:g}

[controller]
rate = "{RATE:g} Hz"
kp = {PID['kp']:g}
ki = {PID['ki']:g}
kd = {PID['kv']:g}
derivative_on = "measurement"
current_limit = "1000 A"

[load]
force = "0 N"
stiffness = "0 N/m"
"""


def simulate(t: np.ndarray, xd: np.ndarray, friction: dict | None) -> tuple[np.ndarray, np.ndarray]:
    """(position, command) at the log times t of a run with set-point xd
    (the log's sample rate is a divisor of RATE)."""
    Ts = 1.0 / RATE
    h = Ts / SUBSTEPS
    n_ctrl = int(round((t[-1] - t[0]) * RATE)) + 1
    tc = t[0] + Ts * np.arange(n_ctrl)
    ref = xd[np.minimum(np.searchsorted(t, tc + 1e-12, side="right") - 1, len(t) - 1)]
    x = v = z = integral = 0.0
    x_prev = 0.0
    X, U = np.empty(n_ctrl), np.empty(n_ctrl)
    for k in range(n_ctrl):
        e = x - ref[k]
        integral += e * Ts
        u = -PID["kv"] * (x - x_prev) / Ts - PID["kp"] * e - PID["ki"] * integral
        X[k], U[k] = x, u
        x_prev = x
        for _ in range(SUBSTEPS):
            F = 0.0
            if friction:
                g = friction["fc"] + (friction["fs"] - friction["fc"]) * np.exp(-(v / friction["vs"]) ** 2)
                rate = friction["sigma0"] * abs(v) / g
                z_ss = v / rate if rate > 0 else z
                z_new = z_ss + (z - z_ss) * np.exp(-rate * h) if rate > 0 else z + v * h
                dz = (z_new - z) / h
                z = z_new
                F = friction["sigma0"] * z + friction["sigma1"] * dz + friction["sigma2"] * v
            v += h * (u - F) / MASS
            x += h * v
    return np.interp(t, tc, X), np.interp(t, tc, U)
