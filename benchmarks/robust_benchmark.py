"""Speed of ``sizing robust`` and ``sizing sweep``.

    python benchmarks/robust_benchmark.py [--designs 10] [--samples 1000] [--workers 2] [--sweep 20]
                                          [--technology piezohydraulic|dc_motor]

1. The seed case (studies/seed-requirements.toml, 2 load cases) is solved
   once; its ``--designs`` best designs (of ``--technology`` when given;
   for the seed the best are DC designs from parts) get ``--samples`` Monte Carlo
   samples each, every sample a full simulation under both load cases, run
   serially and on a local Dask cluster of ``--workers`` processes. Prints
   the wall time, the throughput in simulated candidate-seconds per wall
   second for each, their ratio, and checks that both give the same numbers.
2. Scaling with samples: the serial run at 1/10, 3/10 and all the samples
   (of the first design only, to keep it short).
3. A sweep of ``--sweep`` solves (stroke 35..50 mm x max_temperature
   80..120 degC) on the local cluster: wall time.

Targets: the Monte Carlo under 60 s and the sweep of 20 solves
under 2 minutes on a 2-core machine. The serial run is the reference for
the cluster's. Timings depend on what else the machine runs; today's
figures, with the load they were taken at, are in docs/validation.md,
"Robust sizing".
"""
from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

from sizing.engine.solve import solve
from sizing.io.catalog import load_catalog
from sizing.io.requirements import load_requirements
from sizing.io.schema import load_toml
from sizing.studies.executor import Executor
from sizing.studies.robust import pick_designs, robust
from sizing.studies.sweep import sweep

REQ = Path(__file__).resolve().parents[1] / "studies" / "seed-requirements.toml"


def timed(fn):
    start = time.perf_counter()
    out = fn()
    return out, time.perf_counter() - start


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--designs", type=int, default=10)
    ap.add_argument("--samples", type=int, default=1000)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--sweep", type=int, default=20, help="solves in the sweep (0: skip)")
    ap.add_argument("--technology", choices=["piezohydraulic", "dc_motor"], default=None,
                    help="study only this technology's best designs (default: the best of both)")
    args = ap.parse_args()

    req, sha = load_requirements(REQ)
    cat = load_catalog(None)
    results, t_solve = timed(lambda: solve(req, sha, cat).results)
    designs = pick_designs(results, args.designs, args.technology)
    techs = sorted({d["technology"] for d in designs})
    print(f"seed solve: {t_solve:.1f} s; {len(designs)} designs ({', '.join(techs)}) x {args.samples} samples x 2 load cases")

    serial, t_serial = timed(lambda: robust(req, cat, designs, args.samples, 0, Executor(0)))
    sim_s = serial["simulated_candidate_s"]
    print(f"serial:        {t_serial:6.1f} s  {sim_s / t_serial:8.0f} simulated candidate-s per wall s")
    with Executor(args.workers) as ex:
        # warm-up: the workers import the engine and load the compiled simulator once
        _, t_warm = timed(lambda: robust(req, cat, designs[:1], 2 * args.workers, 0, ex, batch=1))
        print(f"local cluster start-up (imports in the workers): {t_warm:.1f} s, not counted below")
        (local, t_local) = timed(lambda: robust(req, cat, designs, args.samples, 0, ex))
        print(f"local cluster: {t_local:6.1f} s  {sim_s / t_local:8.0f} simulated candidate-s per wall s "
              f"({ex.where}); ratio serial/local {t_serial / t_local:.2f}")
        for out in (serial, local):
            out.pop("where")
        same = json.dumps(serial, sort_keys=True) == json.dumps(local, sort_keys=True)
        print(f"identical numbers serial vs cluster: {same}")
        for frac in (0.1, 0.3, 1.0):
            n = max(1, int(args.samples * frac))
            out, t = timed(lambda: robust(req, cat, designs[:1], n, 0, Executor(0)))
            print(f"scaling: 1 design x {n:5d} samples serial {t:6.2f} s "
                  f"({out['simulated_candidate_s'] / t:8.0f} candidate-s per s)")
        if args.sweep:
            n_stroke = max(1, args.sweep // 4 if args.sweep >= 4 else args.sweep)
            n_temp = max(1, args.sweep // n_stroke)
            vary = [f"stroke=35mm..50mm:{n_stroke}", f"max_temperature=80degC..120degC:{n_temp}"]
            data = load_toml(REQ)
            sw, t_sweep = timed(lambda: sweep(data, REQ, cat, vary, ex))
            print(f"sweep: {len(sw['grid'])} solves in {t_sweep:.1f} s on {ex.where} "
                  f"({t_sweep / len(sw['grid']):.1f} s per solve)")


if __name__ == "__main__":
    main()
