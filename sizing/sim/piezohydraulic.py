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
a seal or a leak at dozens of points with the stacks unchanged; a caller
may keep the drives of its small batches and have them read again
(``simulate_runs(drives=...)``: a fit's points change a seal or a leak,
not the drive).

A candidate's step is a chain of dependent floating-point operations whose
latency, not the processor's throughput, sets its time. The kernel
therefore advances up to LANES tasks (a candidate on a run; several runs in
one call: ``simulate_runs``) together, a step of each in turn, so the
processor overlaps their chains (``_simulate_lanes``); each task performs
exactly the operations of its run alone, so every figure is the same to
the bit whatever the batch (tests/sim/test_sim_piezohydraulic.py). On a
12 000-sample run a candidate that reads its drive took 16-20 ns a step in
lanes against 30-37 ns alone (benchmarks/diagnose_speed.py).
"""
from __future__ import annotations

from collections import OrderedDict
from dataclasses import dataclass

import numba
import numpy as np

from ..errors import SimulationError
from ..threads import core_to_spare
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
def _interp_index(t, t_in, j, last):
    """The interval j (at most ``last``) of t_in that holds t, moving j
    forward only."""
    while j < last and t_in[j + 1] <= t:
        j += 1
    return j


@numba.njit(cache=True, error_model="numpy")
def _interp_at(t, t_in, inv_dt, V, r, j):
    """Linear interpolation of row r of V at t in interval j
    (``_interp_index``); inv_dt[j] = 1 / (t_in[j+1] - t_in[j]), precomputed
    once."""
    t0 = t_in[j]
    if t <= t0:
        return V[r, j]
    if t >= t_in[j + 1]:
        return V[r, j + 1]
    w = (t - t0) * inv_dt[j]
    return V[r, j] * (1.0 - w) + V[r, j + 1] * w


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
READ, INTEGRATE, KEEP = 0, 1, 2     # how a candidate comes by its drive (_simulate_lanes)
LANES = 8           # tasks advanced together, at most (_simulate_lanes)


@numba.njit(cache=True, parallel=True, error_model="numpy", nogil=True)   # nogil: stages run in threads (sim/__init__.py)
def _simulate(P, dts, T_in, V_in, in_at, T_out, out_at, v_stride, vh, tasks, starts, n_first, modes, rows):
    """Task k simulates candidate tasks[k, 0] (a row of P) on run tasks[k, 1]:
    input times T_in[in_at[r]:in_at[r + 1]] (and the same columns of V_in),
    output times T_out[out_at[r]:out_at[r + 1]] (the same columns of the
    result). The tasks ``starts[g]:starts[g + 1]`` of lane group g advance
    together (``_simulate_lanes``); each of ``modes`` INTEGRATEs its drive,
    or KEEPs it in row ``rows`` of the drive buffer vh, or READs it there:
    the first ``n_first`` groups hold the drives kept and the drives read
    that were kept before (given in vh), the others READ the drives they
    keep, once they are done."""
    out = np.empty((P.shape[0], 4, T_out.shape[0]))
    inv_dt = np.zeros(T_in.shape[0])
    for r in range(in_at.shape[0] - 1):
        inv_dt[in_at[r]:in_at[r + 1] - 1] = 1.0 / (T_in[in_at[r] + 1:in_at[r + 1]] - T_in[in_at[r]:in_at[r + 1] - 1])
    for g in numba.prange(n_first):
        _simulate_group(P, dts, T_in, inv_dt, V_in, in_at, T_out, out_at, v_stride, vh, tasks[starts[g]:starts[g + 1]],
                        modes[starts[g]:starts[g + 1]], rows[starts[g]:starts[g + 1]], out)
    for g in numba.prange(n_first, starts.shape[0] - 1):
        _simulate_group(P, dts, T_in, inv_dt, V_in, in_at, T_out, out_at, v_stride, vh, tasks[starts[g]:starts[g + 1]],
                        modes[starts[g]:starts[g + 1]], rows[starts[g]:starts[g + 1]], out)
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


# columns of a lane's state between two steps (_simulate_lanes)
(S_V, S_H, S_CREEP, S_X, S_Y, S_U, S_LEAK, S_PR, S_ZBR, S_Y0, S_AOIL, S_AAW, S_KF, S_IKKF, S_IKF,
 S_SLIDING, S_T, S_DT) = range(18)
# columns of a lane's constants
C_INV_VS, C_FW0, C_FN0, C_LOSS_FWD, C_LOSS_BACK, C_INV_M, C_INV_TAU, C_N_LC, C_AMP = range(9)
# columns of a lane's counters: the sample it is in (from its run's
# first), steps left in the sample, interval of the input, steps done
I_K, I_LEFT, I_J, I_S = range(4)


@numba.njit(cache=True, error_model="numpy")
def _simulate_group(P, dts, T_in, inv_dt, V_in, in_at, T_out, out_at, v_stride, vh, tasks, modes, rows, out):
    """A lane group's tasks: one alone, or lanes."""
    if tasks.shape[0] == 1:
        _simulate_one(P, dts, T_in, inv_dt, V_in, in_at, T_out, out_at, v_stride, vh, tasks[0, 0], tasks[0, 1],
                      modes[0], rows[0], out)
    else:
        _simulate_lanes(P, dts, T_in, inv_dt, V_in, in_at, T_out, out_at, v_stride, vh, tasks, modes, rows, out)


@numba.njit(cache=True, error_model="numpy")
def _start(P, c, t, j, T_in, inv_dt, V_in, v_stride, vh, row, mode, S, C, logc, inv_tl, l, out, o):
    """Candidate c (row c of P) at rest in lane l at time t (input
    interval j): its constants C[l] and inv_tl[l], its state S[l] and
    logc[l], its output sample o; ``mode`` and ``row``: how it comes by
    its drive (``_simulate``)."""
    K, d33, h = P[c, 0], P[c, 1], P[c, 7]
    A_w, A_n, V0, bulk, m = P[c, 8], P[c, 9], P[c, 10], P[c, 11], P[c, 12]
    rho, k_con, k_exp = P[c, 13], P[c, 14], P[c, 15]
    F0, kL = P[c, 20], P[c, 21]
    kappa, tau = P[c, 24], P[c, 25]
    vs, lc, lc_t, eps0, kap = P[c, 31], P[c, 32], P[c, 33], P[c, 34], P[c, 35]
    C[l, C_INV_VS] = 1.0 / vs if vs > 0.0 else 0.0
    C[l, C_N_LC] = LOG_CREEP_MODES if lc > 0.0 else 0
    for i in range(LOG_CREEP_MODES):
        inv_tl[l, i] = 1.0 / (lc_t * 10.0 ** i) if lc_t > 0.0 else 0.0
    C[l, C_FW0], C[l, C_FN0] = P[c, 16], P[c, 17]
    R = A_w / A_n
    bern = 1.0 - 1.0 / (R * R)
    # constants of the step, so the loop multiplies instead of dividing
    a_oil = bulk / V0
    aA_w = a_oil * A_w
    kf = aA_w * A_w
    S[l, S_AOIL], S[l, S_AAW], S[l, S_KF] = a_oil, aA_w, kf
    S[l, S_IKKF], S[l, S_IKF], C[l, C_INV_M] = 1.0 / (K + kf), 1.0 / kf, 1.0 / m
    C[l, C_INV_TAU] = 1.0 / tau if tau > 0.0 else 0.0
    C[l, C_LOSS_FWD], C[l, C_LOSS_BACK] = 0.5 * rho * (bern + k_con), 0.5 * rho * (bern + k_exp)
    if mode == READ:
        v, h = vh[row, 0, 0], vh[row, 1, 0]
    else:
        v = _interp_at(t, T_in, inv_dt, V_in, c * v_stride, j)
        if mode == KEEP:
            vh[row, 0, 0], vh[row, 1, 0] = v, h
    xf_lin = d33 * v + h
    creep = kappa * xf_lin
    xf_tot = xf_lin + creep
    for i in range(int(C[l, C_N_LC])):
        logc[l, i] = lc * xf_lin
        xf_tot = xf_tot + logc[l, i]
    if eps0 > 0.0:
        x, y, pr = _air_equilibrium(K, xf_tot, A_w, A_n, V0, bulk, F0, kL, eps0, kap)
    else:
        x, y, pr = _equilibrium(K, xf_tot, A_w, A_n, V0, bulk, F0, kL)
    S[l, S_V], S[l, S_H], S[l, S_CREEP], S[l, S_X], S[l, S_Y], S[l, S_U] = v, h, creep, x, y, 0.0
    S[l, S_LEAK], S[l, S_PR], S[l, S_ZBR], S[l, S_Y0], S[l, S_SLIDING] = 0.0, pr, 0.0, y, 0.0
    S[l, S_T] = t
    out[c, 0, o], out[c, 1, o], out[c, 2, o], out[c, 3, o] = 0.0, pr, x, v


@numba.njit(cache=True, error_model="numpy")
def _log_creep(logc, inv_tl, l, lc, xf_lin, xf_tot, dt):
    """The log-creep modes logc[l] advanced a step; returns xf_tot with them."""
    for i in range(LOG_CREEP_MODES):
        logc[l, i] += dt * (lc * xf_lin - logc[l, i]) * inv_tl[l, i]
        xf_tot = xf_tot + logc[l, i]
    return xf_tot


@numba.njit(cache=True, error_model="numpy")
def _simulate_one(P, dts, T_in, inv_dt, V_in, in_at, T_out, out_at, v_stride, vh, c, r, mode, row, out):
    """Candidate c on run r alone (``_simulate_lanes`` with one lane, its
    state in registers between two steps)."""
    S = np.empty((1, 18))
    C = np.empty((1, 9))
    logc = np.zeros((1, LOG_CREEP_MODES))
    inv_tl = np.empty((1, LOG_CREEP_MODES))
    o, n_out, last, dt_max = out_at[r], out_at[r + 1] - out_at[r], in_at[r + 1] - 2, dts[c]
    t = T_out[o]
    j = _interp_index(t, T_in, in_at[r], last)
    _start(P, c, t, j, T_in, inv_dt, V_in, v_stride, vh, row, mode, S, C, logc, inv_tl, 0, out, o)
    v, h, creep, x, y, u = S[0, S_V], S[0, S_H], S[0, S_CREEP], S[0, S_X], S[0, S_Y], S[0, S_U]
    v_leak, pr, z_br, y0, sliding = S[0, S_LEAK], S[0, S_PR], S[0, S_ZBR], S[0, S_Y0], S[0, S_SLIDING]
    a_oil, aA_w, kf, inv_Kkf, inv_kf = S[0, S_AOIL], S[0, S_AAW], S[0, S_KF], S[0, S_IKKF], S[0, S_IKF]
    inv_vs, Fw0, Fn0, inv_m, inv_tau = C[0, C_INV_VS], C[0, C_FW0], C[0, C_FN0], C[0, C_INV_M], C[0, C_INV_TAU]
    loss_fwd, loss_back, n_lc = C[0, C_LOSS_FWD], C[0, C_LOSS_BACK], C[0, C_N_LC]
    drive = (P[c, 37], P[c, 26], P[c, 2], P[c, 3], P[c, 4], P[c, 5], P[c, 6], P[c, 39])
    hydraulics = (P[c, 0], P[c, 8], P[c, 9], P[c, 10], P[c, 11], P[c, 12], P[c, 13], P[c, 18], P[c, 19],
                  P[c, 20], P[c, 21], P[c, 22], P[c, 23], P[c, 27], P[c, 29], P[c, 30], P[c, 31], P[c, 34],
                  P[c, 35], P[c, 36], P[c, 38])
    d33, kappa, tau, lc, bw = P[c, 1], P[c, 24], P[c, 25], P[c, 32], P[c, 37]
    s = 0
    for k in range(o, o + n_out - 1):
        nsub = _substeps(T_out[k + 1] - t, dt_max)
        dt = (T_out[k + 1] - t) / nsub
        amp = 1.0 - np.exp(-bw * dt) if bw > 0.0 else 0.0     # first-order amplifier, exact over the step
        for _ in range(nsub):
            s += 1
            if mode != READ:
                t += dt
                j = _interp_index(t, T_in, j, last)
                v, h = _drive_step(drive, v, h, _interp_at(t, T_in, inv_dt, V_in, c * v_stride, j), dt, amp)
                if mode == KEEP:
                    vh[row, 0, s], vh[row, 1, s] = v, h
            else:
                v, h = vh[row, 0, s], vh[row, 1, s]
            xf_lin = d33 * v + h
            if tau > 0.0:
                creep += dt * (kappa * xf_lin - creep) * inv_tau
            xf_tot = xf_lin + creep
            if n_lc > 0.0:
                xf_tot = _log_creep(logc, inv_tl, 0, lc, xf_lin, xf_tot, dt)
            x, y, u, pr, v_leak, z_br, sliding, a_oil, aA_w, kf, inv_Kkf, inv_kf = _output_step(
                hydraulics, xf_tot, dt, x, y, u, pr, v_leak, z_br, sliding, a_oil, aA_w, kf, inv_Kkf, inv_kf,
                inv_vs, Fw0, Fn0, loss_fwd, loss_back, inv_m)
        t = T_out[k + 1]
        out[c, 0, k + 1] = y - y0
        out[c, 1, k + 1] = pr
        out[c, 2, k + 1] = x
        out[c, 3, k + 1] = v


@numba.njit(cache=True, error_model="numpy")
def _begin_sample(P, dts, T_out, S, C, I, l, c, o):
    """Lane l (candidate c) enters the sample interval o, o + 1 of T_out:
    its steps, their length and the amplifier's factor over one."""
    t = S[l, S_T]
    nsub = _substeps(T_out[o + 1] - t, dts[c])
    dt = (T_out[o + 1] - t) / nsub
    bw = P[c, 37]
    C[l, C_AMP] = 1.0 - np.exp(-bw * dt) if bw > 0.0 else 0.0     # first-order amplifier, exact over the step
    S[l, S_DT] = dt
    I[l, I_LEFT] = nsub


@numba.njit(cache=True, error_model="numpy")
def _simulate_lanes(P, dts, T_in, inv_dt, V_in, in_at, T_out, out_at, v_stride, vh, tasks, modes, rows, out):
    """Tasks (candidate, run) advanced together, one step of each in turn: a
    candidate's step is a chain of dependent floating-point operations,
    and the processor overlaps the chains of the others with it. Each
    task's operations are those of its run alone, in the same order
    (``_drive_step``, ``_output_step``): its figures do not depend on its
    companions. ``modes``: INTEGRATE the stack voltage and hysteresis; KEEP:
    and keep them in vh[rows] (vh[.., 0] voltage, vh[.., 1] h; index 0 at
    rest, then a value a step); READ: read them from vh[rows], kept by a
    candidate of the same drive. The rest (creep, oil, pistons, seals, load)
    is the candidate's own."""
    L = tasks.shape[0]
    S = np.empty((L, 18))
    C = np.empty((L, 9))
    I = np.zeros((L, 4), np.int64)
    logc = np.zeros((L, LOG_CREEP_MODES))
    inv_tl = np.empty((L, LOG_CREEP_MODES))
    active = 0
    for l in range(L):
        c, r = tasks[l, 0], tasks[l, 1]
        t = T_out[out_at[r]]
        I[l, I_J] = _interp_index(t, T_in, in_at[r], in_at[r + 1] - 2)
        _start(P, c, t, I[l, I_J], T_in, inv_dt, V_in, v_stride, vh, rows[l], modes[l], S, C, logc, inv_tl, l,
               out, out_at[r])
        if out_at[r + 1] - out_at[r] > 1:
            _begin_sample(P, dts, T_out, S, C, I, l, c, out_at[r])
            active += 1
    while active > 0:
        for l in range(L):
            if I[l, I_LEFT] == 0:
                continue                  # its run is done
            c, r, row = tasks[l, 0], tasks[l, 1], rows[l]
            dt = S[l, S_DT]
            s = I[l, I_S] + 1
            I[l, I_S] = s
            v, h = S[l, S_V], S[l, S_H]
            if modes[l] != READ:
                t = S[l, S_T] + dt
                S[l, S_T] = t
                j = _interp_index(t, T_in, I[l, I_J], in_at[r + 1] - 2)
                I[l, I_J] = j
                v, h = _drive_step((P[c, 37], P[c, 26], P[c, 2], P[c, 3], P[c, 4], P[c, 5], P[c, 6], P[c, 39]),
                                   v, h, _interp_at(t, T_in, inv_dt, V_in, c * v_stride, j), dt, C[l, C_AMP])
                if modes[l] == KEEP:
                    vh[row, 0, s], vh[row, 1, s] = v, h
            else:
                v, h = vh[row, 0, s], vh[row, 1, s]
            xf_lin = P[c, 1] * v + h
            creep = S[l, S_CREEP]
            if P[c, 25] > 0.0:
                creep += dt * (P[c, 24] * xf_lin - creep) * C[l, C_INV_TAU]
            xf_tot = xf_lin + creep
            if C[l, C_N_LC] > 0.0:
                xf_tot = _log_creep(logc, inv_tl, l, P[c, 32], xf_lin, xf_tot, dt)
            (S[l, S_X], S[l, S_Y], S[l, S_U], S[l, S_PR], S[l, S_LEAK], S[l, S_ZBR], S[l, S_SLIDING],
             S[l, S_AOIL], S[l, S_AAW], S[l, S_KF], S[l, S_IKKF], S[l, S_IKF]) = _output_step(
                (P[c, 0], P[c, 8], P[c, 9], P[c, 10], P[c, 11], P[c, 12], P[c, 13], P[c, 18], P[c, 19],
                 P[c, 20], P[c, 21], P[c, 22], P[c, 23], P[c, 27], P[c, 29], P[c, 30], P[c, 31], P[c, 34],
                 P[c, 35], P[c, 36], P[c, 38]), xf_tot, dt,
                S[l, S_X], S[l, S_Y], S[l, S_U], S[l, S_PR], S[l, S_LEAK], S[l, S_ZBR],
                S[l, S_SLIDING], S[l, S_AOIL], S[l, S_AAW], S[l, S_KF], S[l, S_IKKF], S[l, S_IKF],
                C[l, C_INV_VS], C[l, C_FW0], C[l, C_FN0], C[l, C_LOSS_FWD], C[l, C_LOSS_BACK], C[l, C_INV_M])
            S[l, S_V], S[l, S_H], S[l, S_CREEP] = v, h, creep
            I[l, I_LEFT] -= 1
            if I[l, I_LEFT] == 0:         # the end of a sample interval: its output sample
                o = out_at[r] + I[l, I_K] + 1
                I[l, I_K] += 1
                S[l, S_T] = T_out[o]
                out[c, 0, o] = S[l, S_Y] - S[l, S_Y0]
                out[c, 1, o] = S[l, S_PR]
                out[c, 2, o] = S[l, S_X]
                out[c, 3, o] = S[l, S_V]
                if o + 1 < out_at[r + 1]:
                    _begin_sample(P, dts, T_out, S, C, I, l, c, o)
                else:
                    active -= 1


@numba.njit(cache=True, error_model="numpy", inline="always")
def _drive_step(p, v, h, v_cmd, dt, amp):
    """Stack voltage and hysteresis after a step towards the commanded
    voltage v_cmd: the amplifier's first-order lag (``amp`` = 1 -
    exp(-bandwidth dt)), its slew limit, the Bouc-Wen loop; ``p``: the
    amplifier bandwidth, slew rate, alpha, beta, gamma, delta, n and the
    hold rate."""
    bw, slew, al, be, ga, de, nb, hold = p
    v_new = v_cmd
    if bw > 0.0:
        v_new = v + (v_cmd - v) * amp
    if slew > 0.0:
        step = slew * dt
        v_new = min(max(v_new, v - step), v + step)
    h = hysteresis_step(h, v, v_new, dt, al, be, ga, de, nb, hold)
    return v_new, h


@numba.njit(cache=True, error_model="numpy", inline="always")
def _output_step(p, xf_tot, dt, x, y, u, pr, v_leak, z_br, sliding, a_oil, aA_w, kf, inv_Kkf, inv_kf,
                 inv_vs, Fw0, Fn0, loss_fwd, loss_back, inv_m):
    """One step of candidate c (row c of P) from the stacks' free
    displacement ``xf_tot`` on: leak, oil, wide piston, output piston and
    its seal. The state in and out: x, y, u, p, leaked volume, LuGre
    bristle deflection, whether the wide piston slides (1.0) and the oil's
    (tangent) stiffness constants a_oil, aA_w, kf, 1 / (K + kf), 1 / kf."""
    K, A_w, A_n, V0, bulk, m, rho, brk_w, brk_n, F0, kL, cv, G, no_ret, cpw, cpn, vs, eps0, kap, cdA, zpre = p
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
    thr = Fw if sliding > 0.5 else Fw * brk_w
    x, slides = _wide_piston(x, xf_tot, y, v_eff, K, aA_w, A_n, kf, inv_Kkf, inv_kf, Fw, thr, no_ret)
    pr = a_oil * (A_w * x - A_n * y - v_eff)
    p_n = pr - u * abs(u) * (loss_fwd if u >= 0.0 else loss_back)
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
    else:
        # viscous damping implicit in the new speed (stable at any step, the
        # overdamped limit F / c when dt c / m is large). Undamped, the same
        # figures without the two terms that are then exactly zero: (F - 0 u)
        # + 0 u is F + 0.0 (signed zeros included), and a division by 1.0 is
        # exact
        if cv != 0.0:
            F = A_n * p_n - (F0 + kL * y) - cv * u
            F += cv * u
        else:
            F = A_n * p_n - (F0 + kL * y) + 0.0
        if vs > 0.0:
            a = _narrow_accel_stribeck(F, u, Fn, Fn * brk_n, inv_m, inv_vs)
        else:
            a = _narrow_accel(F, u, Fn, Fn * brk_n, inv_m)
        if cv != 0.0:
            u_new = (u + a * dt) / (1.0 + dt * cv * inv_m)
        else:
            u_new = u + a * dt
        if u != 0.0 and u_new * u < 0.0:
            u_new = 0.0
        u = u_new
        y += u * dt
    return x, y, u, pr, v_leak, z_br, 1.0 if slides else 0.0, a_oil, aA_w, kf, inv_Kkf, inv_kf


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


LANE_FREE = [IDX[name] for name in ("narrow_presliding", "air_fraction")]   # zero in a task that takes a lane


def _lanes(P, tasks: np.ndarray) -> list[np.ndarray]:
    """The tasks (rows: candidate, run, mode, row) in lane groups
    (``_simulate_lanes``). A task that reads its drive and whose step is
    short takes a lane: at most LANES a group, groups of about equal size,
    and one group a thread of numba's (so its threads share the work) where
    that leaves at least two tasks a group, or one when a core is free
    (``threads.core_to_spare``: the wall time then counts, not the CPU a
    lane saves). The others run alone: a step that integrates the drive (a
    power a step), sub-steps a LuGre seal (two exponentials a sub-step) or
    follows entrained air (a power) fills the processor's window that the
    lanes overlap, and took 10-15 % longer in lanes than alone."""
    light = (tasks[:, 2] == READ) & np.all(P[tasks[:, 0]][:, LANE_FREE] == 0.0, axis=1)
    alone = [tasks[k:k + 1] for k in np.flatnonzero(~light)]
    tasks = tasks[light]
    if not len(tasks):
        return alone
    fewest = 1 if core_to_spare() else 2
    n = max(-(-len(tasks) // LANES), min(numba.get_num_threads(), len(tasks) // fewest), 1)
    return np.array_split(tasks, n) + alone


DRIVES_KEPT = 16        # drives a DriveMemory keeps (~2 MB each on a 12 000-sample run)
DRIVES_MET = 4096      # drives it knows it met once (their keys only)
DRIVES_REMEMBERED = 8   # drives of a kernel call that may go into it (a fit's batches; not a screen's)


class DriveMemory:
    """Drives (stack voltage and hysteresis at each step: ``_launch``) of a
    caller's runs, kept between kernel calls: a drive met a second time in
    a call with few drives is kept, and read in later calls instead of
    integrated again. Once only, it is not kept: a fit of the amplifier or
    the loop meets each of its drives once, the fits of a seal or a leak
    meet the nominal's again and again."""

    def __init__(self):
        self.kept = OrderedDict()       # key -> (2, steps + 1) drive, the last used last
        self.met = OrderedDict()       # key -> None: met once

    def get(self, key):
        drive = self.kept.get(key)
        if drive is not None:
            self.kept.move_to_end(key)
        return drive

    def met_before(self, key) -> bool:
        """Whether ``key`` was met before; it is now."""
        if key in self.met:
            return True
        self.met[key] = None
        if len(self.met) > DRIVES_MET:
            self.met.popitem(last=False)
        return False

    def keep(self, key, drive) -> None:
        self.kept[key] = drive
        if len(self.kept) > DRIVES_KEPT:
            self.kept.popitem(last=False)


def _launch(P, dts, runs, parts, keys=None, drives=None) -> list[np.ndarray]:
    """One kernel call: (n_cand, 4, n_out) of each of ``runs`` ((t_in, V,
    t_out)) for every candidate of P; ``parts``: (drivers, driver_of,
    kept) of each run (``_drive_groups``, one slice). ``drives``: the
    caller's DriveMemory (see ``simulate_runs``), ``keys`` naming each run
    in it: a drive found there is read, and a drive met before in a call
    with few of them is kept into it."""
    in_at = np.cumsum([0] + [len(t) for t, _, _ in runs]).astype(np.int64)
    out_at = np.cumsum([0] + [len(t) for _, _, t in runs]).astype(np.int64)
    V = np.ascontiguousarray(np.concatenate([v for _, v, _ in runs], axis=1))
    remember = drives is not None and sum(len(p[0]) for p in parts) <= DRIVES_REMEMBERED
    first, then, given, new = [], [], [], []        # given: (row, drive) read; new: (row, key) to remember
    rows = 0
    for r, (drivers, driver_of, kept) in enumerate(parts):
        n = len(driver_of)
        driving = np.zeros(n, bool)
        driving[drivers] = True
        mode = np.where(driving, INTEGRATE, READ)
        row = np.full(n, -1)
        for g, c in enumerate(drivers):
            key = (keys[r], P[c, DRIVE_COLS].tobytes(), float(dts[c])) if drives is not None else None
            known = drives.get(key) if drives is not None else None
            members = driver_of == g
            if known is not None:
                given.append((rows, known))
                mode[members], row[members] = READ, rows
                driving[members] = True             # read from the start: with the drives
            elif (again := remember and drives.met_before(key)) or kept[g] >= 0:
                mode[c], row[members] = KEEP, rows
                if again:
                    new.append((rows, key, _n_steps(dts[c], runs[r][2])))
            else:
                continue
            rows += 1
        task = np.column_stack([np.arange(n), np.full(n, r), mode, np.maximum(row, 0)]).astype(np.int64)
        first.append(task[driving])
        then.append(task[~driving])
    n_steps = max([len(v[0]) - 1 for _, v in given] + [
        _n_steps(dts[c], runs[r][2]) for c, r, m in np.concatenate(first)[:, :3] if m == KEEP] + [0])
    vh = np.empty((max(rows, 1), 2, n_steps + 1))
    for k, known in given:
        vh[k, :, :known.shape[1]] = known
    first, then = _lanes(P, np.concatenate(first)), _lanes(P, np.concatenate(then))
    tasks = np.concatenate(first + then)
    starts = np.cumsum([0] + [len(g) for g in first + then]).astype(np.int64)
    with PARALLEL_LAUNCH:     # one parallel kernel at a time (sim/__init__.py)
        out = _simulate(P, dts, np.concatenate([t for t, _, _ in runs]), V, in_at,
                        np.concatenate([t for _, _, t in runs]), out_at, np.int64(V.shape[0] > 1), vh,
                        np.ascontiguousarray(tasks[:, :2]), starts, np.int64(len(first)),
                        np.ascontiguousarray(tasks[:, 2]), np.ascontiguousarray(tasks[:, 3]))
    for k, key, steps in new:
        drives.keep(key, vh[k, :, :steps + 1].copy())
    return [out[:, :, a:b] for a, b in zip(out_at[:-1], out_at[1:])]


def simulate_runs(model: PiezoHydraulicModel, runs, step_factor: float = STEP_FACTOR, drives=None,
                  keys=None) -> list[dict]:
    """``simulate`` of every candidate of ``model`` on each of ``runs``
    ((t_in, v_in, t_out), t_out None for t_in), in one kernel call where
    the drives allow (the runs' steps advance together: ``_simulate_lanes``).
    Returns a dict of channels for each run.

    ``drives`` (a DriveMemory, with ``keys``: a hashable name of each run)
    remembers the drives (stack voltage and hysteresis at each step, which
    depend on the drive parameters DRIVE, the step and the run only) met
    again in calls with few of them, DRIVES_KEPT at most, and reads them in
    later calls instead of integrating them again: the caller promises that
    a key always names the same times and voltage (a diagnosis's bench,
    whose runs do not change). A drive read is the one integrating it
    gives, to the bit."""
    P = model.matrix()
    dts = stable_step(P, step_factor)
    prepared = []
    for t_in, v_in, t_out in runs:
        t_in = np.ascontiguousarray(t_in, dtype=float)
        V = np.ascontiguousarray(np.atleast_2d(np.asarray(v_in, dtype=float)))
        if V.shape[0] not in (1, P.shape[0]):
            raise ValueError("v_in must be shared or one row per candidate")
        prepared.append((t_in, V, t_in if t_out is None else np.ascontiguousarray(t_out, dtype=float)))
    if any(V.shape[0] > 1 for _, V, _ in prepared):         # a voltage row each: each shared one repeated
        drives = None                                       # (drives kept by candidate, not by run)
        prepared = [(t, np.ascontiguousarray(np.broadcast_to(V, (P.shape[0], V.shape[1]))), u) for t, V, u in prepared]
    v_stride = np.int64(prepared[0][1].shape[0] > 1) if prepared else np.int64(0)
    outs = [None] * len(prepared)
    whole = []                                       # the runs whose drives fit one kernel call
    for r, (t_in, V, t_out) in enumerate(prepared):
        slices = list(_drive_groups(P, dts, v_stride, t_out))
        if len(slices) == 1:
            whole.append((r, slices[0][1:]))
            continue
        outs[r] = np.empty((P.shape[0], len(CHANNELS), len(t_out)))
        for members, drivers, driver_of, kept in slices:
            outs[r][members] = _launch(P[members], dts[members], [(t_in, V[members] if v_stride else V, t_out)],
                                       [(drivers, driver_of, kept)])[0]
    if whole:
        for (r, _), y in zip(whole, _launch(P, dts, [prepared[r] for r, _ in whole], [p for _, p in whole],
                                            None if keys is None else [keys[r] for r, _ in whole], drives)):
            outs[r] = y
    results = []
    for out in outs:
        bad = ~np.all(np.isfinite(out), axis=(1, 2))
        if bad.any():
            raise SimulationError(f"simulation diverged for candidates {np.flatnonzero(bad).tolist()}")
        results.append({name: out[:, i, :] for i, name in enumerate(CHANNELS)})
    return results


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
    return simulate_runs(model, [(t_in, v_in, t_out)], step_factor)[0]
