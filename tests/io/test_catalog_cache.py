"""The parsed catalog is cached by content: the same entries come back, a
changed file is parsed again, and the cache keeps a bounded number of files."""
from __future__ import annotations

import shutil
from pathlib import Path

from sizing.io import catalog as catalog_io

ROOT = Path(__file__).resolve().parents[2]


def test_cache_returns_the_same_entries_and_follows_changes(tmp_path, monkeypatch):
    monkeypatch.setenv("SIZING_CACHE_DIR", str(tmp_path / "cache"))
    folder = tmp_path / "catalogs"
    folder.mkdir()
    for name in ("motors.toml", "drives.toml", "screws.toml"):
        shutil.copy(ROOT / "catalogs" / name, folder / name)
    first = catalog_io.load_catalog(folder)
    assert len(list((tmp_path / "cache" / "catalog").glob("*.pickle"))) == 3
    again = catalog_io.load_catalog(folder)
    assert again.motors == first.motors and again.origin == first.origin
    path = folder / "motors.toml"
    path.write_text(path.read_text().replace('mass = "0.45 kg"', 'mass = "0.55 kg"', 1))
    changed = catalog_io.load_catalog(folder)
    assert changed.motors["gen-bldc42-28v-h"].mass == 0.55 != first.motors["gen-bldc42-28v-h"].mass


def test_cache_is_bounded(tmp_path, monkeypatch):
    monkeypatch.setenv("SIZING_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setattr(catalog_io, "CACHE_KEEP", 2)
    for k in range(4):
        catalog_io._store(f"{k:064x}", [])
    assert len(list((tmp_path / "cache" / "catalog").glob("*.pickle"))) == 2
