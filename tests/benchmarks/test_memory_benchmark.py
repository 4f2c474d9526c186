"""The memory benchmark's harness (benchmarks/memory_benchmark.py): a
campaign it makes is fitted in a child process under a 4 GB address-space
limit, the same limit the benchmark states for the accepted maximum length.
A short campaign keeps the test quick; the full-length figures are the
benchmark's (docs/formats.md, "Limits")."""
import importlib.util
import resource
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
_spec = importlib.util.spec_from_file_location("memory_benchmark", ROOT / "benchmarks" / "memory_benchmark.py")
mb = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(mb)


@pytest.mark.skipif(not hasattr(resource, "RLIMIT_AS"), reason="no address-space limit on this system")
def test_fit_dc_motor_runs_under_a_4_gb_address_space_limit(tmp_path):
    campaign = mb.make_campaign(tmp_path / "campaign", samples=15_000)
    assert len(list((campaign / "runs").glob("*.csv"))) == 3
    code, seconds, peak, err = mb.run_limited(mb.COMMANDS["fit dc-motor"](campaign, tmp_path), 4 * 2**30, ROOT)
    assert code == 0, err
    assert (tmp_path / "motor.toml").exists()
