"""A solved design as ``sizing robust`` perturbs it, to re-run the solve's
checks on perturbed parts, as its technology builds it
(``Technology.study_design``, in its folder): taken from the solve's
records (``records.Stages``) when robust ran the solve; ``read_back``
rebuilds it from a results.json candidate."""
from __future__ import annotations

from ..errors import InputError
from ..io.catalog import Catalog
from ..io.requirements import RequirementsFile
from .candidate import Candidate, as_candidate


def read_back(req: RequirementsFile, catalog: Catalog, cand: Candidate | dict):
    """What robust perturbs, read back from a results.json candidate (a
    solve whose records are gone; a ``Candidate`` or its record)."""
    return study_designs(req, catalog, [cand])[0]


def study_designs(req: RequirementsFile, catalog: Catalog, candidates: list[Candidate], stages=None) -> list:
    """What ``sizing robust`` perturbs, per candidate, as its technology
    builds it (``Technology.study_design``): taken as sized from the solve's
    own records (``stages``, ``records.Stages``) when they hold it, else
    read back from its results.json record."""
    from ..technologies.registry import get
    out = []
    for c in map(as_candidate, candidates):
        tech = get(c.technology)
        if tech is None or tech.study_design is None:
            raise InputError(None, c.id, "expected a design whose parts robust can perturb")
        out.append(tech.study_design(req, catalog, c, stages))
    return out
