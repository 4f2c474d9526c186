"""Dynamic simulation of the piezohydraulic actuator, many candidates at once.

Model (seed eqs. 1-10 with the corrections of docs/models.md):
- stacks: non-symmetric Bouc-Wen free displacement (eqs. 1-2) behind the
  stack stiffness (eq. 3), optionally with first-order creep and one-sided
  contact (no return mechanism: stacks push but cannot pull);
- wide piston: its mass is negligible against the output mass reflected by
  R^2 (docs/models.md), so it is quasi-static: it sits where the stack force,
  the oil pressure and its seal friction balance. With friction this is a
  play (stick band) solved exactly each step, so it cannot chatter;
- oil: a linear spring p = beta (A_w x - A_n y - V_leak) / V0 (fluid
  compliance), with optional leakage V_leak' = G p;
- narrow (output) piston: a mass with the flow loss of eqs. 8-9 written
  u|u| and direction-aware (docs/models.md, corrections to the seed, item 5), viscous damping, Karnopp
  stick-slip seal friction (breakaway > running) whose running value grows
  with the chamber pressure, F = F_0 + c_p |p| (pressure-dependent Karnopp
  friction; both seals), and the load
  F_load = F0 + k_L y.

Integration: semi-implicit Euler at a fixed step chosen per candidate from
its fastest mode (dt <= 0.2 / omega_max). A velocity that would change sign
inside a step under friction is set to zero and the piston sticks, which is
what keeps stick-slip free of chattering. The initial state is the static
equilibrium under the load with zero friction; positions are reported from
that rest point (docs/formats.md, "Test campaigns"). Candidates of one
batch with the same drive (amplifier, Bouc-Wen loop, step and voltage:
``DRIVE``) share its integration, done once for them: a diagnosis screens
a seal or a leak at dozens of points with the stacks unchanged.
"""
from __future__ import annotations

from dataclasses import dataclass

import numba
import numpy as np

from ..errors import SimulationError
from . import PARALLEL_LAUNCH
from .params import StackParameters
from ..physics.bouc_wen import hysteresis_step

# Parameter columns of the matrix handed to the compiled kernel.
PARAMS = (
    "k_stacks", "d33", "alpha", "beta", "gamma", "delta", "n_bw", "h0",
    "wide_area", "narrow_area", "oil_volume", "bulk_modulus", "narrow_mass",
    "density", "k_contract", "k_expand",
    "wide_friction", "narrow_friction", "wide_breakaway", "narrow_breakaway",
    "load_force", "load_stiffness", "viscous_damping", "leak_conductance",
    "creep_fraction", "creep_time", "slew_rate", "no_return", "dt_max",
    "wide_friction_pressure", "narrow_friction_pressure",
    "narrow_stribeck_velocity", "log_creep", "log_creep_time", "air_fraction", "air_polytropic",
    "leak_orifice_area", "amp_bandwidth", "narrow_presliding", "hold_rate",
)
IDX = {name: i for i, name in enumerate(PARAMS)}
CHANNELS = ("position_m", "pressure_Pa", "wide_position_m", "voltage_V")


@dataclass
class PiezoHydraulicModel(StackParameters):
    """Parameters of the dynamic model, each a float or an array (n_cand,):
    the stacks' (StackParameters), then the hydraulics and the load.

    SI throughout: N/m, m/V, m^2, m^3, Pa, kg, kg/m^3, N, N s/m, m^3/(s Pa),
    s, V/s. Breakaway fields are ratios static/running friction (>= 1).
    ``slew_rate`` <= 0 means unlimited; ``creep_time`` <= 0 means no creep.
    """

    PARAMS = PARAMS  # the kernel's column order

    wide_area: object
    narrow_area: object
    oil_volume: object
    bulk_modulus: object
    narrow_mass: object
    density: object = 870.0
    k_contract: object = 0.5
    k_expand: object = 1.0
    wide_friction: object = 0.0
    narrow_friction: object = 0.0
    wide_breakaway: object = 1.0
    narrow_breakaway: object = 1.0
    load_force: object = 0.0
    load_stiffness: object = 0.0
    viscous_damping: object = 0.0
    leak_conductance: object = 0.0
    creep_fraction: object = 0.0
    creep_time: object = 0.0
    slew_rate: object = 0.0
    no_return: object = 0.0
    h0: object = 0.0
    dt_max: object = 5e-5
    wide_friction_pressure: object = 0.0     # N/Pa: running friction grows with |p| (seals at pressure)
    narrow_friction_pressure: object = 0.0
    # Further forms of the diagnosis effects; each is off at its default,
    # and then the kernel runs the nominal path unchanged.
    narrow_stribeck_velocity: object = 0.0   # m/s: Stribeck rise of the output seal (0: Karnopp)
    log_creep: object = 0.0                  # creep per decade of time, fraction of the free stroke
    log_creep_time: object = 0.01            # s: shortest of the LOG_CREEP_MODES modes a decade apart
    air_fraction: object = 0.0               # entrained air, volume fraction at atmospheric pressure
    air_polytropic: object = 1.4             # polytropic index of the entrained air (1: isothermal)
    leak_orifice_area: object = 0.0          # m^2: discharge coefficient x area of an orifice leak
    amp_bandwidth: object = 0.0              # rad/s: first-order amplifier bandwidth (0: unlimited)
    narrow_presliding: object = 0.0          # m: LuGre output seal, bristle deflection at breakaway (0: Karnopp)
    # V/s: the voltage is held (sgn(dV/dt) = 0 in the Bouc-Wen delta term)
    # while it moves slower than this; 0: the exact sign (physics/bouc_wen.py)
    hold_rate: object = 0.0


STEP_FACTOR = 0.2   # dt * omega_max: ~30 steps per period of the fastest mode
LUGRE_STEP = 0.2    # dt * omega of the oil + bristle mode of a LuGre output seal
LUGRE_SUBSTEP = 0.1   # dt * omega of the bristle mode alone, for the output piston's sub-steps


def stable_step(P: np.ndarray, step_factor: float = STEP_FACTOR) -> np.ndarray:
    """Per-candidate time step from the stiffest mode of the output piston
    (oil column with the wide piston stuck, plus the load spring)."""
    A_n = P[:, IDX["narrow_area"]]
    k_oil = P[:, IDX["bulk_modulus"]] * A_n**2 / P[:, IDX["oil_volume"]]
    k = k_oil + np.abs(P[:, IDX["load_stiffness"]])
    m = P[:, IDX["narrow_mass"]]
    omega = np.sqrt(k / m)
    dt = np.minimum(P[:, IDX["dt_max"]], step_factor / omega)
    # a LuGre output seal: its bristle spring sigma0 = F_s / z_pre in parallel
    # (the stick-slip cycle it takes part in needs a finer step than the
    # oil mode: LUGRE_STEP of the combined mode)
    pre = P[:, IDX["narrow_presliding"]]
    lugre = pre > 0
    if lugre.any():
        s0 = P[:, IDX["narrow_friction"]] * P[:, IDX["narrow_breakaway"]] / np.where(lugre, pre, 1.0)
        omega_b = np.sqrt((k + s0) / m)
        dt = np.where(lugre, np.minimum(dt, LUGRE_STEP * step_factor / STEP_FACTOR / omega_b), dt)
    # viscous damping is implicit in the Karnopp piston's step; the LuGre
    # output piston takes it explicitly, stable below dt = 2 m / c
    damping = P[:, IDX["viscous_damping"]]
    explicit = lugre & (damping > 0)
    dt = np.where(explicit, np.minimum(dt, 0.5 * m / np.maximum(damping, 1e-300)), dt)
    return dt


@numba.njit(cache=True, error_model="numpy")
def _equilibrium(K, xf, A_w, A_n, V0, bulk, F0, kL):
    """Static rest under the load, no friction: returns x, y, p. Solves
    K (xf - x) = p A_w, p = bulk (A_w x - A_n y) / V0, p A_n = F0 + kL y."""
    a = bulk / V0
    c = 1.0 + a * A_w * A_w / K
    det = -c * kL - a * A_n * A_n
    p = (-a * A_w * xf * kL - a * A_n * F0) / det
    y = (c * F0 - a * A_n * A_w * xf) / det
    return xf - A_w * p / K, y, p


P_ATM = 1.0e5         # Pa, absolute pressure of the oil at zero gauge (entrained air)
LOG_CREEP_MODES = 4   # creep modes a decade apart (log creep as a Prony series)


@numba.njit(cache=True, error_model="numpy")
def air_strain(p, eps0, kappa, bulk):
    """Volume strain s = -dV/V0 of oil carrying entrained air at gauge
    pressure p, and ds/dp: the oil at its bulk modulus plus a polytropic gas,
    s = (1 - eps0) p / bulk + eps0 (1 - (p_atm / p_abs)^(1/kappa)), so that
    1 / beta(p) = ds/dp = (1 - eps0) / bulk + eps(p) / (kappa p_abs) with
    eps(p) = eps0 (p_atm / p_abs)^(1/kappa) (Merritt 1967, sec. 2.3;
    Gholizadeh, Burton and Schoenau, Int. J. Fluid Power 15 (2014)). Below
    0.2 atm absolute the gas is held at that volume (no cavitation model)."""
    pa = p + P_ATM
    gas = True
    if pa < 0.2 * P_ATM:
        pa = 0.2 * P_ATM
        gas = False
    r = (P_ATM / pa) ** (1.0 / kappa)
    s = (1.0 - eps0) * p / bulk + eps0 * (1.0 - r)
    ds = (1.0 - eps0) / bulk
    if gas:
        ds += eps0 * r / (kappa * pa)
    return s, ds


@numba.njit(cache=True, error_model="numpy")
def _air_equilibrium(K, xf, A_w, A_n, V0, bulk, F0, kL, eps0, kappa):
    """Static rest with entrained air: _equilibrium at the secant bulk
    modulus p / s(p), iterated to its fixed point."""
    x, y, p = _equilibrium(K, xf, A_w, A_n, V0, bulk, F0, kL)
    for _ in range(60):
        s, ds = air_strain(p, eps0, kappa, bulk)
        sec = p / s if abs(p) > 1e-6 and s != 0.0 else 1.0 / ds
        x, y, p_new = _equilibrium(K, xf, A_w, A_n, V0, sec, F0, kL)
        if abs(p_new - p) <= 1e-9 * (abs(p) + 1.0):
            p = p_new
            break
        p = p_new
    return x, y, p


@numba.njit(cache=True, error_model="numpy")
def _interp(t, t_in, inv_dt, v_row, j):
    """Linear interpolation with a forward-moving index j (returns v, j);
    inv_dt[j] = 1 / (t_in[j+1] - t_in[j]), precomputed once."""
    n = t_in.shape[0]
    while j < n - 2 and t_in[j + 1] <= t:
        j += 1
    t0 = t_in[j]
    if t <= t0:
        return v_row[j], j
    if t >= t_in[j + 1]:
        return v_row[j + 1], j
    w = (t - t0) * inv_dt[j]
    return v_row[j] * (1.0 - w) + v_row[j + 1] * w, j


@numba.njit(cache=True, error_model="numpy")
def _wide_piston(x, xf, y, v_leak, K, aA_w, A_n, kf, inv_Kkf, inv_kf, F_run, thr, no_return):
    """Quasi-static wide piston with friction (play). Returns x, sliding.
    aA_w = bulk A_w / V0 and kf = bulk A_w^2 / V0 (reciprocals precomputed:
    this runs every step)."""
    c = aA_w * (A_n * y + v_leak)       # N(x) = K(xf-x)+ + c - kf x
    stack = K * (xf - x)
    if no_return > 0.5 and stack < 0.0:
        stack = 0.0
    N = stack + c - kf * x
    if abs(N) <= thr:
        return x, False
    target = F_run if N > 0.0 else -F_run
    x_new = (K * xf + c - target) * inv_Kkf
    if no_return > 0.5 and x_new > xf:
        x_new = (c - target) * inv_kf
    return x_new, True


@numba.njit(cache=True, error_model="numpy")
def _narrow_accel(F, u, F_run, F_static, inv_m):
    """Karnopp friction: acceleration of the output piston (0 when stuck)."""
    if u == 0.0:
        if abs(F) <= F_static:
            return 0.0
        return (F - (F_run if F > 0.0 else -F_run)) * inv_m
    return (F - (F_run if u > 0.0 else -F_run)) * inv_m


@numba.njit(cache=True, error_model="numpy")
def _narrow_accel_stribeck(F, u, F_run, F_static, inv_m, inv_vs):
    """Karnopp stick with a Stribeck curve while sliding: the friction falls
    from the breakaway F_static at rest to the running F_run as
    F_run + (F_static - F_run) exp(-(u / v_s)^2) (Armstrong-Helouvry,
    Dupont and Canudas de Wit, Automatica 30 (1994) 1083)."""
    if u == 0.0:
        if abs(F) <= F_static:
            return 0.0
        return (F - (F_static if F > 0.0 else -F_static)) * inv_m
    w = u * inv_vs
    Ff = F_run + (F_static - F_run) * np.exp(-w * w)
    return (F - (Ff if u > 0.0 else -Ff)) * inv_m


@numba.njit(cache=True, error_model="numpy")
def _lugre_constants(F_s, z_pre, m, dt):
    """Bristle stiffness sigma0 = F_s / z_pre, bristle damping sigma1 =
    sqrt(sigma0 m) and the denominator m + dt sigma1 + dt^2 sigma0 of
    ``_lugre_step``'s speed, fixed over a step's sub-steps."""
    s0 = F_s / z_pre
    s1 = np.sqrt(s0 * m)
    return s0, s1, m + dt * s1 + dt * dt * s0


@numba.njit(cache=True, error_model="numpy")
def _lugre_g(u, F_c, F_s, inv_vs):
    """The LuGre seal's steady friction at speed u, g(u) = F_c + (F_s - F_c)
    exp(-(u / v_s)^2) (F_c when v_s is 0), at least 1e-12 N."""
    w = u * inv_vs
    g = F_c + (F_s - F_c) * np.exp(-w * w) if inv_vs > 0.0 else F_c
    return max(g, 1e-12)


@numba.njit(cache=True, error_model="numpy")
def _lugre_step(F, u, z, g, s0, s1, den, F_c, F_s, inv_vs, m, dt):
    """One step of the output piston with a LuGre seal (Canudas de Wit,
    Olsson, Astrom and Lischinsky, IEEE TAC 40 (1995) 419): friction
    sigma0 z + sigma1 z', z' = u - sigma0 |u| z / g(u), g(u) = F_c + (F_s -
    F_c) exp(-(u / v_s)^2); bristle stiffness sigma0 = F_s / z_pre (z_pre:
    the presliding deflection at breakaway), bristle damping sigma1 =
    sqrt(sigma0 m) (damping ratio 1/2 of the bristle mode). The speed is
    advanced semi-implicitly (bristle damping implicit), then the bristle
    relaxes exactly towards its steady deflection at the new speed (the
    bristle spring and damping are implicit in the speed: stable at any step).
    ``g`` is g(u) (``_lugre_g``), s0, s1 and den from ``_lugre_constants``.
    Returns the new speed, bristle deflection and g at the new speed."""
    k = s0 * abs(u) / g
    # friction s0 z + s1 z' with z' = u - k z; the bristle spring and damping
    # taken implicitly in u (z -> z + u_new dt), so a stiff bristle (short
    # presliding) stays stable at the step of the hydraulics
    u_new = (m * u + dt * (F - s0 * z + s1 * k * z)) / den
    g = _lugre_g(u_new, F_c, F_s, inv_vs)
    if u_new != 0.0:
        zss = g / s0 * (1.0 if u_new > 0.0 else -1.0)
        z = zss + (z - zss) * np.exp(-s0 * abs(u_new) * dt / g)
    return u_new, z, g


# Parameters of the stacks' drive: the amplifier and the Bouc-Wen loop.
# With the voltage row and the step they fix the stack voltage and the
# hysteresis h at every step, which the stacks' gain, creep, oil, pistons,
# seals and load never feed back into.
DRIVE = ("alpha", "beta", "gamma", "delta", "n_bw", "h0", "slew_rate", "amp_bandwidth", "hold_rate")
DRIVE_COLS = [IDX[name] for name in DRIVE]
DRIVE_BYTES = 2 ** 27   # drive buffers of one kernel call (a larger batch runs in slices)
READ, INTEGRATE, KEEP = 0, 1, 2     # how a candidate comes by its drive (_simulate_one)


@numba.njit(cache=True, parallel=True, error_model="numpy", nogil=True)   # nogil: stages run in threads (sim/__init__.py)
def _simulate(P, dts, t_in, V_in, t_out, v_stride, drivers, driver_of, kept):
    """Candidate c shares the drive (stack voltage and hysteresis at each
    step) of candidate ``drivers[driver_of[c]]``: the drivers integrate it
    (the Bouc-Wen power is a third of a step), those of a drive shared
    (``kept[g]`` >= 0) keep it in row ``kept[g]``, the others read it."""
    n_cand = P.shape[0]
    n_out = t_out.shape[0]
    out = np.empty((n_cand, 4, n_out))
    inv_dt = 1.0 / (t_in[1:] - t_in[:-1])
    n_drv = drivers.shape[0]
    n_steps = 0
    for g in range(n_drv):
        if kept[g] >= 0:
            n_steps = max(n_steps, _n_steps(dts[drivers[g]], t_out))
    vh = np.empty((max(kept.max() + 1, 1), 2, n_steps + 1))
    for g in numba.prange(n_drv):
        c = drivers[g]
        mode = KEEP if kept[g] >= 0 else INTEGRATE
        _simulate_one(P[c], dts[c], t_in, inv_dt, V_in[c * v_stride], t_out, vh[max(kept[g], 0)], mode, out[c])
    for c in numba.prange(n_cand):
        g = driver_of[c]
        if drivers[g] != c:
            _simulate_one(P[c], dts[c], t_in, inv_dt, V_in[c * v_stride], t_out, vh[kept[g]], READ, out[c])
    return out


@numba.njit(cache=True, error_model="numpy")
def _n_steps(dt_max, t_out):
    """Steps of a run: ``_substeps`` of every sample interval."""
    n = 0
    for k in range(t_out.shape[0] - 1):
        n += _substeps(t_out[k + 1] - t_out[k], dt_max)
    return n


@numba.njit(cache=True, error_model="numpy")
def _substeps(span, dt_max):
    nsub = int(np.ceil(span / dt_max - 1e-9))
    return nsub if nsub >= 1 else 1


@numba.njit(cache=True, error_model="numpy")
def _simulate_one(p, dt_max, t_in, inv_dt, v_row, t_out, vh, mode, rec):
    """One candidate. ``mode`` INTEGRATE: integrate the stack voltage and
    hysteresis; KEEP: and keep them in vh (vh[0] voltage, vh[1] h; index 0
    at rest, then a value a step); READ: read them from vh, kept by a
    candidate of the same drive. The rest (creep, oil, pistons, seals,
    load) is the candidate's own."""
    K, d33, al, be, ga, de, nb, h = p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]
    A_w, A_n, V0, bulk, m = p[8], p[9], p[10], p[11], p[12]
    rho, k_con, k_exp = p[13], p[14], p[15]
    Fw, Fn, brk_w, brk_n = p[16], p[17], p[18], p[19]
    F0, kL, cv, G = p[20], p[21], p[22], p[23]
    kappa, tau, slew, no_ret = p[24], p[25], p[26], p[27]
    cpw, cpn = p[29], p[30]
    vs, lc, lc_t, eps0, kap, cdA, bw = p[31], p[32], p[33], p[34], p[35], p[36], p[37]
    zpre, hold = p[38], p[39]
    z_br = 0.0                           # LuGre bristle deflection of the output seal
    inv_vs = 1.0 / vs if vs > 0.0 else 0.0
    n_lc = LOG_CREEP_MODES if lc > 0.0 else 0
    logc = np.zeros(LOG_CREEP_MODES)
    inv_tl = np.empty(LOG_CREEP_MODES)
    for i in range(LOG_CREEP_MODES):
        inv_tl[i] = 1.0 / (lc_t * 10.0 ** i) if lc_t > 0.0 else 0.0
    Fw0, Fn0 = Fw, Fn
    R = A_w / A_n
    bern = 1.0 - 1.0 / (R * R)
    # constants of the step, so the loop multiplies instead of dividing
    a_oil = bulk / V0
    aA_w = a_oil * A_w
    kf = aA_w * A_w
    inv_Kkf, inv_kf, inv_m = 1.0 / (K + kf), 1.0 / kf, 1.0 / m
    inv_tau = 1.0 / tau if tau > 0.0 else 0.0
    loss_fwd, loss_back = 0.5 * rho * (bern + k_con), 0.5 * rho * (bern + k_exp)
    j = 0
    if mode == READ:
        v, h = vh[0, 0], vh[1, 0]
    else:
        v, j = _interp(t_out[0], t_in, inv_dt, v_row, j)
        if mode == KEEP:
            vh[0, 0], vh[1, 0] = v, h
    xf_lin = d33 * v + h
    creep = kappa * xf_lin
    xf_tot = xf_lin + creep
    for i in range(n_lc):
        logc[i] = lc * xf_lin
        xf_tot = xf_tot + logc[i]
    if eps0 > 0.0:
        x, y, pr = _air_equilibrium(K, xf_tot, A_w, A_n, V0, bulk, F0, kL, eps0, kap)
    else:
        x, y, pr = _equilibrium(K, xf_tot, A_w, A_n, V0, bulk, F0, kL)
    y0 = y
    u = 0.0
    v_leak = 0.0
    sliding = False
    s = 0
    t = t_out[0]
    rec[0, 0], rec[1, 0], rec[2, 0], rec[3, 0] = 0.0, pr, x, v
    for k in range(t_out.shape[0] - 1):
        nsub = _substeps(t_out[k + 1] - t, dt_max)
        dt = (t_out[k + 1] - t) / nsub
        amp = 1.0 - np.exp(-bw * dt) if bw > 0.0 else 0.0     # first-order amplifier, exact over the step
        for _ in range(nsub):
            s += 1
            if mode != READ:
                t += dt
                v_cmd, j = _interp(t, t_in, inv_dt, v_row, j)
                v_new = v_cmd
                if bw > 0.0:
                    v_new = v + (v_cmd - v) * amp
                if slew > 0.0:
                    step = slew * dt
                    v_new = min(max(v_new, v - step), v + step)
                h = hysteresis_step(h, v, v_new, dt, al, be, ga, de, nb, hold)
                v = v_new
                if mode == KEEP:
                    vh[0, s], vh[1, s] = v, h
            else:
                v, h = vh[0, s], vh[1, s]
            xf_lin = d33 * v + h
            if tau > 0.0:
                creep += dt * (kappa * xf_lin - creep) * inv_tau
            xf_tot = xf_lin + creep
            for i in range(n_lc):
                logc[i] += dt * (lc * xf_lin - logc[i]) * inv_tl[i]
                xf_tot = xf_tot + logc[i]
            v_leak += G * pr * dt
            if cdA > 0.0:                     # orifice leak, Q = Cd A sgn(p) sqrt(2 |p| / rho)
                v_leak += cdA * np.sqrt(2.0 * abs(pr) / rho) * (1.0 if pr >= 0.0 else -1.0) * dt
            v_eff = v_leak
            if eps0 > 0.0:                    # oil with air: tangent to s(p) at the last pressure
                s_p, ds_p = air_strain(pr, eps0, kap, bulk)
                a_oil = 1.0 / (ds_p * V0)
                aA_w = a_oil * A_w
                kf = aA_w * A_w
                inv_Kkf, inv_kf = 1.0 / (K + kf), 1.0 / kf
                v_eff = v_leak - (pr - s_p / ds_p) / a_oil     # p = a_oil (dV - v_eff)
            Fw = Fw0 + cpw * abs(pr)
            Fn = Fn0 + cpn * abs(pr)
            thr = Fw if sliding else Fw * brk_w
            x, sliding = _wide_piston(x, xf_tot, y, v_eff, K, aA_w, A_n, kf, inv_Kkf, inv_kf,
                                      Fw, thr, no_ret)
            pr = a_oil * (A_w * x - A_n * y - v_eff)
            p_n = pr - u * abs(u) * (loss_fwd if u >= 0.0 else loss_back)
            F = A_n * p_n - (F0 + kL * y) - cv * u
            if zpre > 0.0:                    # LuGre output seal (no stick logic: bristles)
                # the bristle mode sqrt(sigma0 / m) is often faster than the
                # hydraulics: the output piston takes sub-steps of at most
                # LUGRE_SUBSTEP / omega_bristle with the oil pressure following y
                F_s = Fn * brk_n
                n_br = int(dt * np.sqrt(F_s / zpre * inv_m) / LUGRE_SUBSTEP) + 1
                h_dt = dt / n_br
                s0, s1, den = _lugre_constants(F_s, zpre, m, h_dt)
                g_br = _lugre_g(u, Fn, F_s, inv_vs)
                for _ in range(n_br):
                    p_s = a_oil * (A_w * x - A_n * y - v_eff)
                    p_n = p_s - u * abs(u) * (loss_fwd if u >= 0.0 else loss_back)
                    F = A_n * p_n - (F0 + kL * y) - cv * u
                    u, z_br, g_br = _lugre_step(F, u, z_br, g_br, s0, s1, den, Fn, F_s, inv_vs, m, h_dt)
                    y += u * h_dt
                continue
            # viscous damping implicit in the new speed (stable at any step,
            # the overdamped limit F / c when dt c / m is large)
            F += cv * u
            if vs > 0.0:
                a = _narrow_accel_stribeck(F, u, Fn, Fn * brk_n, inv_m, inv_vs)
            else:
                a = _narrow_accel(F, u, Fn, Fn * brk_n, inv_m)
            u_new = (u + a * dt) / (1.0 + dt * cv * inv_m)
            if u != 0.0 and u_new * u < 0.0:
                u_new = 0.0
            u = u_new
            y += u * dt
        t = t_out[k + 1]
        rec[0, k + 1] = y - y0
        rec[1, k + 1] = pr
        rec[2, k + 1] = x
        rec[3, k + 1] = v
    return rec


def _drive_groups(P, dts, v_stride, t_out):
    """Slices of the candidates for the kernel, as (members, drivers,
    driver_of, kept): candidates with the same drive parameters, step and
    voltage row share one drive, integrated by their first member
    (``drivers`` and ``driver_of`` index ``members``); ``kept`` numbers the
    drives shared by more than one candidate (-1: not kept). A slice keeps
    its drives within DRIVE_BYTES."""
    if len(P) == 1:
        yield slice(None), np.zeros(1, np.int64), np.zeros(1, np.int64), np.full(1, -1, np.int64)
        return
    key = np.column_stack([P[:, DRIVE_COLS], dts, np.arange(len(P)) if v_stride else np.zeros(len(P))])
    _, group = np.unique(key, axis=0, return_inverse=True)
    group = group.ravel()
    shared = np.bincount(group) > 1
    steps = (t_out[-1] - t_out[0]) / np.min(dts) + len(t_out)      # at least a run's steps
    per_slice = max(1, int(DRIVE_BYTES // (16 * steps)))
    # slices of consecutive groups holding at most per_slice kept drives
    bounds = np.flatnonzero(np.diff((np.cumsum(shared) - shared) // per_slice)) + 1
    for lo, hi in zip([0, *bounds], [*bounds, len(shared)]):
        whole = lo == 0 and hi == len(shared)
        members = slice(None) if whole else np.flatnonzero((group >= lo) & (group < hi))
        driver_of = group[members] - lo
        drivers = np.unique(driver_of, return_index=True)[1].astype(np.int64)
        kept = np.where(shared[lo:hi], np.cumsum(shared[lo:hi]) - 1, -1).astype(np.int64)
        yield members, drivers, driver_of.astype(np.int64), kept


def simulate(model: PiezoHydraulicModel, t_in, v_in, t_out=None,
             step_factor: float = STEP_FACTOR) -> dict[str, np.ndarray]:
    """Simulate every candidate of ``model`` driven by voltage v_in(t_in).

    t_in : (n_in,) s, increasing. v_in : (n_in,) shared or (n_cand, n_in), V.
    t_out : (n_out,) s, the times to report (default t_in).
    step_factor : dt * omega_max of the fastest mode (accuracy against speed;
    semi-implicit Euler is stable below 2).
    Returns {channel: (n_cand, n_out)} for CHANNELS, positions from rest.
    Raises SimulationError when a candidate's state stops being finite.
    """
    P = model.matrix()
    t_in = np.ascontiguousarray(t_in, dtype=float)
    V = np.ascontiguousarray(np.atleast_2d(np.asarray(v_in, dtype=float)))
    if V.shape[0] not in (1, P.shape[0]):
        raise ValueError("v_in must be shared or one row per candidate")
    t_out = t_in if t_out is None else np.ascontiguousarray(t_out, dtype=float)
    dts = stable_step(P, step_factor)
    v_stride = np.int64(V.shape[0] > 1)
    out = np.empty((P.shape[0], len(CHANNELS), t_out.shape[0]))
    for members, drivers, driver_of, kept in _drive_groups(P, dts, v_stride, t_out):
        with PARALLEL_LAUNCH:     # one parallel kernel at a time (sim/__init__.py)
            out[members] = _simulate(P[members], dts[members], t_in, V[members] if v_stride else V,
                                     t_out, v_stride, drivers, driver_of, kept)
    bad = ~np.all(np.isfinite(out), axis=(1, 2))
    if bad.any():
        raise SimulationError(f"simulation diverged for candidates {np.flatnonzero(bad).tolist()}")
    return {name: out[:, i, :] for i, name in enumerate(CHANNELS)}
