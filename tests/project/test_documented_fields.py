"""The check that a written file carries every field docs/formats.md
documents (tests/documented.py), used by the solve, robust, sweep and
diagnose tests on the files those commands write."""
from ..documented import example, missing_fields


def test_a_dropped_field_is_named_with_its_path():
    written = example("robust.json")
    assert missing_fields("robust.json", written) == []
    del written["designs"][0]["p_ci95"]
    written.pop("seed")
    assert missing_fields("robust.json", written) == ["seed", "designs[].p_ci95"]


def test_data_keyed_maps_are_not_read_as_fields():
    written = example("diagnosis.json")
    written["baseline"]["nrmse"] = {"another_run": 0.1}           # run names are the data's
    assert missing_fields("diagnosis.json", written) == []
    written["candidates"] = []
    assert missing_fields("diagnosis.json", written) == ["candidates"]


def test_candidates_are_matched_by_technology():
    doc = example("results.json")
    dc = {"id": "dc", "technology": "dc_motor"}
    assert missing_fields("results.json", dict(doc, candidates=[dc] + doc["candidates"])) == []
    assert "candidates[].stack_params" in missing_fields("results.json", dict(doc, candidates=[dc]))
