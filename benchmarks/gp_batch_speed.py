"""The piezohydraulic sizing of the seed solve, each figure beside the same
work done the old way (CPU seconds, user + system, so that a shared
machine's load does not enter them):

- the geometric programs of every combination and variant the seed sizes:
  solved at once by ``batch_sizer.BatchSizer`` (numpy, ``batch_gp``)
  against one Clarabel solve after another through cvxpy
  (``convex.GPSizer``, its compiled re-solve; the program compiled before
  the clock starts), with how far the answers are apart;
- the end closures' finite-element check (``physics/plate_fe``): the
  grids of the seed's materials read from the disk cache against solved;
- with ``--solve``: ``sizing solve studies/seed-requirements.toml --fast``
  in a fresh process, warm (catalog and plate caches filled by a first
  run), best of ``--repeat``: the process's CPU time and wall time.

    python benchmarks/gp_batch_speed.py [--solve] [--repeat 3]

The programs' reference is Clarabel one by one in the same run; the
solve's is ``SOLVE_REFERENCE_CPU_S``. Today's figures are in
docs/validation.md, "How the solve is made fast".
"""
from __future__ import annotations

import argparse
import math
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")      # as the command line runs

import numpy as np  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
SEED = ROOT / "studies" / "seed-requirements.toml"
# the reference: the --fast seed solve's CPU, warm, with every program solved
# by Clarabel, the plates solved and pint loaded on every run
SOLVE_REFERENCE_CPU_S = 7.6
POINT_FIELDS = ("ratio", "wide_area", "voltage_fraction", "cap_thickness", "frame_area", "wide_gap",
                "amplifier_units_sized")


def cpu() -> float:
    t = os.times()
    return t.user + t.system


def seed_inputs():
    from sizing.technologies.piezohydraulic.records import PiezoBrief
    from sizing.io.catalog import load_catalog
    from sizing.io.requirements import load_requirements
    from sizing.technologies.piezohydraulic.designs import variant_inputs
    from sizing.technologies.piezohydraulic.search import enumerate_combos
    req, _ = load_requirements(SEED)
    catalog = load_catalog()
    brief = PiezoBrief.of(req)
    combos = [c for c in enumerate_combos(req, catalog) if not c.pruned]
    return tuple(brief.objectives), [s for _, _, s in variant_inputs(brief, catalog, combos)], catalog


def log_objective(sizer, inputs, results) -> np.ndarray:
    from sizing.technologies.piezohydraulic import batch_gp
    from sizing.technologies.piezohydraulic.convex import PARAMETERS, POINT, VARIABLES, parameter_values
    layout = sizer.problem.objective
    theta = np.log([[parameter_values(s)[k] for k in PARAMETERS] for s in inputs])
    y = np.zeros((len(results), len(VARIABLES)))
    y[:, :len(POINT)] = np.log([[getattr(r, f) for f in POINT_FIELDS] for r in results])
    return batch_gp._Posynomials(layout).evaluate(y, theta @ layout.parameter_powers.T
                                                  + layout.log_coefficient)[0].sum(axis=1)


def programs() -> None:
    from sizing.technologies.piezohydraulic.batch_sizer import BatchSizer
    from sizing.technologies.piezohydraulic.convex import GPSizer
    objectives, inputs, _ = seed_inputs()
    reference, batch = GPSizer(objectives), BatchSizer(objectives)
    reference.solve(inputs[0])                               # compiled before the clock
    batch.solve(inputs[:1])
    t = cpu()
    want = [reference.solve(s) for s in inputs]
    t_ref = cpu() - t
    t = cpu()
    got = batch.solve(inputs)
    t_batch = cpu() - t
    ok = [i for i, r in enumerate(want) if r.success]
    d_obj = np.abs(log_objective(batch, [inputs[i] for i in ok], [got[i] for i in ok])
                   - log_objective(batch, [inputs[i] for i in ok], [want[i] for i in ok])).max()
    d_point = max(abs(getattr(got[i], f) / getattr(want[i], f) - 1) for i in ok for f in POINT_FIELDS)
    same = sum(a.success == b.success and a.driver == b.driver for a, b in zip(got, want))
    print(f"programs: {len(inputs)} combinations x variants, {len(ok)} feasible")
    print(f"  Clarabel one by one  {t_ref:6.2f} s CPU")
    print(f"  batch (numpy)        {t_batch:6.2f} s CPU   {t_ref / t_batch:4.1f}x faster"
          f"   left to Clarabel: {'some' if batch._reference is not None else 'none'}")
    print(f"  same feasibility and driver: {same}/{len(inputs)};  objective apart <= {d_obj:.1e} (log),"
          f"  geometry apart <= {d_point:.1e} (relative)")


def plates() -> None:
    from sizing import disk_cache
    from sizing.physics import plate_fe
    _, _, catalog = seed_inputs()
    cases = {(round(float(m.poisson), 6), "simply_supported") for m in catalog.materials.values()}
    with tempfile.TemporaryDirectory() as tmp:
        os.environ["SIZING_CACHE_DIR"] = tmp
        plate_fe._ratio_grid.cache_clear()
        plate_fe._compliance_factor.cache_clear()
        t = cpu()
        solved = [plate_fe._ratio_grid(*c) for c in sorted(cases)]
        t_solve = cpu() - t
        plate_fe._ratio_grid.cache_clear()
        plate_fe._compliance_factor.cache_clear()
        disk_cache.flush()
        plate_fe._compliance_factor.__wrapped__.forget()     # a new process: nothing in memory
        t = cpu()
        read = [plate_fe._ratio_grid(*c) for c in sorted(cases)]
        t_read = cpu() - t
        del os.environ["SIZING_CACHE_DIR"]
    print(f"plate check grids ({len(cases)} Poisson ratios x {len(plate_fe.CHECK_GRID)} thicknesses):"
          f" solved {t_solve:.2f} s CPU, read back {t_read:.3f} s; identical: {solved == read}")


def solve(repeat: int) -> None:
    with tempfile.TemporaryDirectory() as out:
        cmd = [sys.executable, "-m", "sizing.cli", "solve", str(SEED), "--fast", "--out", out]
        subprocess.run(cmd, capture_output=True, check=True)                    # fills the caches
        best = (math.inf, math.inf)
        for _ in range(repeat):
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            t = time.perf_counter()
            subprocess.run(cmd, capture_output=True, check=True)
            wall = time.perf_counter() - t
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            used = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
            best = min(best, (used, wall))
    print(f"seed solve --fast, warm, best of {repeat}: {best[0]:.2f} s CPU, {best[1]:.2f} s wall"
          f" (load {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores); reference {SOLVE_REFERENCE_CPU_S:g} s CPU"
          " (Clarabel one by one, no disk caches)")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--solve", action="store_true", help="also time the whole --fast seed solve")
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    programs()
    plates()
    if args.solve:
        solve(args.repeat)


if __name__ == "__main__":
    main()
