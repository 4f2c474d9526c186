"""Wall time of the whole seed solve, cold (first run: numba compiles or
loads its cache, cvxpy builds its problems) and warm (the same solve again
in the same process), with the share of the DC actuators sized from parts
and of the piezo pump.

    python benchmarks/solve_benchmark.py [--repeat 3] [--requirements studies/seed-requirements.toml]

The seed solve with --fast (force path, a geometric program for every
structure material and compensator of every combination, DC from parts,
the piezo pump) and the default one (with what would flip each verdict,
found by re-solving, and the probability of compliance) should each stay
under 20 s warm on this machine, the pump's share (screen, cycle-resolved
simulation with reed and line dynamics, results records) under 3 s; this
prints the best warm times (wall and CPU: the 2 cores are shared, and the
CPU time is what a quiet machine would take), the flips' re-solves, the
DC part's, the pump's and the compliance's time and the load average, and
exits 1 when a limit is exceeded.

With ``--sizing``, only the piezohydraulic geometric programs of the seed
(every combination the search keeps, every structure material and
compensator) are timed, in CPU seconds, best of ``--repeat``: Clarabel's
direct re-solve of each compiled program (``convex.GPSizer``, the path the
solve takes for the rows its batch sizer does not certify) against cvxpy's
own re-solve of the same programs (``problem.solve(gp=True)`` every time,
the reference), on every ``--stride``-th input, in the same run; the
answers are compared too.

The reference printed beside the default solve, ``EARLIER_DEFAULT_S``, is
that solve's wall time before its flips' re-solves were narrowed. Today's
figures are in docs/validation.md, "Simulator and solve speed".
"""
from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

from sizing.technologies.dc_motor.record import parts_candidate
from sizing.technologies.dc_motor.from_parts import dc_parts_designs
from sizing.engine.evaluate import load_cases
from sizing.technologies.piezo_pump.designs import pump_designs
from sizing.technologies.piezo_pump.record import pump_candidate
from sizing.engine.solve import solve
from sizing.io.catalog import load_catalog
from sizing.io.requirements import load_requirements
from sizing.studies import compliance

LIMIT_S = 20.0            # solve --fast
LIMIT_DEFAULT_S = 20.0    # the default solve: flips and compliance
# the reference: the default seed solve's wall time, warm, before its flips'
# re-solves sized only the variants asked about and read back what they had run
EARLIER_DEFAULT_S = 70.0
PUMP_LIMIT_S = 3.0
ROOT = Path(__file__).resolve().parents[1]


def _timed(step) -> float:
    """Seconds ``step()`` takes (a stage and its results.json records, as the solve runs it)."""
    t0 = time.perf_counter()
    step()
    return time.perf_counter() - t0


def _sizing_inputs(req, catalog) -> tuple[tuple, list]:
    """The seed's programs as ``designs.size`` builds them: objectives and inputs."""
    from sizing.technologies.piezohydraulic.records import PiezoBrief
    from sizing.technologies.piezohydraulic import designs
    from sizing.technologies.piezohydraulic.search import enumerate_combos
    brief = PiezoBrief.of(req)
    vs = designs.variants(brief, catalog)
    inputs = [designs.sizing_input(brief, c, v.material, v.compensator)
              for c in enumerate_combos(req, catalog) if not c.pruned for v in vs]
    return tuple(brief.objectives), inputs


def sizing_speed(req, catalog, repeat: int, stride: int) -> None:
    """CPU seconds of the seed's programs: the sizer against cvxpy's own re-solve."""
    from sizing.technologies.piezohydraulic.convex import GPSizer
    objectives, inputs = _sizing_inputs(req, catalog)
    sample = inputs[::stride]

    def timed(sizer, items) -> tuple[float, list]:
        c0 = time.process_time()
        out = [sizer.solve(s) for s in items]
        return time.process_time() - c0, out

    fast, plain = GPSizer(objectives), GPSizer(objectives)
    for run in plain._runs.values():
        run.direct = False                      # cvxpy's own path for every solve
    for s in inputs:                            # compile every program (phase 1 and the relaxed one too)
        if all(r.compiled for r in fast._runs.values()):
            break
        fast.solve(s)
    fast_all = min(timed(fast, inputs)[0] for _ in range(repeat))
    fast_cpu, fast_res = min(timed(fast, sample) for _ in range(repeat))
    plain_cpu, plain_res = min(timed(plain, sample) for _ in range(repeat))
    worst = max((abs(getattr(a, k) / getattr(b, k) - 1) for a, b in zip(fast_res, plain_res)
                 for k in ("ratio", "wide_area", "voltage_fraction") if a.success and b.success), default=0.0)
    agree = sum(a.success == b.success and a.binding == b.binding for a, b in zip(fast_res, plain_res))
    print(f"sizing: {len(inputs)} programs ({sum(not r.success for r in fast_res)} of {len(sample)} sampled "
          f"infeasible) in {fast_all:.2f} s CPU, {1e3 * fast_all / len(inputs):.2f} ms each")
    print(f"sizing, every {stride}th program: {fast_cpu:.2f} s CPU against cvxpy's own re-solve {plain_cpu:.2f} s, "
          f"x{plain_cpu / fast_cpu:.1f} faster; {agree} of {len(sample)} agree on feasibility and binding, "
          f"ratio, bore and voltage within {worst:.1e} (relative); load average {os.getloadavg()[0]:.1f}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--requirements", default=str(ROOT / "studies" / "seed-requirements.toml"))
    parser.add_argument("--sizing", action="store_true", help="time only the geometric programs, old way and new")
    parser.add_argument("--stride", type=int, default=8, help="--sizing: every n-th program for cvxpy's own re-solve")
    args = parser.parse_args()
    req, sha = load_requirements(args.requirements)
    catalog = load_catalog()
    if args.sizing:
        sizing_speed(req, catalog, args.repeat, args.stride)
        return 0
    loads = [c["load_N"] for c in load_cases(req.load)]
    times, dc_times, pump_times, compliance_times, flips, fast_cpu, attached = [], [], [], [], [], [], []
    for _ in range(args.repeat + 1):
        t0, c0 = time.perf_counter(), time.process_time()
        out = solve(req, sha, catalog, fast=True)
        times.append(time.perf_counter() - t0)
        fast_cpu.append(time.process_time() - c0)
        t0, c0 = time.perf_counter(), time.process_time()
        full = solve(req, sha, catalog)
        flips.append((time.perf_counter() - t0, time.process_time() - c0, full.results["flips_cost"]["re_solves"]))
        dc_times.append(_timed(lambda: [parts_candidate(req, catalog, d)
                                        for d in dc_parts_designs(req, catalog, loads).designs]))
        pump_times.append(_timed(lambda: [pump_candidate(req, d) for d in pump_designs(req, catalog, loads).designs]))
        # what the default solve adds to --fast: the probability of compliance and its policy
        compliance_times.append(_timed(lambda: attached.append(compliance.attach(req, catalog, out.results,
                                                                                  out.stages))))
    counts = out.results["counts"]
    warm, dc_warm = min(times[1:]), min(dc_times[1:])
    print(f"seed solve: cold {times[0]:.2f} s, warm best {warm:.2f} s of {args.repeat} "
          f"(limit {LIMIT_S:g} s); DC from parts alone: warm {dc_warm:.2f} s for "
          f"{counts['dc_parts']['combinations']} combinations, {counts['dc_parts']['simulated']} simulated")
    print(f"piezohydraulic: combinations {counts['combinations']}, sized {counts['sized']}, "
          f"simulated {counts['simulated']}; candidates {len(out.results['candidates'])}")
    pump = counts.get("piezo_pump", {})
    pump_warm = min(pump_times[1:])
    print(f"piezo pump alone: warm {pump_warm:.2f} s (limit {PUMP_LIMIT_S:g} s) for {pump.get('combinations', 0)} "
          f"designs screened, {pump.get('simulated', 0)} simulated")
    rec = attached[-1]["summary"]["comparison"]["recommended"] or {}     # attach returns new results
    print(f"probability of compliance (the default solve over --fast): warm best {min(compliance_times[1:]):.2f} s, "
          f"{len(rec.get('examined', []))} designs examined by the policy; solve with it {warm + min(compliance_times[1:]):.2f} s, "
          f"--fast {warm:.2f} s")
    wall, cpu, re_solves = min(flips[1:])
    default = min(wall, cpu) + min(compliance_times[1:])
    print(f"flips: warm best {wall:.2f} s wall, {cpu:.2f} s CPU for {re_solves} re-solves; the default solve "
          f"(flips and compliance) about {default:.1f} s (limit {LIMIT_DEFAULT_S:g} s), x{default / warm:.1f} --fast")
    print(f"default against --fast, same machine: {wall + min(compliance_times[1:]):.1f} s wall, "
          f"{cpu + min(compliance_times[1:]):.1f} s CPU against {warm:.1f} s wall, {min(fast_cpu[1:]):.1f} s CPU "
          f"(the default solve took about {EARLIER_DEFAULT_S:g} s before its re-solves were narrowed)")
    print(f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    return 0 if warm <= LIMIT_S and pump_warm <= PUMP_LIMIT_S and default <= LIMIT_DEFAULT_S else 1


if __name__ == "__main__":
    sys.exit(main())
