"""``grep`` finds no technology name outside its folder, the registry and
the catalogs: every other module of ``sizing/`` reaches technologies
through ``technologies.registry``.

The allowed homes: a technology's folder (``sizing/technologies/<name>/``),
the registry (``sizing/technologies/``), the catalogs (``catalogs/``, not
code) and the models of one kind of hardware, which keep their names
(a piezo stack driving oil, a DC motor on a lead screw, a pump): the
physics (``physics/``), the simulators (``sim/``), the fits (``fit/``),
the diagnosis of a rig (``diagnose/``) and the rig and run readers
(``io/rig.py``, ``io/runs.py``, ``io/campaign.py``). The solve, the
engine, the application layer, the command line, the report and the
studies name none.

The hardware models that name one are listed below with how many times;
the list may only shrink (a module that names a technology more often, or
a new module that names one, fails)."""
from __future__ import annotations

import re
from pathlib import Path

from sizing.technologies import registry

PACKAGE = Path(__file__).resolve().parents[2] / "sizing"
HOME = "technologies/"
# the models of one kind of hardware (relative to sizing/): they keep their names
HARDWARE = ("physics/", "sim/", "fit/", "diagnose/", "io/rig.py", "io/runs.py", "io/campaign.py")

# hardware model (relative to sizing/) -> how many times it names a technology today
STILL_NAMED = {
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
    "fit/__init__.py": 2,
    "fit/dc_motor.py": 4,
    "io/campaign.py": 1,
    "io/rig.py": 5,
    "io/runs.py": 2,
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


def test_only_hardware_models_are_listed():
    """Nothing outside a technology's folder, the registry and the hardware
    models names a technology: the list holds hardware models alone."""
    assert [k for k in STILL_NAMED if not k.startswith(HARDWARE)] == []


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
