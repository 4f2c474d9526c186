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


# The held-out set: written before the widened effect forms were built and
# never used while building them. Other sizes of every effect, other rig
# set-ups (a longer DC stroke, a loaded DC screw, four stacks, a 3 in piston,
# a lower drive voltage), noisier sensors, other pairs and other seeds
# (``--heldout`` in benchmarks/diagnose_benchmark.py).
NOISY = {"white": 1.2e-3, "flicker": 3e-4}
DC_HELDOUT = [
    ("dc-h-null-stroke", "none", {}, {"stroke": 0.015, "misstate": 0.04}),
    ("dc-h-null-load", "none", {}, {"load": 150.0}),
    ("dc-h-lugre", "coulomb_friction",
     {"friction": dict(fc=35.0, fs=55.0, vs=0.003, sigma0=3e6, sigma1=2.5e3, sigma2=150.0)}, {}),
    ("dc-h-lugre-load", "coulomb_friction",
     {"friction": dict(fc=20.0, fs=45.0, vs=0.004, sigma0=1.5e6, sigma1=1.5e3, sigma2=400.0)}, {"load": 150.0}),
    ("dc-h-backlash", "backlash", {"backlash": dict(gap_m=2e-4, k_N_m=3e6, zeta=0.25, m_kg=1.5, c_ground=350.0)},
     {"stroke": 0.015}),
    ("dc-h-mount", "sensor_vibration", {"mount": dict(f_Hz=25.0, zeta=0.02, gain=0.2)}, {"sensor": NOISY}),
    ("dc-h-pade", "sensor_delay", {"delay_s": 0.01}, {"stroke": 0.015}),
    ("dc-h-ilimit", "current_saturation", {"current_limit": 5.5}, {}),
    ("dc-h-backlash+lugre", "backlash+coulomb_friction",
     {"backlash": dict(gap_m=2.5e-4, k_N_m=4e6, zeta=0.3, m_kg=1.5, c_ground=300.0),
      "friction": dict(fc=30.0, fs=50.0, vs=0.003, sigma0=2e6, sigma1=2e3, sigma2=200.0)}, {}),
    ("dc-h-mount+pade", "sensor_vibration+sensor_delay",
     {"mount": dict(f_Hz=15.0, zeta=0.025, gain=0.25), "delay_s": 0.007}, {}),
    ("dc-h-cogging", "outside:cogging", {"cogging": dict(amp_N=30.0, pitch_m=2e-3 / 8)}, {}),
    ("dc-h-drift", "outside:thermal_drift", {"drift": 0.03}, {"stroke": 0.015}),
    ("dc-h-amp-asym", "outside:amplifier_nonlinearity", {"amp_asymmetry": 0.85}, {}),
]
PIEZO_HELDOUT = [
    ("pz-h-null-4stacks", "none", {}, {"n_stacks": 4}),
    ("pz-h-null-spring", "none", {}, {"load": (3.0, 1500.0), "sensor": NOISY}),
    ("pz-h-seal", "seal_stick_slip", {"seal": dict(fc=2.0, fs=3.5, vs=1.5e-3, sigma2=0.0)}, {"n_stacks": 4}),
    ("pz-h-seal-3in", "seal_stick_slip", {"seal": dict(fc=1.0, fs=2.2, vs=3e-3, sigma2=0.0)}, {"wide_in": 3.0}),
    ("pz-h-logcreep", "stack_creep", {"creep": 0.022}, {"v_max": 120.0}),
    ("pz-h-air", "fluid_compressibility", {"air": dict(eps0=0.02, kappa=1.2)}, {"load": (4.0, 1500.0)}),
    ("pz-h-pade", "sensor_delay", {"delay_s": 0.007}, {"n_stacks": 4}),
    ("pz-h-bandwidth", "amplifier_slew_limit", {"bandwidth": dict(omega=450.0, slew=600.0)}, {}),
    ("pz-h-viscous", "viscous_damping", {"viscous": 350.0}, {"wide_in": 3.0}),
    ("pz-h-leak", "leakage", {"leak": dict(G=3e-14, area_m2=1.5e-10, cd=0.65)}, {"load": (8.0, 1200.0)}),
    ("pz-h-seal+air", "seal_stick_slip+fluid_compressibility",
     {"seal": dict(fc=2.5, fs=4.0, vs=2e-3, sigma2=0.0), "air": dict(eps0=0.025, kappa=1.4)}, {"load": (5.0, 2000.0)}),
    ("pz-h-drift", "outside:thermal_drift", {"drift": 0.03}, {"n_stacks": 4}),
    ("pz-h-amp-compression", "outside:amplifier_nonlinearity", {"amp_compression": 0.1}, {}),
]


# The second held-out set: written independently of the diagnosis: the cases
# were chosen before the changes they measure, and none was run through the
# diagnosis while building them (only checked to generate finite runs). Other
# sizes of every effect, other rigs (a 20 mm and an 8 mm DC stroke, 120-300 N
# DC loads, two and four stacks, 3 and 3.25 in pistons, 100-130 V drives,
# stiffer and softer springs), a noisier sensor, pairs not used before and
# other seeds (``--heldout2`` in benchmarks/diagnose_benchmark.py). Viscous
# damping stays below about 550 N s/m: above it the piezo generator's fixed
# 0.1 ms RK4 step goes unstable on the 20 g output piston (600 N s/m does).
NOISY2 = {"white": 1.5e-3, "flicker": 4e-4, "volt_white": 0.5}
DC_HELDOUT2 = [
    ("dc-h2-null-long", "none", {}, {"stroke": 0.02, "misstate": 0.02}),
    ("dc-h2-null-load", "none", {}, {"load": 300.0, "stroke": 0.012, "misstate": 0.05}),
    ("dc-h2-null-noisy", "none", {}, {"stroke": 0.008, "sensor": NOISY2}),
    ("dc-h2-lugre", "coulomb_friction",
     {"friction": dict(fc=45.0, fs=65.0, vs=0.0025, sigma0=2.5e6, sigma1=2.2e3, sigma2=250.0)}, {"stroke": 0.012}),
    ("dc-h2-lugre-small", "coulomb_friction",
     {"friction": dict(fc=18.0, fs=32.0, vs=0.006, sigma0=1e6, sigma1=1e3, sigma2=100.0)}, {"load": 250.0}),
    ("dc-h2-backlash-stiff", "backlash",
     {"backlash": dict(gap_m=1.2e-4, k_N_m=8e6, zeta=0.15, m_kg=0.8, c_ground=250.0)}, {"stroke": 0.02}),
    ("dc-h2-backlash-wide", "backlash",
     {"backlash": dict(gap_m=3.5e-4, k_N_m=1.5e6, zeta=0.35, m_kg=2.5, c_ground=450.0)}, {"misstate": 0.05}),
    ("dc-h2-mount-high", "sensor_vibration", {"mount": dict(f_Hz=48.0, zeta=0.01, gain=0.12)}, {"stroke": 0.015}),
    ("dc-h2-mount-low", "sensor_vibration", {"mount": dict(f_Hz=12.0, zeta=0.04, gain=0.3)}, {"load": 120.0}),
    ("dc-h2-pade", "sensor_delay", {"delay_s": 0.004}, {"stroke": 0.015}),
    ("dc-h2-ilimit", "current_saturation", {"current_limit": 6.5}, {"stroke": 0.02}),
    ("dc-h2-lugre+mount", "coulomb_friction+sensor_vibration",
     {"friction": dict(fc=28.0, fs=42.0, vs=0.0035, sigma0=2.2e6, sigma1=1.8e3, sigma2=120.0),
      "mount": dict(f_Hz=22.0, zeta=0.02, gain=0.18)}, {}),
    ("dc-h2-backlash+pade", "backlash+sensor_delay",
     {"backlash": dict(gap_m=1.8e-4, k_N_m=2.5e6, zeta=0.25, m_kg=1.2, c_ground=320.0), "delay_s": 0.012},
     {"stroke": 0.012}),
    ("dc-h2-cogging", "outside:cogging", {"cogging": dict(amp_N=50.0, pitch_m=2e-3 / 12)}, {"stroke": 0.012}),
    ("dc-h2-drift", "outside:thermal_drift", {"drift": 0.05}, {"load": 200.0}),
    ("dc-h2-pulses", "outside:force_pulses", {"pulses": [(0.4, 0.02, 450.0), (1.2, 0.04, -250.0)]},
     {"stroke": 0.015}),
    ("dc-h2-amp-asym", "outside:amplifier_nonlinearity", {"amp_asymmetry": 0.75}, {"stroke": 0.008}),
]
PIEZO_HELDOUT2 = [
    ("pz-h2-null-2stacks", "none", {}, {"n_stacks": 2, "v_max": 130.0}),
    ("pz-h2-null-3in-spring", "none", {}, {"wide_in": 3.0, "load": (6.0, 2500.0), "misstate": 0.05}),
    ("pz-h2-null-noisy", "none", {}, {"v_max": 100.0, "sensor": NOISY2}),
    ("pz-h2-seal", "seal_stick_slip", {"seal": dict(fc=1.2, fs=2.9, vs=4e-3, sigma2=0.0)}, {}),
    ("pz-h2-seal-3.25in", "seal_stick_slip", {"seal": dict(fc=3.5, fs=5.0, vs=1.2e-3, sigma2=0.0)},
     {"wide_in": 3.25}),
    ("pz-h2-seal-4stacks", "seal_stick_slip", {"seal": dict(fc=2.2, fs=4.2, vs=2.5e-3, sigma2=0.0)},
     {"n_stacks": 4, "load": (3.0, 800.0)}),
    ("pz-h2-logcreep-small", "stack_creep", {"creep": 0.012}, {"wide_in": 3.0}),
    ("pz-h2-logcreep-large", "stack_creep", {"creep": 0.035}, {"v_max": 100.0}),
    ("pz-h2-air-small", "fluid_compressibility", {"air": dict(eps0=0.012, kappa=1.3)}, {"load": (8.0, 1000.0)}),
    ("pz-h2-air-large", "fluid_compressibility", {"air": dict(eps0=0.038, kappa=1.0)},
     {"load": (3.0, 3000.0), "n_stacks": 4}),
    ("pz-h2-pade", "sensor_delay", {"delay_s": 0.014}, {"n_stacks": 2}),
    ("pz-h2-bandwidth", "amplifier_slew_limit", {"bandwidth": dict(omega=550.0, slew=700.0)}, {"v_max": 130.0}),
    ("pz-h2-viscous", "viscous_damping", {"viscous": 250.0}, {"n_stacks": 4}),
    ("pz-h2-leak", "leakage", {"leak": dict(G=2e-14, area_m2=3e-10, cd=0.6)}, {"load": (9.0, 1800.0)}),
    ("pz-h2-creep+air", "stack_creep+fluid_compressibility",
     {"creep": 0.02, "air": dict(eps0=0.028, kappa=1.3)}, {"load": (5.0, 1200.0)}),
    ("pz-h2-viscous+pade", "viscous_damping+sensor_delay", {"viscous": 450.0, "delay_s": 0.006},
     {"wide_in": 3.25}),
    ("pz-h2-pulses", "outside:force_pulses", {"pulses": [(0.5, 0.02, 4.0), (1.3, 0.05, -2.0)]}, {"wide_in": 3.0}),
    ("pz-h2-amp-compression", "outside:amplifier_nonlinearity", {"amp_compression": 0.2}, {"v_max": 130.0}),
]


# The third held-out set: written independently of the diagnosis, after the
# second held-out set was run and before any change made in response to it was
# measured on this set; none of these cases was run through the diagnosis
# while writing them (only checked to generate finite runs without warnings).
# Other sizes of every effect, other rigs (18, 16, 14, 11 and 9 mm DC strokes,
# 60-275 N DC loads, DC misstatements of 2.5, 3.5 and 4.5 %, a 3.5 in piston,
# two and four stacks, 110-145 V drives, other springs and preloads), a
# noisier sensor of each kind, pairs not used in a held-out set before and
# other seeds (``--heldout3`` in benchmarks/diagnose_benchmark.py). Viscous
# damping stays below about 550 N s/m (see the second set).
NOISY3_DC = {"white": 1.4e-3, "flicker": 3.5e-4}
NOISY3_PZ = {"white": 1.3e-3, "flicker": 3.2e-4, "volt_white": 0.45}
DC_HELDOUT3 = [
    ("dc-h3-null-long", "none", {}, {"stroke": 0.018, "misstate": 0.035}),
    ("dc-h3-null-load", "none", {}, {"load": 275.0, "stroke": 0.014, "misstate": 0.025}),
    ("dc-h3-null-noisy", "none", {}, {"stroke": 0.011, "load": 60.0, "misstate": 0.045, "sensor": NOISY3_DC}),
    ("dc-h3-lugre-stiff", "coulomb_friction",
     {"friction": dict(fc=55.0, fs=72.0, vs=0.0015, sigma0=4.5e6, sigma1=2.6e3, sigma2=350.0)}, {"stroke": 0.016}),
    ("dc-h3-lugre-small", "coulomb_friction",
     {"friction": dict(fc=15.0, fs=26.0, vs=0.007, sigma0=1.2e6, sigma1=1.2e3, sigma2=60.0)}, {"load": 180.0}),
    ("dc-h3-backlash-tight", "backlash",
     {"backlash": dict(gap_m=1e-4, k_N_m=6e6, zeta=0.18, m_kg=0.6, c_ground=220.0)}, {"stroke": 0.009}),
    ("dc-h3-backlash-loose", "backlash",
     {"backlash": dict(gap_m=4e-4, k_N_m=1e6, zeta=0.38, m_kg=3.0, c_ground=480.0)},
     {"load": 80.0, "misstate": 0.045}),
    ("dc-h3-mount-high", "sensor_vibration", {"mount": dict(f_Hz=56.0, zeta=0.012, gain=0.14)}, {"misstate": 0.025}),
    ("dc-h3-mount-low", "sensor_vibration", {"mount": dict(f_Hz=10.0, zeta=0.045, gain=0.28)}, {"sensor": NOISY3_DC}),
    ("dc-h3-pade-short", "sensor_delay", {"delay_s": 0.0035}, {"load": 220.0}),
    ("dc-h3-pade-long", "sensor_delay", {"delay_s": 0.018}, {"stroke": 0.009}),
    ("dc-h3-ilimit", "current_saturation", {"current_limit": 3.5}, {"load": 100.0}),
    ("dc-h3-lugre+pade", "coulomb_friction+sensor_delay",
     {"friction": dict(fc=38.0, fs=52.0, vs=0.0045, sigma0=2.8e6, sigma1=1.6e3, sigma2=180.0), "delay_s": 0.009},
     {"stroke": 0.014}),
    ("dc-h3-backlash+mount", "backlash+sensor_vibration",
     {"backlash": dict(gap_m=2.8e-4, k_N_m=3.5e6, zeta=0.22, m_kg=1.8, c_ground=380.0),
      "mount": dict(f_Hz=30.0, zeta=0.035, gain=0.22)}, {}),
    ("dc-h3-ilimit+pade", "current_saturation+sensor_delay", {"current_limit": 4.8, "delay_s": 0.005},
     {"stroke": 0.018}),
    ("dc-h3-cogging", "outside:cogging", {"cogging": dict(amp_N=22.0, pitch_m=2e-3 / 10)}, {"stroke": 0.016}),
    ("dc-h3-drift", "outside:thermal_drift", {"drift": 0.02}, {"stroke": 0.011, "load": 180.0}),
    ("dc-h3-pulses", "outside:force_pulses", {"pulses": [(0.7, 0.025, 380.0), (1.6, 0.035, -420.0)]},
     {"misstate": 0.035}),
]
PIEZO_HELDOUT3 = [
    ("pz-h3-null-2stacks-3.5in", "none", {}, {"n_stacks": 2, "wide_in": 3.5, "v_max": 145.0, "misstate": 0.045}),
    ("pz-h3-null-4stacks-spring", "none", {}, {"n_stacks": 4, "load": (4.5, 2200.0), "v_max": 110.0}),
    ("pz-h3-null-noisy", "none", {}, {"wide_in": 3.5, "v_max": 140.0, "load": (2.0, 2800.0), "sensor": NOISY3_PZ}),
    ("pz-h3-seal-3.5in", "seal_stick_slip", {"seal": dict(fc=1.8, fs=4.1, vs=3.5e-3, sigma2=0.0)}, {"wide_in": 3.5}),
    ("pz-h3-seal-2stacks", "seal_stick_slip", {"seal": dict(fc=3.8, fs=5.7, vs=1.8e-3, sigma2=0.0)},
     {"n_stacks": 2, "v_max": 140.0}),
    ("pz-h3-seal-loaded", "seal_stick_slip", {"seal": dict(fc=2.7, fs=4.6, vs=4.5e-3, sigma2=0.0)},
     {"n_stacks": 4, "load": (7.0, 1600.0), "misstate": 0.035}),
    ("pz-h3-logcreep-small", "stack_creep", {"creep": 0.016}, {"n_stacks": 2}),
    ("pz-h3-logcreep-large", "stack_creep", {"creep": 0.038}, {"wide_in": 3.5, "v_max": 110.0}),
    ("pz-h3-air-small", "fluid_compressibility", {"air": dict(eps0=0.016, kappa=1.1)}, {"load": (12.0, 1400.0)}),
    ("pz-h3-air-large", "fluid_compressibility", {"air": dict(eps0=0.034, kappa=1.35)},
     {"load": (6.5, 900.0), "wide_in": 3.5}),
    ("pz-h3-pade", "sensor_delay", {"delay_s": 0.011}, {"v_max": 145.0}),
    ("pz-h3-bandwidth", "amplifier_slew_limit", {"bandwidth": dict(omega=250.0, slew=850.0)}, {"n_stacks": 2}),
    ("pz-h3-viscous", "viscous_damping", {"viscous": 180.0}, {"wide_in": 3.5}),
    ("pz-h3-leak", "leakage", {"leak": dict(G=1.2e-14, area_m2=3.6e-10, cd=0.6)}, {"load": (11.0, 700.0)}),
    ("pz-h3-seal+creep", "seal_stick_slip+stack_creep",
     {"seal": dict(fc=1.3, fs=3.1, vs=2.8e-3, sigma2=0.0), "creep": 0.025}, {"v_max": 140.0}),
    ("pz-h3-leak+pade", "leakage+sensor_delay",
     {"leak": dict(G=5.5e-14, area_m2=1.1e-10, cd=0.6), "delay_s": 0.016}, {"load": (14.0, 1100.0), "n_stacks": 4}),
    ("pz-h3-pulses", "outside:force_pulses", {"pulses": [(0.45, 0.03, 3.5), (1.55, 0.025, -4.5)]}, {"n_stacks": 2}),
    ("pz-h3-amp-compression", "outside:amplifier_nonlinearity", {"amp_compression": 0.12},
     {"wide_in": 3.5, "v_max": 145.0}),
]



# The fourth held-out set: written independently of the diagnosis, kept for a
# final measurement: it is not to be run while changing the diagnosis. None of
# these cases was run through the diagnosis while writing them (only checked
# to generate finite runs without warnings). Other sizes of every effect,
# other rigs (8.5-19 mm DC strokes, 70-230 N DC loads, DC misstatements of
# 1.5-4 %, 3, 3.25 and 3.75 in pistons, two, three and four stacks, 115-150 V
# drives, other springs and preloads), a noisier sensor of each kind, pairs
# not used in a held-out set before (coulomb_friction+current_saturation,
# seal_stick_slip+sensor_delay, fluid_compressibility+leakage) and other seeds
# (``--heldout4`` in benchmarks/diagnose_benchmark.py). Viscous damping stays
# below about 550 N s/m (see the second set).
NOISY4_DC = {"white": 1.3e-3, "flicker": 3.8e-4}
NOISY4_PZ = {"white": 1.4e-3, "flicker": 3.6e-4, "volt_white": 0.4}
DC_HELDOUT4 = [
    ("dc-h4-null-short", "none", {}, {"stroke": 0.0085, "misstate": 0.015}),
    ("dc-h4-null-load", "none", {}, {"load": 230.0, "stroke": 0.017, "misstate": 0.04}),
    ("dc-h4-null-noisy", "none", {}, {"stroke": 0.013, "load": 90.0, "misstate": 0.03, "sensor": NOISY4_DC}),
    ("dc-h4-lugre-large", "coulomb_friction",
     {"friction": dict(fc=48.0, fs=68.0, vs=0.0022, sigma0=3.8e6, sigma1=2.8e3, sigma2=280.0)}, {"stroke": 0.019}),
    ("dc-h4-lugre-small", "coulomb_friction",
     {"friction": dict(fc=22.0, fs=36.0, vs=0.0055, sigma0=1.4e6, sigma1=1.3e3, sigma2=80.0)}, {"load": 140.0}),
    ("dc-h4-backlash-tight", "backlash",
     {"backlash": dict(gap_m=1.3e-4, k_N_m=7e6, zeta=0.17, m_kg=0.7, c_ground=240.0)}, {"stroke": 0.013}),
    ("dc-h4-backlash-loose", "backlash",
     {"backlash": dict(gap_m=3.8e-4, k_N_m=1.2e6, zeta=0.32, m_kg=2.8, c_ground=420.0)},
     {"load": 160.0, "misstate": 0.04}),
    ("dc-h4-mount-high", "sensor_vibration", {"mount": dict(f_Hz=42.0, zeta=0.014, gain=0.16)}, {"stroke": 0.017}),
    ("dc-h4-mount-low", "sensor_vibration", {"mount": dict(f_Hz=14.0, zeta=0.035, gain=0.27)},
     {"load": 210.0, "misstate": 0.04}),
    ("dc-h4-pade-short", "sensor_delay", {"delay_s": 0.0045}, {"stroke": 0.019}),
    ("dc-h4-pade-long", "sensor_delay", {"delay_s": 0.0165}, {"load": 130.0, "sensor": NOISY4_DC}),
    ("dc-h4-ilimit", "current_saturation", {"current_limit": 4.4}, {"load": 70.0}),
    ("dc-h4-lugre+ilimit", "coulomb_friction+current_saturation",
     {"friction": dict(fc=32.0, fs=47.0, vs=0.004, sigma0=2.4e6, sigma1=1.9e3, sigma2=140.0), "current_limit": 5.2},
     {"stroke": 0.015}),
    ("dc-h4-backlash+pade", "backlash+sensor_delay",
     {"backlash": dict(gap_m=2.2e-4, k_N_m=2.8e6, zeta=0.28, m_kg=1.4, c_ground=340.0), "delay_s": 0.0075},
     {"load": 110.0}),
    ("dc-h4-lugre+mount", "coulomb_friction+sensor_vibration",
     {"friction": dict(fc=40.0, fs=58.0, vs=0.0032, sigma0=3.2e6, sigma1=2.1e3, sigma2=220.0),
      "mount": dict(f_Hz=27.0, zeta=0.028, gain=0.21)}, {"stroke": 0.0085, "misstate": 0.02}),
    ("dc-h4-cogging", "outside:cogging", {"cogging": dict(amp_N=35.0, pitch_m=2e-3 / 7)}, {"load": 190.0}),
    ("dc-h4-pulses", "outside:force_pulses", {"pulses": [(0.35, 0.03, 330.0), (1.35, 0.02, -480.0)]},
     {"stroke": 0.013}),
    ("dc-h4-amp-asym", "outside:amplifier_nonlinearity", {"amp_asymmetry": 0.78}, {"stroke": 0.017, "misstate": 0.02}),
]
PIEZO_HELDOUT4 = [
    ("pz-h4-null-2stacks-3in", "none", {}, {"n_stacks": 2, "wide_in": 3.0, "v_max": 125.0, "misstate": 0.025}),
    ("pz-h4-null-4stacks-spring", "none", {}, {"n_stacks": 4, "load": (5.5, 1800.0), "v_max": 135.0,
                                               "misstate": 0.04}),
    ("pz-h4-null-noisy", "none", {}, {"wide_in": 3.25, "v_max": 115.0, "sensor": NOISY4_PZ}),
    ("pz-h4-seal-small", "seal_stick_slip", {"seal": dict(fc=1.1, fs=2.4, vs=3.2e-3, sigma2=0.0)},
     {"n_stacks": 4, "v_max": 120.0}),
    ("pz-h4-seal-large", "seal_stick_slip", {"seal": dict(fc=3.3, fs=5.4, vs=1.4e-3, sigma2=0.0)}, {"wide_in": 3.0}),
    ("pz-h4-seal-loaded", "seal_stick_slip", {"seal": dict(fc=2.4, fs=3.9, vs=2.2e-3, sigma2=0.0)},
     {"load": (6.0, 1300.0), "misstate": 0.04}),
    ("pz-h4-logcreep-small", "stack_creep", {"creep": 0.014}, {"n_stacks": 4, "v_max": 135.0}),
    ("pz-h4-logcreep-large", "stack_creep", {"creep": 0.032}, {"wide_in": 3.25}),
    ("pz-h4-air-small", "fluid_compressibility", {"air": dict(eps0=0.014, kappa=1.25)}, {"load": (10.0, 1100.0)}),
    ("pz-h4-air-large", "fluid_compressibility", {"air": dict(eps0=0.031, kappa=1.15)},
     {"load": (4.0, 2400.0), "n_stacks": 2}),
    ("pz-h4-pade", "sensor_delay", {"delay_s": 0.0085}, {"wide_in": 3.0}),
    ("pz-h4-bandwidth", "amplifier_slew_limit", {"bandwidth": dict(omega=380.0, slew=500.0)}, {"v_max": 140.0}),
    ("pz-h4-viscous", "viscous_damping", {"viscous": 300.0}, {"n_stacks": 2}),
    ("pz-h4-leak", "leakage", {"leak": dict(G=4e-14, area_m2=2.5e-10, cd=0.62)}, {"load": (7.5, 1500.0)}),
    ("pz-h4-seal+pade", "seal_stick_slip+sensor_delay",
     {"seal": dict(fc=2.0, fs=3.3, vs=2.6e-3, sigma2=0.0), "delay_s": 0.012}, {"n_stacks": 4}),
    ("pz-h4-air+leak", "fluid_compressibility+leakage",
     {"air": dict(eps0=0.022, kappa=1.3), "leak": dict(G=3.5e-14, area_m2=1.8e-10, cd=0.6)},
     {"load": (9.0, 1600.0), "wide_in": 3.25}),
    ("pz-h4-drift", "outside:thermal_drift", {"drift": 0.025}, {"n_stacks": 2, "v_max": 130.0}),
    ("pz-h4-pulses", "outside:force_pulses", {"pulses": [(0.55, 0.025, -3.8), (1.25, 0.04, 2.5)]},
     {"wide_in": 3.25, "v_max": 135.0}),
]

# The fifth held-out set: written independently of the diagnosis, before any
# of the changes, kept for a final measurement: it is not to be run while
# changing the diagnosis. None of these cases was run through the diagnosis
# while writing them (only checked to generate finite runs without warnings).
# Other sizes of every effect, other rigs (9.5-18.5 mm DC strokes, 40-200 N DC
# loads, DC misstatements of 1.5-3.5 %, 3, 3.25, 3.5 and 3.75 in pistons, two,
# three and four stacks, 120-150 V drives, other springs and preloads), a
# noisier sensor of each kind, pairs not used in a held-out set before
# (backlash+current_saturation, sensor_vibration+current_saturation,
# stack_creep+amplifier_slew_limit, fluid_compressibility+sensor_delay,
# viscous_damping+leakage) besides coulomb_friction+sensor_delay at other
# sizes, and other seeds (``--heldout5`` in benchmarks/diagnose_benchmark.py).
# Viscous damping stays below about 550 N s/m (see the second set).
NOISY5_DC = {"white": 1.35e-3, "flicker": 3.4e-4}
NOISY5_PZ = {"white": 1.45e-3, "flicker": 3.3e-4, "volt_white": 0.42}
DC_HELDOUT5 = [
    ("dc-h5-null-mid", "none", {}, {"stroke": 0.0105, "misstate": 0.035}),
    ("dc-h5-null-load", "none", {}, {"load": 170.0, "stroke": 0.0185, "misstate": 0.015}),
    ("dc-h5-null-noisy", "none", {}, {"stroke": 0.0155, "load": 50.0, "misstate": 0.025, "sensor": NOISY5_DC}),
    ("dc-h5-lugre-large", "coulomb_friction",
     {"friction": dict(fc=42.0, fs=62.0, vs=0.0028, sigma0=3.4e6, sigma1=2.4e3, sigma2=260.0)}, {"stroke": 0.0175}),
    ("dc-h5-lugre-small", "coulomb_friction",
     {"friction": dict(fc=19.0, fs=30.0, vs=0.0065, sigma0=1.1e6, sigma1=1.1e3, sigma2=90.0)},
     {"load": 200.0, "misstate": 0.02}),
    ("dc-h5-backlash-tight", "backlash",
     {"backlash": dict(gap_m=1.1e-4, k_N_m=5.5e6, zeta=0.2, m_kg=0.9, c_ground=260.0)}, {"stroke": 0.0115}),
    ("dc-h5-backlash-loose", "backlash",
     {"backlash": dict(gap_m=3.2e-4, k_N_m=1.8e6, zeta=0.33, m_kg=2.2, c_ground=440.0)},
     {"load": 120.0, "misstate": 0.03}),
    ("dc-h5-mount-high", "sensor_vibration", {"mount": dict(f_Hz=38.0, zeta=0.018, gain=0.17)}, {"load": 60.0}),
    ("dc-h5-mount-low", "sensor_vibration", {"mount": dict(f_Hz=16.0, zeta=0.04, gain=0.24)},
     {"stroke": 0.0095, "sensor": NOISY5_DC}),
    ("dc-h5-pade-short", "sensor_delay", {"delay_s": 0.0055}, {"load": 150.0, "misstate": 0.035}),
    ("dc-h5-pade-long", "sensor_delay", {"delay_s": 0.0135}, {"stroke": 0.0165}),
    ("dc-h5-ilimit", "current_saturation", {"current_limit": 3.9}, {"stroke": 0.0145}),
    ("dc-h5-backlash+ilimit", "backlash+current_saturation",
     {"backlash": dict(gap_m=2.4e-4, k_N_m=3.2e6, zeta=0.26, m_kg=1.6, c_ground=360.0), "current_limit": 4.6},
     {"stroke": 0.0125}),
    ("dc-h5-mount+ilimit", "sensor_vibration+current_saturation",
     {"mount": dict(f_Hz=31.0, zeta=0.022, gain=0.2), "current_limit": 5.8}, {"load": 100.0}),
    ("dc-h5-lugre+pade", "coulomb_friction+sensor_delay",
     {"friction": dict(fc=34.0, fs=50.0, vs=0.0038, sigma0=2.6e6, sigma1=1.7e3, sigma2=170.0), "delay_s": 0.0105},
     {"stroke": 0.0095, "misstate": 0.025}),
    ("dc-h5-cogging", "outside:cogging", {"cogging": dict(amp_N=28.0, pitch_m=2e-3 / 9)},
     {"stroke": 0.0135, "misstate": 0.03}),
    ("dc-h5-drift", "outside:thermal_drift", {"drift": 0.035}, {"load": 140.0}),
    ("dc-h5-amp-asym", "outside:amplifier_nonlinearity", {"amp_asymmetry": 0.82}, {"load": 40.0, "stroke": 0.0115}),
]
PIEZO_HELDOUT5 = [
    ("pz-h5-null-2stacks-3.5in", "none", {}, {"n_stacks": 2, "wide_in": 3.5, "v_max": 140.0, "misstate": 0.035}),
    ("pz-h5-null-4stacks-spring", "none", {}, {"n_stacks": 4, "wide_in": 3.25, "load": (4.0, 2100.0),
                                               "v_max": 125.0, "misstate": 0.02}),
    ("pz-h5-null-noisy", "none", {}, {"wide_in": 3.0, "v_max": 145.0, "load": (3.5, 1400.0), "misstate": 0.03,
                                      "sensor": NOISY5_PZ}),
    ("pz-h5-seal-small", "seal_stick_slip", {"seal": dict(fc=1.4, fs=2.6, vs=2.4e-3, sigma2=0.0)},
     {"n_stacks": 2, "v_max": 135.0}),
    ("pz-h5-seal-large", "seal_stick_slip", {"seal": dict(fc=3.1, fs=5.1, vs=1.6e-3, sigma2=0.0)},
     {"wide_in": 3.5, "load": (4.5, 1700.0)}),
    ("pz-h5-logcreep-small", "stack_creep", {"creep": 0.018}, {"wide_in": 3.0, "v_max": 140.0}),
    ("pz-h5-logcreep-large", "stack_creep", {"creep": 0.029}, {"n_stacks": 4, "misstate": 0.035}),
    ("pz-h5-air-small", "fluid_compressibility", {"air": dict(eps0=0.018, kappa=1.2)}, {"load": (7.0, 1250.0)}),
    ("pz-h5-air-large", "fluid_compressibility", {"air": dict(eps0=0.027, kappa=1.05)},
     {"load": (5.5, 2000.0), "wide_in": 3.25, "v_max": 125.0}),
    ("pz-h5-pade", "sensor_delay", {"delay_s": 0.0095}, {"n_stacks": 2, "wide_in": 3.25}),
    ("pz-h5-bandwidth", "amplifier_slew_limit", {"bandwidth": dict(omega=320.0, slew=750.0)},
     {"wide_in": 3.5, "v_max": 145.0}),
    ("pz-h5-viscous", "viscous_damping", {"viscous": 420.0}, {"v_max": 120.0}),
    ("pz-h5-leak", "leakage", {"leak": dict(G=2.6e-14, area_m2=2.1e-10, cd=0.63)}, {"load": (9.5, 1350.0)}),
    ("pz-h5-creep+bandwidth", "stack_creep+amplifier_slew_limit",
     {"creep": 0.024, "bandwidth": dict(omega=420.0, slew=550.0)}, {"v_max": 130.0}),
    ("pz-h5-air+pade", "fluid_compressibility+sensor_delay",
     {"air": dict(eps0=0.02, kappa=1.35), "delay_s": 0.0075}, {"load": (6.5, 1500.0), "n_stacks": 4}),
    ("pz-h5-viscous+leak", "viscous_damping+leakage",
     {"viscous": 220.0, "leak": dict(G=4.5e-14, area_m2=1.3e-10, cd=0.61)}, {"load": (12.0, 950.0), "wide_in": 3.0}),
    ("pz-h5-pulses", "outside:force_pulses", {"pulses": [(0.4, 0.035, 3.2), (1.45, 0.03, -3.6)]},
     {"n_stacks": 4, "v_max": 125.0}),
    ("pz-h5-amp-compression", "outside:amplifier_nonlinearity", {"amp_compression": 0.13},
     {"wide_in": 3.25, "v_max": 140.0}),
]

# The sixth held-out set: written independently of the diagnosis, kept for a
# final measurement: it is not to be run while changing the diagnosis. None of
# these cases was run through the diagnosis while writing them (only checked
# to generate finite runs without warnings). Other sizes of every effect,
# other rigs (9.2-18.8 mm DC strokes, 45-215 N DC loads, DC misstatements of
# 1.2-3.8 %, 3, 3.25, 3.5 and 3.75 in pistons, two, three and four stacks,
# 118-150 V drives, other springs and preloads), a noisier sensor of each
# kind, DC pairs used at most once in a held-out set before
# (backlash+coulomb_friction, backlash+sensor_vibration,
# sensor_vibration+sensor_delay), piezo pairs not used before
# (seal_stick_slip+leakage, amplifier_slew_limit+sensor_delay,
# fluid_compressibility+viscous_damping) and other seeds (``--heldout6`` in
# benchmarks/diagnose_benchmark.py). Viscous damping stays below about 550 N
# s/m (see the second set).
NOISY6_DC = {"white": 1.38e-3, "flicker": 3.55e-4}
NOISY6_PZ = {"white": 1.42e-3, "flicker": 3.45e-4, "volt_white": 0.44}
DC_HELDOUT6 = [
    ("dc-h6-null-mid", "none", {}, {"stroke": 0.0122, "misstate": 0.038}),
    ("dc-h6-null-load", "none", {}, {"load": 215.0, "stroke": 0.0158, "misstate": 0.022}),
    ("dc-h6-null-noisy", "none", {}, {"stroke": 0.0092, "load": 85.0, "misstate": 0.028, "sensor": NOISY6_DC}),
    ("dc-h6-lugre-large", "coulomb_friction",
     {"friction": dict(fc=46.0, fs=66.0, vs=0.0026, sigma0=3.6e6, sigma1=2.3e3, sigma2=240.0)},
     {"stroke": 0.0138, "misstate": 0.018}),
    ("dc-h6-lugre-small", "coulomb_friction",
     {"friction": dict(fc=17.0, fs=29.0, vs=0.0058, sigma0=1.3e6, sigma1=1.15e3, sigma2=70.0)}, {"load": 185.0}),
    ("dc-h6-backlash-tight", "backlash",
     {"backlash": dict(gap_m=1.4e-4, k_N_m=6.5e6, zeta=0.19, m_kg=0.75, c_ground=230.0)}, {"stroke": 0.0178}),
    ("dc-h6-backlash-loose", "backlash",
     {"backlash": dict(gap_m=3.6e-4, k_N_m=1.4e6, zeta=0.36, m_kg=2.6, c_ground=460.0)},
     {"load": 95.0, "misstate": 0.032}),
    ("dc-h6-mount-high", "sensor_vibration", {"mount": dict(f_Hz=45.0, zeta=0.016, gain=0.155)},
     {"stroke": 0.0108, "load": 125.0}),
    ("dc-h6-mount-low", "sensor_vibration", {"mount": dict(f_Hz=13.0, zeta=0.038, gain=0.26)},
     {"misstate": 0.038, "sensor": NOISY6_DC}),
    ("dc-h6-pade-short", "sensor_delay", {"delay_s": 0.0048}, {"stroke": 0.0168}),
    ("dc-h6-pade-long", "sensor_delay", {"delay_s": 0.0155}, {"load": 165.0, "misstate": 0.012}),
    ("dc-h6-ilimit", "current_saturation", {"current_limit": 4.2}, {"load": 65.0, "stroke": 0.0148}),
    ("dc-h6-backlash+lugre", "backlash+coulomb_friction",
     {"backlash": dict(gap_m=2.6e-4, k_N_m=2.2e6, zeta=0.27, m_kg=1.7, c_ground=330.0),
      "friction": dict(fc=27.0, fs=44.0, vs=0.0042, sigma0=2.1e6, sigma1=1.75e3, sigma2=160.0)},
     {"stroke": 0.0132}),
    ("dc-h6-backlash+mount", "backlash+sensor_vibration",
     {"backlash": dict(gap_m=1.9e-4, k_N_m=4.5e6, zeta=0.23, m_kg=1.3, c_ground=310.0),
      "mount": dict(f_Hz=24.0, zeta=0.032, gain=0.19)}, {"load": 155.0}),
    ("dc-h6-mount+pade", "sensor_vibration+sensor_delay",
     {"mount": dict(f_Hz=20.0, zeta=0.024, gain=0.23), "delay_s": 0.0085}, {"stroke": 0.0102, "misstate": 0.018}),
    ("dc-h6-cogging", "outside:cogging", {"cogging": dict(amp_N=32.0, pitch_m=2e-3 / 11)},
     {"stroke": 0.0128, "misstate": 0.022}),
    ("dc-h6-drift", "outside:thermal_drift", {"drift": 0.028}, {"load": 45.0, "stroke": 0.0188}),
    ("dc-h6-pulses", "outside:force_pulses", {"pulses": [(0.5, 0.025, 360.0), (1.5, 0.03, -340.0)]},
     {"load": 135.0}),
]
PIEZO_HELDOUT6 = [
    ("pz-h6-null-3stacks-3.25in", "none", {}, {"wide_in": 3.25, "v_max": 132.0, "misstate": 0.038}),
    ("pz-h6-null-2stacks-spring", "none", {}, {"n_stacks": 2, "load": (4.8, 1900.0), "v_max": 148.0,
                                               "misstate": 0.022}),
    ("pz-h6-null-noisy", "none", {}, {"n_stacks": 4, "wide_in": 3.5, "v_max": 122.0, "load": (3.8, 2600.0),
                                      "misstate": 0.028, "sensor": NOISY6_PZ}),
    ("pz-h6-seal-small", "seal_stick_slip", {"seal": dict(fc=1.25, fs=2.5, vs=2.9e-3, sigma2=0.0)},
     {"wide_in": 3.25, "v_max": 138.0}),
    ("pz-h6-seal-large", "seal_stick_slip", {"seal": dict(fc=3.4, fs=5.3, vs=1.3e-3, sigma2=0.0)},
     {"n_stacks": 4, "load": (6.8, 1750.0)}),
    ("pz-h6-logcreep-small", "stack_creep", {"creep": 0.013}, {"n_stacks": 2, "wide_in": 3.5}),
    ("pz-h6-logcreep-large", "stack_creep", {"creep": 0.034}, {"v_max": 118.0, "misstate": 0.018}),
    ("pz-h6-air-small", "fluid_compressibility", {"air": dict(eps0=0.015, kappa=1.22)},
     {"load": (8.5, 1150.0), "n_stacks": 2}),
    ("pz-h6-air-large", "fluid_compressibility", {"air": dict(eps0=0.033, kappa=1.08)},
     {"load": (5.2, 2300.0), "wide_in": 3.0, "v_max": 142.0}),
    ("pz-h6-pade", "sensor_delay", {"delay_s": 0.0125}, {"n_stacks": 4, "wide_in": 3.0}),
    ("pz-h6-bandwidth", "amplifier_slew_limit", {"bandwidth": dict(omega=350.0, slew=650.0)},
     {"wide_in": 3.25, "v_max": 128.0}),
    ("pz-h6-viscous", "viscous_damping", {"viscous": 380.0}, {"n_stacks": 2, "wide_in": 3.5}),
    ("pz-h6-leak", "leakage", {"leak": dict(G=3.2e-14, area_m2=2.3e-10, cd=0.64)},
     {"load": (10.5, 1450.0), "wide_in": 3.5}),
    ("pz-h6-seal+leak", "seal_stick_slip+leakage",
     {"seal": dict(fc=2.3, fs=3.7, vs=2.1e-3, sigma2=0.0), "leak": dict(G=2.2e-14, area_m2=2.8e-10, cd=0.6)},
     {"load": (11.5, 850.0), "n_stacks": 4}),
    ("pz-h6-bandwidth+pade", "amplifier_slew_limit+sensor_delay",
     {"bandwidth": dict(omega=280.0, slew=620.0), "delay_s": 0.0068}, {"n_stacks": 2, "v_max": 128.0}),
    ("pz-h6-air+viscous", "fluid_compressibility+viscous_damping",
     {"air": dict(eps0=0.024, kappa=1.32), "viscous": 270.0}, {"load": (7.8, 1050.0), "wide_in": 3.25}),
    ("pz-h6-drift", "outside:thermal_drift", {"drift": 0.033}, {"wide_in": 3.0, "v_max": 122.0}),
    ("pz-h6-amp-compression", "outside:amplifier_nonlinearity", {"amp_compression": 0.17},
     {"n_stacks": 4, "v_max": 138.0}),
]

# The seventh held-out set: written independently of the diagnosis, kept for a
# final measurement: it is not to be run while changing the diagnosis. None of
# these cases was run through the diagnosis while writing them (only checked
# to generate finite runs without warnings). Other sizes of every effect,
# other rigs (8.8-19.5 mm DC strokes, 55-255 N DC loads, DC misstatements of
# 1.4-4.2 %, 3, 3.25, 3.5 and 3.75 in pistons, two, three and four stacks,
# 112-150 V drives, other springs and preloads, piezo misstatements of 1.4-4.2
# %), a noisier sensor of each kind, DC pairs used only once in a held-out set
# before (coulomb_friction+current_saturation,
# sensor_vibration+current_saturation, current_saturation+sensor_delay), piezo
# pairs not used before (seal_stick_slip+viscous_damping, stack_creep+leakage,
# fluid_compressibility+amplifier_slew_limit), every outside form but DC drift
# (DC cogging at a finer pitch, force pulses on both rigs, DC amplifier
# asymmetry, piezo drift and amplifier compression) and other seeds
# (``--heldout7`` in benchmarks/diagnose_benchmark.py). Viscous damping stays
# below about 550 N s/m (see the second set).
NOISY7_DC = {"white": 1.45e-3, "flicker": 3.7e-4}
NOISY7_PZ = {"white": 1.36e-3, "flicker": 3.75e-4, "volt_white": 0.47}
DC_HELDOUT7 = [
    ("dc-h7-null-mid", "none", {}, {"stroke": 0.0118, "misstate": 0.034}),
    ("dc-h7-null-load", "none", {}, {"load": 235.0, "stroke": 0.0172, "misstate": 0.016}),
    ("dc-h7-null-noisy", "none", {}, {"stroke": 0.0098, "load": 75.0, "misstate": 0.026, "sensor": NOISY7_DC}),
    ("dc-h7-lugre-large", "coulomb_friction",
     {"friction": dict(fc=52.0, fs=69.0, vs=0.0024, sigma0=3.9e6, sigma1=2.45e3, sigma2=290.0)},
     {"stroke": 0.0152, "misstate": 0.024}),
    ("dc-h7-lugre-small", "coulomb_friction",
     {"friction": dict(fc=21.0, fs=34.0, vs=0.0062, sigma0=1.25e6, sigma1=1.25e3, sigma2=110.0)}, {"load": 195.0}),
    ("dc-h7-backlash-tight", "backlash",
     {"backlash": dict(gap_m=1.25e-4, k_N_m=7.5e6, zeta=0.16, m_kg=0.65, c_ground=235.0)}, {"stroke": 0.0162}),
    ("dc-h7-backlash-loose", "backlash",
     {"backlash": dict(gap_m=3.4e-4, k_N_m=1.6e6, zeta=0.34, m_kg=2.4, c_ground=430.0)},
     {"load": 105.0, "misstate": 0.042}),
    ("dc-h7-mount-high", "sensor_vibration", {"mount": dict(f_Hz=51.0, zeta=0.013, gain=0.145)},
     {"stroke": 0.0126, "load": 145.0}),
    ("dc-h7-mount-low", "sensor_vibration", {"mount": dict(f_Hz=11.0, zeta=0.042, gain=0.29)},
     {"misstate": 0.014, "sensor": NOISY7_DC}),
    ("dc-h7-pade-short", "sensor_delay", {"delay_s": 0.0042}, {"stroke": 0.0182}),
    ("dc-h7-pade-long", "sensor_delay", {"delay_s": 0.0145}, {"load": 175.0, "misstate": 0.036}),
    ("dc-h7-ilimit", "current_saturation", {"current_limit": 3.7}, {"load": 55.0, "stroke": 0.0142}),
    ("dc-h7-lugre+ilimit", "coulomb_friction+current_saturation",
     {"friction": dict(fc=36.0, fs=53.0, vs=0.0036, sigma0=2.7e6, sigma1=1.85e3, sigma2=190.0), "current_limit": 5.0},
     {"stroke": 0.0134}),
    ("dc-h7-mount+ilimit", "sensor_vibration+current_saturation",
     {"mount": dict(f_Hz=33.0, zeta=0.027, gain=0.185), "current_limit": 6.2}, {"load": 115.0}),
    ("dc-h7-ilimit+pade", "current_saturation+sensor_delay", {"current_limit": 4.5, "delay_s": 0.0065},
     {"stroke": 0.0112, "misstate": 0.016}),
    ("dc-h7-cogging", "outside:cogging", {"cogging": dict(amp_N=38.0, pitch_m=2e-3 / 14)},
     {"stroke": 0.0195, "misstate": 0.024}),
    ("dc-h7-pulses", "outside:force_pulses", {"pulses": [(0.45, 0.022, -400.0), (1.3, 0.032, 310.0)]},
     {"load": 255.0}),
    ("dc-h7-amp-asym", "outside:amplifier_nonlinearity", {"amp_asymmetry": 0.77},
     {"stroke": 0.0088, "misstate": 0.026}),
]
PIEZO_HELDOUT7 = [
    ("pz-h7-null-3stacks-3in", "none", {}, {"wide_in": 3.0, "v_max": 136.0, "misstate": 0.032}),
    ("pz-h7-null-4stacks-spring", "none", {}, {"n_stacks": 4, "load": (6.2, 1650.0), "v_max": 116.0,
                                               "misstate": 0.024}),
    ("pz-h7-null-noisy", "none", {}, {"n_stacks": 2, "wide_in": 3.25, "v_max": 144.0, "load": (4.2, 2050.0),
                                      "misstate": 0.036, "sensor": NOISY7_PZ}),
    ("pz-h7-seal-small", "seal_stick_slip", {"seal": dict(fc=1.15, fs=2.3, vs=3.4e-3, sigma2=0.0)},
     {"n_stacks": 4, "wide_in": 3.5, "v_max": 127.0}),
    ("pz-h7-seal-large", "seal_stick_slip", {"seal": dict(fc=3.6, fs=5.6, vs=1.25e-3, sigma2=0.0)},
     {"load": (9.8, 1550.0), "misstate": 0.014}),
    ("pz-h7-logcreep-small", "stack_creep", {"creep": 0.017}, {"wide_in": 3.25, "v_max": 112.0}),
    ("pz-h7-logcreep-large", "stack_creep", {"creep": 0.036}, {"n_stacks": 2, "misstate": 0.042}),
    ("pz-h7-air-small", "fluid_compressibility", {"air": dict(eps0=0.013, kappa=1.28)},
     {"load": (11.2, 1020.0), "wide_in": 3.5}),
    ("pz-h7-air-large", "fluid_compressibility", {"air": dict(eps0=0.036, kappa=1.12)},
     {"load": (3.2, 2750.0), "n_stacks": 4, "v_max": 134.0}),
    ("pz-h7-pade", "sensor_delay", {"delay_s": 0.0135}, {"wide_in": 3.0, "v_max": 146.0}),
    ("pz-h7-bandwidth", "amplifier_slew_limit", {"bandwidth": dict(omega=260.0, slew=720.0)},
     {"n_stacks": 4, "misstate": 0.026}),
    ("pz-h7-viscous", "viscous_damping", {"viscous": 330.0}, {"wide_in": 3.25, "v_max": 124.0}),
    ("pz-h7-leak", "leakage", {"leak": dict(G=2.8e-14, area_m2=2.6e-10, cd=0.63)},
     {"load": (7.2, 1380.0), "n_stacks": 2}),
    ("pz-h7-seal+viscous", "seal_stick_slip+viscous_damping",
     {"seal": dict(fc=1.9, fs=3.4, vs=2.7e-3, sigma2=0.0), "viscous": 240.0}, {"wide_in": 3.5, "misstate": 0.024}),
    ("pz-h7-creep+leak", "stack_creep+leakage",
     {"creep": 0.027, "leak": dict(G=4.2e-14, area_m2=1.9e-10, cd=0.61)}, {"load": (13.0, 1180.0), "wide_in": 3.25}),
    ("pz-h7-air+bandwidth", "fluid_compressibility+amplifier_slew_limit",
     {"air": dict(eps0=0.021, kappa=1.38), "bandwidth": dict(omega=470.0, slew=560.0)},
     {"load": (5.8, 2450.0), "n_stacks": 2, "v_max": 136.0}),
    ("pz-h7-pulses", "outside:force_pulses", {"pulses": [(0.65, 0.03, -3.3), (1.5, 0.022, 4.2)]},
     {"n_stacks": 2, "wide_in": 3.5, "misstate": 0.036}),
    ("pz-h7-drift", "outside:thermal_drift", {"drift": 0.037}, {"n_stacks": 4, "wide_in": 3.25, "misstate": 0.014}),
    ("pz-h7-amp-compression", "outside:amplifier_nonlinearity", {"amp_compression": 0.16},
     {"wide_in": 3.0, "v_max": 144.0}),
]

# The eighth held-out set: written independently of the diagnosis, kept for a
# final measurement: it is not to be run while changing the diagnosis. None of
# these cases was run through the diagnosis while writing them (only checked
# to generate finite runs without warnings). Other sizes of every effect,
# other rigs (9.3-18.6 mm DC strokes, 48-245 N DC loads, DC misstatements of
# 1.3-4.4 %, 3, 3.25, 3.5 and 3.75 in pistons, two, three and four stacks,
# 114-148 V drives, other springs and preloads, piezo misstatements of 1.3-4.4
# %), a noisier sensor of each kind, the DC pairs used least in a held-out set
# before and not in the sixth or seventh (backlash+current_saturation,
# backlash+sensor_delay, coulomb_friction+sensor_vibration), piezo pairs not
# used before (seal_stick_slip+amplifier_slew_limit,
# stack_creep+viscous_damping, amplifier_slew_limit+leakage), outside forms
# (DC drift, force pulses and amplifier asymmetry; piezo drift, force pulses
# and amplifier compression) and other seeds (``--heldout8`` in
# benchmarks/diagnose_benchmark.py). Viscous damping stays below about 550 N
# s/m (see the second set).
NOISY8_DC = {"white": 1.42e-3, "flicker": 3.6e-4}
NOISY8_PZ = {"white": 1.38e-3, "flicker": 3.5e-4, "volt_white": 0.46}
DC_HELDOUT8 = [
    ("dc-h8-null-mid", "none", {}, {"stroke": 0.0128, "misstate": 0.044}),
    ("dc-h8-null-load", "none", {}, {"load": 245.0, "stroke": 0.0164, "misstate": 0.019}),
    ("dc-h8-null-noisy", "none", {}, {"stroke": 0.0102, "load": 68.0, "misstate": 0.031, "sensor": NOISY8_DC}),
    ("dc-h8-lugre-large", "coulomb_friction",
     {"friction": dict(fc=50.0, fs=67.0, vs=0.0023, sigma0=3.7e6, sigma1=2.55e3, sigma2=270.0)},
     {"stroke": 0.0146, "misstate": 0.028}),
    ("dc-h8-lugre-small", "coulomb_friction",
     {"friction": dict(fc=16.0, fs=28.0, vs=0.0068, sigma0=1.15e6, sigma1=1.05e3, sigma2=75.0)}, {"load": 205.0}),
    ("dc-h8-backlash-tight", "backlash",
     {"backlash": dict(gap_m=1.15e-4, k_N_m=6.8e6, zeta=0.175, m_kg=0.72, c_ground=245.0)}, {"stroke": 0.0186}),
    ("dc-h8-backlash-loose", "backlash",
     {"backlash": dict(gap_m=3.7e-4, k_N_m=1.3e6, zeta=0.37, m_kg=2.7, c_ground=470.0)},
     {"load": 88.0, "misstate": 0.037}),
    ("dc-h8-mount-high", "sensor_vibration", {"mount": dict(f_Hz=53.0, zeta=0.011, gain=0.135)},
     {"stroke": 0.0114, "load": 135.0}),
    ("dc-h8-mount-low", "sensor_vibration", {"mount": dict(f_Hz=12.5, zeta=0.043, gain=0.275)},
     {"misstate": 0.021, "sensor": NOISY8_DC}),
    ("dc-h8-pade-short", "sensor_delay", {"delay_s": 0.0038}, {"stroke": 0.0174, "misstate": 0.013}),
    ("dc-h8-pade-long", "sensor_delay", {"delay_s": 0.0172}, {"load": 158.0}),
    ("dc-h8-ilimit", "current_saturation", {"current_limit": 4.1}, {"load": 48.0, "stroke": 0.0156}),
    ("dc-h8-backlash+ilimit", "backlash+current_saturation",
     {"backlash": dict(gap_m=2.1e-4, k_N_m=3.8e6, zeta=0.24, m_kg=1.45, c_ground=335.0), "current_limit": 5.4},
     {"stroke": 0.0136, "misstate": 0.024}),
    ("dc-h8-backlash+pade", "backlash+sensor_delay",
     {"backlash": dict(gap_m=2.9e-4, k_N_m=2.4e6, zeta=0.29, m_kg=1.9, c_ground=390.0), "delay_s": 0.0095},
     {"load": 125.0}),
    ("dc-h8-lugre+mount", "coulomb_friction+sensor_vibration",
     {"friction": dict(fc=31.0, fs=46.0, vs=0.0041, sigma0=2.3e6, sigma1=1.65e3, sigma2=150.0),
      "mount": dict(f_Hz=29.0, zeta=0.03, gain=0.205)}, {"stroke": 0.0093, "misstate": 0.033}),
    ("dc-h8-drift", "outside:thermal_drift", {"drift": 0.038}, {"stroke": 0.0122, "load": 95.0}),
    ("dc-h8-pulses", "outside:force_pulses", {"pulses": [(0.6, 0.028, 350.0), (1.4, 0.024, -390.0)]},
     {"stroke": 0.0168, "misstate": 0.017}),
    ("dc-h8-amp-asym", "outside:amplifier_nonlinearity", {"amp_asymmetry": 0.81},
     {"load": 175.0, "misstate": 0.039}),
]
PIEZO_HELDOUT8 = [
    ("pz-h8-null-3stacks-3.5in", "none", {}, {"wide_in": 3.5, "v_max": 133.0, "misstate": 0.041}),
    ("pz-h8-null-2stacks-spring", "none", {}, {"n_stacks": 2, "wide_in": 3.0, "load": (5.6, 1750.0),
                                               "v_max": 141.0, "misstate": 0.019}),
    ("pz-h8-null-noisy", "none", {}, {"n_stacks": 4, "wide_in": 3.25, "v_max": 119.0, "load": (3.6, 2350.0),
                                      "misstate": 0.027, "sensor": NOISY8_PZ}),
    ("pz-h8-seal-small", "seal_stick_slip", {"seal": dict(fc=1.35, fs=2.55, vs=3.1e-3, sigma2=0.0)},
     {"n_stacks": 2, "wide_in": 3.25, "v_max": 131.0}),
    ("pz-h8-seal-large", "seal_stick_slip", {"seal": dict(fc=3.25, fs=5.5, vs=1.45e-3, sigma2=0.0)},
     {"n_stacks": 4, "load": (8.2, 1420.0), "misstate": 0.031}),
    ("pz-h8-logcreep-small", "stack_creep", {"creep": 0.0155}, {"wide_in": 3.0, "v_max": 126.0}),
    ("pz-h8-logcreep-large", "stack_creep", {"creep": 0.033}, {"n_stacks": 4, "wide_in": 3.5, "misstate": 0.013}),
    ("pz-h8-air-small", "fluid_compressibility", {"air": dict(eps0=0.0145, kappa=1.18)},
     {"load": (9.6, 1080.0), "n_stacks": 4}),
    ("pz-h8-air-large", "fluid_compressibility", {"air": dict(eps0=0.035, kappa=1.26)},
     {"load": (4.4, 2550.0), "wide_in": 3.25, "v_max": 138.0}),
    ("pz-h8-pade", "sensor_delay", {"delay_s": 0.0105}, {"n_stacks": 2, "wide_in": 3.5, "v_max": 148.0}),
    ("pz-h8-bandwidth", "amplifier_slew_limit", {"bandwidth": dict(omega=410.0, slew=580.0)},
     {"wide_in": 3.0, "misstate": 0.044}),
    ("pz-h8-viscous", "viscous_damping", {"viscous": 400.0}, {"n_stacks": 4, "v_max": 129.0}),
    ("pz-h8-leak", "leakage", {"leak": dict(G=3.7e-14, area_m2=1.7e-10, cd=0.62)},
     {"load": (12.5, 1250.0), "wide_in": 3.0}),
    ("pz-h8-seal+bandwidth", "seal_stick_slip+amplifier_slew_limit",
     {"seal": dict(fc=2.1, fs=3.6, vs=2.3e-3, sigma2=0.0), "bandwidth": dict(omega=340.0, slew=680.0)},
     {"wide_in": 3.25, "v_max": 137.0}),
    ("pz-h8-creep+viscous", "stack_creep+viscous_damping", {"creep": 0.023, "viscous": 290.0},
     {"n_stacks": 2, "misstate": 0.022}),
    ("pz-h8-bandwidth+leak", "amplifier_slew_limit+leakage",
     {"bandwidth": dict(omega=390.0, slew=610.0), "leak": dict(G=3e-14, area_m2=2.2e-10, cd=0.615)},
     {"load": (10.8, 1320.0), "n_stacks": 4, "wide_in": 3.5}),
    ("pz-h8-drift", "outside:thermal_drift", {"drift": 0.029}, {"n_stacks": 2, "wide_in": 3.0, "v_max": 114.0}),
    ("pz-h8-pulses", "outside:force_pulses", {"pulses": [(0.5, 0.026, 3.7), (1.35, 0.034, -2.9)]},
     {"wide_in": 3.5, "misstate": 0.033}),
    ("pz-h8-amp-compression", "outside:amplifier_nonlinearity", {"amp_compression": 0.145},
     {"n_stacks": 4, "wide_in": 3.25, "v_max": 134.0}),
]

# The ninth held-out set: written independently of the diagnosis, kept for a
# final measurement: it is not to be run while changing the diagnosis. None of
# these cases was run through the diagnosis while writing them (only checked
# to generate finite runs without warnings). Other sizes of every effect,
# other rigs (9.6-17.6 mm DC strokes, 44-225 N DC loads, DC misstatements of
# 1.8-4.1 %, 3, 3.25, 3.5 and 3.75 in pistons, two, three and four stacks,
# 118-147 V drives besides the 150 V default, other springs and preloads,
# piezo misstatements of 1.7-3.9 %), a noisier sensor of each kind, the DC
# pairs used least in a held-out set before and not in the seventh or eighth
# (backlash+coulomb_friction, sensor_vibration+sensor_delay,
# backlash+sensor_vibration), the one piezo pair never used before
# (amplifier_slew_limit+viscous_damping) and two used once, long ago
# (seal_stick_slip+fluid_compressibility in the first held-out set,
# stack_creep+sensor_delay only in the development set), outside forms (DC
# cogging at a new pitch, drift and amplifier asymmetry; piezo drift, force
# pulses and amplifier compression) and other seeds (``--heldout9`` in
# benchmarks/diagnose_benchmark.py). Viscous damping stays below about 550 N
# s/m (see the second set).
NOISY9_DC = {"white": 1.47e-3, "flicker": 3.85e-4}
NOISY9_PZ = {"white": 1.34e-3, "flicker": 3.4e-4, "volt_white": 0.43}
DC_HELDOUT9 = [
    ("dc-h9-null-mid", "none", {}, {"stroke": 0.0134, "misstate": 0.029}),
    ("dc-h9-null-load", "none", {}, {"load": 225.0, "stroke": 0.0176, "misstate": 0.041}),
    ("dc-h9-null-noisy", "none", {}, {"stroke": 0.0096, "load": 58.0, "misstate": 0.018, "sensor": NOISY9_DC}),
    ("dc-h9-lugre-large", "coulomb_friction",
     {"friction": dict(fc=53.0, fs=71.0, vs=0.0019, sigma0=4.2e6, sigma1=2.7e3, sigma2=310.0)},
     {"stroke": 0.0158, "misstate": 0.035}),
    ("dc-h9-lugre-small", "coulomb_friction",
     {"friction": dict(fc=23.0, fs=38.0, vs=0.0052, sigma0=1.5e6, sigma1=1.4e3, sigma2=105.0)},
     {"load": 190.0, "misstate": 0.023}),
    ("dc-h9-backlash-tight", "backlash",
     {"backlash": dict(gap_m=1.05e-4, k_N_m=7.2e6, zeta=0.165, m_kg=0.68, c_ground=225.0)}, {"stroke": 0.0106}),
    ("dc-h9-backlash-loose", "backlash",
     {"backlash": dict(gap_m=3.9e-4, k_N_m=1.1e6, zeta=0.35, m_kg=2.9, c_ground=455.0)},
     {"load": 112.0, "misstate": 0.027}),
    ("dc-h9-mount-high", "sensor_vibration", {"mount": dict(f_Hz=46.0, zeta=0.012, gain=0.175)},
     {"stroke": 0.0102, "load": 44.0}),
    ("dc-h9-mount-low", "sensor_vibration", {"mount": dict(f_Hz=11.5, zeta=0.047, gain=0.285)},
     {"stroke": 0.0108, "misstate": 0.032}),
    ("dc-h9-pade-short", "sensor_delay", {"delay_s": 0.0044}, {"load": 148.0, "misstate": 0.038}),
    ("dc-h9-pade-long", "sensor_delay", {"delay_s": 0.0138}, {"stroke": 0.0112, "sensor": NOISY9_DC}),
    ("dc-h9-ilimit", "current_saturation", {"current_limit": 4.6}, {"load": 82.0, "stroke": 0.0172}),
    ("dc-h9-backlash+lugre", "backlash+coulomb_friction",
     {"backlash": dict(gap_m=2.3e-4, k_N_m=3.3e6, zeta=0.26, m_kg=1.55, c_ground=345.0),
      "friction": dict(fc=29.0, fs=43.0, vs=0.0044, sigma0=2.2e6, sigma1=1.7e3, sigma2=135.0)},
     {"stroke": 0.0152, "misstate": 0.021}),
    ("dc-h9-mount+pade", "sensor_vibration+sensor_delay",
     {"mount": dict(f_Hz=26.0, zeta=0.026, gain=0.215), "delay_s": 0.0078}, {"load": 142.0}),
    ("dc-h9-backlash+mount", "backlash+sensor_vibration",
     {"backlash": dict(gap_m=1.7e-4, k_N_m=5.2e6, zeta=0.21, m_kg=1.1, c_ground=285.0),
      "mount": dict(f_Hz=36.0, zeta=0.02, gain=0.175)}, {"stroke": 0.0124, "misstate": 0.036}),
    ("dc-h9-cogging", "outside:cogging", {"cogging": dict(amp_N=43.0, pitch_m=2e-3 / 13)},
     {"stroke": 0.0144, "load": 105.0}),
    ("dc-h9-drift", "outside:thermal_drift", {"drift": 0.032}, {"stroke": 0.0166, "misstate": 0.025}),
    ("dc-h9-amp-asym", "outside:amplifier_nonlinearity", {"amp_asymmetry": 0.79},
     {"stroke": 0.0118, "load": 62.0}),
]
PIEZO_HELDOUT9 = [
    ("pz-h9-null-4stacks-3in", "none", {}, {"n_stacks": 4, "wide_in": 3.0, "v_max": 143.0, "misstate": 0.033}),
    ("pz-h9-null-3stacks-spring", "none", {}, {"wide_in": 3.5, "load": (6.6, 1950.0), "v_max": 121.0,
                                               "misstate": 0.017}),
    ("pz-h9-null-noisy", "none", {}, {"n_stacks": 2, "v_max": 127.0, "load": (3.4, 2200.0), "misstate": 0.039,
                                      "sensor": NOISY9_PZ}),
    ("pz-h9-seal-small", "seal_stick_slip", {"seal": dict(fc=1.3, fs=2.45, vs=3.6e-3, sigma2=0.0)},
     {"n_stacks": 4, "wide_in": 3.0, "v_max": 136.0}),
    ("pz-h9-seal-large", "seal_stick_slip", {"seal": dict(fc=3.5, fs=5.8, vs=1.35e-3, sigma2=0.0)},
     {"wide_in": 3.25, "load": (7.4, 1600.0), "misstate": 0.021}),
    ("pz-h9-logcreep-small", "stack_creep", {"creep": 0.0165}, {"n_stacks": 2, "v_max": 118.0, "misstate": 0.029}),
    ("pz-h9-logcreep-large", "stack_creep", {"creep": 0.031}, {"wide_in": 3.25, "v_max": 146.0}),
    ("pz-h9-air-small", "fluid_compressibility", {"air": dict(eps0=0.0165, kappa=1.24)},
     {"load": (8.8, 1180.0), "wide_in": 3.5}),
    ("pz-h9-air-large", "fluid_compressibility", {"air": dict(eps0=0.032, kappa=1.21)},
     {"load": (4.6, 2650.0), "n_stacks": 2, "v_max": 131.0}),
    ("pz-h9-pade", "sensor_delay", {"delay_s": 0.0115}, {"n_stacks": 4, "wide_in": 3.25, "v_max": 124.0}),
    ("pz-h9-bandwidth", "amplifier_slew_limit", {"bandwidth": dict(omega=430.0, slew=530.0)},
     {"n_stacks": 2, "wide_in": 3.5, "v_max": 140.0}),
    ("pz-h9-viscous", "viscous_damping", {"viscous": 440.0}, {"wide_in": 3.0, "misstate": 0.037}),
    ("pz-h9-leak", "leakage", {"leak": dict(G=3.4e-14, area_m2=2e-10, cd=0.61)},
     {"load": (11.8, 1100.0), "n_stacks": 2, "wide_in": 3.25}),
    ("pz-h9-bandwidth+viscous", "amplifier_slew_limit+viscous_damping",
     {"bandwidth": dict(omega=360.0, slew=640.0), "viscous": 310.0}, {"n_stacks": 4, "wide_in": 3.25,
                                                                     "v_max": 135.0}),
    ("pz-h9-seal+air", "seal_stick_slip+fluid_compressibility",
     {"seal": dict(fc=2.6, fs=4.3, vs=1.9e-3, sigma2=0.0), "air": dict(eps0=0.023, kappa=1.34)},
     {"load": (6.2, 1850.0), "wide_in": 3.5}),
    ("pz-h9-creep+pade", "stack_creep+sensor_delay", {"creep": 0.026, "delay_s": 0.0088},
     {"n_stacks": 2, "v_max": 137.0, "misstate": 0.028}),
    ("pz-h9-drift", "outside:thermal_drift", {"drift": 0.035}, {"wide_in": 3.5, "v_max": 126.0, "misstate": 0.031}),
    ("pz-h9-pulses", "outside:force_pulses", {"pulses": [(0.55, 0.032, -3.4), (1.4, 0.028, 4.0)]},
     {"n_stacks": 4, "wide_in": 3.0}),
    ("pz-h9-amp-compression", "outside:amplifier_nonlinearity", {"amp_compression": 0.135},
     {"n_stacks": 2, "v_max": 147.0, "misstate": 0.019}),
]

# The tenth held-out set: written independently of the diagnosis, kept for a
# final measurement: it is not to be run while changing the diagnosis. None of
# these cases was run through the diagnosis while writing them (only checked
# to generate finite runs without warnings, and each effect's clean output
# compared with the same case generated without it, same seed, so that none is
# buried under the sensor's white noise). Other sizes of every effect, other
# rigs (9.1-18.3 mm DC strokes, 52-262 N DC loads, DC misstatements of
# 1.55-4.3 %, 3, 3.25, 3.5 and 3.75 in pistons, two, three and four stacks,
# 113-149 V drives besides the 150 V default, other springs and preloads,
# piezo misstatements of 1.5-4.3 %), a noisier sensor of each kind, the DC
# pairs used least in a held-out set before
# (coulomb_friction+current_saturation, sensor_vibration+current_saturation,
# current_saturation+sensor_delay: twice each, last in the seventh set), three
# piezo pairs used once, in the second and third sets only
# (stack_creep+fluid_compressibility, viscous_damping+sensor_delay,
# seal_stick_slip+stack_creep), outside forms (DC force pulses, drift and
# amplifier asymmetry; piezo drift, force pulses and amplifier compression)
# and other seeds (``--heldout10`` in benchmarks/diagnose_benchmark.py).
# Viscous damping stays below about 550 N s/m (see the second set).
NOISY10_DC = {"white": 1.44e-3, "flicker": 3.65e-4}
NOISY10_PZ = {"white": 1.37e-3, "flicker": 3.55e-4, "volt_white": 0.41}
DC_HELDOUT10 = [
    ("dc-h10-null-long", "none", {}, {"stroke": 0.0183, "misstate": 0.043}),
    ("dc-h10-null-light", "none", {}, {"load": 52.0, "stroke": 0.0117, "misstate": 0.0155}),
    ("dc-h10-null-noisy", "none", {}, {"stroke": 0.0137, "load": 238.0, "misstate": 0.0335,
                                       "sensor": NOISY10_DC}),
    ("dc-h10-lugre-large", "coulomb_friction",
     {"friction": dict(fc=44.0, fs=63.0, vs=0.0027, sigma0=3.3e6, sigma1=2.35e3, sigma2=230.0)},
     {"stroke": 0.0149, "misstate": 0.0305}),
    ("dc-h10-lugre-small", "coulomb_friction",
     {"friction": dict(fc=20.0, fs=33.0, vs=0.006, sigma0=1.35e6, sigma1=1.2e3, sigma2=95.0)},
     {"load": 168.0, "misstate": 0.0215}),
    ("dc-h10-backlash-tight", "backlash",
     {"backlash": dict(gap_m=1.35e-4, k_N_m=6.2e6, zeta=0.185, m_kg=0.78, c_ground=250.0)}, {"stroke": 0.0099}),
    ("dc-h10-backlash-loose", "backlash",
     {"backlash": dict(gap_m=3.3e-4, k_N_m=1.7e6, zeta=0.31, m_kg=2.3, c_ground=425.0)},
     {"load": 97.0, "misstate": 0.0375}),
    ("dc-h10-mount-high", "sensor_vibration", {"mount": dict(f_Hz=40.0, zeta=0.017, gain=0.19)},
     {"stroke": 0.0127, "load": 73.0}),
    ("dc-h10-mount-low", "sensor_vibration", {"mount": dict(f_Hz=17.0, zeta=0.036, gain=0.245)},
     {"stroke": 0.0091, "misstate": 0.0285}),
    ("dc-h10-pade-short", "sensor_delay", {"delay_s": 0.0052}, {"load": 208.0, "misstate": 0.0395}),
    ("dc-h10-pade-long", "sensor_delay", {"delay_s": 0.0128}, {"stroke": 0.0161, "sensor": NOISY10_DC}),
    ("dc-h10-ilimit", "current_saturation", {"current_limit": 4.3}, {"load": 127.0, "stroke": 0.0169}),
    ("dc-h10-lugre+ilimit", "coulomb_friction+current_saturation",
     {"friction": dict(fc=37.0, fs=54.0, vs=0.0034, sigma0=2.65e6, sigma1=1.95e3, sigma2=205.0),
      "current_limit": 4.9}, {"stroke": 0.0179, "misstate": 0.0245}),
    ("dc-h10-mount+ilimit", "sensor_vibration+current_saturation",
     {"mount": dict(f_Hz=21.0, zeta=0.029, gain=0.225), "current_limit": 5.3}, {"load": 152.0, "stroke": 0.0153}),
    ("dc-h10-ilimit+pade", "current_saturation+sensor_delay", {"current_limit": 4.7, "delay_s": 0.0092},
     {"stroke": 0.0131, "load": 187.0}),
    ("dc-h10-pulses", "outside:force_pulses", {"pulses": [(0.48, 0.027, 370.0), (1.38, 0.026, -410.0)]},
     {"stroke": 0.0104, "load": 118.0}),
    ("dc-h10-drift", "outside:thermal_drift", {"drift": 0.045}, {"stroke": 0.0139, "misstate": 0.0165}),
    ("dc-h10-amp-asym", "outside:amplifier_nonlinearity", {"amp_asymmetry": 0.76},
     {"stroke": 0.0157, "load": 262.0}),
]
PIEZO_HELDOUT10 = [
    ("pz-h10-null-2stacks", "none", {}, {"n_stacks": 2, "v_max": 139.0, "misstate": 0.034}),
    ("pz-h10-null-4stacks-spring", "none", {}, {"n_stacks": 4, "wide_in": 3.5, "load": (5.4, 1520.0),
                                                "v_max": 113.0, "misstate": 0.023}),
    ("pz-h10-null-noisy", "none", {}, {"wide_in": 3.25, "load": (9.3, 1280.0), "v_max": 149.0, "misstate": 0.016,
                                       "sensor": NOISY10_PZ}),
    ("pz-h10-seal-small", "seal_stick_slip", {"seal": dict(fc=1.6, fs=2.85, vs=3.0e-3, sigma2=0.0)},
     {"n_stacks": 2, "wide_in": 3.0, "v_max": 123.0}),
    ("pz-h10-seal-large", "seal_stick_slip", {"seal": dict(fc=3.7, fs=5.9, vs=1.55e-3, sigma2=0.0)},
     {"n_stacks": 4, "load": (6.4, 2080.0), "misstate": 0.043}),
    ("pz-h10-logcreep-small", "stack_creep", {"creep": 0.019}, {"wide_in": 3.0, "v_max": 117.0}),
    ("pz-h10-logcreep-large", "stack_creep", {"creep": 0.0335}, {"n_stacks": 4, "misstate": 0.015}),
    ("pz-h10-air-small", "fluid_compressibility", {"air": dict(eps0=0.0175, kappa=1.16)},
     {"load": (7.7, 1720.0), "n_stacks": 2}),
    ("pz-h10-air-large", "fluid_compressibility", {"air": dict(eps0=0.0295, kappa=1.29)},
     {"load": (5.3, 2380.0), "wide_in": 3.0}),
    ("pz-h10-pade", "sensor_delay", {"delay_s": 0.0098}, {"n_stacks": 2, "wide_in": 3.5, "v_max": 129.0}),
    ("pz-h10-bandwidth", "amplifier_slew_limit", {"bandwidth": dict(omega=400.0, slew=590.0)},
     {"n_stacks": 4, "wide_in": 3.0}),
    ("pz-h10-viscous", "viscous_damping", {"viscous": 360.0}, {"n_stacks": 2, "wide_in": 3.25, "misstate": 0.0225}),
    ("pz-h10-leak", "leakage", {"leak": dict(G=2.4e-14, area_m2=2.4e-10, cd=0.62)},
     {"load": (12.8, 980.0), "wide_in": 3.5}),
    ("pz-h10-creep+air", "stack_creep+fluid_compressibility",
     {"creep": 0.021, "air": dict(eps0=0.026, kappa=1.19)}, {"load": (4.3, 2480.0), "v_max": 143.0}),
    ("pz-h10-viscous+pade", "viscous_damping+sensor_delay", {"viscous": 460.0, "delay_s": 0.0082},
     {"n_stacks": 4, "wide_in": 3.25, "v_max": 127.0}),
    ("pz-h10-seal+creep", "seal_stick_slip+stack_creep",
     {"seal": dict(fc=2.9, fs=4.8, vs=1.75e-3, sigma2=0.0), "creep": 0.028},
     {"wide_in": 3.5, "v_max": 119.0, "misstate": 0.041}),
    ("pz-h10-drift", "outside:thermal_drift", {"drift": 0.027}, {"n_stacks": 2, "wide_in": 3.0, "misstate": 0.026}),
    ("pz-h10-pulses", "outside:force_pulses", {"pulses": [(0.42, 0.03, 3.6), (1.32, 0.026, -3.1)]},
     {"wide_in": 3.25, "v_max": 131.0, "misstate": 0.038}),
    ("pz-h10-amp-compression", "outside:amplifier_nonlinearity", {"amp_compression": 0.125},
     {"n_stacks": 4, "wide_in": 3.5, "v_max": 137.0}),
]

# The eleventh held-out set: written independently of the diagnosis, kept for
# a final measurement: it is not to be run while changing the diagnosis. None
# of these cases was run through the diagnosis while writing them (only
# checked to generate finite runs without warnings). Other sizes of every
# effect, other rigs (8.9-18.1 mm DC strokes, 47-268 N DC loads, DC
# misstatements of 1.35-4.45 %, 3, 3.25, 3.5 and 3.75 in pistons, two, three
# and four stacks, 104-146 V drives besides the 150 V default, other springs
# and preloads, piezo misstatements of 1.45-4.35 %), a noisier sensor of each
# kind, the DC pairs used least in a held-out set before
# (coulomb_friction+sensor_delay and backlash+current_saturation: twice each,
# last in the fifth and eighth sets; coulomb_friction+sensor_vibration, last
# in the eighth), three piezo pairs used once, in the fourth and fifth sets
# only (seal_stick_slip+sensor_delay, fluid_compressibility+leakage,
# stack_creep+amplifier_slew_limit), outside forms (DC cogging at a new, finer
# pitch, force pulses and drift; piezo drift, force pulses and amplifier
# compression) and other seeds (``--heldout11`` in
# benchmarks/diagnose_benchmark.py). Viscous damping stays below about 550 N
# s/m (see the second set).
NOISY11_DC = {"white": 1.48e-3, "flicker": 3.9e-4}
NOISY11_PZ = {"white": 1.47e-3, "flicker": 3.65e-4, "volt_white": 0.48}
DC_HELDOUT11 = [
    ("dc-h11-null-short", "none", {}, {"stroke": 0.0089, "misstate": 0.0445}),
    ("dc-h11-null-load", "none", {}, {"load": 268.0, "stroke": 0.0163, "misstate": 0.0195}),
    ("dc-h11-null-noisy", "none", {}, {"stroke": 0.0141, "load": 109.0, "misstate": 0.0275,
                                       "sensor": NOISY11_DC}),
    ("dc-h11-lugre-large", "coulomb_friction",
     {"friction": dict(fc=47.0, fs=64.0, vs=0.0021, sigma0=3.5e6, sigma1=2.5e3, sigma2=255.0)},
     {"stroke": 0.0171, "misstate": 0.0225}),
    ("dc-h11-lugre-small", "coulomb_friction",
     {"friction": dict(fc=18.5, fs=31.0, vs=0.0059, sigma0=1.45e6, sigma1=1.3e3, sigma2=85.0)},
     {"load": 214.0, "misstate": 0.0345}),
    ("dc-h11-backlash-tight", "backlash",
     {"backlash": dict(gap_m=1.18e-4, k_N_m=6.6e6, zeta=0.172, m_kg=0.74, c_ground=238.0)},
     {"stroke": 0.0151, "load": 63.0}),
    ("dc-h11-backlash-loose", "backlash",
     {"backlash": dict(gap_m=3.55e-4, k_N_m=1.45e6, zeta=0.325, m_kg=2.45, c_ground=445.0)},
     {"load": 147.0, "misstate": 0.0135}),
    ("dc-h11-mount-high", "sensor_vibration", {"mount": dict(f_Hz=49.0, zeta=0.0125, gain=0.15)},
     {"stroke": 0.0094, "load": 91.0}),
    ("dc-h11-mount-low", "sensor_vibration", {"mount": dict(f_Hz=14.5, zeta=0.041, gain=0.265)},
     {"misstate": 0.0385, "sensor": NOISY11_DC}),
    ("dc-h11-pade-short", "sensor_delay", {"delay_s": 0.0047}, {"load": 173.0, "misstate": 0.0295}),
    ("dc-h11-pade-long", "sensor_delay", {"delay_s": 0.0152}, {"stroke": 0.0119, "load": 47.0}),
    ("dc-h11-ilimit", "current_saturation", {"current_limit": 3.8}, {"load": 161.0, "stroke": 0.0181}),
    ("dc-h11-lugre+pade", "coulomb_friction+sensor_delay",
     {"friction": dict(fc=33.0, fs=48.0, vs=0.0039, sigma0=2.5e6, sigma1=1.8e3, sigma2=165.0), "delay_s": 0.0108},
     {"stroke": 0.0121, "misstate": 0.0415}),
    ("dc-h11-backlash+ilimit", "backlash+current_saturation",
     {"backlash": dict(gap_m=2.05e-4, k_N_m=3.0e6, zeta=0.245, m_kg=1.35, c_ground=325.0), "current_limit": 5.1},
     {"load": 133.0, "stroke": 0.0143}),
    ("dc-h11-lugre+mount", "coulomb_friction+sensor_vibration",
     {"friction": dict(fc=39.0, fs=56.0, vs=0.0031, sigma0=2.9e6, sigma1=2.05e3, sigma2=210.0),
      "mount": dict(f_Hz=23.0, zeta=0.025, gain=0.195)}, {"stroke": 0.0107, "load": 79.0}),
    ("dc-h11-cogging", "outside:cogging", {"cogging": dict(amp_N=37.0, pitch_m=2e-3 / 16)},
     {"stroke": 0.0159, "misstate": 0.0315}),
    ("dc-h11-pulses", "outside:force_pulses", {"pulses": [(0.62, 0.024, -360.0), (1.52, 0.029, 430.0)]},
     {"stroke": 0.0133, "load": 197.0}),
    ("dc-h11-drift", "outside:thermal_drift", {"drift": 0.042},
     {"load": 229.0, "stroke": 0.0113, "misstate": 0.0175}),
]
PIEZO_HELDOUT11 = [
    ("pz-h11-null-2stacks-3.25in", "none", {}, {"n_stacks": 2, "wide_in": 3.25, "v_max": 111.0, "misstate": 0.0435}),
    ("pz-h11-null-4stacks-spring", "none", {}, {"n_stacks": 4, "wide_in": 3.0, "load": (7.1, 2170.0),
                                                "v_max": 106.0, "misstate": 0.0185}),
    ("pz-h11-null-noisy", "none", {}, {"wide_in": 3.5, "load": (2.6, 2900.0), "misstate": 0.0265,
                                       "sensor": NOISY11_PZ}),
    ("pz-h11-seal-small", "seal_stick_slip", {"seal": dict(fc=1.45, fs=2.65, vs=3.3e-3, sigma2=0.0)},
     {"n_stacks": 4, "wide_in": 3.25, "v_max": 108.0}),
    ("pz-h11-seal-large", "seal_stick_slip", {"seal": dict(fc=3.45, fs=5.65, vs=1.5e-3, sigma2=0.0)},
     {"n_stacks": 2, "load": (5.9, 1830.0), "misstate": 0.0325}),
    ("pz-h11-logcreep-small", "stack_creep", {"creep": 0.0145}, {"n_stacks": 2, "wide_in": 3.5, "v_max": 134.0}),
    ("pz-h11-logcreep-large", "stack_creep", {"creep": 0.037}, {"wide_in": 3.0, "misstate": 0.0205}),
    ("pz-h11-air-small", "fluid_compressibility", {"air": dict(eps0=0.0155, kappa=1.27)},
     {"load": (10.4, 1240.0), "n_stacks": 4, "wide_in": 3.25}),
    ("pz-h11-air-large", "fluid_compressibility", {"air": dict(eps0=0.0345, kappa=1.14)},
     {"load": (3.9, 2620.0), "n_stacks": 2, "v_max": 104.0}),
    ("pz-h11-pade", "sensor_delay", {"delay_s": 0.0118}, {"n_stacks": 4, "wide_in": 3.5, "misstate": 0.0355}),
    ("pz-h11-bandwidth", "amplifier_slew_limit", {"bandwidth": dict(omega=335.0, slew=635.0)},
     {"n_stacks": 2, "wide_in": 3.25, "v_max": 146.0}),
    ("pz-h11-viscous", "viscous_damping", {"viscous": 395.0}, {"wide_in": 3.0, "v_max": 128.0, "misstate": 0.0145}),
    ("pz-h11-leak", "leakage", {"leak": dict(G=3.6e-14, area_m2=2.15e-10, cd=0.635)},
     {"load": (13.6, 1060.0), "n_stacks": 2, "wide_in": 3.0}),
    ("pz-h11-seal+pade", "seal_stick_slip+sensor_delay",
     {"seal": dict(fc=2.45, fs=4.05, vs=2.15e-3, sigma2=0.0), "delay_s": 0.0093}, {"wide_in": 3.0, "v_max": 111.0}),
    ("pz-h11-air+leak", "fluid_compressibility+leakage",
     {"air": dict(eps0=0.0235, kappa=1.33), "leak": dict(G=3.1e-14, area_m2=1.6e-10, cd=0.605)},
     {"load": (11.4, 1470.0), "wide_in": 3.5, "misstate": 0.0395}),
    ("pz-h11-creep+bandwidth", "stack_creep+amplifier_slew_limit",
     {"creep": 0.0235, "bandwidth": dict(omega=440.0, slew=575.0)}, {"n_stacks": 4, "v_max": 138.0}),
    ("pz-h11-drift", "outside:thermal_drift", {"drift": 0.032}, {"n_stacks": 4, "wide_in": 3.25, "v_max": 109.0}),
    ("pz-h11-pulses", "outside:force_pulses", {"pulses": [(0.58, 0.027, 3.9), (1.46, 0.031, -3.5)]},
     {"n_stacks": 2, "wide_in": 3.0, "misstate": 0.0245}),
    ("pz-h11-amp-compression", "outside:amplifier_nonlinearity", {"amp_compression": 0.155},
     {"wide_in": 3.5, "v_max": 141.0, "misstate": 0.0175}),
]

# The twelfth held-out set: written independently of the diagnosis, kept for a
# final measurement: it is not to be run while changing the diagnosis. None of
# these cases was run through the diagnosis while writing them (only checked
# to generate finite runs without warnings). Other sizes of every effect,
# other rigs (9.4-17.4 mm DC strokes, 56-252 N DC loads, DC misstatements of
# 1.55-4.25 %, 3, 3.25, 3.5 and 3.75 in pistons, two, three and four stacks,
# 112-145 V drives besides the 150 V default, other springs and preloads,
# piezo misstatements of 1.55-4.35 %), a noisier sensor of each kind, the DC
# pairs used least recently in a held-out set (backlash+sensor_delay, last in
# the eighth; sensor_vibration+sensor_delay, last in the ninth;
# coulomb_friction+current_saturation, last in the tenth: three times each),
# three piezo pairs used once, in the third and eighth sets only
# (viscous_damping+stack_creep, leakage+sensor_delay,
# seal_stick_slip+amplifier_slew_limit), outside forms (DC cogging at a new
# pitch, force pulses and amplifier asymmetry; piezo drift, force pulses and
# amplifier compression) and other seeds (``--heldout12`` in
# benchmarks/diagnose_benchmark.py). Viscous damping stays below about 550 N
# s/m (see the second set).
NOISY12_DC = {"white": 1.46e-3, "flicker": 3.75e-4}
NOISY12_PZ = {"white": 1.41e-3, "flicker": 3.6e-4, "volt_white": 0.455}
DC_HELDOUT12 = [
    ("dc-h12-null-mid", "none", {}, {"stroke": 0.0147, "misstate": 0.0365}),
    ("dc-h12-null-load", "none", {}, {"load": 252.0, "stroke": 0.0108, "misstate": 0.0215}),
    ("dc-h12-null-noisy", "none", {}, {"stroke": 0.0166, "load": 84.0, "misstate": 0.0155,
                                       "sensor": NOISY12_DC}),
    ("dc-h12-lugre-large", "coulomb_friction",
     {"friction": dict(fc=51.0, fs=68.0, vs=0.0024, sigma0=3.9e6, sigma1=2.45e3, sigma2=285.0)},
     {"stroke": 0.0137, "misstate": 0.0265}),
    ("dc-h12-lugre-small", "coulomb_friction",
     {"friction": dict(fc=21.5, fs=35.0, vs=0.0056, sigma0=1.25e6, sigma1=1.15e3, sigma2=90.0)},
     {"load": 196.0, "misstate": 0.0425}),
    ("dc-h12-backlash-tight", "backlash",
     {"backlash": dict(gap_m=1.25e-4, k_N_m=5.9e6, zeta=0.19, m_kg=0.82, c_ground=262.0)},
     {"stroke": 0.0174, "load": 71.0}),
    ("dc-h12-backlash-loose", "backlash",
     {"backlash": dict(gap_m=3.45e-4, k_N_m=1.55e6, zeta=0.34, m_kg=2.6, c_ground=438.0)},
     {"load": 122.0, "misstate": 0.0185}),
    ("dc-h12-mount-high", "sensor_vibration", {"mount": dict(f_Hz=44.0, zeta=0.0135, gain=0.16)},
     {"stroke": 0.0101, "load": 103.0}),
    ("dc-h12-mount-low", "sensor_vibration", {"mount": dict(f_Hz=16.0, zeta=0.039, gain=0.255)},
     {"misstate": 0.0335, "sensor": NOISY12_DC}),
    ("dc-h12-pade-short", "sensor_delay", {"delay_s": 0.0057}, {"load": 184.0, "misstate": 0.0245}),
    ("dc-h12-pade-long", "sensor_delay", {"delay_s": 0.0146}, {"stroke": 0.0129, "load": 56.0}),
    ("dc-h12-ilimit", "current_saturation", {"current_limit": 4.45}, {"load": 139.0, "stroke": 0.0161}),
    ("dc-h12-backlash+pade", "backlash+sensor_delay",
     {"backlash": dict(gap_m=2.6e-4, k_N_m=2.7e6, zeta=0.275, m_kg=1.7, c_ground=365.0), "delay_s": 0.0086},
     {"stroke": 0.0153, "misstate": 0.0305}),
    ("dc-h12-lugre+ilimit", "coulomb_friction+current_saturation",
     {"friction": dict(fc=35.0, fs=51.0, vs=0.0037, sigma0=2.75e6, sigma1=1.9e3, sigma2=190.0),
      "current_limit": 5.0}, {"load": 158.0, "stroke": 0.0118}),
    ("dc-h12-mount+pade", "sensor_vibration+sensor_delay",
     {"mount": dict(f_Hz=31.0, zeta=0.023, gain=0.2), "delay_s": 0.0069}, {"stroke": 0.0135, "load": 94.0}),
    ("dc-h12-cogging", "outside:cogging", {"cogging": dict(amp_N=41.0, pitch_m=2e-3 / 15)},
     {"stroke": 0.0126, "load": 115.0}),
    ("dc-h12-pulses", "outside:force_pulses", {"pulses": [(0.52, 0.025, 395.0), (1.42, 0.03, -340.0)]},
     {"stroke": 0.0094, "misstate": 0.0395}),
    ("dc-h12-amp-asym", "outside:amplifier_nonlinearity", {"amp_asymmetry": 0.83},
     {"load": 216.0, "stroke": 0.0142}),
]
PIEZO_HELDOUT12 = [
    ("pz-h12-null-3stacks-3.25in", "none", {}, {"wide_in": 3.25, "v_max": 132.0, "misstate": 0.0285}),
    ("pz-h12-null-2stacks-spring", "none", {}, {"n_stacks": 2, "wide_in": 3.5, "load": (6.1, 1640.0),
                                                "v_max": 116.0, "misstate": 0.0405}),
    ("pz-h12-null-noisy", "none", {}, {"n_stacks": 4, "wide_in": 3.0, "load": (4.8, 2290.0), "v_max": 145.0,
                                       "misstate": 0.0195, "sensor": NOISY12_PZ}),
    ("pz-h12-seal-small", "seal_stick_slip", {"seal": dict(fc=1.4, fs=2.75, vs=3.4e-3, sigma2=0.0)},
     {"n_stacks": 2, "wide_in": 3.5, "v_max": 121.0}),
    ("pz-h12-seal-large", "seal_stick_slip", {"seal": dict(fc=3.35, fs=5.45, vs=1.6e-3, sigma2=0.0)},
     {"n_stacks": 4, "wide_in": 3.25, "load": (7.8, 1390.0), "misstate": 0.0345}),
    ("pz-h12-logcreep-small", "stack_creep", {"creep": 0.0175}, {"n_stacks": 4, "wide_in": 3.0, "v_max": 112.0}),
    ("pz-h12-logcreep-large", "stack_creep", {"creep": 0.0325}, {"n_stacks": 2, "misstate": 0.0255}),
    ("pz-h12-air-small", "fluid_compressibility", {"air": dict(eps0=0.0135, kappa=1.22)},
     {"load": (9.9, 1150.0), "wide_in": 3.0, "v_max": 135.0}),
    ("pz-h12-air-large", "fluid_compressibility", {"air": dict(eps0=0.0315, kappa=1.31)},
     {"load": (4.1, 2730.0), "n_stacks": 4, "misstate": 0.0225}),
    ("pz-h12-pade", "sensor_delay", {"delay_s": 0.0109}, {"n_stacks": 2, "wide_in": 3.25, "v_max": 142.0}),
    ("pz-h12-bandwidth", "amplifier_slew_limit", {"bandwidth": dict(omega=375.0, slew=560.0)},
     {"n_stacks": 4, "wide_in": 3.5, "misstate": 0.0155}),
    ("pz-h12-viscous", "viscous_damping", {"viscous": 425.0}, {"n_stacks": 2, "wide_in": 3.0, "v_max": 133.0}),
    ("pz-h12-leak", "leakage", {"leak": dict(G=2.9e-14, area_m2=1.9e-10, cd=0.625)},
     {"load": (12.2, 1160.0), "n_stacks": 4, "wide_in": 3.25}),
    ("pz-h12-viscous+creep", "viscous_damping+stack_creep", {"viscous": 335.0, "creep": 0.0245},
     {"wide_in": 3.5, "v_max": 118.0, "misstate": 0.0315}),
    ("pz-h12-leak+pade", "leakage+sensor_delay",
     {"leak": dict(G=3.3e-14, area_m2=1.8e-10, cd=0.615), "delay_s": 0.0079},
     {"load": (11.1, 1360.0), "n_stacks": 2, "wide_in": 3.0}),
    ("pz-h12-seal+bandwidth", "seal_stick_slip+amplifier_slew_limit",
     {"seal": dict(fc=2.3, fs=3.85, vs=2.05e-3, sigma2=0.0), "bandwidth": dict(omega=355.0, slew=655.0)},
     {"n_stacks": 4, "v_max": 126.0, "misstate": 0.0435}),
    ("pz-h12-drift", "outside:thermal_drift", {"drift": 0.034}, {"n_stacks": 2, "wide_in": 3.25, "misstate": 0.0365}),
    ("pz-h12-pulses", "outside:force_pulses", {"pulses": [(0.47, 0.029, -3.8), (1.37, 0.027, 3.3)]},
     {"wide_in": 3.5, "v_max": 139.0}),
    ("pz-h12-amp-compression", "outside:amplifier_nonlinearity", {"amp_compression": 0.14},
     {"n_stacks": 4, "wide_in": 3.0, "misstate": 0.0275}),
]

# Each set: its DC and piezo tables and the seed offset of its campaigns
# (other noise and misstatements per set).
SETS = {
    "dev": (DC, PIEZO, 0),
    "heldout": (DC_HELDOUT, PIEZO_HELDOUT, 5000),
    "heldout2": (DC_HELDOUT2, PIEZO_HELDOUT2, 9000),
    "heldout3": (DC_HELDOUT3, PIEZO_HELDOUT3, 13000),
    "heldout4": (DC_HELDOUT4, PIEZO_HELDOUT4, 17000),
    "heldout5": (DC_HELDOUT5, PIEZO_HELDOUT5, 21000),
    "heldout6": (DC_HELDOUT6, PIEZO_HELDOUT6, 25000),
    "heldout7": (DC_HELDOUT7, PIEZO_HELDOUT7, 29000),
    "heldout8": (DC_HELDOUT8, PIEZO_HELDOUT8, 33000),
    "heldout9": (DC_HELDOUT9, PIEZO_HELDOUT9, 37000),
    "heldout10": (DC_HELDOUT10, PIEZO_HELDOUT10, 41000),
    "heldout11": (DC_HELDOUT11, PIEZO_HELDOUT11, 45000),
    "heldout12": (DC_HELDOUT12, PIEZO_HELDOUT12, 49000),
}


def generate(case, seed: int, technology: str):
    """(rig.toml, runs, holdout run) of one case."""
    from . import dc, piezo

    name, truth, effects, options = case
    if technology == "dc_motor":
        keys = ("stroke", "misstate", "load", "sensor")
        rig, runs = dc.campaign(effects, seed, **{k: options[k] for k in keys if k in options})
        return rig, runs, "stairs_b"
    keys = ("v_max", "misstate", "load", "n_stacks", "wide_in", "sensor")
    rig, runs = piezo.campaign(effects, seed, **{k: options[k] for k in keys if k in options})
    return rig, runs, "stairs_b"
