"""Speed of `sizing diagnose --check` on a shipped campaign, against the
same work done by another revision of the code in the same run.

Each case of the withheld-effect check (every library effect at each of its
sizes, and the null cases) is one diagnosis of one campaign: the script
prints the CPU time (``time.process_time``, all threads: the machine may be
loaded, so CPU is the figure to compare) and the wall time of each case, the
median per campaign and the whole check. With ``--reference REV`` the same
cases are run first by revision REV of this repository (exported with
``git archive`` into a temporary folder, run in a subprocess), and the
verdicts of the two runs are compared case by case: a speed-up must not
change a verdict.

    python benchmarks/diagnose_speed.py [--campaign DIR] [--cases 0,5,30] [--workers N]
                                        [--reference REV] [--json FILE]

Figures recorded before the simulators' idle threads were made to sleep
(sizing/sim/__init__.py): the piezo campaign's --check took 442 s on a
busy 2-core machine, and a median of 106 s a campaign (DC 31 s) while the
independent sets were scored. Measured on the same busy machine (load 6-9
on 2 cores), the 31 cases of the piezo campaign's check one after the
other, the old code then this: CPU 188 s -> 111 s (median a campaign 6.3 s
-> 3.7 s), summed wall 607 s -> 369 s (median 16.7 s -> 11.4 s); every
case's diagnosis.json identical (the seconds aside). Three cases of the
DC campaign's check (0, 5, 10) against 14828dd in the same run: CPU 9.7 s
-> 2.7 s (median a campaign 3.0 s -> 0.9 s), verdicts unchanged. ``--workers 2``
(one process a core) was checked for identical verdicts
(tests/diagnose/test_check.py) but its wall time not yet measured on a
quiet machine.
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
OLD_CHECK_S = 442.0            # --check of the piezo campaign, busy machine, before (benchmark docstring)


def _cpu() -> float:
    """CPU seconds of this process and of its finished worker processes."""
    import resource

    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return time.process_time() + children.ru_utime + children.ru_stime


def _skip_cases(check, keep: set) -> None:
    """A revision whose check runs every case: the cases not in ``keep``
    (numbered in the check's order) are synthesised but not diagnosed."""
    from types import SimpleNamespace

    diagnose, count = check.diagnose_runs, [0]

    def only_kept(*args, **kwargs):
        count[0] += 1
        if count[0] - 1 in keep:
            return diagnose(*args, **kwargs)
        return SimpleNamespace(verdict={"effect": None, "shrink_holdout": 0.0}, seconds=0.0)

    check.diagnose_runs = only_kept


def measure(campaign: str, cases: list[int] | None, workers: int) -> dict:
    """Run the check's cases with the ``sizing`` importable here; {case: verdict, CPU, wall}."""
    from sizing.threads import single_threaded_blas

    single_threaded_blas()
    import inspect

    from sizing.diagnose import check
    from sizing.diagnose.bench import Bench
    from sizing.io.campaign import campaign_split, load_campaign

    loaded = load_campaign(campaign)
    holdout = [loaded.runs[-1].name]
    campaign_split(loaded, holdout)
    bench = Bench(loaded.kind, loaded.rig, loaded.runs, holdout)
    noise = check.campaign_noise(bench, 0)            # also compiles (or loads) the simulator kernels
    rows, last = [], [time.process_time(), time.perf_counter()]

    def progress(case):
        # a case's CPU is measurable here only when it ran in this process
        now = [time.process_time(), time.perf_counter()]
        rows.append({"truth": case.truth, "size": case.size, "predicted": case.predicted, "shrink": case.shrink,
                     "cpu_s": now[0] - last[0] if workers <= 1 else float("nan"), "wall_s": case.seconds})
        last[:] = now

    options = {}
    accepted = inspect.signature(check.check_runs).parameters
    if "only" in accepted:
        options["only"] = cases
    elif cases is not None:
        _skip_cases(check, set(cases))
    if "workers" in accepted:
        options["workers"] = workers
    start = [_cpu(), time.perf_counter()]
    result = check.check_runs(loaded.kind, loaded.rig, check.clean_inputs(bench), holdout, noise, seed=0,
                              progress=progress, **options)
    cpu, wall = _cpu() - start[0], time.perf_counter() - start[1]
    if "only" not in options and cases is not None:  # a revision without ``only``: the others were skipped
        rows = [rows[j] for j in cases]
    return {"cases": rows, "cpu_s": cpu, "wall_s": wall, "n_cases": len(result.cases)}


def measure_revision(rev: str, campaign: str, cases, workers: int) -> dict:
    """``measure`` run by revision ``rev`` in a subprocess."""
    with tempfile.TemporaryDirectory() as tree:
        archive = subprocess.run(["git", "-C", str(ROOT), "archive", rev], check=True, capture_output=True).stdout
        subprocess.run(["tar", "-x", "-C", tree], input=archive, check=True)
        out = Path(tree) / "measured.json"
        args = [sys.executable, __file__, "--campaign", str(Path(campaign).resolve()), "--worker", str(out),
                "--tree", tree, "--workers", str(workers)] + (["--cases", ",".join(map(str, cases))] if cases else [])
        subprocess.run(args, check=True, cwd=tree, env=dict(os.environ, PYTHONPATH=tree))
        return json.loads(out.read_text())


def summary(label: str, m: dict) -> str:
    import statistics

    cpu = [r["cpu_s"] for r in m["cases"]]
    wall = [r["wall_s"] for r in m["cases"]]
    return (f"{label:<10} {len(cpu):3d} cases: CPU {m['cpu_s']:7.1f} s (median a campaign {statistics.median(cpu):5.2f} s), "
            f"wall {m['wall_s']:7.1f} s (median a campaign {statistics.median(wall):5.2f} s)")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--campaign", default=str(ROOT / "studies/campaigns/piezo-prototype"))
    parser.add_argument("--cases", default="", help="comma-separated case numbers of the check (default: all)")
    parser.add_argument("--workers", type=int, default=1, help="processes for the check's cases")
    parser.add_argument("--reference", metavar="REV", help="a git revision to time on the same cases first")
    parser.add_argument("--json", type=Path, help="write both measurements here")
    parser.add_argument("--worker", type=Path, help=argparse.SUPPRESS)      # measure and write JSON here
    parser.add_argument("--tree", help=argparse.SUPPRESS)                   # the source tree to import
    args = parser.parse_args(argv)
    sys.path.insert(0, args.tree or str(ROOT))
    cases = [int(c) for c in args.cases.split(",")] if args.cases else None
    if args.worker:
        args.worker.write_text(json.dumps(measure(args.campaign, cases, args.workers), default=float))
        return 0
    reference = measure_revision(args.reference, args.campaign, cases, args.workers) if args.reference else None
    current = measure(args.campaign, cases, args.workers)
    if reference:
        print(summary(args.reference, reference))
    print(summary("this tree", current))
    changed = []
    if reference:
        for old, new in zip(reference["cases"], current["cases"]):
            if (old["truth"], old["size"], old["predicted"]) != (new["truth"], new["size"], new["predicted"]) \
                    or abs(old["shrink"] - new["shrink"]) > 1e-9:
                changed.append((old, new))
        print(f"verdicts changed: {len(changed)} of {len(current['cases'])}")
        for old, new in changed:
            print(f"  {old['truth']} size {old['size']}: {old['predicted']} ({old['shrink']:.4f}) -> "
                  f"{new['predicted']} ({new['shrink']:.4f})")
        print(f"CPU ratio (this tree / {args.reference}): {current['cpu_s'] / reference['cpu_s']:.2f}")
    if "piezo" in Path(args.campaign).name and not cases:
        print(f"--check wall {current['wall_s']:.0f} s against {OLD_CHECK_S:.0f} s recorded before (busy machine)")
    if args.json:
        args.json.write_text(json.dumps({"reference": reference, "current": current}, indent=2, default=float))
    return 1 if changed else 0


if __name__ == "__main__":
    sys.exit(main())
