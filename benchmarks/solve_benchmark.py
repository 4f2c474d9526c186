"""Wall time of `sizing solve` on the seed's requirements, warm (issue 9:
it must stay under 10 s on this machine with the whole force path, every
structure material and every compensator in the search).

    python benchmarks/solve_benchmark.py [--repeat 2]

The first solve compiles and caches the numba kernels and cvxpy's problem;
the later ones are timed. Prints each time, the split (sizing, simulation)
from the results, and the machine's load average, since the 2 cores are
shared.
"""
from __future__ import annotations

import argparse
import os
import time
from pathlib import Path

from sizing.engine.solve import solve
from sizing.io.catalog import load_catalog
from sizing.io.requirements import load_requirements

REPO = Path(__file__).resolve().parents[1]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=2)
    args = ap.parse_args()
    req, sha = load_requirements(REPO / "studies" / "seed-requirements.toml")
    catalog = load_catalog()
    solve(req, sha, catalog)                        # warm-up: numba and cvxpy compile
    times = []
    for _ in range(args.repeat):
        t0 = time.perf_counter()
        out = solve(req, sha, catalog)
        times.append(time.perf_counter() - t0)
    counts = out.results["counts"]
    print(f"warm solve: {', '.join(f'{t:.2f} s' for t in times)} (best {min(times):.2f} s, limit 10 s)")
    print(f"combinations {counts['combinations']}, sized {counts['sized']}, designs {counts['gp_feasible']} "
          f"GP-feasible, simulated {counts['simulated']}, candidates {len(out.results['candidates'])}")
    print(f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")


if __name__ == "__main__":
    main()
