"""Speed of the batch piezohydraulic simulator against scipy's solve_ivp on
the same candidates at matched accuracy.

    python benchmarks/sim_benchmark.py [--candidates 400]

The comparison uses the friction-free model (solve_ivp cannot step through
Karnopp stick-slip; with friction it only gets slower), with Bouc-Wen
hysteresis, fluid compliance, flow losses and viscous damping. Accuracy is
the RMS position error against a DOP853 solution at rtol 1e-10, over the
stroke. Both sides are swept (the batch simulator's step factor; solve_ivp's
RK45, LSODA and Radau at several tolerances) and each is timed at its fastest
setting whose error is at most 0.1% of the stroke; solve_ivp's time per
candidate is measured on a sample of candidates. Prints the speed ratio and the throughput in simulated
candidate-seconds per wall-clock second. solve_ivp is the reference; today's
figures are in docs/validation.md, "The batch simulator against scipy".
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp

from sizing.physics import hydraulics
from sizing.sim.piezohydraulic import IDX, PiezoHydraulicModel, simulate

if __package__ in (None, ""):      # run as a script: the repository root holds the benchmarks package
    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from benchmarks.timing import best_of  # noqa: E402

T_END, RISE = 0.5, 0.3
SEED_BW = (8.15e-7, -2.23e-7, 0.134, 0.0755, -5.46e-8, 1.14)   # seed Table 1


def candidates(n: int, rng: np.random.Generator) -> PiezoHydraulicModel:
    """Table 3-like prototypes with varied stack count, ratio and masses."""
    n_stacks = rng.integers(2, 6, n)
    ratio = rng.uniform(40, 150, n)
    A_w = float(hydraulics.area(3.75 * 0.0254)) * rng.uniform(0.6, 1.4, n)
    A_n = A_w / ratio
    return PiezoHydraulicModel(
        k_stacks=n_stacks * 1.96e7, d33=SEED_BW[0], alpha=SEED_BW[1], beta=SEED_BW[2], gamma=SEED_BW[3],
        delta=SEED_BW[4], n_bw=SEED_BW[5], wide_area=A_w, narrow_area=A_n, oil_volume=A_w * 3e-3 + A_n * 0.02,
        bulk_modulus=1.5e9, narrow_mass=rng.uniform(0.01, 0.05, n), viscous_damping=rng.uniform(5, 20, n),
        load_force=0.0)


def drive(t):
    return 150.0 * np.clip(t / RISE, 0.0, 1.0)


def rhs_factory(p: np.ndarray):
    """solve_ivp right-hand side of the same model (states h, y, u)."""
    K, d33, al, be, ga, de, nb = (p[IDX[k]] for k in ("k_stacks", "d33", "alpha", "beta", "gamma", "delta", "n_bw"))
    A_w, A_n, V0, bulk, m = (p[IDX[k]] for k in ("wide_area", "narrow_area", "oil_volume", "bulk_modulus", "narrow_mass"))
    rho, kc, ke, cv = (p[IDX[k]] for k in ("density", "k_contract", "k_expand", "viscous_damping"))
    bern = 1 - (A_n / A_w) ** 2
    kf = bulk * A_w**2 / V0

    def rhs(t, s):
        h, y, u = s
        v = 150.0 * min(t / RISE, 1.0)
        vdot = 150.0 / RISE if t < RISE else 0.0
        sv = np.sign(vdot)
        dh = (al - (be * np.sign(vdot * h) + ga) * abs(h) ** nb) * vdot + de * v * sv
        xf = d33 * v + h
        x = (K * xf + bulk * A_w / V0 * A_n * y) / (K + kf)
        pr = bulk * (A_w * x - A_n * y) / V0
        k = kc if u >= 0 else ke
        pn = pr - 0.5 * rho * u * abs(u) * (bern + k)
        return [dh, u, (A_n * pn - cv * u) / m]

    return rhs


def ivp_solve(p, t_eval, method="RK45", rtol=1e-6):
    sol = solve_ivp(rhs_factory(p), (0, T_END), [0.0, 0.0, 0.0], method=method, t_eval=t_eval,
                    rtol=rtol, atol=rtol * 1e-6, max_step=RISE / 4)
    return sol.y[1]


TARGET = 1e-3   # matched accuracy: RMS position error at most 0.1% of the stroke


def rms_error(y, truth):
    return np.sqrt(np.mean((y - truth) ** 2, axis=1)) / np.ptp(truth, axis=1)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--candidates", type=int, default=400)
    parser.add_argument("--sample", type=int, default=6, help="candidates timed with solve_ivp")
    args = parser.parse_args()
    model = candidates(args.candidates, np.random.default_rng(7)).replace(dt_max=1.0)
    P = model.matrix()
    t = np.linspace(0, T_END, 1001)
    v = drive(t)
    sample = np.arange(args.sample)
    truth = np.array([ivp_solve(P[i], t, "DOP853", 1e-10) for i in sample])
    simulate(model, t[:10], v[:10])  # compile once, outside the timing

    print(f"{args.candidates} candidates, {T_END} s simulated each; matched accuracy: RMS error <= {TARGET:.0e} of stroke")
    ours = None
    for factor in (1.2, 0.8, 0.4, 0.2, 0.1):
        wall, out = best_of(lambda: simulate(model, t, v, step_factor=factor), 5)
        y, per_cand = out["position_m"], wall / args.candidates
        err = float(np.max(rms_error(y[sample], truth)))
        print(f"  batch   step factor {factor:<5g} {per_cand * 1e3:8.3f} ms/candidate  error {err:.1e}")
        if err <= TARGET and ours is None:
            ours = (factor, per_cand, err)
    ivp = None   # the fastest solve_ivp method and tolerance that meets the target
    for method in ("RK45", "LSODA", "Radau"):
        for rtol in (1e-2, 3e-3, 1e-3, 1e-4, 1e-5):
            wall, y = best_of(lambda: np.array([ivp_solve(P[i], t, method, rtol) for i in sample]), 2)
            per_cand = wall / args.sample
            err = float(np.max(rms_error(y, truth)))
            print(f"  {method:<7} rtol {rtol:<12g} {per_cand * 1e3:8.3f} ms/candidate  error {err:.1e}")
            if err <= TARGET:
                if ivp is None or per_cand < ivp[2]:
                    ivp = (method, rtol, per_cand, err)
                break
    if ours is None or ivp is None:
        print("no setting reached the target accuracy")
        return
    wall = ours[1] * args.candidates
    print(f"batch (step factor {ours[0]:g}) vs solve_ivp {ivp[0]} (rtol {ivp[1]:g}) at error <= {TARGET:.0e}: "
          f"speed ratio {ivp[2] / ours[1]:.0f}x")
    print(f"throughput: {args.candidates * T_END / wall:.0f} simulated candidate-seconds per wall-clock second")


if __name__ == "__main__":
    main()
