"""``sizing evaluate`` on a piezo pump design (technologies/piezo_pump/evaluate.py): a
frequency sweep of the seed's closest pump, the reeds' and the line's
dynamics moving the flow's peak, warnings above the valve's rating and the
refusal at its wetted resonance."""
from __future__ import annotations

import numpy as np
import pytest

from sizing.technologies.piezo_pump.evaluate import evaluate_pump
from sizing.errors import InputError
from sizing.io.catalog import load_catalog
from sizing.technologies.piezo_pump.design_file import PumpDesignFile

from ..conftest import run_cli

# the seed solve's closest pump (one P-056.90 on an 80 mm piston at 50 Hz
# into a 19 mm bore), as its results.json design block writes it
CLOSEST = dict(technology="piezo_pump", stack="pi-p-056.90", n_stacks=1, voltage=1000.0, pump_frequency=50.0,
               pump_diameter=0.08, cylinder_diameter=0.019, bias_pressure=5e5, valve="reed-steel-6mm",
               accumulator="bias-0.5mpa-20cc", fluid="mil-prf-87257", seal="ptfe-spring-energised",
               amplifier="pi-e-481", temperature=100.0)
FREQUENCIES = (25.0, 50.0, 100.0, 150.0, 200.0, 300.0, 400.0, 600.0, 800.0, 1000.0)


def _sweep(catalog, **over) -> np.ndarray:
    """Mean speed under the largest load at each of FREQUENCIES, m/s."""
    return np.array([evaluate_pump(PumpDesignFile.model_validate(dict(CLOSEST, pump_frequency=f, **over)), catalog,
                                   "design.toml")["simulated"]["worst"]["mean_speed_m_s"] for f in FREQUENCIES])


@pytest.fixture(scope="module")
def sweeps():
    cat = load_catalog()
    valve = cat.valves["reed-steel-6mm"]
    stiff = load_catalog()
    stiff.valves[valve.id] = valve.model_copy(update={"reed_stiffness": 4 * valve.reed_stiffness})
    return {"base": _sweep(cat), "stiff valve": _sweep(stiff), "long line": _sweep(cat, line_length=0.6)}


def test_flow_peaks_below_the_valves_wetted_resonance(sweeps):
    """Flow no longer grows with frequency: it peaks well inside the sweep
    and falls to a few per cent of the peak as the reeds lag (below their
    1.1 kHz wetted resonance, above their 350 Hz rating)."""
    v = sweeps["base"]
    k = int(np.argmax(v))
    assert 0 < k < len(FREQUENCIES) - 1
    assert FREQUENCIES[k] < 1109.0 / 3
    assert v[-1] < 0.1 * v[k]


def test_the_peak_moves_up_with_a_stiffer_valve_and_down_with_a_longer_line(sweeps):
    """Four times the reed stiffness doubles its wetted resonance: the flow
    holds on to higher frequencies (its flow-weighted mean frequency rises;
    the grid's argmax moves in 50-100 Hz steps); three times the line's
    length (its oil's reflected mass) brings the peak down (to 100 Hz,
    with a second hump near 300 Hz, the line's oil ringing on the high side)."""
    def centre(v):
        return float(np.sum(np.asarray(FREQUENCIES) * v) / np.sum(v))
    assert centre(sweeps["stiff valve"]) > 1.1 * centre(sweeps["base"])
    peak = {name: FREQUENCIES[int(np.argmax(v))] for name, v in sweeps.items()}
    assert peak["stiff valve"] >= peak["base"] > peak["long line"], peak
    # above the base's peak the stiffer reeds deliver more (they lag less)
    above = np.asarray(FREQUENCIES) > peak["base"]
    assert sweeps["stiff valve"][above].sum() > 1.2 * sweeps["base"][above].sum()


def test_above_the_rating_a_warning_at_the_wetted_resonance_a_refusal():
    cat = load_catalog()
    r = evaluate_pump(PumpDesignFile.model_validate(dict(CLOSEST, pump_frequency=600.0)), cat, "design.toml")
    assert any("above valve reed-steel-6mm's rating 350 Hz" in w for w in r["warnings"])
    assert r["valve"]["wetted_resonance_Hz"] == pytest.approx(1109.0, rel=2e-3)
    with pytest.raises(InputError, match="pump_frequency.*wetted resonance"):
        evaluate_pump(PumpDesignFile.model_validate(dict(CLOSEST, pump_frequency=1600.0)), cat, "design.toml")


def test_evaluate_command_reads_a_pump_design(tmp_path):
    path = tmp_path / "pump.toml"
    path.write_text("".join(f"{k} = {v!r}\n".replace("'", '"') for k, v in CLOSEST.items()))
    code, out, err = run_cli("evaluate", path)
    assert code == 0, err
    assert "piezo_pump design" in out and "amplifier_units" in out
    bad = tmp_path / "bad.toml"
    bad.write_text(path.read_text().replace('valve = "reed-steel-6mm"', 'valve = "no-such-valve"'))
    code, _, err = run_cli("evaluate", bad)
    assert code == 2 and "valve" in err and "no-such-valve" in err


def test_a_design_too_long_to_simulate_is_refused_before_it_runs():
    """A 0.01 mm/s requirement over 40 mm at 1 kHz: 8000 s of pumping at
    10 us a step, 1.6e9 steps, beyond the 1e8 limit (exit 2 naming the field)."""
    with pytest.raises(InputError, match="simulation steps"):
        evaluate_pump(PumpDesignFile.model_validate(dict(CLOSEST, pump_frequency=1000.0, speed=1e-5)),
                      load_catalog(), "design.toml")
