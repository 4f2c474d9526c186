"""The application layer: a command computes a typed result, and writing its
files is one separate step (``api.output``) shared by every command."""
from __future__ import annotations

import ast
import os
from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar

import pytest

from sizing import api
from sizing.api import output
from sizing.errors import InputError
from ..conftest import REPO, STUDIES


@dataclass(frozen=True)
class Folder(output.Payload):
    data: dict
    inputs: tuple = ()
    layout: ClassVar[str] = "folder"

    def _payload(self):
        return self.data

    def files(self):
        return {"a.json": "{}\n", "sub/b.txt": lambda: "made while written\n"}


def test_a_folder_result_is_written_by_the_shared_step(tmp_path):
    result = Folder({"x": 1})
    written = output.write(result, tmp_path / "out")
    assert written == [str(tmp_path / "out" / "a.json"), str(tmp_path / "out" / "sub" / "b.txt")]
    assert (tmp_path / "out" / "sub" / "b.txt").read_text() == "made while written\n"
    assert result["x"] == 1 and dict(result) == {"x": 1}       # reads as its payload


def test_produce_checks_the_destination_before_any_work(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("not a folder")
    calls = []
    with pytest.raises(InputError, match="expected a folder, got a file"):
        output.produce(["a.json"], blocker, (), lambda: calls.append(1))
    assert calls == []
    assert output.produce(["a.json"], None, (), lambda: Folder({})) == Folder({})      # no folder: nothing written


def test_a_result_never_overwrites_its_inputs(tmp_path):
    source = tmp_path / "in.toml"
    source.write_text("x = 1\n")
    with pytest.raises(InputError, match="inputs"):
        output.write(api.CatalogUpdate({}, {source: "y = 2\n"}, inputs=(source,)))
    assert source.read_text() == "x = 1\n"


def test_evaluate_returns_a_typed_result_and_writes_nothing(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = api.evaluate(STUDIES / "seed-dc-step.toml")
    assert isinstance(result, api.EvaluateResult)
    assert result["static"] == result.figures["static"] and result.warnings == result.figures["warnings"]
    assert result.summary().startswith(f"{result['technology']} design")
    assert os.listdir(tmp_path) == []


def test_fit_result_reads_as_the_documented_mapping(tmp_path):
    result = api.FitResult("dc-motor", "[motor]\nc1 = 1.0\n", {"model": "dc-motor"}, ("slow",),
                           out=tmp_path / "fit.toml")
    assert dict(result) == {"toml": result.toml, "warnings": ["slow"], "result": {"model": "dc-motor"},
                            "written": []}
    assert list(result.files()) == [tmp_path / "fit.toml"]
    assert api.write(result) == [str(tmp_path / "fit.toml")]
    assert (tmp_path / "fit.toml").read_text() == result.toml


def test_fit_targets_put_the_report_beside_the_toml(tmp_path):
    from sizing.api.fitting import targets
    assert targets(tmp_path / "f.toml", None) == (tmp_path / "f.toml", tmp_path / "f.html")
    assert targets(None, None) == (None, None)
    with pytest.raises(InputError, match="would overwrite the --out file"):
        targets(tmp_path / "f.toml", tmp_path / "f.toml")


def test_an_unknown_catalog_entry_names_the_nearest():
    with pytest.raises(InputError, match="did you mean thorlabs-pk4ga7p1"):
        api.catalog_entry("thorlabs-pk4ga7p2")
    found = api.catalog_entry("thorlabs-pk4ga7p1")
    assert found.kind == "stack" and found.to_dict()["id"] == "thorlabs-pk4ga7p1"


def test_the_command_line_calls_only_the_api():
    """cli.py imports nothing of sizing but the api, its errors and limits
    (and the BLAS thread policy, applied before numpy loads)."""
    tree = ast.parse((REPO / "sizing" / "cli.py").read_text(encoding="utf-8"))
    used = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.level:
            used |= {f"{node.module}" if node.module else alias.name for alias in node.names}
    assert used <= {"api", "errors", "limits", "threads", "__version__"}, used


def test_every_command_family_is_one_module():
    families = {p.stem for p in Path(api.__file__).parent.glob("*.py")}
    assert {"solution", "evaluation", "fitting", "diagnosis", "studies", "catalogs", "output"} <= families


def test_a_command_runs_with_rare_full_collections_and_restores_the_collector(tmp_path):
    """While ``produce`` computes and writes, the collector's full pass comes
    after FULL_COLLECTION_EVERY young passes (not Python's 10); its
    thresholds are restored afterwards, also when the command fails."""
    import gc
    before = gc.get_threshold()
    seen = []

    def compute():
        seen.append(gc.get_threshold())
        raise RuntimeError("fails")
    with pytest.raises(RuntimeError):
        output.produce(["a.txt"], tmp_path / "out", (), compute)
    assert seen == [(before[0], before[1], max(before[2], output.FULL_COLLECTION_EVERY))]
    assert gc.get_threshold() == before


def test_commands_running_at_once_leave_the_collector_as_it_was():
    """Two commands whose runs overlap (threads): the collector keeps the
    raised threshold until the last returns, then has its own back."""
    import gc
    before = gc.get_threshold()
    first, second = output.few_full_collections(), output.few_full_collections()
    first.__enter__()
    second.__enter__()
    first.__exit__(None, None, None)
    assert gc.get_threshold()[2] == max(before[2], output.FULL_COLLECTION_EVERY)
    second.__exit__(None, None, None)
    assert gc.get_threshold() == before
