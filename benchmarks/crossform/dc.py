"""Cross-form DC motor lead-screw servo (rotary state form, RK4).

State per run: motor angle th (rad), speed w (rad/s), LuGre bristle z (m),
load position yl and speed vl (m, backlash with contact stiffness), sensor
mount deflection q and rate dq (m). Plant: w' = c1 w + c2 (i_act - i_ext),
where i_ext is every output force referred to the motor current
(lead / (2 pi eta kt) A per N). The controller (PID, derivative on the
measurement, clamped integrator) samples the motor encoder (quantised) at
its rate and holds the current. Logged: the external sensor's position of
the load (through the mount and a Pade delay), the command current.
"""
from __future__ import annotations

import numpy as np

from .common import position_reading, rk4

NOMINAL = {"c1": -25.5552, "c2": 2987.02, "lead": 2e-3, "kt": 0.05, "eta": 0.9, "rate": 1250.0,
           "kp": 4000.0, "ki": 8000.0, "kd": 90.0, "i_max": 10.0, "F0": 0.0, "kL": 0.0}
SUBSTEPS = 8
ENCODER_LSB_M = 2e-3 / 4096          # 1024-line encoder, x4, on a 2 mm lead


def rig_toml(nom: dict) -> str:
    return f"""kind = "dc_motor"
notes = "cross-form generator (benchmarks/crossform): stated nominal"

[motor]
c1 = {nom['c1']:.6g}
c2 = {nom['c2']:.6g}
screw_lead = "{nom['lead'] * 1e3:.6g} mm"
torque_constant = "{nom['kt']:.6g} N*m/A"
screw_efficiency = {nom['eta']:.6g}

[controller]
rate = "{nom['rate']:.6g} Hz"
kp = {nom['kp']:.6g}
ki = {nom['ki']:.6g}
kd = {nom['kd']:.6g}
derivative_on = "measurement"
current_limit = "{nom['i_max']:.6g} A"

[load]
force = "{nom['F0']:.6g} N"
stiffness = "{nom['kL']:.6g} N/m"
"""


def excitations(stroke: float, fs: float = 1000.0, duration: float = 2.0) -> dict:
    """Reference runs of the same length: two staircases (own levels) and a
    smooth periodic move."""
    t = np.arange(0.0, duration, 1.0 / fs)

    def stairs(levels):
        levels = np.asarray(levels, float)
        return stroke * levels[np.minimum((t / (duration / len(levels))).astype(int), len(levels) - 1)]

    periodic = 0.25 * stroke * (1 - np.cos(2 * np.pi * 2.5 * t)) * np.minimum(t / 0.2, 1.0)
    return {"stairs_a": stairs([0, 0.8, 0.3, 0.9, 0.1, 0.55]), "wave": periodic,
            "stairs_b": stairs([0, 0.45, 1.0, 0.25, 0.75, 0.05])}, t


def lugre_g(v, fc, fs_, vs):
    return fc + (fs_ - fc) * np.exp(-(v / vs) ** 2)


def simulate(t: np.ndarray, R: np.ndarray, true: dict, effects: dict, rng):
    """Clean (load position, command current) for each reference row of R."""
    n_runs, n = R.shape
    Ts = 1.0 / true["rate"]
    dt = Ts / SUBSTEPS
    to_i = true["lead"] / (2 * np.pi * true["eta"] * true["kt"])     # A per N at the output
    th_to_x = true["lead"] / (2 * np.pi)
    fr = effects.get("friction")          # LuGre: fc, fs, vs, sigma0, sigma1, sigma2 (N, m/s, N/m, N s/m)
    bl = effects.get("backlash")          # gap_m, k_N_m, zeta, m_kg, c_ground (load damping to ground)
    mnt = effects.get("mount")            # f_Hz, zeta, gain
    cog = effects.get("cogging")          # amp_N, pitch_m
    pulses = effects.get("pulses")        # list of (t0, width, force)
    asym = effects.get("amp_asymmetry")   # gain of negative currents
    i_lim = effects.get("current_limit", true["i_max"])
    F0, kL = true["F0"], true["kL"]

    def ext_force(tt, x, v, z, dz):
        F = F0 + kL * x
        if fr:
            F = F + fr["sigma0"] * z + fr["sigma1"] * dz + fr["sigma2"] * v
        if cog:
            F = F + cog["amp_N"] * np.sin(2 * np.pi * x / cog["pitch_m"])
        if pulses:
            for t0, width, force in pulses:
                if t0 <= tt < t0 + width:
                    F = F + force
        return F

    def rhs(tt, s, i_act):
        th, w, z, yl, vl, q, dq = s
        x, v = th * th_to_x, w * th_to_x
        dz = np.zeros_like(z)
        if fr:
            dz = v - fr["sigma0"] * np.abs(v) * z / lugre_g(v, fr["fc"], fr["fs"], fr["vs"])
        F = ext_force(tt, x, v, z, dz)
        acc_load = np.zeros_like(x)
        if bl:
            d = x - yl
            half = 0.5 * bl["gap_m"]
            pen = np.where(d > half, d - half, np.where(d < -half, d + half, 0.0))
            contact = pen != 0
            c = 2 * bl["zeta"] * np.sqrt(bl["k_N_m"] * bl["m_kg"])
            Fc = np.where(contact, bl["k_N_m"] * pen + c * (v - vl), 0.0)
            F = F + Fc
            acc_load = (Fc - bl["c_ground"] * vl) / bl["m_kg"]
        dw = true["c1"] * w + true["c2"] * (i_act - F * to_i)
        a_out = acc_load if bl else dw * th_to_x
        dvl = acc_load
        ddq = np.zeros_like(q)
        if mnt:
            om = 2 * np.pi * mnt["f_Hz"]
            ddq = -2 * mnt["zeta"] * om * dq - om * om * q - mnt["gain"] * a_out
        return np.array([w, dw, dz, vl if bl else v, dvl, dq, ddq])

    s = np.zeros((7, n_runs))
    integ = F0 * to_i / true["ki"] if true["ki"] else 0.0
    integ = np.full(n_runs, integ)
    i_cmd = true["ki"] * integ
    y_prev = np.zeros(n_runs)
    t_fine, Y, I = [0.0], [s[3].copy() + s[5]], [i_cmd.copy()]
    tt = 0.0
    n_ticks = int(np.ceil(t[-1] / Ts)) + 1
    for _ in range(n_ticks):
        i_act = np.clip(i_cmd, -i_lim, i_lim)
        if asym is not None:
            i_act = np.where(i_act < 0, asym * i_act, i_act)
        for _k in range(SUBSTEPS):
            s = rk4(lambda a, b: rhs(a, b, i_act), tt, s, dt)
            if fr:   # bristles: the exact relaxation for the step's speed (stable for stiff sigma0)
                v = s[1] * th_to_x
                g = lugre_g(v, fr["fc"], fr["fs"], fr["vs"])
                zss = g * np.sign(v) / fr["sigma0"]
                s[2] = np.where(v != 0, zss + (s[2] - zss) * np.exp(-fr["sigma0"] * np.abs(v) * dt / g), s[2])
            tt += dt
            t_fine.append(tt)
            Y.append((s[3] if bl else s[0] * th_to_x) + s[5])
            I.append(i_cmd.copy())
        # controller tick
        y_enc = np.round(s[0] * th_to_x / ENCODER_LSB_M) * ENCODER_LSB_M
        r = np.array([np.interp(tt, t, R[k]) for k in range(n_runs)])
        err = r - y_enc
        deriv = -(y_enc - y_prev) / Ts
        i_try = true["kp"] * err + true["ki"] * (integ + err * Ts) + true["kd"] * deriv
        grow = (np.abs(i_try) < true["i_max"]) | (i_try * err < 0)
        integ = np.where(grow, integ + err * Ts, integ)
        i_cmd = np.clip(true["kp"] * err + true["ki"] * integ + true["kd"] * deriv, -true["i_max"], true["i_max"])
        y_prev = y_enc
    t_fine = np.array(t_fine)
    Y, I = np.array(Y), np.array(I)
    ys = np.array([np.interp(t, t_fine, Y[:, k]) for k in range(n_runs)])
    # the logged current is the command held over each period: sample it, not interpolate
    idx = np.clip(np.searchsorted(t_fine, t, side="right") - 1, 0, len(t_fine) - 1)
    cur = I[idx].T
    return ys, cur


def campaign(effects: dict, seed: int, stroke: float = 0.01, misstate: float = 0.03, load: float = 0.0,
             sensor: dict | None = None, current_noise_A: float = 0.01):
    """(rig.toml text, {run: columns}) of a DC campaign with ``effects``
    and a nominal stated ``misstate`` off the truth (c1, c2)."""
    rng = np.random.default_rng(seed)
    nom = dict(NOMINAL, F0=load)
    true = dict(nom)
    true["c1"] = nom["c1"] * (1 + misstate * rng.choice([-1, 1]))
    true["c2"] = nom["c2"] * (1 + misstate * rng.choice([-1, 1]))
    refs, t = excitations(stroke)
    names = list(refs)
    R = np.vstack([refs[k] for k in names])
    ys, cur = simulate(t, R, true, effects, rng)
    sensor = sensor or {}
    runs = {}
    for k, name in enumerate(names):
        ym = position_reading(t, ys[k], effects, rng, sensor, 1e-6, lambda tt: 1 - np.exp(-tt / 3.0))
        runs[name] = {"time_s": t, "reference_m": R[k], "position_m": ym,
                      "current_A": cur[k] + current_noise_A * rng.normal(size=t.size)}
    return rig_toml(nom), runs
