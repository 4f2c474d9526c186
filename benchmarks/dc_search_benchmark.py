"""The DC parts search at catalog scale: catalog load time (parsed, and from
its cache), the pruned search over every motor x mountable gear x screw x
drive, and the whole DC-from-parts step (search, screen, simulation of the
best), each the best of a few runs.

    python benchmarks/dc_search_benchmark.py [--repeat 3] [--requirements studies/seed-requirements.toml]

Exits 1 when the DC step takes longer than LIMIT_S warm (the seed solve's
budget leaves it a few seconds) or the catalog, from its cache, longer than
LOAD_LIMIT_S (every command loads it). The parsed load is the cache's
reference; today's figures are in docs/dc-parts.md.
"""
from __future__ import annotations

import argparse
import os
import sys
import tempfile
import time
from pathlib import Path

LIMIT_S = 5.0
LOAD_LIMIT_S = 0.5
ROOT = Path(__file__).resolve().parents[1]

if __package__ in (None, ""):      # run as a script: the repository root holds the benchmarks package
    sys.path.insert(0, str(ROOT))

from benchmarks.timing import best_of  # noqa: E402


def _dc_step(req, catalog, loads, designs, serialise) -> tuple:
    """The DC-from-parts step as the solve runs it: the designs and their
    results.json records (the imports wait for the cold catalog cache)."""
    out = designs(req, catalog, loads)
    return out, [serialise(req, catalog, d) for d in out.designs]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--requirements", default=str(ROOT / "studies" / "seed-requirements.toml"))
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as cache:
        os.environ["SIZING_CACHE_DIR"] = cache          # a cold cache first
        from sizing.technologies.dc_motor import search as dc_search
        from sizing.technologies.dc_motor.record import parts_candidate
        from sizing.technologies.dc_motor.from_parts import dc_parts_designs
        from sizing.engine.evaluate import load_cases
        from sizing.io.catalog import load_catalog
        from sizing.io.requirements import load_requirements
        t0 = time.perf_counter()
        catalog = load_catalog()
        parsed = time.perf_counter() - t0
        cached, _ = best_of(load_catalog, args.repeat)
    req, _ = load_requirements(args.requirements)
    loads = [c["load_N"] for c in load_cases(req.load)]
    t_search, found = best_of(lambda: dc_search.search(catalog, req, loads), args.repeat)
    t_dc, (out, candidates) = best_of(lambda: _dc_step(req, catalog, loads, dc_parts_designs, parts_candidate),
                                    args.repeat)
    print(f"catalog: {len(catalog.motors)} motors, {len(catalog.gears)} gears, {len(catalog.screws)} screws, "
          f"{len(catalog.drives)} drives; load parsed {parsed:.2f} s, from its cache {cached:.3f} s "
          f"(limit {LOAD_LIMIT_S:g} s)")
    print(f"search: {found.combinations:,} combinations, {found.screened:,} screened, {found.n_feasible:,} "
          f"statically feasible, {t_search:.2f} s")
    print(f"DC from parts (search, screen, {len(candidates)} simulated): {t_dc:.2f} s (limit {LIMIT_S:g} s)")
    print("ruled out: " + ", ".join(f"{k} {v:,}" for k, v in sorted(out.ruled_out.items(), key=lambda x: -x[1])))
    print(f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    return 0 if t_dc <= LIMIT_S and cached <= LOAD_LIMIT_S else 1


if __name__ == "__main__":
    sys.exit(main())
