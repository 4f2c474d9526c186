"""Wall time of the whole seed solve, cold (first run: numba compiles or
loads its cache, cvxpy builds its problems) and warm (the same solve again
in the same process), with the share of the DC actuators sized from parts
and of the piezo pump; and the default solve (with what would flip each
verdict, found by re-solving) against ``solve --fast`` (without).

    python benchmarks/solve_benchmark.py [--repeat 3] [--requirements studies/seed-requirements.toml]

The seed solve without flips (force path, every structure material and
compensator, DC from parts, the piezo pump) stays under 15 s warm on this
machine, the default one with flips under 20 s; this prints the best warm
times (wall and CPU: the 2 cores are shared, and the CPU time is what a
quiet machine would take), the flips' re-solves, the DC part's and the
pump's time and the load average, and exits 1 when a warm solve is slower.
"""
from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

from sizing.engine.dc_candidate import parts_candidate
from sizing.engine.dc_sizing import dc_parts_designs
from sizing.engine.evaluate import load_cases
from sizing.engine.pump import pump_designs
from sizing.engine.pump_candidate import pump_candidate
from sizing.engine.solve import solve
from sizing.io.catalog import load_catalog
from sizing.io.requirements import load_requirements

LIMIT_S = 15.0            # solve --fast
LIMIT_FLIPS_S = 20.0      # the default solve, with flips
ROOT = Path(__file__).resolve().parents[1]


def _timed(step) -> float:
    """Seconds ``step()`` takes (a stage and its results.json records, as the solve runs it)."""
    t0 = time.perf_counter()
    step()
    return time.perf_counter() - t0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--requirements", default=str(ROOT / "studies" / "seed-requirements.toml"))
    args = parser.parse_args()
    req, sha = load_requirements(args.requirements)
    catalog = load_catalog()
    loads = [c["load_N"] for c in load_cases(req.load)]
    times, dc_times, pump_times, flips = [], [], [], []
    for _ in range(args.repeat + 1):
        t0 = time.perf_counter()
        out = solve(req, sha, catalog, fast=True)
        times.append(time.perf_counter() - t0)
        t0, c0 = time.perf_counter(), time.process_time()
        full = solve(req, sha, catalog)
        flips.append((time.perf_counter() - t0, time.process_time() - c0, full.results["flips_cost"]["re_solves"]))
        dc_times.append(_timed(lambda: [parts_candidate(req, catalog, d)
                                        for d in dc_parts_designs(req, catalog, loads).designs]))
        pump_times.append(_timed(lambda: [pump_candidate(req, d) for d in pump_designs(req, catalog, loads).designs]))
    counts = out.results["counts"]
    warm, dc_warm = min(times[1:]), min(dc_times[1:])
    print(f"seed solve: cold {times[0]:.2f} s, warm best {warm:.2f} s of {args.repeat} "
          f"(limit {LIMIT_S:g} s); DC from parts alone: warm {dc_warm:.2f} s for "
          f"{counts['dc_parts']['combinations']} combinations, {counts['dc_parts']['simulated']} simulated")
    print(f"piezohydraulic: combinations {counts['combinations']}, sized {counts['sized']}, "
          f"simulated {counts['simulated']}; candidates {len(out.results['candidates'])}")
    pump = counts.get("piezo_pump", {})
    print(f"piezo pump alone: warm {min(pump_times[1:]):.2f} s for {pump.get('combinations', 0)} designs screened, "
          f"{pump.get('simulated', 0)} simulated")
    wall, cpu, re_solves = min(flips[1:])
    print(f"default solve with flips: warm best {wall:.2f} s wall, {cpu:.2f} s CPU (limit {LIMIT_FLIPS_S:g} s), "
          f"{re_solves} re-solves; x{wall / warm:.2f} the --fast solve")
    print(f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    return 0 if warm <= LIMIT_S and min(wall, cpu) <= LIMIT_FLIPS_S else 1


if __name__ == "__main__":
    sys.exit(main())
