"""Short human names of candidates (at most 32 characters): what an
engineer would say of the design, the ``id`` staying the machines' key.

Each technology names its own designs (``short_name`` of its registered
``Technology``, in its folder's ``words.py``) from the helpers here, e.g.

    "17xP056.90 87257 PTFE-OR Al orif"   stacks, fluid, seal, structure, compensation
    "DC MF0127008 R12-05K4 belt-2"       motor, screw, gear
    "PP 1xP056.90 r6 p80 50Hz 0.5mpa"    stacks, valve, piston, frequency (bias where it differs)

and ``unique`` keeps them apart within one list.
"""
from __future__ import annotations

from collections import Counter
from typing import TYPE_CHECKING

from ..technologies import registry

if TYPE_CHECKING:
    from .candidate import Candidate

MAX_NAME = 32
_MAKERS = ("pi-", "thorlabs-", "maxon-", "faulhaber-", "allied-", "gen-", "thk-", "hiwin-")


def short_id(part_id: str | None, keep: int = 14) -> str:
    """A part id without its maker's prefix, at most ``keep`` characters."""
    text = str(part_id or "")
    for prefix in _MAKERS:
        if text.startswith(prefix):
            text = text[len(prefix):]
            break
    return text[:keep]


# words an engineer abbreviates; any other id token is cut to its first letters
_WORDS = {"ptfe": "PTFE", "fkm": "FKM", "o": "O", "ring": "R", "spring": "S", "energised": "E", "al": "Al",
          "steel": "St", "ti": "Ti", "invar": "Inv", "orifice": "orif", "reservoir": "", "bellows": "bell",
          "accumulator": "", "silicone": "sil", "mil": "", "prf": "", "iso": "", "vg": "VG", "mineral": ""}


def abbreviated(part_id: str | None, tokens: int = 2) -> str:
    """A few letters for a part: its first ``tokens`` id tokens, known words
    abbreviated, numbers kept short (mil-prf-87257 -> 87257, ptfe-o-ring -> PTFE-OR)."""
    out = []
    for tok in str(part_id or "").split("-"):
        word = _WORDS.get(tok, tok if any(ch.isdigit() for ch in tok) else tok[:3])
        if word:
            out.append(word)
        if len(out) == tokens:
            break
    if len(out) > 1 and all(len(w) <= 1 for w in out[1:]):
        return out[0] + "-" + "".join(out[1:])          # ptfe-o-ring -> PTFE-OR
    return "-".join(out)


def id_tokens(part_id: str | None, n: int) -> str:
    """The first ``n`` tokens of a part id after its maker (maxon-606793 -> 606793)."""
    return "-".join(short_id(part_id, 64).split("-")[:n])


def name(c: Candidate) -> str:
    """The candidate's short name, at most MAX_NAME characters."""
    tech = registry.get(c.technology)
    text = tech.short_name(c) if tech is not None else str(c.id)
    return text[:MAX_NAME]


def unique(candidates: list[Candidate]) -> list[str]:
    """Each candidate's name, in order, unique within the list: designs
    whose names would coincide add the part they differ in (the drive, the
    amplifier, ...), and a few letters of their id's hash when even that
    coincides, so a name depends only on the design, not on its rank."""
    out = [name(c) for c in candidates]
    groups: dict[str, list[int]] = {}
    for i, text in enumerate(out):
        groups.setdefault(text, []).append(i)
    for text, rows in groups.items():
        if len(rows) > 1:
            for i, tag in zip(rows, _tags([candidates[i] for i in rows])):
                out[i] = _with_tag(text, tag)
    known = Counter(out)                    # a cut that made two names one again
    return [_with_tag(n, _hash(c.id)) if known[n] > 1 else n for n, c in zip(out, candidates)]


def _tags(group: list[Candidate]) -> list[str]:
    """What tells apart the designs of ``group``, whose names coincide."""
    tags = [_difference(c, group) for c in group]
    if len(set(tags)) < len(group):
        tags = [f"{t} {_hash(c.id)}".strip() for t, c in zip(tags, group)]
    return tags


def _with_tag(text: str, tag: str) -> str:
    """``text`` and ``tag`` within MAX_NAME, ``text`` cut at a word boundary."""
    room = MAX_NAME - len(tag) - 1
    if len(text) > room:
        text = text[:room + 1].rsplit(" ", 1)[0]
    return f"{text} {tag}"


def _difference(c: Candidate, group: list[Candidate]) -> str:
    """The first component in which ``c`` differs from others of ``group``,
    abbreviated (servo-96v-12a -> 96v)."""
    comp = c.components
    for key in comp:
        if len({str(g.components.get(key)) for g in group}) > 1:
            tokens = short_id(str(comp[key]), 64).split("-")
            return tokens[min(1, len(tokens) - 1)][:8]        # servo-96v-12a -> 96v
    return ""


def _hash(text: str) -> str:
    import hashlib
    return hashlib.sha1(text.encode()).hexdigest()[:4]
