"""Memory and time per measured sample of `sizing fit dc-motor` and
`sizing diagnose` on a campaign at a given length, each command run in its
own process under an address-space limit (RLIMIT_AS).

    python benchmarks/memory_benchmark.py [--samples 1000000] [--limit-gb 4]

The campaign is the shipped DC rig (studies/campaigns/dc-motor/rig.toml)
driven by steps and a sine, simulated by the package's own closed loop with
2 um of sensor noise and split into three runs; ``--samples`` counts all
runs together (the accepted maximum is ``limits.Limits.samples``). Prints,
per command, the exit code, wall time, time per sample and the peak
resident memory (ru_maxrss of the child) against the limit; today's
figures are in docs/formats.md, beside the ``--max-samples`` limit.
"""
from __future__ import annotations

import argparse
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
RIG = REPO / "studies" / "campaigns" / "dc-motor" / "rig.toml"


def make_campaign(folder: Path, samples: int, rate_hz: float = 1000.0, seed: int = 0) -> Path:
    """A null DC campaign of ``samples`` samples in three runs (the shipped rig, no effect)."""
    from sizing.io.rig import load_rig
    from sizing.sim.rigs import dc_model

    (folder / "runs").mkdir(parents=True, exist_ok=True)
    shutil.copy(RIG, folder / "rig.toml")
    model = dc_model(load_rig(folder / "rig.toml"))
    rng = np.random.default_rng(seed)
    per_run = samples // 3
    for name in ("steps_a", "steps_b", "sine"):
        t = np.arange(per_run) / rate_hz
        if name == "sine":
            ref = 0.004 * np.sin(2 * np.pi * 0.5 * t)
        else:
            levels = rng.uniform(-0.008, 0.008, size=int(t[-1] / 0.5) + 2)
            ref = levels[(t / 0.5).astype(int)]
        from sizing.sim.dc_motor import simulate

        x = simulate(model, t, ref)["position_m"][0] + 2e-6 * rng.standard_normal(per_run)
        np.savetxt(folder / "runs" / f"{name}.csv", np.column_stack([t, ref, x]), delimiter=",",
                   header="time_s,reference_m,position_m", comments="", fmt="%.9g")
    return folder


def _limit(bytes_: int):
    def apply():
        resource.setrlimit(resource.RLIMIT_AS, (bytes_, bytes_))
    return apply


def run_limited(args: list[str], limit_bytes: int, cwd: Path) -> tuple[int, float, float, str]:
    """(exit code, seconds, peak RSS in bytes, stderr tail) of ``sizing ARGS`` under the limit."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "sizing.cli", *args], cwd=cwd, capture_output=True, text=True,
                          preexec_fn=_limit(limit_bytes))
    seconds = time.perf_counter() - start
    peak = max(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss, before) * 1024
    return done.returncode, seconds, peak, done.stderr[-400:]


COMMANDS = {
    "fit dc-motor": lambda c, out: ["fit", "dc-motor", *map(str, sorted((c / "runs").glob("*.csv"))),
                                     "--rig", str(c / "rig.toml"), "--holdout", "sine", "--out", str(out / "motor.toml")],
    "diagnose": lambda c, out: ["diagnose", str(c), "--holdout", "sine", "--out", str(out / "diagnosis")],
}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=1_000_000)
    parser.add_argument("--limit-gb", type=float, default=4.0)
    parser.add_argument("--commands", nargs="*", default=list(COMMANDS))
    a = parser.parse_args()
    limit = int(a.limit_gb * 2**30)
    with tempfile.TemporaryDirectory() as tmp:
        campaign = make_campaign(Path(tmp) / "campaign", a.samples)
        print(f"campaign: {a.samples} samples in 3 runs; limit {a.limit_gb:g} GB of address space")
        for name in a.commands:
            code, seconds, peak, err = run_limited(COMMANDS[name](campaign, Path(tmp)), limit, REPO)
            print(f"{name:14s} exit {code}  {seconds:7.1f} s  {seconds / a.samples * 1e6:6.1f} us/sample  "
                  f"peak RSS {peak / 2**30:.2f} GB" + (f"\n  {err}" if code else ""))


if __name__ == "__main__":
    main()
