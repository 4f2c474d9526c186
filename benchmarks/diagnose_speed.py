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
change a verdict. With one process (``--workers 1``, the default) each
case's whole diagnosis.json is compared (a digest of it, the seconds
aside). ``--folders DIR ...`` times ``sizing diagnose`` on campaign folders
instead (one diagnosis each, in this process; the holdout run named by the
folder's set's answers file, ``SET-answers/NAME.json``, else its last run),
for example a sample of the independent generator's campaigns.

    python benchmarks/diagnose_speed.py [--campaign DIR] [--cases 0,5,30] [--workers N]
                                        [--reference REV] [--json FILE]
    python benchmarks/diagnose_speed.py --folders DIR [DIR ...] [--reference REV] [--json FILE]

Today's figure, against the code before the piezo kernel's lanes (main at
6092192, whose simulator and bench are e9a0f29's: each candidate alone,
a run a call, a drive integrated in every call), both revisions in the
same run: every campaign of the independent generator's six sets, one
diagnosis each (``--folders gen/{piezo,dc}-{a,b,c}/*/ --reference main``,
2026-11-27 20:27-20:44 UTC, the shared 2-core machine at a load average
of 3.6-5.2). Median a campaign,
old -> new: the 33 piezo campaigns 11.69 s -> 10.54 s of CPU (wall 12.64 s
-> 11.43 s; set A, logged at 2 kHz, 14.49 -> 12.33 s of CPU; B 11.69 ->
10.04 s; C 10.30 -> 9.62 s), the 21 DC campaigns 1.00 -> 0.92 s, all 54
9.01 -> 8.17 s (wall 9.42 -> 8.88 s); summed CPU 470 s -> 426 s (x 0.91);
every diagnosis.json identical (the seconds aside). The same load makes
the old code's piezo median 12.6 s of wall against 10.4 s on the quiet
machine (docs/diagnosis-benchmarks.md).

Where a piezo campaign's time goes: the simulator's kernel is 80-85 % of
its CPU. A candidate's step is a chain of dependent floating-point
operations, latency-bound: 30-37 ns a step alone with its drive (stack
voltage and Bouc-Wen loop), 21-23 ns reading a drive integrated before,
16-20 ns in lanes (sizing/sim/piezohydraulic.py). The bench keeps the
drives it meets again (a fit's points change a seal or a leak, not the
drive) and simulates a fit's point on its training runs in one call. What
is left is mostly what cannot share a drive or a lane: the LuGre seal's
candidates (each its own step, two exponentials a sub-step: 60-75 ns a
step, a quarter of a campaign's CPU where it is fitted from several
starts), the amplifier's and the loop's (each its own drive), entrained
air.
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


def digest(found) -> str:
    """A digest of a diagnosis's diagnosis.json without its ``seconds``."""
    import hashlib

    doc = found.to_json()
    doc.pop("seconds", None)
    return hashlib.sha256(json.dumps(doc, sort_keys=True, default=float).encode()).hexdigest()


def _record_digests(check, digests: list) -> None:
    """Each diagnosis the check makes in this process leaves its digest in ``digests``."""
    diagnose = check.diagnose_runs

    def recorded(*args, **kwargs):
        found = diagnose(*args, **kwargs)
        digests.append(digest(found))
        return found

    check.diagnose_runs = recorded


def measure(campaign: str, cases: list[int] | None, workers: int) -> dict:
    """Run the check's cases with the ``sizing`` importable here; {case: verdict, CPU, wall}
    (and, in one process, the digest of each case's diagnosis.json)."""
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
    digests = []
    if workers <= 1:
        _record_digests(check, digests)
    start = [_cpu(), time.perf_counter()]
    result = check.check_runs(loaded.kind, loaded.rig, check.clean_inputs(bench), holdout, noise, seed=0,
                              progress=progress, **options)
    cpu, wall = _cpu() - start[0], time.perf_counter() - start[1]
    if "only" not in options and cases is not None:  # a revision without ``only``: the others were skipped
        rows = [rows[j] for j in cases]
    for row, code in zip(rows, digests):
        row["digest"] = code
    return {"cases": rows, "cpu_s": cpu, "wall_s": wall, "n_cases": len(result.cases)}


def holdout_of(folder: Path) -> str:
    """The holdout run of a campaign folder: the one its set's answers name
    (``SET-answers/NAME.json``, the independent generator's layout), else
    its last run."""
    answers = folder.parent.parent / f"{folder.parent.name}-answers" / f"{folder.name}.json"
    if answers.exists():
        return json.loads(answers.read_text())["holdout"]
    return sorted(p.stem for p in (folder / "runs").glob("*.csv"))[-1]


def measure_folders(folders: list[str]) -> dict:
    """``sizing diagnose FOLDER --holdout RUN`` in this process (nothing
    written) on each folder: CPU, wall and the digest of its diagnosis.json."""
    from sizing.threads import single_threaded_blas

    single_threaded_blas()
    from sizing.api.diagnosis import run_diagnose

    # loads and compiles (or loads) both technologies' kernels, not timed: a
    # revision exported for --reference compiles them in its first diagnosis
    run_diagnose(ROOT / "studies/campaigns/dc-motor", ["steps"])
    run_diagnose(ROOT / "studies/campaigns/piezo-prototype", ["steps"])
    rows = []
    for folder in map(Path, folders):
        start = [time.process_time(), time.perf_counter()]
        found = run_diagnose(folder, [holdout_of(folder)]).diagnosis
        rows.append({"truth": folder.name, "size": 0, "predicted": found.verdict["effect"] or "none",
                     "shrink": float(found.verdict["shrink_holdout"]), "digest": digest(found),
                     "cpu_s": time.process_time() - start[0], "wall_s": time.perf_counter() - start[1]})
    return {"cases": rows, "cpu_s": sum(r["cpu_s"] for r in rows), "wall_s": sum(r["wall_s"] for r in rows),
            "n_cases": len(rows)}


def measure_revision(rev: str, campaign: str, cases, workers: int, folders=None) -> dict:
    """``measure`` (``measure_folders`` with ``folders``) run by revision ``rev`` in a subprocess."""
    with tempfile.TemporaryDirectory() as tree:
        archive = subprocess.run(["git", "-C", str(ROOT), "archive", rev], check=True, capture_output=True).stdout
        subprocess.run(["tar", "-x", "-C", tree], input=archive, check=True)
        out = Path(tree) / "measured.json"
        args = [sys.executable, __file__, "--campaign", str(Path(campaign).resolve()), "--worker", str(out),
                "--tree", tree, "--workers", str(workers)] + (["--cases", ",".join(map(str, cases))] if cases else [])
        if folders:
            args += ["--folders"] + [str(Path(f).resolve()) for f in folders]
        subprocess.run(args, check=True, cwd=tree, env=dict(os.environ, PYTHONPATH=tree))
        return json.loads(out.read_text())


def summary(label: str, m: dict) -> str:
    import statistics

    cpu = [r["cpu_s"] for r in m["cases"] if r["cpu_s"] == r["cpu_s"]]     # a case in a worker: not measured
    wall = [r["wall_s"] for r in m["cases"]]
    median_cpu = f"{statistics.median(cpu):5.2f} s" if cpu else "-"
    return (f"{label:<10} {len(wall):3d} cases: CPU {m['cpu_s']:7.1f} s (median a campaign {median_cpu}), "
            f"wall {m['wall_s']:7.1f} s (median a campaign {statistics.median(wall):5.2f} s)")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--campaign", default=str(ROOT / "studies/campaigns/piezo-prototype"))
    parser.add_argument("--cases", default="", help="comma-separated case numbers of the check (default: all)")
    parser.add_argument("--workers", type=int, default=1, help="processes for the check's cases")
    parser.add_argument("--reference", metavar="REV", help="a git revision to time on the same cases first")
    parser.add_argument("--folders", nargs="+", metavar="DIR",
                        help="instead of the check: diagnose each of these campaign folders once (holdout: "
                             "the one its set's answers name, else its last run)")
    parser.add_argument("--json", type=Path, help="write both measurements here")
    parser.add_argument("--worker", type=Path, help=argparse.SUPPRESS)      # measure and write JSON here
    parser.add_argument("--tree", help=argparse.SUPPRESS)                   # the source tree to import
    args = parser.parse_args(argv)
    sys.path.insert(0, args.tree or str(ROOT))
    cases = [int(c) for c in args.cases.split(",")] if args.cases else None
    run = (lambda: measure_folders(args.folders)) if args.folders else \
        (lambda: measure(args.campaign, cases, args.workers))
    if args.worker:
        args.worker.write_text(json.dumps(run(), default=float))
        return 0
    reference = measure_revision(args.reference, args.campaign, cases, args.workers, args.folders) \
        if args.reference else None
    current = run()
    if reference:
        print(summary(args.reference, reference))
    print(summary("this tree", current))
    changed = []
    if reference:
        for old, new in zip(reference["cases"], current["cases"]):
            if (old["truth"], old["size"], old["predicted"]) != (new["truth"], new["size"], new["predicted"]) \
                    or abs(old["shrink"] - new["shrink"]) > 1e-9 or old.get("digest") != new.get("digest"):
                changed.append((old, new))
        compared = "diagnosis.json" if all("digest" in r for r in current["cases"]) else "verdicts"
        print(f"{compared} changed: {len(changed)} of {len(current['cases'])}")
        for old, new in changed:
            print(f"  {old['truth']} size {old['size']}: {old['predicted']} ({old['shrink']:.4f}) -> "
                  f"{new['predicted']} ({new['shrink']:.4f})")
        print(f"CPU ratio (this tree / {args.reference}): {current['cpu_s'] / reference['cpu_s']:.2f}")
    if "piezo" in Path(args.campaign).name and not cases and not args.folders:
        print(f"--check wall {current['wall_s']:.0f} s against {OLD_CHECK_S:.0f} s recorded before (busy machine)")
    if args.json:
        args.json.write_text(json.dumps({"reference": reference, "current": current}, indent=2, default=float))
    return 1 if changed else 0


if __name__ == "__main__":
    sys.exit(main())
