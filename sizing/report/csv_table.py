"""candidates.csv: one row per candidate, the flat view of results.json."""
from __future__ import annotations

import csv
import io

COMPONENTS = ("stack", "n_stacks", "ratio", "fluid", "seal", "amplifier", "actuator")
STATIC = ("free_stroke_m", "blocked_force_N", "blocked_force_compliant_N", "blocked_pressure_Pa",
          "natural_frequency_Hz", "required_current_A", "thermal_drift_m", "wide_diameter_m", "narrow_diameter_m")
SIMULATED = ("stroke_m", "time_to_stroke_s", "speed_m_s", "overshoot")
METRICS = ("mass_kg", "cost_usd", "volume_m3", "power_W")


def candidates_csv(results: dict) -> str:
    margin_keys = sorted({k for c in results["candidates"] for k in c["margins"]})
    header = (["rank", "id", "technology", "name", "variant", "stage", "feasible", "driver", "pareto"]
              + list(COMPONENTS) + [f"static_{k}" for k in STATIC] + [f"simulated_{k}" for k in SIMULATED]
              + [f"margin_{k}" for k in margin_keys] + list(METRICS))
    out = io.StringIO()
    w = csv.writer(out, lineterminator="\n")
    w.writerow(header)
    for c in results["candidates"]:
        comp, st, sim, m = c["components"], c.get("static", {}), c.get("simulated", {}), c.get("metrics", {})
        row = [c["rank"], c["id"], c["technology"], c.get("name", ""), c.get("variant", ""), c.get("stage", ""), c["feasible"],
               c["driver"], c["pareto"]]
        row += [comp.get(k, "") for k in COMPONENTS]
        row += [st.get(k, "") for k in STATIC] + [sim.get(k, "") for k in SIMULATED]
        row += [c["margins"].get(k, "") for k in margin_keys] + [m.get(k, "") for k in METRICS]
        w.writerow(["" if v is None else v for v in row])
    return out.getvalue()
