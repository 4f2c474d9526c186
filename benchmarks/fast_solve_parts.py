"""CPU time of the seed's ``solve --fast`` outside the piezohydraulic sizing,
each piece beside the same work done the old way, on the same inputs and
in the same run, with a check that both give the same answer to the bit:

- the DC parts search's reason counts (``technologies/dc_motor/search.py``):
  each gear x screw row and each statically infeasible row labelled by the
  first check it misses, as strings compared per reason (old) or as
  integer codes counted by ``bincount``;
- the DC structure (``technologies/dc_motor/structure.py``): nut, rod and
  housing bisected for every screened combination (old) or once per
  distinct row (``once_per_distinct``);
- the DC simulator's reference lookup (``sim/dc_motor.py``): numba's
  ``np.interp`` on a scalar (old, three arrays a call) or ``_interp``, in a
  loop of as many lookups as the seed's DC simulations make;
- the pump simulator (``sim/pump.py``): its step's functions left to LLVM
  (old, the module's source without ``inline="always"``, compiled outside
  the timing) or inlined by numba, on the seed's and the low-duty
  solve's pump candidates;
- the piezohydraulic designs' build (``technologies/piezohydraulic/designs.py``
  ``_build``): each design's candidate row copied out of the batch
  (``Candidates.take([i])``, old) or a one-row view (``Candidates.rows``),
  and its force path read from the members' arrays (old) or from lists
  made once (``force_path.listed``), on the seed's built designs;
- the stages side by side (``engine/solve.py`` ``_stages``): the seed's
  ``--fast`` solve in this process, warm, results written, with every
  technology's stage run one after another (old) or those marked
  ``Technology.alongside`` (the DC motor and the piezo pump) in a worker
  thread beside the piezohydraulic stage (forced here: the solve does so
  only when ``threads.core_to_spare``): CPU of the process, CPU of the
  main thread (the wall time of a quiet two-core machine follows it) and
  wall time, and results.json the same (its run time aside);
- the whole command (``sizing solve studies/seed-requirements.toml --fast``,
  a fresh process each time, warm caches), with the collector's full pass
  every 10 gen-1 passes (Python's default, old) or every
  ``FULL_COLLECTION_EVERY`` (``api/output.py``), and its CPU by part.

    python benchmarks/fast_solve_parts.py [--repeat 3] [--only piezo_build,stages_alongside]

CPU is user + system time (``time.process_time``, ``getrusage`` for the
child processes), best of ``--repeat``: the machine is shared, and CPU time
is what the other jobs do not change much.

Each reference (marked old above) is the straightforward version of the
same work, run beside it here. Today's figures are in docs/validation.md,
"How the solve is made fast".
"""
from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")      # as the command line runs

import numpy as np  # noqa: E402

REPO = Path(__file__).resolve().parents[1]
SEED = REPO / "studies" / "seed-requirements.toml"


def best(fn, repeat: int) -> tuple[float, object]:
    """Least CPU of ``repeat`` calls of ``fn`` and its last answer."""
    times, out = [], None
    for _ in range(repeat):
        t = time.process_time()
        out = fn()
        times.append(time.process_time() - t)
    return min(times), out


def seed_inputs():
    from sizing.engine.loads import load_cases
    from sizing.io.catalog import load_catalog
    from sizing.io.requirements import load_requirements
    req, _ = load_requirements(SEED)
    return req, load_catalog(None), [c["load_N"] for c in load_cases(req.load)]


def reason_counts(repeat: int) -> None:
    """The gear x screw rows' first missed check counted both ways."""
    rng = np.random.default_rng(0)
    n = 500_000                                   # the seed's gear x screw rows
    conds = [rng.random(n) < p for p in (0.01, 0.3, 0.1, 0.2)]
    names = ["temperature", "blocked_force", "gear_torque", "speed"]

    def old():
        label = np.select(conds, names, "")
        counts = {r: int(np.sum(label == r)) for r in set(label) - {""}}
        return counts, label == ""

    def new():
        code = np.select(conds, np.arange(1, 5), 0)
        counts = {r: int(k) for r, k in zip(names, np.bincount(code, minlength=5)[1:]) if k}
        return counts, code == 0
    t_old, (c_old, ok_old) = best(old, repeat)
    t_new, (c_new, ok_new) = best(new, repeat)
    same = c_old == c_new and np.array_equal(ok_old, ok_new)
    print(f"DC search reason counts ({n} rows): {t_old:.3f} s strings, {t_new:.3f} s codes "
          f"({t_old / t_new:.1f}x), same counts: {same}")


def structure(repeat: int) -> None:
    """The seed's screened DC combinations' structure, every row against
    each distinct row once."""
    from sizing.technologies.dc_motor import search, structure as st
    req, cat, loads = seed_inputs()
    rows = {}
    size = st.size

    def capture(values, travel, peak, holding, rev, screw_length):
        if len(np.atleast_1d(peak)) > len(rows.get("peak", ())):
            rows.update(values=values, travel=travel, peak=peak, holding=holding, rev=rev, length=screw_length)
        return size(values, travel, peak, holding, rev, screw_length)
    st.size = capture
    try:
        search.search(cat, req, loads)
    finally:
        st.size = size
    v, F = rows["values"], st.ULTIMATE_FACTOR * np.asarray(rows["peak"], float)
    shaft = st.shaft_diameter(v["screw_mass_per_length"])

    def every_row():
        return st.nut_diameter(v["screw_nut_mass"], shaft), st.rod(F, shaft, rows["travel"])

    def distinct_rows():
        return (st.once_per_distinct(st.nut_diameter, v["screw_nut_mass"], shaft),
                st.once_per_distinct(st.rod, F, shaft, travel=rows["travel"]))
    t_old, (nut_old, rod_old) = best(every_row, repeat)
    t_new, (nut_new, rod_new) = best(distinct_rows, repeat)
    def bits(a, b):
        a, b = np.broadcast_arrays(a, b)
        return a.tobytes() == b.tobytes()
    same = bits(nut_old, nut_new) and all(bits(rod_old[k], rod_new[k]) for k in rod_old)
    print(f"DC structure, nut and rod of {len(F)} screened combinations: {t_old:.3f} s every row, "
          f"{t_new:.3f} s once per distinct row ({t_old / t_new:.1f}x), bit-identical: {same}")


def reference_lookup(repeat: int) -> None:
    """numba's np.interp against _interp, the same lookups."""
    import numba

    from sizing.sim.dc_motor import _interp

    @numba.njit(cache=False)
    def with_np_interp(ts, xp, fp):
        s = 0.0
        for t in ts:
            s += np.interp(t, xp, fp)
        return s

    @numba.njit(cache=False)
    def with_scalar(ts, xp, fp):
        s = 0.0
        for t in ts:
            s += _interp(t, xp, fp)
        return s
    xp = np.linspace(0.0, 0.4, 801)
    fp = np.full_like(xp, 0.05)
    fp[0] = 0.0
    ts = np.arange(1, 2_000_001) * 2e-7          # two million ticks over 0.4 s (the seed's DC runs: millions)
    with_np_interp(ts[:10], xp, fp), with_scalar(ts[:10], xp, fp)       # compiled outside the timing
    t_old, a = best(lambda: with_np_interp(ts, xp, fp), repeat)
    t_new, b = best(lambda: with_scalar(ts, xp, fp), repeat)
    print(f"DC reference lookup, {len(ts)} ticks: {t_old:.3f} s np.interp, {t_new:.3f} s _interp "
          f"({t_old / t_new:.1f}x), same sum to the bit: {a == b}")


def pump_kernel(repeat: int) -> None:
    """The pump kernel as the module is and with its step's functions not inlined,
    on the rows the seed's and low-duty solves simulate."""
    import importlib.util

    import sizing.sim.pump as pump
    from sizing.engine.loads import load_cases
    from sizing.io.catalog import load_catalog
    from sizing.io.requirements import load_requirements
    from sizing.technologies.piezo_pump import designs
    source = Path(pump.__file__).read_text().replace(', inline="always"', "")
    folder = Path(tempfile.mkdtemp(prefix="pump-not-inlined-"))
    (folder / "pump_not_inlined.py").write_text(source.replace("from ..physics", "from sizing.physics")
                                                .replace("from .params", "from sizing.sim.params"))
    spec = importlib.util.spec_from_file_location("pump_not_inlined", folder / "pump_not_inlined.py")
    old = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = old                  # its dataclass looks its module up
    spec.loader.exec_module(old)
    rows, run = [], pump._run

    def capture(P, out):
        rows.append(P.copy())
        run(P, out)
    pump._run = capture
    try:
        for path in (SEED, SEED.with_name("seed-requirements-low-duty.toml")):
            req = load_requirements(path)[0]
            designs.pump_designs(req, load_catalog(None), [c["load_N"] for c in load_cases(req.load)])
    finally:
        pump._run = run

    def every(kernel):
        outs = [np.zeros((len(P), len(pump.OUTPUTS))) for P in rows]
        for P, out in zip(rows, outs):
            kernel(P, out)
        return outs
    every(old._run)                               # compiled outside the timing
    t_old, a = best(lambda: every(old._run), repeat)
    t_new, b = best(lambda: every(run), repeat)
    same = all(x.tobytes() == y.tobytes() for x, y in zip(a, b))
    print(f"pump simulations ({sum(len(P) for P in rows)} runs): {t_old:.3f} s not inlined, "
          f"{t_new:.3f} s inlined ({t_old / t_new:.2f}x), bit-identical: {same}")


def piezo_build(repeat: int) -> None:
    """The seed's built piezohydraulic designs split into one-row candidates
    and their force paths listed, both ways."""
    from sizing.technologies.piezohydraulic import designs, force_path
    from sizing.technologies.piezohydraulic.parts import Candidates
    from sizing.technologies.piezohydraulic.records import PiezoBrief
    from sizing.technologies.piezohydraulic.search import enumerate_combos
    req, cat, _ = seed_inputs()
    brief = PiezoBrief.of(req)
    built = [d for d in designs.designs(brief, cat, designs.size(
        brief, cat, [c for c in enumerate_combos(req, cat) if not c.pruned])) if d.built]
    c = Candidates(**{name: np.concatenate([getattr(d.cand, name) for d in built])
                      for name in Candidates.__dataclass_fields__})
    members = force_path.members(c)

    def old():
        return ([c.take([i]) for i in range(len(c))],
                [force_path.as_list(members, i, "m", None) for i in range(len(c))])

    def new():
        listed = force_path.listed(members)
        return c.rows(), [force_path.as_list(listed, i, "m", None) for i in range(len(c))]
    t_old, (rows_old, paths_old) = best(old, repeat)
    t_new, (rows_new, paths_new) = best(new, repeat)
    same = paths_old == paths_new and all(
        getattr(a, k).tobytes() == getattr(b, k).tobytes() for a, b in zip(rows_old, rows_new)
        for k in Candidates.__dataclass_fields__)
    print(f"piezohydraulic build, {len(c)} designs' rows and force paths: {t_old:.3f} s copies and arrays, "
          f"{t_new:.3f} s views and lists ({t_old / t_new:.1f}x), bit-identical: {same}")


def stages_alongside(repeat: int) -> None:
    """The --fast solve in this process with the stages one after another,
    then with those that may run beside the piezohydraulic stage."""
    import dataclasses
    import json
    import shutil

    from sizing.api import solve
    from sizing.engine import solve as engine_solve
    from sizing.technologies import registry
    from sizing.threads import core_to_spare
    out = Path(tempfile.mkdtemp(prefix="fast-solve-stages-"))
    techs = {t.name: t for t in registry.technologies()}
    spare_now = core_to_spare()
    engine_solve.core_to_spare = lambda: True       # side by side whatever the load: the mechanism's figures

    def run(alongside: bool, k: int) -> tuple[float, float, float, dict]:
        for name, t in techs.items():
            registry.register(dataclasses.replace(t, alongside=t.alongside and alongside))
        folder = out / f"{alongside}-{k}"
        t0, c0, m0 = time.perf_counter(), time.process_time(), time.thread_time()
        solve(SEED, folder, fast=True)
        figures = time.perf_counter() - t0, time.process_time() - c0, time.thread_time() - m0
        results = json.loads((folder / "results.json").read_text())
        results.pop("runtime_s")
        shutil.rmtree(folder)
        return (*figures, results)
    try:
        run(True, -1)                                   # numba's caches, plotly's validators
        runs = {False: [], True: []}
        for k in range(repeat):
            for alongside in (False, True):
                runs[alongside].append(run(alongside, k))
    finally:
        for t in techs.values():
            registry.register(t)
        engine_solve.core_to_spare = core_to_spare
    (w_old, c_old, m_old), (w_new, c_new, m_new) = ([min(r[i] for r in runs[a]) for i in range(3)]
                                                    for a in (False, True))
    same = runs[False][0][3] == runs[True][0][3]
    print(f"sizing solve seed --fast in this process, warm: one stage after another {c_old:.2f} s CPU "
          f"({m_old:.2f} s of it in the main thread), wall {w_old:.2f} s; DC and pump beside the "
          f"piezohydraulic stage {c_new:.2f} s CPU ({m_new:.2f} s in the main thread), wall {w_new:.2f} s; "
          f"same results.json: {same}; load average {os.getloadavg()[0]:.1f} "
          f"(a core to spare now: {spare_now}; the solve puts its stages side by side only then)")


SOLVE = """
import sys
from sizing.api import output
output.FULL_COLLECTION_EVERY = int(sys.argv[1])
sys.argv = ["sizing", "solve", sys.argv[2], "--fast", "--out", sys.argv[3]]
from sizing.cli import main
main()
"""


def whole_solve(repeat: int) -> None:
    """The command in a fresh process, CPU of the child (user + system)."""
    out = Path(tempfile.mkdtemp(prefix="fast-solve-"))
    figures = {}
    for label, every in (("full pass every 10 gen-1 passes", 10), ("every FULL_COLLECTION_EVERY", None)):
        from sizing.api.output import FULL_COLLECTION_EVERY
        every = every or FULL_COLLECTION_EVERY
        subprocess.run([sys.executable, "-c", SOLVE, str(every), str(SEED), str(out / "warm")],
                       check=True, capture_output=True)
        times = []
        for k in range(repeat):
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            subprocess.run([sys.executable, "-c", SOLVE, str(every), str(SEED), str(out / f"{every}-{k}")],
                           check=True, capture_output=True)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            times.append(after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)
        figures[label] = min(times)
    (old, t_old), (new, t_new) = figures.items()
    print(f"sizing solve seed --fast, CPU of the process: {t_old:.2f} s ({old}), {t_new:.2f} s ({new}); "
          f"load average {os.getloadavg()[0]:.1f}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--only", default="", help="comma-separated parts to run (default: all)")
    args = ap.parse_args()
    parts = (reason_counts, structure, reference_lookup, pump_kernel, piezo_build, stages_alongside, whole_solve)
    only = set(filter(None, args.only.split(",")))
    for part in parts:
        if not only or part.__name__ in only:
            part(args.repeat)


if __name__ == "__main__":
    main()
