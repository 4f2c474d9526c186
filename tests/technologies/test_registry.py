"""The registry: the shipped technologies found from their folders, in
order, each with what the shared stages read of it."""
from __future__ import annotations

import importlib

from sizing.io.catalog import KINDS
from sizing.technologies import registry


def test_the_shipped_technologies_are_found_in_order():
    assert [t.name for t in registry.technologies()] == ["piezohydraulic", "dc_motor", "piezo_pump"]
    assert registry.get("dc_motor").actuator == "DC motor actuator"
    assert registry.label("piezo_pump") == "piezo pump"
    assert registry.label("not_registered") == "not registered"


def test_each_draws_on_catalog_kinds_and_rests_on_models_that_exist():
    kinds = {kind for kind, _ in KINDS.values()}
    for t in registry.technologies():
        assert t.part_kinds and set(t.part_kinds) <= kinds, t.name
        for module in t.rests_on:
            importlib.import_module(module)


def test_summary_groups_have_distinct_variants_and_labels():
    for t in registry.technologies():
        variants = [g.variant for g in t.groups]
        assert len(set(variants)) == len(variants) and all(g.label for g in t.groups), t.name


def test_a_registered_technology_replaces_one_of_its_name_and_goes():
    from dataclasses import replace
    dc = registry.get("dc_motor")
    try:
        registry.register(replace(dc, label="brushless DC"))
        assert registry.label("dc_motor") == "brushless DC"
    finally:
        registry.register(dc)
    assert registry.label("dc_motor") == "DC motor"


def test_the_names_without_importing_are_the_registered_names():
    """``names()`` reads the folders (an option checked before the engine
    loads); each folder's technology carries the folder's name."""
    import subprocess
    import sys
    code = ("from sizing.technologies import registry; n = registry.names(); import sys; "
            "print(sorted(n), 'cvxpy' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    from sizing.technologies.registry import technologies
    assert out.strip() == f"{sorted(t.name for t in technologies())} False"
