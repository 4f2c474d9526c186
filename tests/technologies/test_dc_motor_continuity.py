"""The simulated margins of a DC design from parts move continuously with
the requirement: the seed's recommended design (Allied Motion MF0095020,
HIWIN R12-05K4, 2:1 belt, 48 V 10 A drive) re-sized at strokes 0.1 mm
apart gives small, same-sign changes of its speed and winding margins, and
no stroke is singled out by how the output samples fall on the 1.25 kHz
controller (the RMS current read from output samples failed the winding
temperature of a seed design at exactly 80 mm and passed it at 79 and
80.8 mm)."""
from __future__ import annotations

import numpy as np
import pytest

from sizing.engine.candidate import Candidate
from sizing.engine.loads import load_cases
from sizing.io.catalog import load_catalog
from sizing.io.requirements import load_requirements
from sizing.technologies.dc_motor.from_parts import dc_parts_designs

from ..conftest import STUDIES

ROW = ("allied-mf0095020-48v", "hiwin-r12-05k4-fscdin", "belt-2", "servo-48v-10a")


@pytest.fixture(scope="module")
def seed():
    req, _ = load_requirements(STUDIES / "seed-requirements.toml")
    from sizing.technologies.dc_motor.resolving import parts_of as dc_parts_of
    row = Candidate(id="row", technology="dc_motor", components=dict(zip(("motor", "screw", "gear", "drive"), ROW)))
    parts = dc_parts_of(load_catalog(None), (row,))
    return req, parts, [c["load_N"] for c in load_cases(req.load)]


def _margins(seed, stroke) -> dict:
    req, cat, loads = seed
    changed = req.model_copy(update={"requirements": req.requirements.model_copy(update={"stroke": stroke})})
    found = dc_parts_designs(changed, cat, loads, rows={ROW}).designs
    (d,) = [d for d in found if (d.parts.motor, d.parts.screw, d.parts.gear, d.parts.drive) == ROW]
    return dict(d.margins)


def test_the_speed_and_winding_margins_change_by_small_same_sign_steps_with_the_stroke(seed):
    """39.0 ... 40.0 mm: the pole slows with the stroke (it is placed for
    stroke / speed) while the slew at the limits does not, so the speed
    margin rises, by about 0.3 % per mm; the winding margin rises too. No
    step of 0.1 mm moves either by more than 0.1 % or against the trend."""
    m = [_margins(seed, s) for s in np.linspace(0.039, 0.040, 11)]
    for key in ("speed", "winding_temperature"):
        steps = np.diff([x[key] for x in m])
        assert np.all(steps > 0) and np.all(steps < 1e-3), (key, steps)


def test_no_stroke_is_singled_out_by_the_output_grid(seed):
    """80 mm (3.2 s simulated: 3200 output samples at 1 kHz against the
    1.25 kHz controller) between 79 and 80.8 mm: its winding and drive
    current margins lie between theirs."""
    lo, mid, hi = (_margins(seed, s) for s in (0.079, 0.080, 0.0808))
    for key in ("winding_temperature", "drive_current", "continuous_torque"):
        assert min(lo[key], hi[key]) <= mid[key] <= max(lo[key], hi[key]), (key, lo[key], mid[key], hi[key])
