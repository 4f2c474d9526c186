"""A technology is named only in its own folder, the registry and the
catalogs: every other module of ``sizing/`` reaches technologies through
``technologies.registry``.

The modules that still name one are listed below with how many times; the
list may only shrink (a module that names a technology more often, or a
new module that names one, fails). Physics, simulators, rigs, fits and
diagnosis effects are models of one kind of hardware and keep their
names; the others are the work left."""
from __future__ import annotations

import re
from pathlib import Path

from sizing.technologies import registry

PACKAGE = Path(__file__).resolve().parents[2] / "sizing"
HOME = "technologies/"

# module (relative to sizing/) -> how many times it names a technology today
STILL_NAMED = {
    "api/fitting.py": 6,
    "cli.py": 1,
    "diagnose/bench.py": 11,
    "diagnose/check.py": 2,
    "diagnose/diagnosis.py": 2,
    "diagnose/effects/__init__.py": 8,
    "diagnose/effects/amplifier_slew_limit.py": 2,
    "diagnose/effects/backlash.py": 4,
    "diagnose/effects/base.py": 2,
    "diagnose/effects/coulomb_friction.py": 4,
    "diagnose/effects/current_saturation.py": 4,
    "diagnose/effects/fluid_compressibility.py": 3,
    "diagnose/effects/leakage.py": 2,
    "diagnose/effects/no_return.py": 1,
    "diagnose/effects/seal_stick_slip.py": 3,
    "diagnose/effects/sensor_delay.py": 2,
    "diagnose/effects/sensor_vibration.py": 5,
    "diagnose/effects/stack_creep.py": 2,
    "diagnose/effects/viscous_damping.py": 1,
    "diagnose/floor.py": 2,
    "diagnose/recalibrate.py": 4,
    "diagnose/synth.py": 2,
    "engine/evaluate.py": 4,
    "engine/flip.py": 10,
    "engine/judge.py": 13,
    "engine/records.py": 12,
    "engine/resolve.py": 18,
    "engine/sized.py": 9,
    "engine/solve_summary.py": 1,
    "fit/dc_motor.py": 4,
    "io/campaign.py": 1,
    "io/design.py": 3,
    "io/rig.py": 4,
    "io/runs.py": 2,
    "limits.py": 2,
    "physics/dc_motor.py": 1,
    "physics/geometry.py": 2,
    "physics/hydraulics.py": 1,
    "physics/motor.py": 1,
    "physics/pump.py": 1,
    "physics/sensor_mount.py": 2,
    "physics/structure.py": 1,
    "physics/thermal.py": 1,
    "sim/dc_motor.py": 2,
    "sim/piezohydraulic.py": 1,
    "sim/pump.py": 1,
    "sim/rigs.py": 2,
}


def technology_words() -> list[str]:
    """The technology folders' names and their labels."""
    folders = {p.name for p in (PACKAGE / "technologies").iterdir() if (p / "technology.py").exists()}
    labels = {t.label for t in registry.technologies() if t.name in folders}
    return sorted(folders | labels)


def named(text: str, words: list[str]) -> int:
    pattern = re.compile(r"(?<![A-Za-z0-9_])(" + "|".join(re.escape(w) for w in words) + r")(?![A-Za-z0-9_])")
    return len(pattern.findall(text))


def found() -> dict[str, int]:
    words = technology_words()
    out = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        rel = path.relative_to(PACKAGE).as_posix()
        if rel.startswith(HOME):
            continue
        n = named(path.read_text(encoding="utf-8"), words)
        if n:
            out[rel] = n
    return out


def test_the_words_are_the_folders_and_their_labels():
    words = technology_words()
    assert {"piezohydraulic", "dc_motor", "piezo_pump", "DC motor", "piezo pump"} <= set(words)


def test_the_scan_counts_whole_words_only():
    words = ["dc_motor", "piezo pump"]
    assert named("fit_dc_motor(); the dc_motor rig; a piezo pump", words) == 2
    assert named("piezo_pumps", ["piezo_pump"]) == 0


def test_no_module_names_a_technology_more_than_the_list_allows():
    now = found()
    grown = {k: (v, STILL_NAMED.get(k, 0)) for k, v in now.items() if v > STILL_NAMED.get(k, 0)}
    assert not grown, ("these modules name a technology (found, allowed); reach it through "
                       f"technologies.registry instead: {grown}")


def test_the_list_only_shrinks():
    """A module that names technologies less often than listed: lower its
    entry (or drop it), so the list keeps the work left exactly."""
    now = found()
    stale = {k: (now.get(k, 0), v) for k, v in STILL_NAMED.items() if now.get(k, 0) < v}
    assert not stale, f"lower these entries of STILL_NAMED to what is found (found, listed): {stale}"
