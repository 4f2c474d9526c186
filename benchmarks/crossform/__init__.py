"""A second, independent generator of test campaigns for `sizing diagnose`.

Written without importing anything from sizing.diagnose or sizing.sim: its
own integrator (classical fixed-step Runge-Kutta 4 on its own state forms,
operator splitting for the friction and stick states), its own forms of the
effects (LuGre friction with Stribeck, log creep as a sum of decades,
backlash with contact stiffness and a load mass, a resonant sensor mount
driven by the output's acceleration, second-order Pade delay, entrained air
with a pressure-dependent bulk modulus, orifice leakage, amplifier
bandwidth), effects outside the diagnose library (cogging, thermal drift,
external force pulses, amplifier gain asymmetry), a nominal stated a few
percent off the truth, and noise that is white plus 1/f plus quantisation.
It writes campaign folders (rig.toml and runs/NAME.csv) by itself.
"""
