"""Generate the example test campaigns of `sizing diagnose` (synthetic
"measured" data, seed 20261122 for the noise).

- piezo-prototype/: the seed's Table 3 prototype (rig.toml as in
  docs/formats.md), a ramp run and a steps run, with seal stick-slip injected
  (3 N running friction on the output seal, breakaway 2x: the stepped
  response and the ~0.5 mm short stroke of the first prototype, seed sec. 4).
- dc-motor/: the seed's Ultra Motion actuator (sec. 3; PID gains of the
  catalog entry ultramotion-amcx8b-b0m1), two runs of steps and a chirp,
  with sensor vibration injected (12 Hz mount, zeta 0.01, gain 0.3: the
  steady-state oscillation of Figure 15).

Noise: position 0.1 % of the run's span, piezo voltage 0.3 V rms.
Run: python studies/campaigns/make_campaigns.py
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from sizing.diagnose import synth
from sizing.diagnose.effects import get
from sizing.io.rig import load_rig

SEED = 20261122
HERE = Path(__file__).resolve().parent

PIEZO_RIG = '''kind = "piezohydraulic"
notes = "seed ARL-TR-10251 Table 3 prototype (diameters as corrected in PHYSICS-NOTES item 1)"

[stack]
count = 3
stiffness = "1.96e7 N/m"      # per stack
d33 = "8.15e-7 m/V"           # per stack, as in the seed's eq. 1

[stack.bouc_wen]              # seed eq. 2, SI units
alpha = -2.23e-7
beta = 0.134
gamma = 0.0755
delta = -5.46e-8
n = 1.14

[hydraulics]
wide_diameter = "3.75 in"
narrow_diameter = "0.375 in"
wide_piston_mass = "0.30 kg"
narrow_piston_mass = "0.02 kg"
fluid_density = "870 kg/m^3"
loss_coefficient = 0.5        # K_loss of eq. 8

[seals]
wide_friction = "10 N"        # running (Coulomb) friction of each seal
narrow_friction = "0.2 N"

[load]                        # force on the output: force + stiffness * position
force = "0 N"
stiffness = "0 N/m"
'''

DC_RIG = '''kind = "dc_motor"
notes = "seed ARL-TR-10251 sec. 3; PID gains of catalog entry ultramotion-amcx8b-b0m1 (assumed, see catalogs/dc_actuators.toml)"

[motor]
c1 = -25.5552                 # 1/s, seed eq. 13
c2 = 2987.02                  # seed eq. 13
screw_lead = "2 mm"
torque_constant = "0.05 N*m/A"

[controller]
rate = "1250 Hz"
kp = 4000.0                   # A/m
ki = 8000.0                   # A/(m s)
kd = 90.0                     # A s/m
derivative_on = "measurement"
current_limit = "10 A"

[load]
force = "0 N"
stiffness = "0 N/m"
'''


def write_campaign(folder: Path, rig_text: str, runs, input_column: str) -> None:
    (folder / "runs").mkdir(parents=True, exist_ok=True)
    (folder / "rig.toml").write_text(rig_text, encoding="utf-8")
    for run in runs:
        data = np.column_stack([run.time, run[input_column], run["position_m"]])
        header = f"time_s,{input_column},position_m"
        np.savetxt(folder / "runs" / f"{run.name}.csv", data, delimiter=",", header=header, comments="",
                   fmt=["%.6f", "%.6g", "%.6e"])


def main() -> None:
    piezo = HERE / "piezo-prototype"
    piezo.mkdir(exist_ok=True)
    (piezo / "rig.toml").write_text(PIEZO_RIG, encoding="utf-8")
    rig = load_rig(piezo / "rig.toml")
    effect = get("piezohydraulic", "seal_stick_slip")
    inputs = {k: v for k, v in synth.piezo_excitations(150.0).items() if k in ("ramp", "steps")}
    runs = synth.synthesize("piezohydraulic", rig, inputs, [effect],
                            [{"narrow_friction_N": 3.0, "breakaway_ratio": 2.0}], noise=synth.Noise(seed=SEED))
    write_campaign(piezo, PIEZO_RIG, runs, "voltage_V")

    dc = HERE / "dc-motor"
    dc.mkdir(exist_ok=True)
    (dc / "rig.toml").write_text(DC_RIG, encoding="utf-8")
    rig = load_rig(dc / "rig.toml")
    effect = get("dc_motor", "sensor_vibration")
    runs = synth.synthesize("dc_motor", rig, synth.dc_excitations(0.01), [effect],
                            [{"frequency_Hz": 12.0, "damping_ratio": 0.01, "gain": 0.3}],
                            noise=synth.Noise(seed=SEED + 1))
    write_campaign(dc, DC_RIG, runs, "reference_m")
    print(f"wrote {piezo} and {dc}")


if __name__ == "__main__":
    main()
