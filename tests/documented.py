"""The fields docs/formats.md documents for an output file, checked against
a file a command wrote: each section's JSON example is the contract (keys
spelled "..." are placeholders; maps whose keys are data, such as run
names or requirement names, are checked to be maps)."""
from __future__ import annotations

import json
import re
from pathlib import Path

FORMATS = Path(__file__).resolve().parents[1] / "docs" / "formats.md"

# example paths whose keys are the data's own (run, requirement, parameter names)
DATA_KEYED = {
    "diagnosis.json": {"baseline.nrmse", "candidates[].params", "candidates[].shrink_holdout_channels"},
    "robust.json": {"designs[].p_requirement", "designs[].sensitivity"},
    "sweep.json": {"grid[].requirements", "grid[].feasible", "grid[].best.metrics"},
    "results.json": {"candidates[].components", "candidates[].stack_params", "candidates[].static",
                     "candidates[].simulated", "candidates[].margins", "candidates[].metrics"},
}


def example(filename: str) -> dict:
    """The JSON example of the section ``## filename`` of docs/formats.md."""
    text = FORMATS.read_text(encoding="utf-8")
    section = text.split(f"\n## {filename}\n", 1)[1].split("\n## ", 1)[0]
    return json.loads(re.search(r"```json\n(.*?)```", section, re.S).group(1))


def missing_fields(filename: str, written: dict) -> list[str]:
    """The documented key paths absent from ``written`` (empty: all there)."""
    return _missing(example(filename), written, "", DATA_KEYED.get(filename, set()))


def _missing(doc, out, path: str, data_keyed: set) -> list[str]:
    if isinstance(doc, list):
        if not isinstance(out, list) or not out:
            return [path] if doc else []
        return _missing(doc[0], _alike(doc[0], out), path + "[]", data_keyed)
    if not isinstance(doc, dict):
        return []
    if not isinstance(out, dict):
        return [path]
    if path in data_keyed:
        return []
    gaps = []
    for key, value in doc.items():
        if key == "...":
            continue
        sub = f"{path}.{key}" if path else key
        gaps += [sub] if key not in out else _missing(value, out[key], sub, data_keyed)
    return gaps


def _alike(doc_item, items: list):
    """The written list item most like the documented one: the same
    technology where items carry one, else the first."""
    if isinstance(doc_item, dict) and "technology" in doc_item:
        same = [i for i in items if isinstance(i, dict) and i.get("technology") == doc_item["technology"]]
        if same:
            return same[0]
    return items[0]
