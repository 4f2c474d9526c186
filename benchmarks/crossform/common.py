"""Shared pieces of the cross-form generator: RK4, noise, Pade delay,
writers, and the case sets read from data files (``load_set``). numpy/scipy
only (no sizing import)."""
from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy import signal


def rk4(f, t, x, dt):
    """One classical Runge-Kutta 4 step of x' = f(t, x)."""
    k1 = f(t, x)
    k2 = f(t + 0.5 * dt, x + 0.5 * dt * k1)
    k3 = f(t + 0.5 * dt, x + 0.5 * dt * k2)
    k4 = f(t + dt, x + dt * k3)
    return x + dt / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)


def pade_delay(t: np.ndarray, y: np.ndarray, tau: float) -> np.ndarray:
    """y through a second-order Pade approximant of exp(-s tau)
    (1 - s tau/2 + (s tau)^2/12) / (1 + s tau/2 + (s tau)^2/12), discretised
    by the bilinear transform on the log grid, starting at rest at y[0]."""
    if tau <= 0:
        return y.copy()
    fs = 1.0 / float(np.median(np.diff(t)))
    num = [tau * tau / 12.0, -tau / 2.0, 1.0]
    den = [tau * tau / 12.0, tau / 2.0, 1.0]
    b, a = signal.bilinear(num, den, fs=fs)
    return y[0] + signal.lfilter(b, a, y - y[0])


def pink(n: int, rng) -> np.ndarray:
    """Unit-rms 1/f noise (white noise shaped by 1/sqrt(f) in frequency)."""
    w = np.fft.rfft(rng.normal(size=n))
    f = np.arange(w.size, dtype=float)
    f[0] = 1.0
    x = np.fft.irfft(w / np.sqrt(f), n)
    return x / (np.std(x) or 1.0)


def measure(y: np.ndarray, rng, white: float, flicker: float, lsb: float) -> np.ndarray:
    """A sensor reading of y: white (rms ``white``), 1/f (rms ``flicker``)
    and quantisation to ``lsb``."""
    out = y + white * rng.normal(size=y.size) + flicker * pink(y.size, rng)
    return np.round(out / lsb) * lsb if lsb > 0 else out


def position_reading(t, y, effects: dict, rng, sensor: dict, lsb: float, drift_shape) -> np.ndarray:
    """The logged position of a clean output y: Pade delay and thermal drift
    (``drift_shape(t)`` from 0 to about 1, times effects["drift"] of the
    span) when asked, then the sensor (``measure``; white 0.08 %, 1/f 0.02 %
    of the span unless ``sensor`` says otherwise)."""
    if "delay_s" in effects:
        y = pade_delay(t, y, effects["delay_s"])
    if "drift" in effects:
        y = y + effects["drift"] * np.ptp(y) * drift_shape(t)
    span = float(np.ptp(y)) or 1e-3
    return measure(y, rng, sensor.get("white", 8e-4) * span, sensor.get("flicker", 2e-4) * span,
                   sensor.get("lsb", lsb))


def write_campaign(folder: Path, rig_toml: str, runs: dict[str, dict[str, np.ndarray]]) -> Path:
    """Write rig.toml and runs/NAME.csv (columns in the dict's order)."""
    folder = Path(folder)
    (folder / "runs").mkdir(parents=True, exist_ok=True)
    (folder / "rig.toml").write_text(rig_toml)
    for name, cols in runs.items():
        keys = list(cols)
        data = np.column_stack([cols[k] for k in keys])
        np.savetxt(folder / "runs" / f"{name}.csv", data, delimiter=",", header=",".join(keys),
                   comments="", fmt="%.9g")
    return folder


@dataclass(frozen=True)
class Case:
    """One campaign of a case set: ``truth`` is the library effect a right
    diagnosis names ("none" for a null case, "outside:<what>" for an
    effect the library does not hold, "a+b" for a pair); ``effects`` and
    ``options`` are the generator's; ``seed`` the campaign's noise seed."""

    name: str
    technology: str
    truth: str
    effects: dict
    options: dict
    seed: int


@dataclass(frozen=True)
class CaseSet:
    """A case set of a generator, as its manifest declares it."""

    name: str
    purpose: str
    seed_offset: int
    cases: tuple

    def case(self, name: str) -> Case:
        return next(c for c in self.cases if c.name == name)


TECHNOLOGIES = ("dc_motor", "piezohydraulic")


def manifest(folder: Path) -> dict:
    """The manifest of a folder of case sets (``sets/manifest.json``):
    {"seed_base": int, "sets": [{"name", "file", "seed_offset", "purpose"}]}."""
    return json.loads((Path(folder) / "manifest.json").read_text())


def load_set(folder: Path, name: str) -> CaseSet:
    """A case set read from ``folder`` (its data file named in the manifest).
    The seed of a case is seed_base + the set's seed_offset + its index in
    its technology's table."""
    m = manifest(folder)
    entry = next((s for s in m["sets"] if s["name"] == name), None)
    if entry is None:
        raise KeyError(f"no case set {name!r} in {folder} (sets: {', '.join(set_names(folder))})")
    tables = json.loads((Path(folder) / entry["file"]).read_text())
    seed0 = m["seed_base"] + entry["seed_offset"]
    cases = tuple(Case(c["name"], tech, c["truth"], c.get("effects", {}), c.get("options", {}), seed0 + k)
                  for tech in TECHNOLOGIES for k, c in enumerate(tables.get(tech, [])))
    return CaseSet(name, entry["purpose"], entry["seed_offset"], cases)


def set_names(folder: Path) -> list[str]:
    return [s["name"] for s in manifest(folder)["sets"]]
