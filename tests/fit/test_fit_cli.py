"""`sizing fit hysteresis` and `sizing fit dc-motor` end to end (CONTRACTS.md:
fit output TOML, exit 2 naming file, line and column)."""
import tomllib

import numpy as np
import pytest

from sizing.physics.bouc_wen import BoucWen, free_displacement
from sizing.sim.dc_motor import DCMotorModel, simulate

from ..conftest import SEED_BOUC_WEN, run_cli

SEED = BoucWen(**SEED_BOUC_WEN)


def write_csv(path, header, columns):
    rows = [",".join(f"{v:.9g}" for v in row) for row in zip(*columns)]
    path.write_text(",".join(header) + "\n" + "\n".join(rows) + "\n")
    return path


@pytest.fixture(scope="module")
def piezo_runs(tmp_path_factory):
    folder = tmp_path_factory.mktemp("piezo")
    rng = np.random.default_rng(11)
    t = np.arange(0.0, 2.0, 1 / 1000)
    paths = []
    for a in (50.0, 100.0, 150.0):
        v = a / 2 * (1 - np.cos(2 * np.pi * t))
        x = free_displacement(t, v, SEED) + 3e-7 * rng.standard_normal(len(t))
        paths.append(write_csv(folder / f"a{int(a)}.csv", ["time_s", "voltage_V", "position_m"], [t, v, x]))
    return paths


def test_fit_hysteresis_writes_contract_toml_and_html(piezo_runs, tmp_path):
    out = tmp_path / "fit" / "stack.toml"
    code, stdout, stderr = run_cli("fit", "hysteresis", *piezo_runs, "--holdout", "a100", "--out", out, "--starts", "2")
    assert code == 0, stderr
    data = tomllib.loads(out.read_text())
    assert set(data["stack"]) >= {"d33", "bouc_wen"}
    assert set(data["stack"]["bouc_wen"]) == {"alpha", "beta", "gamma", "delta", "n"}
    assert data["stack"]["d33"] == pytest.approx(SEED.d33, rel=0.05)
    fit = data["fit"]
    assert fit["model"] == "bouc-wen" and fit["holdout_runs"] == ["a100"]
    assert 0 < fit["nrmse_train"] < 0.02 and 0 < fit["nrmse_holdout"] < 0.02
    lo, hi = fit["ci95"]["d33"]
    assert lo < data["stack"]["d33"] < hi
    assert "nrmse_holdout" in fit["prandtl_ishlinskii"]
    html = out.with_suffix(".html").read_text()
    # plotly.js once per folder, beside the page, never from a CDN
    assert "src='plotly.min.js'" in html and "http" not in html.split("<body>")[0] and "voltage vs displacement" in html
    assert (out.parent / "plotly.min.js").stat().st_size > 1_000_000
    # the report says which model wins and what the data determine
    assert "Model choice" in html and "What the data determine" in html and "prior share" in html


def test_fit_hysteresis_prints_toml_without_out_and_pi_model(piezo_runs):
    code, stdout, stderr = run_cli("fit", "hysteresis", *piezo_runs[1:], "--model", "prandtl-ishlinskii", "--starts", "1")
    assert code == 0, stderr
    data = tomllib.loads(stdout)
    assert data["fit"]["model"] == "prandtl-ishlinskii" and "nrmse_holdout" not in data["fit"]
    assert min(data["prandtl_ishlinskii"]["weights_m_V"]) >= 0
    assert "nrmse_train" in data["fit"]["bouc_wen"]


@pytest.mark.parametrize("edit, where", [
    (lambda rows: rows.__setitem__(5, "0.004,nan,1e-6"), "line 6, column voltage_V"),
    (lambda rows: rows.__setitem__(5, "0.001,1,1e-6"), "line 6, column time_s"),
    (lambda rows: rows.__delitem__(slice(2, None)), "line 3, column time_s"),
    (lambda rows: rows.__setitem__(0, "time_s,voltage_V"), "line 1: missing column 'position_m'"),
])
def test_bad_data_exit_2_naming_file_line_column(tmp_path, edit, where):
    rows = ["time_s,voltage_V,position_m"] + [f"{k * 1e-3:.3f},{k},{k * 1e-7}" for k in range(30)]
    edit(rows)
    path = tmp_path / "bad.csv"
    path.write_text("\n".join(rows) + "\n")
    code, stdout, stderr = run_cli("fit", "hysteresis", path)
    assert code == 2
    line = stderr.strip().splitlines()[-1]
    assert str(path) in line and where in line, line
    assert "Traceback" not in stderr and stdout == ""


def test_data_that_cannot_support_a_fit_exit_2(tmp_path):
    t = np.arange(0, 1, 1e-3)
    path = write_csv(tmp_path / "ramp.csv", ["time_s", "voltage_V", "position_m"], [t, 100 * t, 1e-5 * t])
    code, _, stderr = run_cli("fit", "hysteresis", path, "--out", tmp_path / "x.toml")
    assert code == 2 and "ramp.csv" in stderr and "no reversal" in stderr
    assert not (tmp_path / "x.toml").exists()
    code, _, stderr = run_cli("fit", "hysteresis", path, "--model", "preisach")
    assert code == 2 and "--model" in stderr


def test_fit_dc_motor_cli(tmp_path):
    rig = tmp_path / "rig.toml"
    rig.write_text("""kind = "dc_motor"
[motor]
c1 = -15.0
c2 = 2000.0
screw_lead = "2 mm"
torque_constant = "0.05 N*m/A"
[controller]
rate = "1250 Hz"
kp = 4000.0
ki = 8000.0
kd = 0.0
derivative_on = "measurement"
current_limit = "10 A"
""")
    model = DCMotorModel(c1=-25.5552, c2=2987.02, lead=0.002, kp=4000.0, ki=8000.0,
                         derivative_on_measurement=1.0, current_limit=10.0, torque_constant=0.05)
    t = np.arange(0.0, 0.6, 1e-3)
    paths = []
    for name, step in (("step10", 0.010), ("step5", 0.005)):
        ref = np.where(t >= 0.05, step, 0.0)
        x = simulate(model, t, ref)["position_m"][0]
        paths.append(write_csv(tmp_path / f"{name}.csv", ["time_s", "reference_m", "position_m"], [t, ref, x]))
    out = tmp_path / "motor.toml"
    code, _, stderr = run_cli("fit", "dc-motor", *paths, "--rig", rig, "--holdout", "step5", "--out", out)
    assert code == 0, stderr
    data = tomllib.loads(out.read_text())
    assert data["motor"]["c1"] == pytest.approx(-25.5552, rel=0.01)
    assert data["motor"]["c2"] == pytest.approx(2987.02, rel=0.01)
    assert data["fit"]["model"] == "dc-motor" and data["fit"]["nrmse_holdout"] < 0.01
    assert out.with_suffix(".html").exists()


@pytest.mark.parametrize("command", ["hysteresis", "dc-motor"])
def test_fit_commands_have_help(command):
    code, stdout, _ = run_cli("fit", command, "--help")
    assert code == 0 and "--holdout" in stdout and "--out" in stdout
