"""How fast the tool answers, each figure beside the same work done the old
way:

- ``sizing --help`` and an input error (``sizing solve missing.toml``): a
  fresh interpreter, best of ``--repeat``, beside the same command with
  what the command line imported before its imports were deferred
  imported first (``EAGER``; measured in the same run);
- the seed solve with ``--fast`` (``sizing solve studies/seed-requirements.toml
  --fast``, results and report written), warm: the second and later runs of
  one process, best of ``--repeat``, with its profile's top entries by
  module family (``--profile``); and the whole command as a user runs it
  again (``solve_fast cmd``: a fresh interpreter with its bytecode, numba
  kernels and catalogs cached: imports, kernel loading, solve and files);
- with ``--suite``: the README's test command (minutes; busy CPU);
- with ``--diagnose-check``: ``sizing diagnose --check`` on the shipped
  piezo campaign (minutes).

The solve, suite and check figures stand beside the reference figures
below (``REFERENCES``: each the same command on this 2-core machine before
the work it names); help and the input error beside ``EAGER``, in the same
run.

    python benchmarks/tool_speed.py [--repeat 3] [--profile] [--suite] [--diagnose-check]

Prints each figure, its reference, the ratio and the load average (the
machine is shared: a figure taken under load is slower by about the load
over the core count). Exits 1 when a quick figure (help, input error)
exceeds its limit. Today's figures, and where the solve's time goes, are
in docs/validation.md, "Simulator and solve speed".
"""
from __future__ import annotations

import argparse
import cProfile
import io
import os
import pstats
import shlex
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SEED = ROOT / "studies" / "seed-requirements.toml"
PIEZO_CAMPAIGN = ROOT / "studies" / "campaigns" / "piezo-prototype"

# (reference seconds, how the reference was done, limit seconds): the
# --fast solve before results.json's encoder and the deferred imports, the
# test command when every test ran in one tier, and the piezo campaign's
# check before the simulators' idle threads slept
REFERENCES = {
    "solve_fast": (9.3, "seed solve --fast, warm, before the JSON and import work", 2.0),
    "suite": (12 * 60.0, "README command, every test in one tier, 936 tests", 180.0),
    "diagnose_check": (442.0, "diagnose --check, piezo campaign, busy machine", 60.0),
}


def _load() -> str:
    return " ".join(f"{x:.1f}" for x in os.getloadavg())


LIMITS = {"help": 0.5, "input_error": 1.0}
# the reference for help and an input error, imported first: every module
# of sizing.api (the fits' numba and scipy.signal with them) and the engine
# (cvxpy), as the command line imported them before its imports were deferred
EAGER = tuple(f"sizing.api.{m}" for m in ("catalogs", "checks", "diagnosis", "evaluation", "fitting", "output",
                                           "solution", "studies")) + ("sizing.engine.solve",)


# A fresh interpreter as a user's shell starts one: Python writes and reads
# its bytecode cache (an environment with PYTHONDONTWRITEBYTECODE set
# compiles every module of sizing from source at each start, 0.2-0.3 s).
USER_ENV = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}


def _fresh(*args: str, eager: bool = False) -> float:
    """Wall seconds of ``sizing ARGS`` in a fresh interpreter (its exit code
    ignored); ``eager``: with every module of sizing.api imported first."""
    first = "".join(f"import {m}; " for m in EAGER) if eager else ""
    code = f"import sys; {first}from sizing.cli import main; main(sys.argv[1:])"
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-c", code, *args], capture_output=True, cwd=ROOT, env=USER_ENV)
    return time.perf_counter() - t0


def _solve_fast(out: Path) -> None:
    from sizing.cli import main
    try:
        main(["solve", str(SEED), "--out", str(out), "--quiet", "--fast"])
    except SystemExit as exc:
        if exc.code:
            raise


def _profile_families(profile: cProfile.Profile, top: int = 12) -> str:
    """Cumulative seconds of the heaviest functions of sizing/, and total
    own time per top-level package (numpy, cvxpy, sizing.engine, ...)."""
    stats = pstats.Stats(profile)
    own: dict[str, float] = {}
    for (path, _, _), (_, _, tottime, _, _) in stats.stats.items():
        parts = Path(path).parts
        if "sizing" in parts and "site-packages" not in parts:
            family = "sizing." + parts[parts.index("sizing") + 1].removesuffix(".py")
        elif "site-packages" in parts:
            family = parts[parts.index("site-packages") + 1]
        elif path == "~":
            family = "compiled (solvers, numba kernels, builtins)"
        else:
            family = "python"
        own[family] = own.get(family, 0.0) + tottime
    lines = ["own time by package (s): " + ", ".join(f"{k} {v:.2f}" for k, v in
                                                     sorted(own.items(), key=lambda kv: -kv[1])[:top])]
    text = io.StringIO()
    pstats.Stats(profile, stream=text).sort_stats("cumulative").print_stats(r"/sizing/", top)
    lines += [line for line in text.getvalue().splitlines() if "/sizing/" in line]
    return "\n".join(lines)


def _row(name: str, seconds: float) -> tuple[str, bool]:
    ref, how, limit = REFERENCES[name]
    over = limit is not None and seconds > limit
    return (f"{name:<15} {seconds:8.2f} s   reference {ref:7.1f} s ({how})   x{ref / seconds:5.1f} faster"
            f"   limit {limit:g} s{'  EXCEEDED' if over else ''}   load {_load()}"), over


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--profile", action="store_true", help="profile one warm --fast solve")
    parser.add_argument("--suite", action="store_true", help="also time the README's test command")
    parser.add_argument("--diagnose-check", action="store_true", help="also time diagnose --check (piezo campaign)")
    args = parser.parse_args()
    failed = False
    for name, cmd in (("help", ("--help",)), ("input_error", ("solve", "missing-requirements.toml"))):
        new = min(_fresh(*cmd) for _ in range(args.repeat))
        old = min(_fresh(*cmd, eager=True) for _ in range(args.repeat))
        over = new > LIMITS[name]
        print(f"{name:<15} {new:8.2f} s   eager imports {old:7.2f} s (same run)   x{old / new:5.1f} faster"
              f"   limit {LIMITS[name]:g} s{'  EXCEEDED' if over else ''}   load {_load()}", flush=True)
        failed |= over
    with tempfile.TemporaryDirectory() as tmp:
        _solve_fast(Path(tmp) / "cold")                       # numba's cache, cvxpy's problems, imports
        warm, cpu = [], []
        for i in range(args.repeat):
            t0, c0 = time.perf_counter(), time.process_time()
            _solve_fast(Path(tmp) / f"warm{i}")
            warm.append(time.perf_counter() - t0)
            cpu.append(time.process_time() - c0)
        print(_row("solve_fast", min(warm))[0], flush=True)
        print(f"{'solve_fast cpu':<15} {min(cpu):8.2f} s   (every thread's CPU time: steadier than wall time "
              f"on a shared machine)", flush=True)
        command = min(_fresh("solve", str(SEED), "--out", str(Path(tmp) / f"fresh{i}"), "--quiet", "--fast")
                      for i in range(args.repeat))
        print(f"{'solve_fast cmd':<15} {command:8.2f} s   (the whole command in a fresh interpreter, warm caches: "
              f"imports, cached kernels loaded, solve, files)   load {_load()}", flush=True)
        if args.profile:
            profile = cProfile.Profile()
            profile.runcall(_solve_fast, Path(tmp) / "profiled")
            print(_profile_families(profile), flush=True)
    if args.suite:
        command = next(line for line in (ROOT / "README.md").read_text().splitlines()
                       if "pip install -e '.[test]'" in line).rpartition("&& ")[2]
        t0 = time.perf_counter()
        subprocess.run(shlex.split(command), cwd=ROOT, capture_output=True)
        print(_row("suite", time.perf_counter() - t0)[0], flush=True)
    if args.diagnose_check:
        print(_row("diagnose_check", _fresh("diagnose", str(PIEZO_CAMPAIGN), "--check"))[0], flush=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
