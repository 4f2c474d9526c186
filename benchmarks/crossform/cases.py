"""The cross-form campaigns: case sets as data (``sets/*.json``, listed with
their purpose and seed offset in ``sets/manifest.json``).

Each case: name, truth (the library effect a correct diagnosis names;
"none" for a null case, "outside:<what>" for an effect the library does not
hold; a pair is "a+b"), the generator's effects and options (dc.campaign,
piezo.campaign). Sizes are realistic (docs/diagnosis-benchmarks.md).
"""
from __future__ import annotations

from pathlib import Path

from .common import Case, CaseSet, load_set, set_names

SETS_DIR = Path(__file__).resolve().parent / "sets"


def sets() -> list[str]:
    """The names of the case sets, in the manifest's order."""
    return set_names(SETS_DIR)


def case_set(name: str) -> CaseSet:
    return load_set(SETS_DIR, name)


def find(name: str) -> Case:
    """The case named ``name``, in whichever set holds it."""
    for s in sets():
        found = [c for c in case_set(s).cases if c.name == name]
        if found:
            return found[0]
    raise KeyError(name)


def generate(case: Case):
    """(rig.toml, runs, holdout run) of one case."""
    from . import dc, piezo

    if case.technology == "dc_motor":
        keys = ("stroke", "misstate", "load", "sensor")
        rig, runs = dc.campaign(case.effects, case.seed, **{k: case.options[k] for k in keys if k in case.options})
        return rig, runs, "stairs_b"
    keys = ("v_max", "misstate", "load", "n_stacks", "wide_in", "sensor")
    rig, runs = piezo.campaign(case.effects, case.seed, **{k: case.options[k] for k in keys if k in case.options})
    return rig, runs, "stairs_b"
