"""Compiled kernels are cached per version of every file that holds one,
so an edit to a function another file's kernel inlines recompiles it."""
from __future__ import annotations

import os
import re
import shutil
from pathlib import Path

from sizing import kernel_cache

PACKAGE = Path(kernel_cache.__file__).parent


def test_every_file_with_a_kernel_is_in_the_digest():
    holding = {p for p in PACKAGE.rglob("*.py")
               if re.search(r"numba\.(njit|jit|vectorize|guvectorize)\b|^\s*@njit\b", p.read_text(), re.M)}
    assert len(holding) >= 5
    assert holding <= set(kernel_cache.kernel_modules())


def test_an_edit_to_an_inlined_function_moves_the_cache(tmp_path):
    """The piezohydraulic kernel inlines physics/bouc_wen.py's step: a
    change there alone gives another cache folder."""
    copy = tmp_path / "sizing"
    for path in kernel_cache.kernel_modules():
        module = path.relative_to(PACKAGE)
        (copy / module).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(path, copy / module)
    before = kernel_cache.sources_digest(copy)
    assert before == kernel_cache.sources_digest(PACKAGE)
    bouc_wen = copy / "physics" / "bouc_wen.py"
    bouc_wen.write_text(bouc_wen.read_text() + "\n# an edit\n")
    assert kernel_cache.sources_digest(copy) != before


def test_numba_caches_in_the_folder_of_these_sources(monkeypatch):
    import numba

    monkeypatch.delenv("NUMBA_CACHE_DIR", raising=False)
    monkeypatch.setattr(numba.config, "CACHE_DIR", numba.config.CACHE_DIR)
    kernel_cache.configure()
    assert os.environ["NUMBA_CACHE_DIR"] == numba.config.CACHE_DIR == str(kernel_cache.cache_folder())
    assert Path(numba.config.CACHE_DIR).name == kernel_cache.sources_digest()


def test_a_folder_the_user_chose_is_kept(monkeypatch, tmp_path):
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(tmp_path))
    kernel_cache.configure()
    assert os.environ["NUMBA_CACHE_DIR"] == str(tmp_path)
