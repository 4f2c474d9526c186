"""Cross-form piezohydraulic actuator (pressure state form, RK4).

State per run: amplifier voltage va (V), Bouc-Wen state h (m), creep modes
c_1..c_4 (m), oil pressure p (Pa), wide piston x (m), output y (m) and its
speed u (m/s). The oil pressure is a state: p' = beta(p) / V0 (A_w x' -
A_n u - Q(p)); the wide piston is massless, so while it slides x' = xf' -
A_w p' / K, and while its seal sticks x' = 0. The output seal is LuGre
(bristles relaxed exactly each step, operator splitting); its nominal form
has no Stribeck rise (Fs = Fc). Creep: four modes at time constants a
decade apart with equal weights, the sum-of-exponentials form of the
logarithmic creep of PZT. Entrained air: 1 / beta(p) = (1 - eps) / beta_oil
+ eps / (kappa p_abs) with eps = eps0 (p_atm / p_abs)^(1/kappa).
"""
from __future__ import annotations

import numpy as np

from .common import measure, position_reading, rk4

IN = 0.0254
NOMINAL = {"count": 3, "k_stack": 1.96e7, "d33": 8.15e-7, "alpha": -2.23e-7, "beta": 0.134, "gamma": 0.0755,
           "delta": -5.46e-8, "n": 1.14, "wide_d": 3.75 * IN, "narrow_d": 0.375 * IN, "m_wide": 0.30,
           "m_narrow": 0.02, "rho": 870.0, "k_loss": 0.5, "Fw": 10.0, "Fn": 0.2, "F0": 0.0, "kL": 0.0,
           "bulk": 1.5e9, "gap": 3e-3, "narrow_len": 0.02}
CREEP_TAUS = (0.01, 0.1, 1.0, 10.0)
P_ATM = 1.0e5
DT = 1e-4
EVENT_SUBSTEPS = 25     # a step in which the wide seal sticks or breaks away is redone this finely


def rig_toml(nom: dict) -> str:
    return f"""kind = "piezohydraulic"
notes = "cross-form generator (benchmarks/crossform): stated nominal"

[stack]
count = {nom['count']}
stiffness = "{nom['k_stack']:.6g} N/m"
d33 = "{nom['d33']:.6g} m/V"

[stack.bouc_wen]
alpha = {nom['alpha']:.6g}
beta = {nom['beta']:.6g}
gamma = {nom['gamma']:.6g}
delta = {nom['delta']:.6g}
n = {nom['n']:.6g}

[hydraulics]
wide_diameter = "{nom['wide_d'] / IN:.6g} in"
narrow_diameter = "{nom['narrow_d'] / IN:.6g} in"
wide_piston_mass = "{nom['m_wide']:.6g} kg"
narrow_piston_mass = "{nom['m_narrow']:.6g} kg"
fluid_density = "{nom['rho']:.6g} kg/m^3"
loss_coefficient = {nom['k_loss']:.6g}

[seals]
wide_friction = "{nom['Fw']:.6g} N"
narrow_friction = "{nom['Fn']:.6g} N"

[load]
force = "{nom['F0']:.6g} N"
stiffness = "{nom['kL']:.6g} N/m"
"""


def excitations(v_max: float, fs: float = 1000.0, duration: float = 2.0) -> tuple[dict, np.ndarray]:
    """A trapezoid up and down (own corners) and two staircases (own levels)."""
    t = np.arange(0.0, duration, 1.0 / fs)
    trap = v_max * np.interp(t, [0, 0.15, 0.85, 1.05, 1.65, duration], [0, 0, 1, 1, 0, 0])

    def stairs(levels):      # steps commanded as 40 ms ramps (a test amplifier's rate limit)
        levels = np.asarray(levels, float)
        edges = np.arange(len(levels)) * duration / len(levels)
        knots_t = np.ravel([[e, e + 0.04] for e in edges[1:]])
        knots_v = np.ravel([[a, b] for a, b in zip(levels[:-1], levels[1:])])
        return v_max * np.interp(t, np.r_[0.0, knots_t], np.r_[levels[0], knots_v])

    return {"trapezoid": trap, "stairs_a": stairs([0, 0.4, 0.9, 0.6, 0.1, 0.75, 0.3, 0.0]),
            "stairs_b": stairs([0, 0.65, 0.25, 1.0, 0.45, 0.85, 0.1, 0.5])}, t


def simulate(t: np.ndarray, V: np.ndarray, tr: dict, eff: dict) -> np.ndarray:
    """Clean output position (from rest) of each voltage row of V."""
    n_runs = V.shape[0]
    A_w, A_n = np.pi * tr["wide_d"] ** 2 / 4, np.pi * tr["narrow_d"] ** 2 / 4
    Rr = A_w / A_n
    V0 = A_w * tr["gap"] + A_n * tr["narrow_len"]
    K = tr["count"] * tr["k_stack"]
    bern = 1 - 1 / Rr ** 2
    k_exp = (1 - 1 / Rr) ** 2
    fr = eff.get("seal", {"fc": tr["Fn"], "fs": tr["Fn"], "vs": 1e-3, "sigma2": 0.0})
    sig0 = fr["fs"] / 1e-5 if fr["fs"] > 0 else 0.0          # 10 um presliding
    sig1 = np.sqrt(sig0 * tr["m_narrow"]) if sig0 > 0 else 0.0
    air = eff.get("air")             # eps0 (volume fraction at 1 atm), kappa
    leak = eff.get("leak")           # laminar G (m^3/(s Pa)), orifice area_m2, cd
    creep = eff.get("creep", 0.0)    # weight per creep mode (fraction of the free stroke)
    bw = eff.get("bandwidth")        # omega_rad_s, slew_V_s
    visc = eff.get("viscous", 0.0)
    gain_asym = eff.get("amp_compression", 0.0)
    pulses = eff.get("pulses", [])
    slope = np.diff(V, axis=1) / np.diff(t)[None, :]

    def beta_e(p):
        if not air:
            return tr["bulk"]
        pa = np.maximum(p + P_ATM, 0.2 * P_ATM)
        eps = air["eps0"] * (P_ATM / pa) ** (1 / air["kappa"])
        return 1.0 / ((1 - eps) / tr["bulk"] + eps / (air["kappa"] * pa))

    def flow_leak(p):
        if not leak:
            return 0.0
        return leak.get("G", 0.0) * p + leak.get("cd", 0.6) * leak.get("area_m2", 0.0) * np.sign(p) * np.sqrt(2 * np.abs(p) / tr["rho"])

    def vcmd(tt):
        k = min(int(tt * 1000.0 + 1e-9), t.size - 2)
        w = (tt - t[k]) / (t[k + 1] - t[k])
        return V[:, k] * (1 - w) + V[:, k + 1] * w, slope[:, k]

    def amp(v_lin):
        return v_lin * (1 - gain_asym * v_lin / 150.0)

    def rhs(tt, s, stuck, z):
        va, h, c, p, x, y, u = s[0], s[1], s[2:6], s[6], s[7], s[8], s[9]
        vc, dvc = vcmd(tt)
        if bw:
            dva = np.clip(bw["omega"] * (amp(vc) - va), -bw["slew"], bw["slew"])
        else:
            dva = dvc * (1 - 2 * gain_asym * vc / 150.0)
        sv = np.sign(dva)
        dh = (tr["alpha"] - (tr["beta"] * np.sign(dva * h) + tr["gamma"]) * np.abs(h) ** tr["n"]) * dva + tr["delta"] * va * sv
        xf0 = tr["d33"] * va + h
        dc = (creep * xf0[None, :] - c) / np.array(CREEP_TAUS)[:, None]
        dxf = tr["d33"] * dva + dh + dc.sum(axis=0)
        be = beta_e(p)
        Q = flow_leak(p)
        slide = (be / V0) * (A_w * dxf - A_n * u - Q) / (1 + be * A_w ** 2 / (V0 * K))
        dp = np.where(stuck, (be / V0) * (-A_n * u - Q), slide)
        dx = np.where(stuck, 0.0, dxf - A_w * dp / K)
        loss = 0.5 * tr["rho"] * u * np.abs(u) * (bern + np.where(u >= 0, tr["k_loss"], k_exp))
        F_load = tr["F0"] + tr["kL"] * y + sum(f for t0, w, f in pulses if t0 <= tt < t0 + w)
        g = fr["fc"] + (fr["fs"] - fr["fc"]) * np.exp(-(u / fr["vs"]) ** 2)
        dz = u - sig0 * np.abs(u) * z / np.maximum(g, 1e-12) if sig0 > 0 else 0.0
        F_fr = sig0 * z + sig1 * dz + fr.get("sigma2", 0.0) * u
        du = (A_n * (p - loss) - F_load - F_fr - visc * u) / tr["m_narrow"]
        return np.vstack([dva, dh, dc, dp, dx, u, du])

    def decide(s, direction):
        """The wide seal at the start of a step: (direction, state with the
        sliding piston on its friction limit)."""
        if tr["Fw"] <= 0:
            return direction, s
        xf = tr["d33"] * s[0] + s[1] + s[2:6].sum(axis=0)
        N = K * (xf - s[7]) - A_w * s[6]
        free = rhs(tt, s, np.zeros(n_runs, bool), z)[7]
        release = (direction == 0) & (np.abs(N) > tr["Fw"])
        direction = np.where(release, np.sign(N), direction)
        direction = np.where((direction != 0) & ~release & (direction * free < 0), 0.0, direction)
        s = s.copy()
        s[7] = np.where(direction == 0, s[7], xf - (A_w * s[6] + direction * tr["Fw"]) / K)
        return direction, s

    def advance(s, z, direction, h):
        """One RK4 step of length h with the seal decided at its start."""
        s = rk4(lambda a, b: rhs(a, b, direction == 0, z), tt, s, h)
        u = s[9]
        if sig0 > 0:
            g = fr["fc"] + (fr["fs"] - fr["fc"]) * np.exp(-(u / fr["vs"]) ** 2)
            zss = g * np.sign(u) / sig0
            z = np.where(u != 0, zss + (z - zss) * np.exp(-sig0 * np.abs(u) * h / g), z)
        return s, z

    # rest: no load, no friction, everything at zero (the runs start at 0 V)
    s = np.zeros((10, n_runs))
    p_rest = tr["F0"] / A_n
    s[6] = p_rest
    s[7] = -A_w * p_rest / K
    z = np.zeros(n_runs)
    n_sub = int(round((t[1] - t[0]) / DT))
    out = np.empty((n_runs, t.size))
    y0 = s[8].copy()
    out[:, 0] = 0.0
    tt = 0.0
    direction = np.zeros(n_runs)            # sliding direction of the wide piston (0: stuck)
    for k in range(1, t.size):
        for _ in range(n_sub):
            direction, s = decide(s, direction)
            s1, z1 = advance(s, z, direction, DT)
            if np.any(decide(s1, direction)[0] != direction):
                # the wide seal sticks or breaks away inside this step: redone
                # in EVENT_SUBSTEPS steps, so the instant it does is resolved
                # to DT / EVENT_SUBSTEPS (deciding once per DT left a first-
                # order error that piled up over a staircase's holds: 0.3-0.4 %
                # of the span against DT / 4)
                t_step, h = tt, DT / EVENT_SUBSTEPS
                for j in range(EVENT_SUBSTEPS):
                    tt = t_step + j * h
                    direction, s = decide(s, direction)
                    s, z = advance(s, z, direction, h)
                tt = t_step
            else:
                s, z = s1, z1
            tt += DT
        out[:, k] = s[8] - y0
    return out


def campaign(effects: dict, seed: int, v_max: float = 150.0, misstate: float = 0.03, load=(0.0, 0.0),
             n_stacks: int = 3, wide_in: float = 3.75, sensor: dict | None = None):
    """(rig.toml text, {run: columns}) of a piezo campaign with ``effects``;
    d33, the stack stiffness and the seal friction are stated ``misstate`` off."""
    rng = np.random.default_rng(seed)
    nom = dict(NOMINAL, F0=load[0], kL=load[1], count=n_stacks, wide_d=wide_in * IN)
    tr = dict(nom)
    for key in ("d33", "k_stack", "bulk"):
        tr[key] = nom[key] * (1 + misstate * rng.uniform(-1, 1))
    tr["Fw"] = nom["Fw"] * (1 + 5 * misstate * rng.uniform(-1, 1))
    refs, t = excitations(v_max)
    names = list(refs)
    V = np.vstack([refs[k] for k in names])
    ys = simulate(t, V, tr, effects)
    sensor = sensor or {}
    runs = {}
    for k, name in enumerate(names):
        ym = position_reading(t, ys[k], effects, rng, sensor, 0.5e-6, lambda tt: tt / tt[-1])
        vm = measure(V[k], rng, sensor.get("volt_white", 0.3), 0.05, 0.01)
        runs[name] = {"time_s": t, "voltage_V": vm, "position_m": ym}
    return rig_toml(nom), runs
