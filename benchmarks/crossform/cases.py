"""The cross-form campaigns: (name, technology, truth, effects, options).

truth: the library effect a correct diagnosis names ("none" for a null
case, "outside:<what>" for an effect the library does not hold; a pair is
"a+b"). Sizes are realistic (see the README's diagnose section).
"""
from __future__ import annotations

LUGRE_A = dict(fc=25.0, fs=40.0, vs=0.005, sigma0=2e6, sigma1=2e3, sigma2=300.0)
LUGRE_B = dict(fc=50.0, fs=70.0, vs=0.002, sigma0=4e6, sigma1=3e3, sigma2=0.0)
BACKLASH_A = dict(gap_m=1.5e-4, k_N_m=2e6, zeta=0.3, m_kg=2.0, c_ground=400.0)
BACKLASH_B = dict(gap_m=3e-4, k_N_m=5e6, zeta=0.2, m_kg=1.0, c_ground=300.0)
MOUNT_A = dict(f_Hz=18.0, zeta=0.03, gain=0.25)
MOUNT_B = dict(f_Hz=35.0, zeta=0.015, gain=0.15)

DC = [
    ("dc-null-1", "none", {}, {}),
    ("dc-null-2", "none", {}, {"misstate": 0.05}),
    ("dc-lugre-a", "coulomb_friction", {"friction": LUGRE_A}, {}),
    ("dc-lugre-b", "coulomb_friction", {"friction": LUGRE_B}, {}),
    ("dc-backlash-a", "backlash", {"backlash": BACKLASH_A}, {}),
    ("dc-backlash-b", "backlash", {"backlash": BACKLASH_B}, {}),
    ("dc-mount-a", "sensor_vibration", {"mount": MOUNT_A}, {}),
    ("dc-mount-b", "sensor_vibration", {"mount": MOUNT_B}, {}),
    ("dc-pade-a", "sensor_delay", {"delay_s": 0.006}, {}),
    ("dc-pade-b", "sensor_delay", {"delay_s": 0.015}, {}),
    ("dc-ilimit", "current_saturation", {"current_limit": 4.0}, {}),
    ("dc-lugre+pade", "coulomb_friction+sensor_delay", {"friction": LUGRE_A, "delay_s": 0.008}, {}),
    ("dc-cogging", "outside:cogging", {"cogging": dict(amp_N=40.0, pitch_m=2e-3 / 6)}, {}),
    ("dc-drift", "outside:thermal_drift", {"drift": 0.04}, {}),
    ("dc-pulses", "outside:force_pulses", {"pulses": [(0.55, 0.03, 300.0), (1.45, 0.03, -300.0)]}, {}),
    ("dc-amp-asym", "outside:amplifier_nonlinearity", {"amp_asymmetry": 0.8}, {}),
]

SEAL_A = dict(fc=1.5, fs=2.7, vs=2e-3, sigma2=0.0)
SEAL_B = dict(fc=3.0, fs=6.0, vs=1e-3, sigma2=0.0)
PIEZO = [
    ("pz-null-1", "none", {}, {}),
    ("pz-null-2", "none", {}, {"load": (5.0, 2000.0)}),
    ("pz-seal-a", "seal_stick_slip", {"seal": SEAL_A}, {}),
    ("pz-seal-b", "seal_stick_slip", {"seal": SEAL_B}, {}),
    ("pz-logcreep-a", "stack_creep", {"creep": 0.015}, {}),
    ("pz-logcreep-b", "stack_creep", {"creep": 0.03}, {}),
    ("pz-air", "fluid_compressibility", {"air": dict(eps0=0.03, kappa=1.4)}, {"load": (5.0, 2000.0)}),
    ("pz-pade", "sensor_delay", {"delay_s": 0.01}, {}),
    ("pz-bandwidth", "amplifier_slew_limit", {"bandwidth": dict(omega=300.0, slew=400.0)}, {}),
    ("pz-viscous", "viscous_damping", {"viscous": 500.0}, {}),
    ("pz-orifice-leak", "leakage", {"leak": dict(G=5e-14, area_m2=2e-10, cd=0.6)}, {"load": (10.0, 1000.0)}),
    ("pz-creep+pade", "stack_creep+sensor_delay", {"creep": 0.03, "delay_s": 0.01}, {}),
    ("pz-drift", "outside:thermal_drift", {"drift": 0.04}, {}),
    ("pz-pulses", "outside:force_pulses", {"pulses": [(0.6, 0.03, 3.0), (1.4, 0.03, -3.0)]}, {}),
    ("pz-amp-compression", "outside:amplifier_nonlinearity", {"amp_compression": 0.15}, {}),
]


def generate(case, seed: int, technology: str):
    """(rig.toml, runs, holdout run) of one case."""
    from . import dc, piezo

    name, truth, effects, options = case
    if technology == "dc_motor":
        rig, runs = dc.campaign(effects, seed, misstate=options.get("misstate", 0.03))
        return rig, runs, "stairs_b"
    rig, runs = piezo.campaign(effects, seed, load=options.get("load", (0.0, 0.0)))
    return rig, runs, "stairs_b"
